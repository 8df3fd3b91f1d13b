#pragma once
// ISO 8601 UTC times for the scenario's environment.time_utc:
// "YYYY-MM-DDThh:mm[:ss[.fff]]Z" ("+00:00" is accepted for "Z").

#include <optional>
#include <string>
#include <string_view>

#include "options/shading_options.h"

namespace ig::io {

// Years the sun's ephemeris is made for (environment/sun_position.h).
constexpr int kMinUtcYear = 1900;
constexpr int kMaxUtcYear = 2100;

// The time, or nullopt with `why` set to a one-line reason (bad form, a
// field out of range, a day the month does not have, a zone other than UTC,
// a year outside [kMinUtcYear, kMaxUtcYear]). Leap seconds (:60) are refused.
std::optional<options::UtcDateTime> parse_utc_time(std::string_view text, std::string& why);
// This machine's clock, in UTC.
options::UtcDateTime utc_now();

}  // namespace ig::io
