#include "cli_args.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "gl/shader_program.h"

namespace ig::app {
namespace {

// A CLI11 validator from a check that throws UsageError("flag: reason"):
// CLI11 prefixes the option's name itself, so only the reason is kept.
template <class Check>
CLI::Validator validator(const char* description, Check check) {
  return CLI::Validator(
      [check](std::string& value) -> std::string {
        try {
          check(value);
          return {};
        } catch (const UsageError& e) {
          const std::string what = e.what();
          return what.substr(what.find(": ") + 2);
        }
      },
      description);
}

// All of `text` read by `read` (std::stol, std::stod: value, characters
// used); nullopt when it does not parse or leaves characters over.
template <class Read>
auto read_whole(const std::string& text, Read read) -> std::optional<decltype(read(text, nullptr))> {
  size_t used = 0;
  try {
    const auto value = read(text, &used);
    if (used == text.size()) return value;
  } catch (const std::logic_error&) {  // std::invalid_argument, std::out_of_range
  }
  return std::nullopt;
}

}  // namespace

int parse_positive_int(const std::string& flag, const std::string& v) {
  const auto n = read_whole(v, [](const std::string& t, size_t* used) { return std::stol(t, used); });
  if (!n || *n <= 0 || *n > 1000000000L) throw UsageError(flag + ": expected a positive integer, got '" + v + "'");
  return int(*n);
}

double parse_double(const std::string& flag, const std::string& v) {
  const auto d = read_whole(v, [](const std::string& t, size_t* used) { return std::stod(t, used); });
  if (!d || !std::isfinite(*d)) throw UsageError(flag + ": expected a number, got '" + v + "'");
  return *d;
}

namespace {
// `text` broken into lines of at most `width` characters (words kept whole).
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines(1);
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!lines.back().empty() && lines.back().size() + 1 + word.size() > width) lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + word;
    start = end + 1;
  }
  return lines;
}
}  // namespace

std::string describe_options(const CLI::App& app, int width) {
  constexpr std::size_t kColumn = 26;  // where descriptions start
  std::string out;
  auto block = [&](const std::string& head, const std::string& description) {
    const auto lines = wrap(description, std::size_t(std::max(width, 60)) - kColumn);
    std::string first = "  " + head;
    if (first.size() + 1 < kColumn) {
      first.resize(kColumn, ' ');
    } else {
      out += first + "\n";
      first = std::string(kColumn, ' ');
    }
    out += first + lines.front() + "\n";
    for (std::size_t k = 1; k < lines.size(); ++k) out += std::string(kColumn, ' ') + lines[k] + "\n";
  };
  const auto positionals = app.get_options([](const CLI::Option* o) { return o->get_positional(); });
  if (!positionals.empty()) out += "arguments:\n";
  for (const CLI::Option* o : positionals) block(o->get_option_text().empty() ? o->get_name() : o->get_option_text(), o->get_description());
  const auto options = app.get_options([](const CLI::Option* o) { return o->nonpositional(); });
  if (!options.empty()) out += "options:\n";
  for (const CLI::Option* o : options) {
    std::string head = o->get_name();
    if (!o->get_option_text().empty()) head += " " + o->get_option_text();
    block(head, o->get_description());
  }
  block("--help", "print this help and exit");
  return out;
}

void parse_command_line(CLI::App& app, const std::vector<std::string>& argv) {
  app.set_help_flag();
  if (help_requested(argv)) throw HelpRequested{describe_options(app)};
  app.allow_extras();
  for (CLI::Option* option : app.get_options())  // given twice, the last value counts (repeatable ones keep all)
    if (option->get_multi_option_policy() == CLI::MultiOptionPolicy::Throw)
      option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  try {
    app.parse(std::vector<std::string>(argv.rbegin(), argv.rend()));
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  for (const std::string& extra : app.remaining()) {
    if (!extra.empty() && extra[0] == '-') throw UsageError("unknown option " + extra);
    throw UsageError("unexpected argument " + extra);
  }
}

const CLI::Validator& positive_int() {
  static const CLI::Validator v = validator("N>0", [](const std::string& s) { parse_positive_int("", s); });
  return v;
}

const CLI::Validator& positive_number() {
  static const CLI::Validator v = validator("X>0", [](const std::string& s) {
    if (!(parse_double("", s) > 0)) throw UsageError(": must be > 0");
  });
  return v;
}

const CLI::Validator& probability() {
  static const CLI::Validator v = validator("P in [0, 1]", [](const std::string& s) {
    const double d = parse_double("", s);
    if (!(d >= 0 && d <= 1)) throw UsageError(": must be in [0, 1]");
  });
  return v;
}

const CLI::Validator& can_node_id() {
  static const CLI::Validator v = validator("0..255", [](const std::string& s) {
    char* end = nullptr;
    const long n = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end || n < 0 || n > 255) throw UsageError(": expected 0..255, got '" + s + "'");
  });
  return v;
}

const CLI::Validator& can_altitude_id() {
  static const CLI::Validator v = validator("320|322|332", [](const std::string& s) {
    const int id = parse_positive_int("", s);
    if (id != 320 && id != 322 && id != 332)
      throw UsageError(": expected 320, 322 or 332, got " + std::to_string(id));
  });
  return v;
}

CLI::Validator one_of(std::vector<std::string> choices) {
  std::string list;
  for (size_t k = 0; k < choices.size(); ++k)
    list += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k];
  return validator(list.c_str(), [choices, list](const std::string& s) {
    if (std::find(choices.begin(), choices.end(), s) == choices.end())
      throw UsageError(": expected " + list + ", got '" + s + "'");
  });
}

CLI::Option* add_view_options(CLI::App& app, session::RunOptions& run) {
  add_size_option(app, "--size", run.width, run.height)
      ->description("image size in pixels, e.g. 320x240 (default: the scenario's render.width x render.height)")
      ->option_text("WxH");
  app.add_option("--method", run.method,
                 "terrain LOD method: twolevel, reference, roam, geomipmap, chunked, quadtree or cdlod "
                 "(default: the scenario's render.method, else twolevel)")
      ->option_text("NAME");
  auto* headless = app.add_flag("--headless")->description("render off-screen (EGL, no display needed; the default)");
  return app.add_flag("--window")
      ->description("show the (first) channel in a window (GLFW, needs X); stops when it is closed")
      ->excludes(headless);
}

CLI::Option* add_shader_dir_option(CLI::App& app, std::string& dir) {
  return app.add_option("--shader-dir", dir,
                        "where the GLSL shaders are (default: shaders/ beside the binary, or $IG_SHADER_DIR)")
      ->option_text("DIR");
}

CLI::Option* add_size_option(CLI::App& app, const std::string& name, std::optional<int>& width,
                             std::optional<int>& height) {
  return app.add_option_function<std::string>(name, [name, &width, &height](const std::string& v) {
    const auto x = v.find('x');
    width = parse_positive_int(name, v.substr(0, x));
    height = parse_positive_int(name, v.substr(x + 1));
  })->check(validator("WxH", [](const std::string& v) {
    const auto x = v.find('x');
    if (x == std::string::npos) throw UsageError(": expected WxH, got '" + v + "'");
    parse_positive_int("", v.substr(0, x));
    parse_positive_int("", v.substr(x + 1));
  }));
}

std::string default_scenario_file() {
  if (auto dir = gl::installed_data_dir("scenarios", "default.json"); !dir.empty()) return dir + "/default.json";
  return "scenarios/default.json";  // relative to the working directory: no source path is compiled in
}

}  // namespace ig::app
