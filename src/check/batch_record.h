// What a --batch CSV was graded with, in a file beside it (GRADES.csv.battery.json): the battery (seed, cases,
// mode, protocol version, --two-res), the limits and the command, raycam's version, the shard and every
// student of the batch's folder.
// `check merge` compares these before joining shards. A sidecar rather than a line in the CSV, so the CSV
// stays one header line and one row per student, as a grade book's import expects.
#pragma once

#include <string>
#include <vector>

#include "check/battery.h"
#include "check/shards.h"

namespace raycam::check {

// raycam's version as the build names it (CMake's PROJECT_VERSION).
std::string raycam_version();

struct BatchRecord {
  std::string raycam = raycam_version();
  unsigned long long seed = 0;
  int cases = 0;
  std::string mode;
  // The protocol the battery followed (battery.h's kProtocolVersion; a record without the field is version
  // 1's) and whether it asked the two-resolution case: shards graded with and without it are not one grading.
  int protocol = kProtocolVersion;
  bool two_res = false;
  double timeout_seconds = 0;
  int memory_mb = 0, disk_mb = 0, processes = 0;  // the per-run bounds: a bound decides a run's outcome
  std::string student_cmd;
  Shard shard;
  std::vector<std::string> students;  // every folder of the batch, sorted, not only this shard's

  // The fields that must agree for two CSVs to be one grading (all but the shard and the students: a student
  // added after one shard ran is the merge's business), named when they do not. Empty when they agree.
  std::string difference_from(const BatchRecord& other) const;
};

std::string battery_sidecar_path(const std::string& csv_path);
std::string battery_record_json(const BatchRecord& record);
// Throws std::invalid_argument naming `path` and the field when it is missing or not a record.
BatchRecord read_battery_record(const std::string& path);

}  // namespace raycam::check
