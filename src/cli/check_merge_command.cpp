// `raycam-cli check merge --csv OUT SHARD.csv...`: the CSVs of `check --batch --shard i/N` joined into the one
// CSV a single run would have written (docs/check.md, "A large course").
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "batch_record.h"
#include "check_report.h"
#include "commands.h"
#include "csv_merge.h"
#include "flag_values.h"

namespace raycam::cli {

int run_check_merge(const Args& args) {
  std::string out;
  std::vector<std::string> shards;
  CLI::App app{"Joins the CSVs of `check --batch --shard i/N` (each with the .battery.json check wrote beside "
               "it) into the CSV one run over every student writes, byte for byte. Refuses (exit 2, naming "
               "them) shards graded with another battery, students in two shards, and students in none.",
               "raycam-cli check merge"};
  app.add_option("--csv", out, "the merged CSV (its .battery.json is written beside it)")->required();
  app.add_option("shards", shards, "the shards' CSV files")->required();
  if (const std::optional<int> done = flags::parse_command_line(app, args)) return *done;  // --help, bad usage
  const check::MergedCsv merged = check::merge_shard_csvs(shards);
  check::write_text_file(out, merged.text);
  check::write_text_file(check::battery_sidecar_path(out), check::battery_record_json(merged.record));
  std::printf("wrote %s (%zu students from %zu shards)\n", out.c_str(), merged.record.students.size(), shards.size());
  return 0;
}

}  // namespace raycam::cli
