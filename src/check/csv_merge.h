// `check merge`: the shards' CSVs joined into the CSV one --batch run over every student would have written,
// byte for byte. Rows are opaque lines keyed by their first field (the student), so whatever columns a row
// holds are carried over as they are; only the header lines must be equal.
#pragma once

#include <string>
#include <vector>

#include "check/batch_record.h"

namespace raycam::check {

struct MergedCsv {
  std::string text;    // the header line, then every student's row in the batch's (sorted) order
  BatchRecord record;  // the shards' record as shard 1/1: what a single run writes beside its CSV
};

// Reads each CSV and its battery sidecar. The batch is every student any shard saw (a student added after
// a shard ran is missing until that student's slice is graded again; the others need not be). Throws
// std::invalid_argument listing every problem: a different battery or header, a student in two shards (or
// twice in one), a student in no shard (with its slice, and the shards not given), a row for a student its
// shard did not see or in another slice, a row cut off.
MergedCsv merge_shard_csvs(const std::vector<std::string>& csv_paths);

// CSV records (lines, except that a newline inside double quotes stays in its record), each with its "\n";
// a last record without its "\n" (a write cut off) is returned without it.
std::vector<std::string> csv_records(const std::string& text);
// A record's first field as written (still quoted when it was).
std::string csv_first_field(const std::string& record);
// The student's field as csv_row writes it (quoted, escaped, whatever csv_row does): the key rows join by.
std::string csv_student_field(const std::string& student);

}  // namespace raycam::check
