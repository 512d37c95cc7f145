// raycam-cli: the headless front end (no display needed). One CLI11 app, one subcommand per job.
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "flags/flag_values.h"

int main(int argc, char** argv) {
  CLI::App cli("raycam-cli: the raycam camera chapter without a display (render, figure, check, shot, record, bench)", "raycam-cli");
  cli.require_subcommand(1);
  int exit_code = 0;
  raycam::cli::add_render_command(cli, exit_code);
  raycam::cli::add_figure_command(cli, exit_code);
  raycam::cli::add_check_command(cli, exit_code);
  raycam::cli::add_bench_command(cli, exit_code);
#ifdef RAYCAM_HAVE_SHOT
  raycam::cli::add_shot_command(cli, exit_code);
  raycam::cli::add_record_command(cli, exit_code);
#endif
  if (const auto usage_exit = raycam::flags::parse_command_line(cli, argc, argv)) return *usage_exit;
  return exit_code;
}
