// Flag values on CLI11, with ONE message format for every bad value (docs/cli.md):
//   --res: expected a number in ]0, 1], got '0'
//   --threads: expected an integer in [1, 256], got nothing
// Each rule says what it accepts (`expected`) and parses the text; add_checked_option() turns a rule into a
// CLI11 option whose validator gives that message and whose callback stores the parsed value.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace raycam::flags {

template <class T>
struct ValueRule {
  std::string expected;  // "a number in ]0, 1]": what the message says is accepted
  std::function<std::optional<T>(const std::string&)> parse;  // nullopt: refused
  // When a value has more than one shape (--res R or RC,RL): what a refused text's shape expects, so that
  // --res 0 says "a number in ]0, 1]". Empty: `expected`.
  std::function<std::string(const std::string&)> expected_for = nullptr;
};

// What the message for a refused `text` says is expected.
template <class T>
std::string expected_of(const ValueRule<T>& rule, const std::string& text) {
  return rule.expected_for ? rule.expected_for(text) : rule.expected;
}

// An interval of reals; open bounds are excluded ("]0, 1]").
struct Interval {
  double lo, hi;
  bool lo_open = false, hi_open = false;
};

// A finite number in `range`. Subnormal and underflowing values are numbers like any other (strtod's ERANGE
// on underflow is not an error); overflow (1e999), NaN and infinities are refused. `noun` starts the
// expected text: "a number", "an angle in degrees".
ValueRule<double> number_in(Interval range, const std::string& noun = "a number");
// A decimal integer in [lo, hi].
ValueRule<int> integer_in(int lo, int hi);
// One of the names; the value is its index in `names`.
ValueRule<int> one_of(const std::vector<std::string>& names);

// A non-empty file name (whether it can be opened is the command's business).
ValueRule<std::string> file_name();

// "a, b or c"
std::string name_list(const std::vector<std::string>& names);
// 1e12 -> "1e12", 0.5 -> "0.5", 1048576 -> "1048576"
std::string short_number(double x);

// The one message format.
std::string bad_value_message(const std::string& flag, const std::string& expected, const std::string& got);

// Adds `names` ("--res") taking one value checked by `rule`; `store` gets the parsed value. Given twice, the
// last value wins. The expected text becomes the validator's name, for the missing-value message.
// For parsers not (yet) on CLI11: the value of `text` given to `flag`, or std::invalid_argument with the
// one message format.
template <class T>
T checked_value(const ValueRule<T>& rule, const std::string& text, const std::string& flag) {
  const std::optional<T> value = rule.parse(text);
  if (!value) throw std::invalid_argument(bad_value_message(flag, expected_of(rule, text), text));
  return *value;
}

// The CLI11 validator of a rule: its message is "expected EXPECTED, got 'TEXT'" (CLI11 puts the flag in
// front), its name the expected text.
template <class T>
CLI::Validator checked(const ValueRule<T>& rule) {
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        return rule.parse(text) ? std::string() : "expected " + expected_of(rule, text) + ", got '" + text + "'";
      },
      "", rule.expected);
}

template <class T>
CLI::Option* add_checked_option(CLI::App& app, const std::string& names, const std::string& metavar,
                                const std::string& description, ValueRule<T> rule,
                                std::function<void(T)> store) {
  return app
      .add_option_function<std::string>(
          names, [rule, store](const std::string& text) { store(*rule.parse(text)); }, description)
      ->type_name(metavar)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->check(checked(rule));
}

// The same for a comma-separated list ("--spp 1,4,16"): every item is checked by `rule`; `store` gets them
// all, in order.
template <class T>
CLI::Option* add_checked_list(CLI::App& app, const std::string& names, const std::string& metavar,
                              const std::string& description, ValueRule<T> rule,
                              std::function<void(std::vector<T>)> store) {
  return app
      .add_option_function<std::vector<std::string>>(
          names,
          [rule, store](const std::vector<std::string>& texts) {
            std::vector<T> values;
            for (const std::string& text : texts) values.push_back(*rule.parse(text));
            store(values);
          },
          description)
      ->type_name(metavar)
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(checked(rule));
}

// Parses the command line with `app` and runs its callbacks (a subcommand's work runs in its callback).
// Returns nullopt when the program should go on, or the exit code to return now:
//   --help: the generated help on stdout, 0;
//   bad usage (a bad or missing value, an unknown option, std::invalid_argument from a callback): one line
//     "PROGRAM [SUBCOMMAND]: error: MESSAGE" on stderr, 2;
//   any other exception from a callback: the same line, 1.
// `args` excludes the program name.
std::optional<int> parse_command_line(CLI::App& app, std::vector<std::string> args);
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv);

// The message for a CLI11 parse error, in the one format ("--res: expected …, got '…'"; a missing value
// names what was expected and says "got nothing"; an unknown option names it and points at --help).
std::string usage_error_message(const CLI::App& app, const CLI::Error& error);

}  // namespace raycam::flags
