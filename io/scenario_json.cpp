#include "io/scenario_json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace ig::io::scenario_json {


// Error helpers. Internal errors carry "<key path>: <reason>"; the public
// entry points prefix the origin (file name or "<string>").

[[noreturn]] void fail(const std::string& key_path, const std::string& reason) {
  throw ScenarioError(key_path + ": " + reason);
}

std::string child(const std::string& path, std::string_view key) {
  // A key that is not a plain name (a space, a dot, nothing) is quoted, so
  // "hpr " reads as itself in a message.
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
  std::string out = path;
  if (!out.empty()) out += '.';
  if (!plain) out += '"';
  out.append(key.data(), key.size());
  if (!plain) out += '"';
  return out;
}

std::string element(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// Shortest text that reads back as the same double.
std::string num(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// The offending value, shortened, for "(got ...)" in messages.
std::string shown(const json& j) {
  std::string s = j.is_number() ? num(j.get<double>()) : j.dump();
  if (s.size() > 48) s = s.substr(0, 45) + "...";
  return s;
}

std::string got(const json& j) { return " (got " + shown(j) + ")"; }

// Typed getters. Every one names the key path on failure.

void require_object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("must be an object (got ") + j.type_name() + ")");
}

void require_array(const json& j, const std::string& path) {
  if (!j.is_array()) fail(path, std::string("must be an array (got ") + j.type_name() + ")");
}

// Rejects every key of object `j` that is not listed.
void check_keys(const json& j, const std::string& path, std::initializer_list<std::string_view> allowed) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) {
      if (!list.empty()) list += ", ";
      list += a;
    }
    fail(child(path, key), "unknown key (expected one of: " + list + ")");
  }
}

double get_number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, std::string("must be a number (got ") + j.type_name() + ")");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "must be a finite number");
  return v;
}

// Closed range [lo, hi].
double get_number_in(const json& j, const std::string& path, double lo, double hi) {
  const double v = get_number(j, path);
  if (!(v >= lo && v <= hi)) fail(path, "must be in [" + num(lo) + ", " + num(hi) + "]" + got(j));
  return v;
}

// (0, hi]
double get_positive(const json& j, const std::string& path, double hi) {
  const double v = get_number(j, path);
  if (!(v > 0.0 && v <= hi)) fail(path, "must be > 0 and <= " + num(hi) + got(j));
  return v;
}

long long get_integer(const json& j, const std::string& path, long long lo, long long hi) {
  const std::string range = "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
  if (!j.is_number()) fail(path, range + " (got " + j.type_name() + ")");
  if (j.is_number_unsigned()) {
    const auto u = j.get<unsigned long long>();
    if (hi < 0 || u > static_cast<unsigned long long>(hi) || static_cast<long long>(u) < lo) fail(path, range + got(j));
    return static_cast<long long>(u);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<long long>();
    if (v < lo || v > hi) fail(path, range + got(j));
    return v;
  }
  // A float that happens to be integral (e.g. 640.0) is accepted.
  const double d = j.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || d < static_cast<double>(lo) ||
      d > static_cast<double>(hi)) {
    fail(path, range + got(j));
  }
  return static_cast<long long>(d);
}

std::string get_string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, std::string("must be a string (got ") + j.type_name() + ")");
  return j.get<std::string>();
}

std::string get_nonempty_string(const json& j, const std::string& path) {
  std::string s = get_string(j, path);
  if (s.empty()) fail(path, "must be a non-empty string");
  return s;
}

bool get_bool(const json& j, const std::string& path) {
  if (!j.is_boolean()) fail(path, std::string("must be true or false (got ") + j.type_name() + ")");
  return j.get<bool>();
}

std::string get_choice(const json& j, const std::string& path, std::initializer_list<std::string_view> choices) {
  std::string list;
  for (std::string_view c : choices) {
    if (!list.empty()) list += "|";
    list += c;
  }
  if (!j.is_string()) fail(path, "must be one of " + list + " (got " + j.type_name() + ")");
  const std::string s = j.get<std::string>();
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) {
    fail(path, "must be one of " + list + got(j));
  }
  return s;
}

std::array<double, 3> get_vec3(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) {
    fail(path, std::string("must be an array of 3 numbers (got ") +
                   (j.is_array() ? std::to_string(j.size()) + " elements" : std::string(j.type_name())) + ")");
  }
  std::array<double, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) v[i] = get_number(j[i], element(path, i));
  return v;
}

glm::vec3 get_colour(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) {
    fail(path, std::string("must be an array of 3 numbers in [0, 1] (got ") +
                   (j.is_array() ? std::to_string(j.size()) + " elements" : std::string(j.type_name())) + ")");
  }
  glm::vec3 c{};
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<float>(get_number_in(j[i], element(path, std::size_t(i)), 0.0, 1.0));
  }
  return c;
}

// Names end up in output file names: keep them to something path-safe.
std::string get_name(const json& j, const std::string& path) {
  std::string s = get_nonempty_string(j, path);
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f || c == '/' || c == '\\') {
      fail(path, "must not contain '/', '\\' or control characters" + got(j));
    }
  }
  if (s == "." || s == "..") fail(path, "must not be \".\" or \"..\"");
  return s;
}

}  // namespace ig::io::scenario_json
