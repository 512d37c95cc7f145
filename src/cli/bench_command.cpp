// `raycam-cli bench accuracy|speed`: the two benchmarks behind one command.
#include <cstdio>
#include <stdexcept>

#include "commands.h"

namespace raycam::cli {

int run_bench(const Args& args) {
  const char* usage =
      "usage: raycam-cli bench speed [options]      raycam's casters against Embree 3 (README, \"Speed\")\n"
      "       raycam-cli bench accuracy [options]   time against error, --stress, --angles (README, \"Accuracy\")\n"
      "(raycam-cli bench NAME --help for the options)\n";
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(usage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const Args rest(args.begin() + 1, args.end());
  if (args[0] == "speed") return run_bench_speed(rest);
  if (args[0] == "accuracy") return run_bench_accuracy(rest);
  throw std::invalid_argument("bench: unknown benchmark '" + args[0] + "' (expected speed or accuracy)");
}

}  // namespace raycam::cli
