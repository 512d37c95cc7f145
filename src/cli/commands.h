// raycam-cli subcommands. Each takes the arguments after its name and returns the process exit code.
// Bad arguments throw std::invalid_argument (exit 2, message on stderr); other failures std::runtime_error
// (exit 1). A new subcommand is one function here and one row in main.cpp's table.
#pragma once

#include <string>
#include <vector>

namespace raycam::cli {

using Args = std::vector<std::string>;

int run_render(const Args& args);
int run_check(const Args& args);  // check_command.cpp, on the raycam_check library (src/check)
int run_shot(const Args& args);  // only in builds with RAYCAM_BUILD_APP (needs OSMesa)
// `bench accuracy` (bench_accuracy.cpp) and `bench speed` (bench_speed.cpp), dispatched by run_bench.
int run_bench(const Args& args);
int run_bench_accuracy(const Args& args);
int run_bench_speed(const Args& args);

}  // namespace raycam::cli
