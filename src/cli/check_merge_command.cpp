// `raycam-cli check merge --csv OUT SHARD.csv...`: the CSVs of `check --batch --shard i/N` joined into the one
// CSV a single run would have written (docs/check.md, "A large course").
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "check/batch_record.h"
#include "check/check_report.h"
#include "check/check_texts.h"
#include "cli/commands.h"
#include "check/csv_merge.h"
#include "flags/flag_values.h"

namespace raycam::cli {

int run_check_merge(const Args& args) {
  std::string out;
  std::vector<std::string> shards;
  CLI::App app{"Joins the CSVs of `check --batch --shard i/N` (each with the .battery.json check wrote beside "
               "it) into the CSV one run over every student writes, byte for byte. Refuses (exit 2, naming "
               "them) shards graded with another battery, students in two shards, and students in none.",
               "raycam-cli check merge"};
  app.add_option("--csv", out, "the merged CSV (its .battery.json is written beside it)")->required();
  app.add_option("shards", shards, "the shards' CSV files");
  // Not CLI11's "shards is required": say what to give, with an example.
  app.callback([&shards] {
    if (shards.empty())
      throw std::invalid_argument("expected the shards' CSV files (the --csv of each `check --batch DIR --shard i/N`), "
                                  "e.g. raycam-cli check merge --csv all.csv shard1.csv shard2.csv shard3.csv");
  });
  if (const std::optional<int> done = flags::parse_command_line(app, args)) return *done;  // --help, bad usage
  const check::MergedCsv merged = check::merge_shard_csvs(shards);
  check::write_text_file(out, merged.text);
  check::write_text_file(check::battery_sidecar_path(out), check::battery_record_json(merged.record));
  std::printf("wrote %s (%zu students from %s)\n", out.c_str(), merged.record.students.size(),
              formatted(Language::en, "%zu {{shard|shards}}", shards.size()).c_str());
  return 0;
}

}  // namespace raycam::cli
