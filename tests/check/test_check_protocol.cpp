// The grader's protocol is the handout's by default: one resolution variable ("une (ou deux) variables de
// résolution": the second is optional). A program written to one passes the default battery; --two-res asks
// the 3D case whose res is a pair, and a program failing only that case is told so in one line, in English
// and French. Every case, report and batch record states the protocol version it follows.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../scratch_dir.h"
#include "check/batch_record.h"
#include "check/battery.h"
#include "check/check_report.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace raycam;
using namespace raycam::check;

namespace {
constexpr int kDefaultCases = 12;   // the designed battery, 6 per dimension
constexpr int kTwoResCase = 8;      // docs/check.md: the two-resolution case is case 8 of --mode both

std::string scratch(const std::string& name) {
  static const raycam::test::ScratchDir root("check-protocol");
  const std::string dir = root.path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Checked {
  int exit_code = -1;
  json report;
  std::string output;
};

// `raycam-cli check ARGS`, with --report FILE unless `report` is false; its output and its report.
Checked run_check(const std::string& args, const std::string& name, bool report_file = true) {
  const std::string dir = scratch(name);
  const std::string report = dir + "/report.json", output = dir + "/output.txt";
  const std::string command = std::string(RAYCAM_CLI) + " check " + args +
                              (report_file ? " --report " + report : std::string()) + " > " + output + " 2>&1";
  const int status = std::system(command.c_str());
  Checked c;
  c.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::stringstream text;
  text << std::ifstream(output).rdbuf();
  c.output = text.str();
  if (std::ifstream in(report); in && fs::is_regular_file(report)) c.report = json::parse(in);
  return c;
}

// A student written to one resolution variable (tests/check/students/one_res_camera.py).
const std::string kOneRes = std::string("--student \"python3 ") + ONE_RES_PY + " " + EXAMPLES_DIR + "\"";

// The note's words that do not depend on the case number, as a grader reading the line would look for them.
const char* const kEnglishNote = "fails only the two-resolution case (case 8";
const char* const kFrenchNote = "seul le cas à deux résolutions échoue (cas 8";
}  // namespace

TEST_CASE("a program that reads res as one number passes every default case", "[check][cli][protocol]") {
  const Checked c = run_check(kOneRes, "one_res_default");
  INFO(c.output);
  CHECK(c.exit_code == 0);
  CHECK(c.report["cases"] == kDefaultCases);
  CHECK(c.report["passed"] == kDefaultCases);
  CHECK(c.report["protocol"] == kProtocolVersion);
  CHECK(c.report["two_res"] == false);
  CHECK_FALSE(c.report.contains("two_res_note"));
}

TEST_CASE("with --two-res it fails only the two-resolution case, and is told so in English and French",
          "[check][cli][protocol][language]") {
  const Checked c = run_check(kOneRes + " --two-res", "one_res_two");
  INFO(c.output);
  CHECK(c.exit_code == 1);
  CHECK(c.report["two_res"] == true);
  CHECK(c.report["passed"] == kDefaultCases - 1);
  for (const json& r : c.report["results"])
    CHECK((r["status"] == "pass") == (r["case"] != kTwoResCase));
  CHECK_THAT(c.output, Catch::Contains(kEnglishNote) && Catch::Contains("--two-res"));
  REQUIRE(c.report.contains("two_res_note"));
  CHECK_THAT(c.report["two_res_note"].get<std::string>(), Catch::StartsWith(kEnglishNote));

  const Checked fr = run_check(kOneRes + " --two-res --lang fr", "one_res_two_fr");
  INFO(fr.output);
  CHECK_THAT(fr.output, Catch::Contains(kFrenchNote) && Catch::Contains("--two-res"));
  CHECK_THAT(fr.output, !Catch::Contains(kEnglishNote));
  CHECK_THAT(fr.report["two_res_note"].get<std::string>(), Catch::StartsWith(kFrenchNote));
}

TEST_CASE("a program that reads both resolutions passes --two-res, with no note", "[check][cli][protocol]") {
  // The examples (examples/student/) read res as a number or a pair.
  for (const std::string student : {std::string(EXAMPLE_STUDENT_CPP), std::string("python3 ") + EXAMPLE_STUDENT_PY}) {
    const Checked c = run_check("--two-res --student \"" + student + "\"", "example_two");
    INFO(student << "\n" << c.output);
    CHECK(c.exit_code == 0);
    CHECK(c.report["passed"] == kDefaultCases);
    CHECK_FALSE(c.report.contains("two_res_note"));
    CHECK_THAT(c.output, !Catch::Contains("two-resolution"));
  }
}

TEST_CASE("the note is for the two-resolution case alone: another failure, or the checker's, has none",
          "[check][protocol][language]") {
  const std::vector<CheckCase> two = make_battery(BatteryMode::three_d, 6, kDefaultSeed, /*two_res=*/true);
  const std::vector<CheckCase> one = make_battery(BatteryMode::three_d, 6, kDefaultSeed);
  // Case 4 of --mode 3d is the two-resolution one (docs/check.md).
  const auto report_failing = [](std::vector<std::pair<int, CaseStatus>> failing) {
    StudentReport report;
    for (int i = 1; i <= 6; ++i) {
      CaseResult r;
      r.number = i;
      r.dimension = 3;
      for (const auto& [number, status] : failing)
        if (number == i) r.status = status;
      report.results.push_back(r);
    }
    return report;
  };
  const StudentReport crashed = report_failing({{4, CaseStatus::crash}});
  CHECK_THAT(two_res_note(Language::en, two, crashed), Catch::StartsWith("fails only the two-resolution case (case 4"));
  CHECK_THAT(two_res_note(Language::fr, two, crashed),
             Catch::StartsWith("seul le cas à deux résolutions échoue (cas 4") && Catch::Contains("--two-res"));
  CHECK_THAT(two_res_note(Language::en, two, report_failing({{4, CaseStatus::fail}})), Catch::Contains("case 4"));
  CHECK(two_res_note(Language::en, two, report_failing({{4, CaseStatus::crash}, {2, CaseStatus::fail}})).empty());
  CHECK(two_res_note(Language::en, two, report_failing({{4, CaseStatus::checker_error}})).empty());
  CHECK(two_res_note(Language::en, two, report_failing({})).empty());
  CHECK(two_res_note(Language::en, one, crashed).empty());  // the default battery's case 4 has one res
}

TEST_CASE("written cases state their protocol, and only --two-res writes a pair res", "[check][cli][protocol]") {
  for (const bool two_res : {false, true}) {
    const std::string dir = scratch(two_res ? "cases_two" : "cases_one");
    const Checked c = run_check("--write-cases " + dir + (two_res ? " --two-res" : ""), two_res ? "write_two" : "write_one");
    REQUIRE(c.exit_code == 0);
    int pairs = 0;
    for (int i = 1; i <= kDefaultCases; ++i) {
      const std::string name = dir + "/case_" + (i < 10 ? "0" : "") + std::to_string(i) + ".json";
      std::ifstream in(name);
      const json file = json::parse(in);
      INFO(name);
      CHECK(file["protocol"] == kProtocolVersion);
      pairs += file["camera"]["res"].is_array();
    }
    CHECK(pairs == (two_res ? 1 : 0));
  }
}

TEST_CASE("the flag --two-res on a battery without the two-resolution case is bad usage", "[check][cli][protocol][usage]") {
  for (const std::string args : {"--mode 2d", "--cases 7"}) {
    INFO(args);
    const Checked c = run_check("--two-res --write-cases " + scratch("never") + " " + args, "two_res_usage");
    CHECK(c.exit_code == 2);
    CHECK_THAT(c.output, Catch::Contains("--two-res"));
  }
  CHECK(run_check("--two-res --write-cases " + scratch("eight") + " --cases 8", "two_res_eight").exit_code == 0);
}

TEST_CASE("a batch's record says the protocol and --two-res, so merge refuses shards graded both ways",
          "[check][cli][protocol][merge]") {
  const std::string root = scratch("class");
  const std::string folder = root + "/ann";
  fs::create_directories(folder);
  // A program of its own in the student's folder (the sandbox hides the build tree's /tmp).
  fs::copy_file(EXAMPLE_STUDENT_PY, folder + "/camera.py");
  std::vector<std::string> csvs;
  for (const bool two_res : {false, true}) {
    const std::string out = scratch(two_res ? "out_two" : "out_one");
    const std::string csv = out + "/grades.csv";
    const Checked c = run_check("--batch " + root + " --student-cmd \"python3 {dir}/camera.py\" --csv " + csv +
                                " --mode 3d" + (two_res ? " --two-res" : ""),
                            two_res ? "batch_two" : "batch_one");
    INFO(c.output);
    REQUIRE(c.exit_code == 0);
    std::ifstream in(battery_sidecar_path(csv));
    const json record = json::parse(in);
    CHECK(record["protocol"] == kProtocolVersion);
    CHECK(record["two_res"] == two_res);
    csvs.push_back(csv);
  }
  const std::string merged = scratch("merged") + "/grades.csv";
  const Checked refused = run_check("merge --csv " + merged + " " + csvs[0] + " " + csvs[1], "merge_refused", false);
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("two_res false vs true") || Catch::Contains("two_res true vs false"));
  CHECK_FALSE(fs::exists(merged));
}
