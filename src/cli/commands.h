// raycam-cli subcommands on CLI11. Each add_*_command adds its subcommand (options, generated help) to the
// dispatcher `cli`; the subcommand's callback does the work and stores the process exit code in `exit_code`.
// Bad usage throws (CLI11 errors, std::invalid_argument: exit 2 with one message line), other failures
// std::runtime_error (exit 1): flags::parse_command_line reports both. A new subcommand is one function here
// and one call in main.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace raycam::cli {

using Args = std::vector<std::string>;

// A subcommand with its one-line summary (listed by `raycam-cli --help`) and a longer description shown
// under its own --help.
inline CLI::App* add_described_subcommand(CLI::App& parent, const std::string& name, const std::string& summary,
                                          const std::string& description) {
  CLI::App* command = parent.add_subcommand(name, summary);
  command->footer(description);
  return command;
}

void add_render_command(CLI::App& cli, int& exit_code);
void add_figure_command(CLI::App& cli, int& exit_code);  // the construction of M_d as figures (cairo)
void add_shot_command(CLI::App& cli, int& exit_code);  // only in builds with RAYCAM_BUILD_APP (needs OSMesa)
void add_record_command(CLI::App& cli, int& exit_code);  // the same frames along a camera path, as a video
// `bench accuracy` and `bench speed` (src/bench, bench_commands.h) under `bench`.
void add_bench_command(CLI::App& cli, int& exit_code);
// `check` (check_command.cpp, on the raycam_check library) parses its own arguments with CLI11.
void add_check_command(CLI::App& cli, int& exit_code);  // passes its arguments to run_check
int run_check(const Args& args);
int run_check_merge(const Args& args);  // `check merge` (check_merge_command.cpp)

}  // namespace raycam::cli
