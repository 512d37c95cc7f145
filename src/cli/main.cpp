// raycam-cli: the headless front end (no display needed). Dispatches to one subcommand.
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "commands.h"

namespace {
using raycam::cli::Args;

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const Args&);
};

// One row per subcommand.
const Command kCommands[] = {
    {"render", "cast the primary rays and write the colour map (PNG) and object ids (text)",
     raycam::cli::run_render},
    {"check", "grade a student's camera program (stdin case -> stdout ids) and name its classic mistakes",
     raycam::cli::run_check},
    {"bench", "benchmarks: `bench speed` (casters against Embree), `bench accuracy` (time against error)",
     raycam::cli::run_bench},
#ifdef RAYCAM_HAVE_SHOT
    {"shot", "render the app's whole window headless (OSMesa) to PNG; --soak N for a long run",
     raycam::cli::run_shot},
#endif
};

void print_usage(std::FILE* out) {
  std::fprintf(
      out,
      "usage: raycam-cli COMMAND [options]   (raycam-cli COMMAND --help for its options)\n\ncommands:\n");
  for (const Command& command : kCommands) std::fprintf(out, "  %-8s %s\n", command.name, command.summary);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return 0;
  }
  for (const Command& command : kCommands) {
    if (name != command.name) continue;
    try {
      return command.run(Args(argv + 2, argv + argc));
    } catch (const std::invalid_argument& error) {
      std::fprintf(stderr, "raycam-cli %s: error: %s\n", command.name, error.what());
      return 2;
    } catch (const std::exception& error) {
      std::fprintf(stderr, "raycam-cli %s: error: %s\n", command.name, error.what());
      return 1;
    }
  }
  std::fprintf(stderr, "raycam-cli: unknown command '%s'\n", name.c_str());
  print_usage(stderr);
  return 2;
}
