#include "io/utc_time.h"

#include <chrono>

namespace ig::io {
namespace {

// Reads exactly `n` digits at `pos`; advances pos.
bool digits(std::string_view s, std::size_t& pos, int n, int& value) {
  if (pos + n > s.size()) return false;
  value = 0;
  for (int k = 0; k < n; ++k) {
    const char c = s[pos + k];
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  pos += n;
  return true;
}

bool expect(std::string_view s, std::size_t& pos, char c) {
  if (pos >= s.size() || s[pos] != c) return false;
  ++pos;
  return true;
}

}  // namespace

std::optional<options::UtcDateTime> parse_utc_time(std::string_view s, std::string& why) {
  const std::string form = "must be an ISO 8601 UTC time YYYY-MM-DDThh:mm[:ss[.fff]]Z, e.g. 2026-06-21T14:30:00Z";
  options::UtcDateTime t;
  std::size_t pos = 0;
  if (!digits(s, pos, 4, t.year) || !expect(s, pos, '-') || !digits(s, pos, 2, t.month) || !expect(s, pos, '-') ||
      !digits(s, pos, 2, t.day)) {
    why = form;
    return std::nullopt;
  }
  if (pos == s.size()) {
    why = form + " (the time of day is missing)";
    return std::nullopt;
  }
  if (!expect(s, pos, 'T') || !digits(s, pos, 2, t.hour) || !expect(s, pos, ':') || !digits(s, pos, 2, t.minute)) {
    why = form;
    return std::nullopt;
  }
  int whole = 0;
  if (pos < s.size() && s[pos] == ':') {
    ++pos;
    if (!digits(s, pos, 2, whole)) {
      why = form;
      return std::nullopt;
    }
    t.second = whole;
    if (pos < s.size() && s[pos] == '.') {
      ++pos;
      double scale = 0.1;
      const std::size_t first = pos;
      while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') {
        t.second += (s[pos] - '0') * scale;
        scale *= 0.1;
        ++pos;
      }
      if (pos == first) {
        why = form + " (no digits after the decimal point)";
        return std::nullopt;
      }
    }
  }
  const std::string_view zone = s.substr(pos);
  if (zone.empty()) {
    why = form + " (the zone is missing: end the time with Z for UTC)";
    return std::nullopt;
  }
  if (zone != "Z" && zone != "+00:00") {
    why = "must be in UTC (end with Z, or +00:00): convert local times to UTC";
    return std::nullopt;
  }
  if (t.year < kMinUtcYear || t.year > kMaxUtcYear) {
    why = "year " + std::to_string(t.year) + " is outside " + std::to_string(kMinUtcYear) + ".." +
          std::to_string(kMaxUtcYear) + " (the span the sun's ephemeris is made for)";
    return std::nullopt;
  }
  if (t.month < 1 || t.month > 12) {
    why = "month " + std::to_string(t.month) + " is not 01..12";
    return std::nullopt;
  }
  const std::chrono::year_month_day ymd{std::chrono::year(t.year), std::chrono::month(unsigned(t.month)),
                                        std::chrono::day(unsigned(t.day))};
  if (!ymd.ok()) {
    why = "day " + std::to_string(t.day) + " does not exist in " + std::to_string(t.year) + "-" +
          (t.month < 10 ? "0" : "") + std::to_string(t.month);
    return std::nullopt;
  }
  if (t.hour > 23) {
    why = "hour " + std::to_string(t.hour) + " is not 00..23";
    return std::nullopt;
  }
  if (t.minute > 59) {
    why = "minute " + std::to_string(t.minute) + " is not 00..59";
    return std::nullopt;
  }
  if (whole > 59) {
    why = "second " + std::to_string(whole) + " is not 00..59 (leap seconds are not taken)";
    return std::nullopt;
  }
  return t;
}

options::UtcDateTime utc_now() {
  const auto now = std::chrono::system_clock::now();
  const auto day = std::chrono::floor<std::chrono::days>(now);
  const std::chrono::year_month_day ymd(day);
  const std::chrono::hh_mm_ss time(std::chrono::duration_cast<std::chrono::milliseconds>(now - day));
  return {int(ymd.year()), int(unsigned(ymd.month())), int(unsigned(ymd.day())), int(time.hours().count()),
          int(time.minutes().count()), double(time.seconds().count()) + time.subseconds().count() / 1000.0};
}

}  // namespace ig::io
