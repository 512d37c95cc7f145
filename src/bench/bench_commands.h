// The benchmarks behind `raycam-cli bench`: `accuracy` (bench_accuracy.cpp, run time against error, with
// --stress and --angles from accuracy_tables.cpp) and `speed` (bench_speed.cpp, the casters against Embree 3
// and the floor). raycam-cli's `bench` command (src/cli/bench_command.cpp) only hands them its arguments.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace raycam::bench {

using Args = std::vector<std::string>;

// Adds `accuracy` under the `bench` command; its callback stores the exit code in `exit_code`.
void add_bench_accuracy_command(CLI::App& bench, int& exit_code);
// `bench speed` parses its own arguments: everything after `bench speed` (its --help included).
int run_bench_speed(const Args& args);

}  // namespace raycam::bench
