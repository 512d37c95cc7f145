// Every byte a student controls (a folder's name, its stderr, what it printed) reaches the instructor as inert
// text (issue #44): on the terminal, in the CSV a spreadsheet opens, in the JSON reports. The escaping byte by
// byte, its invariant over random bytes, and the CSV's formula guard through csv_row and check merge.
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "check/batch_record.h"
#include "check/check_report.h"
#include "check/csv_merge.h"
#include "check/escaped_text.h"
#include "check/lms_grades.h"

using namespace raycam::check;
using json = nlohmann::json;

namespace {
std::string hex(unsigned char byte) {
  char code[5];
  std::snprintf(code, sizeof code, "\\x%02x", byte);
  return code;
}

// `text` for a failure's message: printable ASCII as it is (a backslash doubled), every other byte in hex, so
// that a raw byte and its escaped form differ there (never the code under test).
std::string bytes_of(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '\\' ? "\\\\" : c >= 0x20 && c < 0x7f ? std::string(1, c) : hex(static_cast<unsigned char>(c));
  return out;
}

// The code points of `text` when it is valid UTF-8 (RFC 3629), else nothing. Written apart from the checker's
// own decoder (which follows Unicode's table 3-7 byte ranges): decode, then refuse overlong forms, surrogates
// and values past U+10FFFF.
std::optional<std::vector<char32_t>> utf8_code_points(const std::string& text) {
  std::vector<char32_t> points;
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const int length = lead < 0x80 ? 1 : lead >> 5 == 0x6 ? 2 : lead >> 4 == 0xe ? 3 : lead >> 3 == 0x1e ? 4 : 0;
    if (length == 0 || i + std::size_t(length) > text.size()) return std::nullopt;
    char32_t point = length == 1 ? lead : lead & (0x7f >> length);
    for (int k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
      if (next >> 6 != 0x2) return std::nullopt;
      point = point << 6 | (next & 0x3f);
    }
    const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (point < smallest[length] || (point >= 0xd800 && point <= 0xdfff) || point > 0x10ffff) return std::nullopt;
    points.push_back(point);
    i += std::size_t(length);
  }
  return points;
}

// What escaped text may hold: valid UTF-8, no C0 control but tab (and newline when kept), no DEL, no C1.
bool inert(const std::string& text, bool newlines_kept) {
  const auto points = utf8_code_points(text);
  if (!points) return false;
  for (char32_t c : *points)
    if ((c < 0x20 && c != '\t' && !(newlines_kept && c == '\n')) || (c >= 0x7f && c <= 0x9f)) return false;
  return true;
}
}  // namespace

TEST_CASE("escaping: every byte alone", "[check][text]") {
  for (int b = 0; b < 256; ++b) {
    const auto byte = static_cast<unsigned char>(b);
    const std::string alone(1, char(byte));
    INFO("byte " << b);
    const bool printable = (byte >= 0x20 && byte < 0x7f) || byte == '\t';
    CHECK(escaped_control(alone) == (printable ? alone : hex(byte)));  // 0x80..0xff alone: never valid UTF-8
    CHECK(escaped_control(alone, true) == (printable || byte == '\n' ? alone : hex(byte)));
  }
}

TEST_CASE("escaping: valid UTF-8 stays, C1 in UTF-8 and every invalid sequence are escaped as xNN", "[check][text]") {
  for (const char* kept : {"\xc3\xa9l\xc3\xa8ve", "M\xc3\xbcller", "\xe5\xad\xa6\xe7\x94\x9f", "\xf0\x9f\x98\x80",
                           "\xc2\xa0", "\xc2\xbf", "\xdf\xbf", "\xe0\xa0\x80", "\xed\x9f\xbf", "\xee\x80\x80",
                           "\xef\xbf\xbf", "\xf0\x90\x80\x80", "\xf4\x8f\xbf\xbf", "back\\slash"}) {
    INFO(kept);
    CHECK(escaped_control(kept) == kept);
  }
  const std::vector<std::pair<std::string, std::string>> escaped = {
      {"\xc2\x9b" "2J", "\\xc2\\x9b2J"},              // CSI as UTF-8 (U+009B)
      {"a\x9b[2Jb", "a\\x9b[2Jb"},                    // the 8-bit CSI, a raw byte
      {"\xc0\xaf", "\\xc0\\xaf"},                     // overlong '/'
      {"\xc1\xbf", "\\xc1\\xbf"},                     // overlong DEL
      {"\xe0\x80\xaf", "\\xe0\\x80\\xaf"},            // overlong, 3 bytes
      {"\xe0\x9f\xbf", "\\xe0\\x9f\\xbf"},            // overlong, the largest
      {"\xf0\x80\x80\xaf", "\\xf0\\x80\\x80\\xaf"},   // overlong, 4 bytes
      {"\xed\xa0\x80", "\\xed\\xa0\\x80"},            // surrogate U+D800
      {"\xed\xbf\xbf", "\\xed\\xbf\\xbf"},            // surrogate U+DFFF
      {"\xf4\x90\x80\x80", "\\xf4\\x90\\x80\\x80"},   // U+110000
      {"\xf5\x80\x80\x80", "\\xf5\\x80\\x80\\x80"},   // lead byte past U+10FFFF
      {"\xe2\x82" "A", "\\xe2\\x82A"},                // truncated, then ASCII
      {"\xf0\x9f\x98", "\\xf0\\x9f\\x98"},            // truncated at the end
      {"\xe2\x82\xc3\xa9", "\\xe2\\x82\xc3\xa9"},     // truncated, then a valid character (kept)
      {"\x80\xbf", "\\x80\\xbf"},                     // lone continuation bytes
      {"\xc3\x1b[2J", "\\xc3\\x1b[2J"},               // a lead byte swallowing ESC does not hide it
  };
  for (const auto& [raw, shown] : escaped) {
    INFO(shown);
    CHECK(escaped_control(raw) == shown);
  }
}

TEST_CASE("escaping: over random bytes the result is valid UTF-8 without controls, valid text unchanged",
          "[check][text]") {
  std::mt19937 random(44);
  // Bytes biased towards the interesting ones: controls, lead and continuation bytes, ASCII.
  const std::string pool = std::string("\x00\x07\x09\x0a\x0d\x1b\x7f\x80\x9b\x9f\xa0\xbf\xc0\xc1\xc2\xc3\xdf\xe0"
                                       "\xe2\xed\xef\xf0\xf4\xf5\xff" "aZ\\ \"=,",
                                       33);
  for (int round = 0; round < 20000; ++round) {
    std::string text;
    const int length = int(random() % 24);
    for (int i = 0; i < length; ++i)
      text += random() % 3 ? pool[random() % pool.size()] : char(random() % 256);
    for (bool newlines : {false, true}) {
      const std::string shown = escaped_control(text, newlines);
      INFO("round " << round << ": " << bytes_of(shown));
      REQUIRE(inert(shown, newlines));
      if (inert(text, newlines)) REQUIRE(shown == text);  // nothing to escape: nothing changed
    }
  }
  // Valid UTF-8 of random code points (controls left out) comes out unchanged.
  std::uniform_int_distribution<std::uint32_t> points(0xa0, 0x10ffff);
  for (int round = 0; round < 5000; ++round) {
    std::string text;
    for (int i = 0; i < 6; ++i) {
      std::uint32_t c = points(random);
      if (c >= 0xd800 && c <= 0xdfff) c = 0xe9;  // no surrogate: é instead
      if (c < 0x800) text += {char(0xc0 | c >> 6), char(0x80 | (c & 0x3f))};
      else if (c < 0x10000) text += {char(0xe0 | c >> 12), char(0x80 | (c >> 6 & 0x3f)), char(0x80 | (c & 0x3f))};
      else
        text += {char(0xf0 | c >> 18), char(0x80 | (c >> 12 & 0x3f)), char(0x80 | (c >> 6 & 0x3f)),
                 char(0x80 | (c & 0x3f))};
    }
    REQUIRE(utf8_code_points(text));
    REQUIRE(escaped_control(text) == text);
  }
}

namespace {
// Folder names a hostile student would choose: formulas, a leading tab, the 8-bit CSI and invalid UTF-8.
const std::vector<std::string> kHostile = {
    "=HYPERLINK(\"http://x\",\"y\")", "+1", "-2", "@SUM(1)", "\tTAB", "\r=1", "a\x9b[2Jb\xff\xc0\xaf", "\xc3\xa9lise",
    "a;=1+1"};
// How each is written as the CSV's first field: formulas as text (' inside quotes), the rest escaped.
const std::vector<std::string> kWritten = {
    "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"", "\"'+1\"", "\"'-2\"", "\"'@SUM(1)\"", "\"'\tTAB\"",
    "\\x0d=1", "a\\x9b[2Jb\\xff\\xc0\\xaf", "\xc3\xa9lise",
    "\"a;=1+1\""};  // quoted: a spreadsheet splitting on ';' (a French locale) starts no cell with '='


StudentReport one_case_report() {
  StudentReport report;
  CaseResult r;
  r.number = 1;
  r.status = CaseStatus::crash;
  r.detail = "exit status 1 from /class/a\x9b\xff/run.sh";
  r.stderr_text = "\x9b" "2J\x1b[Hscore: 12 / 12\n\xff\xfe bad \xed\xa0\x80 utf-8\n\xc3\xa9 kept\n";
  report.results.push_back(r);
  return report;
}
}  // namespace

TEST_CASE("csv: a name a spreadsheet would read as a formula is text, numbers are left as they are",
          "[check][text][csv]") {
  const StudentReport report = one_case_report();
  const std::string plain = csv_row("alice", report, true);
  const std::string numbers = plain.substr(plain.find(','));  // every column but the student's
  for (std::size_t i = 0; i < kHostile.size(); ++i) {
    INFO(bytes_of(kWritten[i]));
    const std::string row = csv_row(kHostile[i], report, true);
    CHECK(row == kWritten[i] + numbers);
    CHECK(csv_student_field(kHostile[i]) == kWritten[i]);
    CHECK(csv_first_field(row) == kWritten[i]);
    CHECK(inert(row, true));
    // The grade book's column after the row: a number, never guarded.
    CHECK(with_last_field(row, scaled_grade(report, 20)) == kWritten[i] + numbers.substr(0, numbers.size() - 1) + ",0.00\n");
  }
}

TEST_CASE("csv: check merge joins the rows of hostile names, recorded beside each shard as they are",
          "[check][text][csv][merge]") {
  raycam::test::ScratchDir dir("hostile-merge");
  const StudentReport report = one_case_report();
  std::vector<std::string> students = kHostile;
  std::sort(students.begin(), students.end());
  std::vector<std::string> paths;
  std::string expected = with_last_field(csv_header(), "grade_20");
  for (const std::string& s : students) expected += with_last_field(csv_row(s, report, true), "0.00");
  for (int index = 1; index <= 2; ++index) {
    BatchRecord record;
    record.seed = 7;
    record.cases = 1;
    record.mode = "both";
    record.student_cmd = "{dir}/run.sh";
    record.shard = Shard{index, 2};
    record.students = students;
    paths.push_back(dir.path("shard" + std::to_string(index) + ".csv"));
    std::ofstream(battery_sidecar_path(paths.back())) << battery_record_json(record);
    std::ofstream csv(paths.back(), std::ios::binary);
    csv << with_last_field(csv_header(), "grade_20");
    for (const std::string& s : students)
      if (shard_of(s, 2) == index) csv << with_last_field(csv_row(s, report, true), "0.00");
  }
  // Each name read back byte for byte: its slice and its CSV field are those of the folder's own name.
  CHECK(read_battery_record(battery_sidecar_path(paths[0])).students == students);
  const MergedCsv merged = merge_shard_csvs(paths);
  CHECK(merged.text == expected);
  CHECK(merged.record.students == students);
  CHECK(inert(merged.text, true));
  // A shard left out: the message names its students escaped (it goes to the terminal).
  const std::string garbled = kHostile[6];
  std::string message;
  try {
    merge_shard_csvs({paths[std::size_t(2 - shard_of(garbled, 2))]});
  } catch (const std::invalid_argument& error) {
    message = error.what();
  }
  INFO(bytes_of(message));
  CHECK(inert(message, false));
  CHECK_THAT(message, Catch::Contains("missing students: ") && Catch::Contains(kWritten[6]));
}

TEST_CASE("json and text reports: a student's invalid UTF-8 and 8-bit controls are escaped as xNN, the JSON valid",
          "[check][text][json]") {
  const StudentReport report = one_case_report();
  ReportHeader header;
  header.mode = "both";
  const std::vector<CheckCase> cases(1);
  std::string text;
  REQUIRE_NOTHROW(text = json_report(header, cases, report));
  json parsed;
  REQUIRE_NOTHROW(parsed = json::parse(text));  // strict: throws on invalid UTF-8
  CHECK(parsed["results"][0]["stderr"] ==
        "\\x9b2J\\x1b[Hscore: 12 / 12\n\\xff\\xfe bad \\xed\\xa0\\x80 utf-8\n\xc3\xa9 kept\n");
  CHECK(parsed["results"][0]["detail"] == "exit status 1 from /class/a\\x9b\\xff/run.sh");
  const std::string table = text_report(header, cases, report);
  CHECK(inert(table, true));
  CHECK_THAT(table, Catch::Contains("| \\x9b2J\\x1b[Hscore: 12 / 12") && Catch::Contains("\\xff\\xfe bad"));
  const std::string gradescope = gradescope_results_json(header, cases, report, 20, "visible");
  REQUIRE_NOTHROW(parsed = json::parse(gradescope));
  CHECK(inert(parsed["output"].get<std::string>(), true));
}

namespace {
std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

TEST_CASE("batch: hostile folder names reach the CSV as text and the terminal escaped", "[check][text][cli]") {
  namespace fs = std::filesystem;
  raycam::test::ScratchDir scratch("hostile-batch");
  fs::permissions(scratch.dir, fs::perms(0777));  // the sandbox's user crosses it
  const std::string root = scratch.path("class");
  const std::string garbled = "a\x9b[2Jb\xff\xc0\xaf";
  // A student folder as a checkout gives it, readable by anyone: the example student, or `body`.
  auto student = [&](const std::string& name, const std::string& body) {
    const std::string folder = root + "/" + name;
    fs::create_directories(folder);
    std::ofstream(folder + "/run.sh") << "#!/bin/sh\ncd \"$(dirname \"$0\")\"\n" << body << "\n";
    fs::copy_file(EXAMPLE_STUDENT_PY, folder + "/camera.py");
    fs::permissions(folder + "/run.sh", fs::perms(0755));
    fs::permissions(folder + "/camera.py", fs::perms(0644));
    fs::permissions(folder, fs::perms(0755));
  };
  for (const char* name : {"=HYPERLINK(\"x\",\"y\")", "+1", "-2", "@SUM(1)", "\tTAB"}) student(name, "exec python3 camera.py");
  // The 8-bit CSI and invalid UTF-8 in its name and on its stderr (octal: dash's printf).
  student(garbled, "printf '\\233[2J\\377\\300\\257 score: 12 / 12\\n' >&2; exit 1");
  // Its report cannot be written (a folder is in the way): the error naming it is escaped too.
  const std::string blocked = "b\x9b\xfe";
  student(blocked, "exec python3 camera.py");
  fs::create_directories(scratch.path("reports/" + blocked + ".json"));
  const std::string csv = scratch.path("grades.csv");
  const std::string command = std::string("/usr/bin/timeout 120 ") + RAYCAM_CLI + " check --batch " + root +
                              " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --report " + scratch.path("reports") +
                              " --cases 1 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  const int status = pclose(pipe);
  INFO(bytes_of(output));
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);  // one student fails

  const std::string rows = file_text(csv);
  const std::string tail = ",1,1,100.0,";  // passed, cases, score: numbers as they are
  CHECK(rows.find("\n\"'\tTAB\"" + tail) != std::string::npos);
  CHECK(rows.find("\n\"'+1\"" + tail) != std::string::npos);
  CHECK(rows.find("\n\"'-2\"" + tail) != std::string::npos);
  CHECK(rows.find("\n\"'=HYPERLINK(\"\"x\"\",\"\"y\"\")\"" + tail) != std::string::npos);
  CHECK(rows.find("\n\"'@SUM(1)\"" + tail) != std::string::npos);
  CHECK(rows.find("\na\\x9b[2Jb\\xff\\xc0\\xaf,0,1,0.0,") != std::string::npos);
  CHECK(inert(rows, true));
  CHECK(inert(output, true));  // the terminal: progress lines name every folder
  CHECK_THAT(output, Catch::Contains("a\\x9b[2Jb\\xff\\xc0\\xaf: 0/1"));
  CHECK_THAT(output, Catch::Contains("/b\\x9b\\xfe.json: cannot write"));
  json report;
  REQUIRE_NOTHROW(report = json::parse(file_text(scratch.path("reports/" + garbled + ".json"))));
  CHECK(report["results"][0]["stderr"] == "\\x9b[2J\\xff\\xc0\\xaf score: 12 / 12\n");
}
