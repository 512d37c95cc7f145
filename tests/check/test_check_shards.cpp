// A large course (docs/check.md): the shards' split (a published hash of the folder name, stable when
// students are added, balanced), and `check merge` on hand-written shards: rows joined whatever their
// columns, and every refusal naming what is wrong.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "check/batch_record.h"
#include "check/csv_merge.h"
#include "check/shards.h"

using namespace raycam::check;

TEST_CASE("the shard hash is FNV-1a 64 (its published test vectors)", "[check][shards]") {
  CHECK(fnv1a_64("") == 0xcbf29ce484222325ull);  // the offset basis
  CHECK(fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a_64("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("every student is in exactly one slice, the slices are even, a slice is the name's hash alone",
          "[check][shards]") {
  for (int count : {1, 2, 3, 7, 16}) {
    std::vector<int> sizes(std::size_t(count) + 1, 0);
    for (int i = 0; i < 3000; ++i) {
      const int slice = shard_of("student" + std::to_string(i), count);
      REQUIRE(slice >= 1);
      REQUIRE(slice <= count);
      ++sizes[std::size_t(slice)];
    }
    for (int slice = 1; slice <= count; ++slice) {
      INFO(count << " slices, slice " << slice);
      CHECK(std::abs(sizes[std::size_t(slice)] - 3000.0 / count) < 0.15 * 3000.0 / count + 10);
    }
  }
  CHECK(shard_of("alice", 3) == int(fnv1a_64("alice") % 3) + 1);  // the documented rule
}

TEST_CASE("the flag --shard accepts i/N with 1 <= i <= N and refuses the rest, naming the flag", "[check][shards]") {
  CHECK(parse_shard("1/1", "--shard").count == 1);
  CHECK(parse_shard("3/3", "--shard").index == 3);
  CHECK(parse_shard("10000/10000", "--shard").index == 10000);
  for (const char* bad : {"0/3", "4/3", "3", "1/0", "a/b", "1/3x", " 1/3", "-1/3", "+1/3", "1/10001", "1/3/4", ""}) {
    INFO(bad);
    CHECK_THROWS_WITH(parse_shard(bad, "--shard"), Catch::Contains("--shard: expected i/N with 1 <= i <= N"));
  }
}

TEST_CASE("csv records keep a quoted newline and the first field keeps its quotes", "[check][shards]") {
  const std::vector<std::string> records = csv_records("a,b\n\"x\ny\",1\n\"o,b\",\"\"\"q\"\"\",2\ncut");
  REQUIRE(records.size() == 4);
  CHECK(records[1] == "\"x\ny\",1\n");
  CHECK(csv_first_field(records[2]) == "\"o,b\"");
  CHECK(records[3] == "cut");
}

namespace {
// Shard `index` of `count` written by hand: its battery record (every student of `students`) and a CSV of the
// given rows, each "NAME,REST" with NAME as csv_row writes it.
struct HandShards {
  raycam::test::ScratchDir dir{"shards"};
  std::vector<std::string> students = {"ann", "bo", "cy", "di", "ed", "fa", "gil", "hu", "o,brien"};
  std::string header = "student,passed,score,extra_column,grade_20\n";
  int disk_mb = 256;  // a per-run bound: shards with other bounds graded differently
  bool two_res = false;  // --two-res: another battery

  std::string write(const std::string& file, int index, int count, const std::vector<std::string>& rows,
                    unsigned long long seed = 7) {
    BatchRecord record;
    record.seed = seed;
    record.cases = 4;
    record.mode = "both";
    record.timeout_seconds = 10;
    record.memory_mb = 2048;
    record.disk_mb = disk_mb;
    record.two_res = two_res;
    record.processes = 256;
    record.student_cmd = "{dir}/run.sh";
    record.shard = Shard{index, count};
    record.students = students;
    const std::string path = dir.path(file);
    std::ofstream(battery_sidecar_path(path)) << battery_record_json(record);
    std::ofstream csv(path, std::ios::binary);
    csv << header;
    for (const std::string& row : rows) csv << row;
    return path;
  }
  // A row with columns a shard would not know the meaning of (quoted commas, a newline inside quotes).
  static std::string row(const std::string& student) {
    const std::string key = student.find(',') == std::string::npos ? student : "\"" + student + "\"";
    return key + ",3,75.0,\"x, \"\"y\"\"\nz\",15.00\n";
  }
  // Every student's row sorted into the given slices.
  std::vector<std::vector<std::string>> slices(int count) const {
    std::vector<std::vector<std::string>> rows(std::size_t(count) + 1);
    for (const std::string& s : students) rows[std::size_t(shard_of(s, count))].push_back(row(s));
    return rows;
  }
};

std::string refusal(const std::vector<std::string>& paths) {
  try {
    merge_shard_csvs(paths);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(merged)";
}
}  // namespace

TEST_CASE("merge joins the shards' rows in the batch's order, whatever their columns", "[check][shards][merge]") {
  HandShards hand;
  const auto rows = hand.slices(3);
  // Rows written in the order students finished, not sorted: the merge sorts them as a single run does.
  std::vector<std::string> paths;
  for (int i = 3; i >= 1; --i) {
    std::vector<std::string> finished(rows[std::size_t(i)].rbegin(), rows[std::size_t(i)].rend());
    paths.push_back(hand.write("s" + std::to_string(i) + ".csv", i, 3, finished));
  }
  std::string expected = hand.header;
  for (const std::string& s : hand.students) expected += HandShards::row(s);
  const MergedCsv merged = merge_shard_csvs(paths);
  CHECK(merged.text == expected);
  CHECK(merged.record.shard.count == 1);
  CHECK(merged.record.students == hand.students);
}

TEST_CASE("merge refuses missing students, overlaps, another battery or header, strangers and cut rows",
          "[check][shards][merge]") {
  HandShards hand;
  auto rows = hand.slices(2);
  const std::string one = hand.write("one.csv", 1, 2, rows[1]);
  const std::string two = hand.write("two.csv", 2, 2, rows[2]);
  REQUIRE(refusal({one, two}) == "(merged)");
  REQUIRE_FALSE(rows[2].empty());
  const std::string first_of_two = rows[2][0].substr(0, rows[2][0].find(','));

  SECTION("a shard not given: its students named, and the shard") {
    const std::string message = refusal({one});
    CHECK_THAT(message, Catch::Contains("missing students: ") && Catch::Contains(first_of_two) &&
                            Catch::Contains("shards not given: 2/2"));
  }
  SECTION("a student missing from a shard (an interrupted run)") {
    std::vector<std::string> partial(rows[2].begin() + 1, rows[2].end());
    const std::string message = refusal({one, hand.write("partial.csv", 2, 2, partial)});
    CHECK_THAT(message, Catch::Contains("missing students: " + first_of_two));
    CHECK_THAT(message, !Catch::Contains("shards not given"));
  }
  SECTION("the same shard twice, and a student twice") {
    const std::string message = refusal({one, two, hand.write("again.csv", 2, 2, rows[2])});
    CHECK_THAT(message, Catch::Contains("shard 2/2 given twice"));
    CHECK_THAT(message, Catch::Contains("overlap: " + first_of_two + " is in " + two + " and "));
  }
  SECTION("another seed, another bound, another count of slices, another header") {
    CHECK_THAT(refusal({one, hand.write("seed.csv", 2, 2, rows[2], 8)}),
               Catch::Contains("graded differently") && Catch::Contains("seed 8 vs 7"));
    CHECK_THAT(refusal({one, hand.write("three.csv", 2, 3, hand.slices(3)[2])}), Catch::Contains("shard count 3 vs 2"));
    hand.disk_mb = 512;
    CHECK_THAT(refusal({one, hand.write("disk.csv", 2, 2, rows[2])}), Catch::Contains("disk 512 vs 256"));
    hand.disk_mb = 256;
    hand.header = "student,passed,score,grade_100\n";
    CHECK_THAT(refusal({one, hand.write("header.csv", 2, 2, rows[2])}), Catch::Contains("header line differs"));
  }
  SECTION("the two-resolution case asked in one shard and not the other, or a record from before protocols") {
    hand.two_res = true;
    CHECK_THAT(refusal({one, hand.write("two_res.csv", 2, 2, rows[2])}),
               Catch::Contains("graded differently") && Catch::Contains("two_res true vs false"));
    hand.two_res = false;
    // A record written before protocols had versions is version 1's: another battery.
    const std::string old = hand.write("old.csv", 2, 2, rows[2]);
    nlohmann::json record = nlohmann::json::parse(std::ifstream(battery_sidecar_path(old)));
    REQUIRE(record.at("protocol") == kProtocolVersion);
    record.erase("protocol");
    record.erase("two_res");
    std::ofstream(battery_sidecar_path(old)) << record.dump();
    CHECK_THAT(refusal({one, old}), Catch::Contains("protocol 1 vs 2"));
  }
  SECTION("a row for a student not in the batch, or in another slice") {
    rows[2].push_back("zed,1,25.0,x,5.00\n");
    CHECK_THAT(refusal({one, hand.write("zed.csv", 2, 2, rows[2])}), Catch::Contains("a row for zed, who is not in the batch"));
    rows[2].pop_back();
    rows[2].push_back(rows[1][0]);
    CHECK_THAT(refusal({hand.write("both.csv", 2, 2, rows[2])}), Catch::Contains("who is in shard 1, not 2/2"));
  }
  SECTION("a last row cut off") {
    rows[2].back().pop_back();
    CHECK_THAT(refusal({one, hand.write("cut.csv", 2, 2, rows[2])}), Catch::Contains("is cut off"));
  }
  SECTION("a CSV without its battery record") {
    std::ofstream(hand.dir.path("bare.csv")) << hand.header;
    CHECK_THAT(refusal({one, hand.dir.path("bare.csv")}), Catch::Contains("bare.csv.battery.json: cannot read"));
  }
}

TEST_CASE("a student added after some shards ran: only that student's slice is graded again",
          "[check][shards][merge]") {
  HandShards hand;
  const std::vector<std::string> before = hand.students;
  const std::string late = "latecomer";  // sorts between the others
  const int slice = shard_of(late, 2), other = 3 - slice;
  std::vector<std::string> after = before;
  after.push_back(late);
  std::sort(after.begin(), after.end());

  hand.students = after;  // every slice's rows, the newcomer's included
  const auto rows = hand.slices(2);
  hand.students = before;  // the other slice ran before the newcomer arrived
  const std::string earlier = hand.write("other.csv", other, 2, rows[std::size_t(other)]);

  SECTION("its slice graded after it arrived: merged, the newcomer in its place") {
    hand.students = after;
    const std::string graded = hand.write("late.csv", slice, 2, rows[std::size_t(slice)]);
    const MergedCsv merged = merge_shard_csvs({earlier, graded});
    std::string expected = hand.header;
    for (const std::string& s : after) expected += HandShards::row(s);
    CHECK(merged.text == expected);
    CHECK(merged.record.students == after);
  }
  SECTION("its slice graded before it arrived: the newcomer is missing, with its slice") {
    std::vector<std::string> without;
    for (const std::string& row : rows[std::size_t(slice)])
      if (row.rfind(late + ",", 0) != 0) without.push_back(row);
    const std::string stale = hand.write("stale.csv", slice, 2, without);
    hand.students = after;
    const std::string newer = hand.write("newer.csv", other, 2, rows[std::size_t(other)]);
    CHECK_THAT(refusal({stale, newer}),
               Catch::Contains("missing students: " + late + " (" + std::to_string(slice) + "/2)"));
  }
}

TEST_CASE("check merge of one shard says \"from 1 shard\"", "[check][shards][merge]") {
  HandShards hand;
  const std::string only = hand.write("only.csv", 1, 1, hand.slices(1)[1]);
  const std::string merged = hand.dir.path("merged.csv"), output = hand.dir.path("merge_output.txt");
  const std::string command = std::string(RAYCAM_CLI) + " check merge --csv " + merged + " " + only + " > " + output + " 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  std::stringstream text;
  text << std::ifstream(output).rdbuf();
  INFO(text.str());
  CHECK(text.str().find(std::to_string(hand.students.size()) + " students from 1 shard)") != std::string::npos);
}
