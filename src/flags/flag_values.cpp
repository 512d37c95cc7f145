#include "flags/flag_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace raycam::flags {

namespace {
std::optional<double> finite_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  // ERANGE is also set on underflow (a subnormal or zero result): those are in-range values. Overflow
  // returns ±HUGE_VAL, which the isfinite test refuses.
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// The deepest subcommand the parser selected (the root itself when none was).
const CLI::App& selected_command(const CLI::App& app) {
  const CLI::App* at = &app;
  for (;;) {
    const CLI::App* next = nullptr;
    for (const CLI::App* sub : at->get_subcommands())  // those parsed; option groups are nameless
      if (!sub->get_name().empty()) next = sub;
    if (!next) return *at;
    at = next;
  }
}

std::string command_path(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* up = command.get_parent(); up; up = up->get_parent())
    if (!up->get_name().empty()) path = up->get_name() + " " + path;
  return path;
}

// The option called `name` in `command` or its option groups, or nullptr.
const CLI::Option* find_option(const CLI::App& command, const std::string& name) {
  for (const CLI::Option* option : command.get_options())
    if (option->check_name(name)) return option;
  for (const CLI::App* group :
       command.get_subcommands([](const CLI::App* sub) { return sub->get_name().empty(); }))
    if (const CLI::Option* option = find_option(*group, name)) return option;
  return nullptr;
}
}  // namespace

std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  std::string s = text;
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

std::string name_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return list;
}

std::string bad_value_message(const std::string& flag, const std::string& expected, const std::string& got) {
  return flag + ": expected " + expected + ", got '" + got + "'";
}

ValueRule<double> number_in(Interval range, const std::string& noun) {
  const std::string expected = noun + " in " + (range.lo_open ? "]" : "[") + short_number(range.lo) + ", " +
                               short_number(range.hi) + (range.hi_open ? "[" : "]");
  return {expected, [range](const std::string& text) -> std::optional<double> {
            const std::optional<double> x = finite_number(text);
            if (!x) return std::nullopt;
            const bool above_lo = range.lo_open ? *x > range.lo : *x >= range.lo;
            const bool below_hi = range.hi_open ? *x < range.hi : *x <= range.hi;
            if (!above_lo || !below_hi) return std::nullopt;
            return x;
          }};
}

ValueRule<int> integer_in(int lo, int hi) {
  return {"an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
          [lo, hi](const std::string& text) -> std::optional<int> {
            if (text.empty()) return std::nullopt;
            char* end = nullptr;
            errno = 0;
            const long value = std::strtol(text.c_str(), &end, 10);
            if (end != text.c_str() + text.size() || errno == ERANGE || value < lo || value > hi)
              return std::nullopt;
            return int(value);
          }};
}

ValueRule<int> one_of(const std::vector<std::string>& names) {
  return {name_list(names), [names](const std::string& text) -> std::optional<int> {
            const auto at = std::find(names.begin(), names.end(), text);
            if (at == names.end()) return std::nullopt;
            return int(at - names.begin());
          }};
}

ValueRule<std::string> file_name() {
  return {"a file name", [](const std::string& text) -> std::optional<std::string> {
            if (text.empty()) return std::nullopt;
            return text;
          }};
}

std::string usage_error_message(const CLI::App& app, const CLI::Error& error) {
  const CLI::App& command = selected_command(app);
  const std::string see = " (see " + command_path(command) + " --help)";
  if (dynamic_cast<const CLI::ValidationError*>(&error)) return error.what();  // "--res: expected …, got '…'"
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    // CLI11: "--threads: 1 required T missing" (or "Expected exactly 1 arguments to --threads, got 0").
    const std::string text = error.what();
    std::string name = text.substr(0, text.find(':'));
    if (name.rfind("Expected", 0) == 0) {
      const std::size_t to = text.find(" to ");
      name = to == std::string::npos ? name : text.substr(to + 4, text.find(',', to) - to - 4);
    }
    if (const CLI::Option* option = find_option(command, name)) {
      // Given twice ("--student: At Most 1 required but received 2"): one message, not CLI11's.
      if (text.find("received") != std::string::npos) return name + ": expected one value, given more than once";
      std::string expected = "a value";
      try {
        const CLI::Validator* rule = const_cast<CLI::Option*>(option)->get_validator(0);
        if (rule && !rule->get_name().empty()) expected = rule->get_name();
      } catch (const CLI::OptionNotFound&) {  // an option without a rule
      }
      return name + ": expected " + expected + ", got nothing";
    }
    return text + see;
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error) && command.get_require_subcommand_min() > 0 &&
      command.get_subcommands().empty()) {
    std::vector<std::string> names;
    for (const CLI::App* sub :
         command.get_subcommands([](const CLI::App* s) { return !s->get_name().empty(); }))
      names.push_back(sub->get_name());
    return "expected a command: " + name_list(names) + see;
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    const std::vector<std::string> extras = command.remaining();
    if (!extras.empty()) {
      const std::string& first = extras.front();
      return (first.rfind("-", 0) == 0 ? "unknown option '" : "unexpected argument '") + first + "'" + see;
    }
  }
  return error.what() + see;
}

std::optional<int> parse_command_line(CLI::App& app, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  const auto fail = [&](const std::string& message, int code) {
    std::fprintf(stderr, "%s: error: %s\n", command_path(selected_command(app)).c_str(), message.c_str());
    return std::optional<int>(code);
  };
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);  // the selected subcommand's, named from the root
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
    return 0;
  } catch (const CLI::Error& error) {
    return fail(usage_error_message(app, error), 2);
  } catch (const std::invalid_argument& error) {
    return fail(error.what(), 2);
  } catch (const std::exception& error) {
    return fail(error.what(), 1);
  }
  return std::nullopt;
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  return parse_command_line(app, std::vector<std::string>(argv + 1, argv + argc));
}

}  // namespace raycam::flags
