#include "check/csv_merge.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "check/check_report.h"
#include "check/escaped_text.h"

namespace raycam::check {

namespace {
constexpr std::size_t kNamesShown = 20;  // a missing shard of a large course: the first names, then a count

std::string name_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < kNamesShown; ++i) list += (i ? ", " : "") + names[i];
  if (names.size() > kNamesShown) list += ", ... (" + std::to_string(names.size()) + " in all)";
  return list;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

std::vector<std::string> csv_records(const std::string& text) {
  std::vector<std::string> records;
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"') quoted = !quoted;  // "" inside a quoted field toggles twice: no change
    else if (text[i] == '\n' && !quoted) {
      records.push_back(text.substr(start, i + 1 - start));
      start = i + 1;
    }
  }
  if (start < text.size()) records.push_back(text.substr(start));
  return records;
}

std::string csv_first_field(const std::string& record) {
  bool quoted = false;
  for (std::size_t i = 0; i < record.size(); ++i) {
    if (record[i] == '"') quoted = !quoted;
    else if (!quoted && (record[i] == ',' || record[i] == '\n')) return record.substr(0, i);
  }
  return record;
}

std::string csv_student_field(const std::string& student) {
  return csv_first_field(csv_row(student, StudentReport{}, false));
}

MergedCsv merge_shard_csvs(const std::vector<std::string>& csv_paths) {
  if (csv_paths.empty()) throw std::invalid_argument("merge: expected the shards' CSV files");
  std::vector<std::string> problems;
  std::string header;
  BatchRecord first;
  std::map<std::string, std::string> row_of_key, file_of_key;  // key: the student's field as the row writes it
  std::set<int> shards_given;
  std::set<std::string> batch;  // every student any shard saw: one added after a shard ran is in later ones only
  for (std::size_t f = 0; f < csv_paths.size(); ++f) {
    const std::string& path = csv_paths[f];
    const BatchRecord record = read_battery_record(battery_sidecar_path(path));
    std::vector<std::string> records = csv_records(read_file(path));
    if (records.empty()) throw std::invalid_argument(path + ": empty (not a check --batch CSV)");
    if (f == 0) {
      first = record;
      header = records[0];
    } else if (const std::string difference = record.difference_from(first); !difference.empty()) {
      problems.push_back(path + " was graded differently from " + csv_paths[0] + ": " + difference);
      continue;
    } else if (records[0] != header) {
      problems.push_back(path + ": its header line differs from " + csv_paths[0] + "'s (other columns)");
      continue;
    }
    if (!shards_given.insert(record.shard.index).second)
      problems.push_back(path + ": shard " + shard_text(record.shard) + " given twice");
    batch.insert(record.students.begin(), record.students.end());
    std::map<std::string, const std::string*> student_of_key;
    for (const std::string& student : record.students) student_of_key[csv_student_field(student)] = &student;
    for (std::size_t r = 1; r < records.size(); ++r) {
      const std::string& row = records[r];
      const std::string key = csv_first_field(row);
      const std::string shown = escaped_control(key);  // a row of a file given: its bytes reach the terminal
      const auto student = student_of_key.find(key);
      if (row.back() != '\n') {
        problems.push_back(path + ": its last row (" + shown + ") is cut off: grade that shard again");
      } else if (student == student_of_key.end()) {
        problems.push_back(path + ": a row for " + shown + ", who is not in the batch it saw");
      } else if (shard_of(*student->second, record.shard.count) != record.shard.index) {
        problems.push_back(path + ": a row for " + shown + ", who is in shard " +
                           std::to_string(shard_of(*student->second, record.shard.count)) + ", not " +
                           shard_text(record.shard));
      } else if (const auto seen = file_of_key.find(key); seen != file_of_key.end()) {
        problems.push_back("overlap: " + shown + " is in " + seen->second + " and " + path);
      } else {
        row_of_key[key] = row;
        file_of_key[key] = path;
      }
    }
  }
  MergedCsv merged{header, first};
  merged.record.shard = Shard{1, 1};
  merged.record.students.assign(batch.begin(), batch.end());  // sorted as a single run sorts its folders
  std::vector<std::string> missing;  // "name (i/N)": the slice to grade again
  for (const std::string& student : merged.record.students) {
    const auto row = row_of_key.find(csv_student_field(student));
    if (row == row_of_key.end())
      missing.push_back(escaped_control(student) + " (" + shard_text(Shard{shard_of(student, first.shard.count), first.shard.count}) + ")");
    else merged.text += row->second;
  }
  if (!missing.empty()) {
    std::string not_given;
    for (int i = 1; i <= first.shard.count; ++i)
      if (!shards_given.count(i)) not_given += (not_given.empty() ? "" : ", ") + shard_text(Shard{i, first.shard.count});
    problems.push_back("missing students: " + name_list(missing) +
                       (not_given.empty() ? "" : " (shards not given: " + not_given + ")"));
  }
  if (!problems.empty()) {
    std::string message = "merge refused (nothing written): ";
    for (std::size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
    throw std::invalid_argument(message);
  }
  return merged;
}

}  // namespace raycam::check
