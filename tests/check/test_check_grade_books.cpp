// Grades where a course keeps them: Gradescope's results.json checked against the fields Gradescope's
// autograder specification documents (names, types, statuses, visibilities, scores adding up), and the --batch
// CSV's last column, the grade out of --scale (20 by default) that Moodle's grade import reads. And the
// command line of a large course's shards (bad usage, an empty slice, merge's usage).
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "../scratch_dir.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {
const raycam::test::ScratchDir& scratch() {
  static const raycam::test::ScratchDir dir("grade-books");
  return dir;
}

// `raycam-cli check ARGS`: the exit status and the output.
std::pair<int, std::string> run_check(const std::string& args) {
  const std::string output = scratch().path("output.txt");
  const int status = std::system((std::string(RAYCAM_CLI) + " check " + args + " > " + output + " 2>&1").c_str());
  std::ifstream in(output);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// Gradescope's autograder specification (results.json): the top-level fields and a test's fields it documents,
// and the values it accepts for status and visibility.
const std::set<std::string> kTopFields = {"score", "execution_time", "output", "output_format", "test_output_format",
                                          "test_name_format", "visibility", "stdout_visibility", "extra_data",
                                          "tests", "leaderboard"};
const std::set<std::string> kTestFields = {"score", "max_score", "status", "name", "name_format", "number",
                                           "output", "output_format", "tags", "visibility", "extra_data"};
const std::set<std::string> kVisibilities = {"hidden", "after_due_date", "after_published", "visible"};

// Validates `results` as Gradescope reads it; returns the sum of the tests' max_score.
double validate_gradescope(const json& results) {
  REQUIRE(results.is_object());
  for (const auto& [key, value] : results.items()) {
    INFO(key);
    CHECK(kTopFields.count(key) == 1);
  }
  REQUIRE(results.at("score").is_number());
  REQUIRE(results.at("tests").is_array());
  CHECK(results.at("output").is_string());
  CHECK(kVisibilities.count(results.at("visibility").get<std::string>()) == 1);
  double score = 0, max_score = 0;
  for (const json& test : results["tests"]) {
    for (const auto& [key, value] : test.items()) {
      INFO(key);
      CHECK(kTestFields.count(key) == 1);
    }
    REQUIRE(test.at("score").is_number());
    REQUIRE(test.at("max_score").is_number());
    CHECK(test["score"].get<double>() >= 0);
    CHECK(test["score"].get<double>() <= test["max_score"].get<double>());
    const std::string status = test.at("status").get<std::string>();
    CHECK((status == "passed" || status == "failed"));
    CHECK(test["score"].get<double>() == (status == "passed" ? test["max_score"].get<double>() : 0.0));
    CHECK(test.at("name").is_string());
    CHECK(test.at("number").is_string());
    CHECK(test.at("output").is_string());
    CHECK(kVisibilities.count(test.at("visibility").get<std::string>()) == 1);
    score += test["score"].get<double>();
    max_score += test["max_score"].get<double>();
  }
  CHECK(results["score"].get<double>() == Approx(score));  // the top-level score overrides: they must agree
  return max_score;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  return json::parse(in);
}
}  // namespace

TEST_CASE("the flag --gradescope writes a results.json with Gradescope's documented fields", "[check][gradescope]") {
  const std::string file = scratch().path("results.json");
  SECTION("a passing camera: every test passed, the score out of 20") {
    const auto [status, output] = run_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 4 --gradescope " + file);
    INFO(output);
    CHECK(status == 0);
    const json results = read_json(file);
    CHECK(validate_gradescope(results) == Approx(20));
    CHECK(results["tests"].size() == 4);
    CHECK(results["score"].get<double>() == 20);
  }
  SECTION("a mirrored camera: failed tests whose output names the mistake, score out of --scale") {
    const auto [status, output] = run_check(std::string("--student \"") + MISTAKEN_STUDENT +
                                            " --mistake mirrored\" --cases 4 --scale 100 --visibility after_published "
                                            "--gradescope " + file);
    INFO(output);
    CHECK(status == 1);
    const json results = read_json(file);
    CHECK(validate_gradescope(results) == Approx(100));
    CHECK(results["score"].get<double>() == 0);
    for (const json& test : results["tests"]) {
      CHECK(test["status"] == "failed");
      CHECK(test["visibility"] == "after_published");
      CHECK_THAT(test["output"].get<std::string>(), Catch::Contains("mirrored"));
    }
  }
  SECTION("bad usage: another visibility, a batch, a missing folder") {
    auto [status, output] = run_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --visibility public --gradescope " + file);
    CHECK(status == 2);
    CHECK_THAT(output, Catch::Contains("--visibility") && Catch::Contains("after_due_date"));
    std::tie(status, output) = run_check("--batch . --student-cmd x --csv " + scratch().path("g.csv") + " --gradescope " + file);
    CHECK(status == 2);
    CHECK_THAT(output, Catch::Contains("--gradescope"));
    std::tie(status, output) = run_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --gradescope " +
                                         scratch().path("no/results.json"));
    CHECK(status == 2);
    CHECK_THAT(output, Catch::Contains("--gradescope"));
  }
}

TEST_CASE("the batch CSV's last column is the grade out of --scale, for Moodle's import", "[check][moodle][batch]") {
  const std::string root = scratch().path("class");
  for (const auto& [name, command] : {std::pair<std::string, std::string>{"ann", EXAMPLE_STUDENT_CPP},
                                      {"bob", std::string(MISTAKEN_STUDENT) + " --mistake res_truncated"}}) {
    fs::create_directories(root + "/" + name);
    const fs::path program = fs::path(command.substr(0, command.find(' ')));
    fs::copy_file(program, root + "/" + name + "/" + program.filename().string(), fs::copy_options::overwrite_existing);
    std::ofstream(root + "/" + name + "/run.sh") << "#!/bin/sh\ncd \"$(dirname \"$0\")\"\nexec ./"
                                                << program.filename().string() << command.substr(program.string().size()) << "\n";
    fs::permissions(root + "/" + name + "/run.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
  }
  for (const auto& [flag, column, scale] : {std::tuple<std::string, std::string, double>{"", "grade_20", 20},
                                            {"--scale 12.5", "grade_12.5", 12.5}}) {
    const std::string csv = scratch().path("grades.csv");
    const auto [status, output] = run_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --cases 6 --csv " + csv + " " + flag);
    INFO(output);
    CHECK(status == 1);  // bob fails some cases
    std::ifstream in(csv);
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(line.substr(line.rfind(',') + 1) == column);
    int rows = 0, partly = 0;
    while (std::getline(in, line)) {
      ++rows;
      std::vector<std::string> fields;
      std::stringstream split(line);
      for (std::string field; std::getline(split, field, ',');) fields.push_back(field);
      const double passed = std::stod(fields[1]), cases = std::stod(fields[2]);
      CHECK(std::stod(fields.back()) == Approx(scale * passed / cases).margin(0.005));  // two decimals
      partly += passed > 0 && passed < cases;
    }
    CHECK(rows == 2);
    CHECK(partly == 1);  // bob: a grade strictly between 0 and the scale
  }
}

TEST_CASE("shards on the command line: bad usage before any run, an empty slice, merge's own usage",
          "[check][shards][cli]") {
  const std::string root = scratch().path("lone");
  fs::create_directories(root + "/ann");
  fs::copy_file(EXAMPLE_STUDENT_CPP, root + "/ann/camera", fs::copy_options::overwrite_existing);
  const std::string batch = "--batch " + root + " --student-cmd \"{dir}/camera\" --cases 1 ";
  auto [status, output] = run_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --shard 1/2");
  CHECK(status == 2);
  CHECK_THAT(output, Catch::Contains("--shard: only with --batch"));
  std::tie(status, output) = run_check(batch + "--csv " + scratch().path("bad.csv") + " --shard 3/2");
  CHECK(status == 2);
  CHECK_THAT(output, Catch::Contains("--shard: expected i/N with 1 <= i <= N"));
  CHECK_FALSE(fs::exists(scratch().path("bad.csv")));  // nothing ran, nothing written

  // One student in two slices: one slice is empty (its CSV is the header line) and still exits 0.
  std::vector<std::string> csvs;
  for (int i = 1; i <= 2; ++i) {
    csvs.push_back(scratch().path("lone" + std::to_string(i) + ".csv"));
    std::tie(status, output) = run_check(batch + "--csv " + csvs.back() + " --shard " + std::to_string(i) + "/2");
    INFO(output);
    CHECK(status == 0);
  }
  std::tie(status, output) = run_check(batch + "--csv " + scratch().path("lone.csv"));
  CHECK(status == 0);
  std::tie(status, output) = run_check("merge --csv " + scratch().path("merged.csv") + " " + csvs[0] + " " + csvs[1]);
  INFO(output);
  CHECK(status == 0);
  auto text = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  };
  const std::string both = text(csvs[0]) + text(csvs[1]);
  CHECK(std::count(both.begin(), both.end(), '\n') == 3);  // two header lines, one row
  // Byte for byte the row its shard wrote; against a second, single run, all but the measured columns (CPU
  // time and peak memory differ between any two runs of the same program).
  const std::string full = text(csvs[0]).size() > text(csvs[1]).size() ? text(csvs[0]) : text(csvs[1]);
  CHECK(text(scratch().path("merged.csv")) == full);
  auto unmeasured = [](const std::string& csv) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(csv);
    for (std::string line; std::getline(lines, line);) {
      rows.emplace_back();
      std::istringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) rows.back().push_back(field);
    }
    for (std::size_t c = 0; !rows.empty() && c < rows[0].size(); ++c)
      if (rows[0][c] == "cpu_seconds" || rows[0][c] == "peak_memory_mb")
        for (std::size_t r = 1; r < rows.size(); ++r) rows[r].at(c) = "measured";
    return rows;
  };
  CHECK(unmeasured(text(scratch().path("merged.csv"))) == unmeasured(text(scratch().path("lone.csv"))));

  std::tie(status, output) = run_check("merge " + csvs[0]);
  CHECK(status == 2);
  CHECK_THAT(output, Catch::Contains("--csv"));
  std::tie(status, output) = run_check("merge --csv " + scratch().path("m.csv") + " " + scratch().path("none.csv"));
  CHECK(status == 2);
  CHECK_THAT(output, Catch::Contains("none.csv.battery.json: cannot read"));
}
