// `raycam-cli bench accuracy|speed`: the two benchmarks behind one command.
#include <cstdio>

#include "cli/commands.h"
#ifdef RAYCAM_HAVE_BENCH
#include "bench/bench_commands.h"
#endif

namespace raycam::cli {

void add_bench_command(CLI::App& cli, int& exit_code) {
  CLI::App* bench = cli.add_subcommand(
      "bench", "benchmarks: casters against Embree (speed), time against error (accuracy)");
#ifndef RAYCAM_HAVE_BENCH
  // Built with RAYCAM_BUILD_BENCH=OFF (no Google Benchmark): the command says so instead of being unknown.
  bench->prefix_command();
  bench->set_help_flag();
  bench->callback([&exit_code] {
    std::fprintf(stderr,
                 "raycam-cli bench: error: this raycam-cli was built without the benchmarks: configure with "
                 "-DRAYCAM_BUILD_BENCH=ON (needs Google Benchmark, libbenchmark-dev)\n");
    exit_code = 2;
  });
#else
  bench->require_subcommand(1);
  bench::add_bench_accuracy_command(*bench, exit_code);
  // `bench speed` keeps its own parser (docs/speed.md): it gets every argument after its name, --help too.
  CLI::App* speed = bench->add_subcommand(
      "speed", "raycam's casters against Embree 3 (docs/speed.md; bench speed --help)");
  speed->prefix_command();
  speed->set_help_flag();
  speed->callback([speed, &exit_code] { exit_code = bench::run_bench_speed(speed->remaining()); });
#endif
}

void add_check_command(CLI::App& cli, int& exit_code) {
  // `check` keeps its own CLI11 parser (check_command.cpp): it gets every argument after its name.
  CLI::App* check = cli.add_subcommand(
      "check", "grade a student's camera program (stdin case -> stdout ids) and name its classic mistakes");
  check->prefix_command();
  check->set_help_flag();
  check->callback([check, &exit_code] { exit_code = run_check(check->remaining()); });
}

}  // namespace raycam::cli
