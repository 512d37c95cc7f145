// The check library's parts: splitting a command without a shell, running a program (exit codes, stdin,
// timeout, output cap), reading answers, ambiguous pixels, grading.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <random>
#include <string>

#include "check/answer.h"
#include "check/case_image.h"
#include "check/grading.h"
#include "check/student_process.h"

using namespace raycam;
using namespace raycam::check;

TEST_CASE("a command is split like a shell word list and never given to a shell", "[check][process]") {
  using V = std::vector<std::string>;
  CHECK(split_command("python3  camera.py\t--fast", "--student") == V{"python3", "camera.py", "--fast"});
  CHECK(split_command("prog 'a b' \"c \\\"d\\\"\" e\\ f ''", "--student") ==
        V{"prog", "a b", "c \"d\"", "e f", ""});
  CHECK(split_command("echo $HOME; rm -rf x", "--student") == V{"echo", "$HOME;", "rm", "-rf", "x"});
  CHECK_THROWS_WITH(split_command("prog 'open", "--student"), Catch::Contains("--student: unclosed '"));
  CHECK_THROWS_WITH(split_command("  ", "--student-cmd"),
                    Catch::Contains("--student-cmd: expected a command"));

  // Run for real: the ';' and '$HOME' reach echo as text (a shell would have run `rm` and expanded $HOME).
  const RunResult run =
      run_student(split_command("echo $HOME; rm -rf x", "t"), "", RunLimits{}, std::nullopt);
  CHECK(run.end == RunResult::End::exited);
  CHECK(run.out == "$HOME; rm -rf x\n");
}

TEST_CASE("running a program: stdin, exit status, signals, timeout, output cap, missing program",
          "[check][process]") {
  RunLimits limits;
  limits.timeout_seconds = 5;
  const std::string big(3 << 20, 'x');  // larger than a pipe buffer: input and output must be interleaved
  RunResult run = run_student({"cat"}, big, limits, std::nullopt);
  CHECK(run.end == RunResult::End::exited);
  CHECK(run.out == big);

  run = run_student({"sh", "-c", "echo oops >&2; exit 3"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::exited);
  CHECK(run.exit_code == 3);
  CHECK(run.err == "oops\n");

  run = run_student({"sh", "-c", "kill -SEGV $$"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::signalled);
  CHECK(run.signal == 11);

  limits.timeout_seconds = 0.3;
  run = run_student({"sleep", "30"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::timed_out);
  CHECK(run.seconds < 5);

  limits.timeout_seconds = 20;
  limits.max_stdout_bytes = 1 << 16;
  run = run_student({"yes"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::output_too_large);
  CHECK(run.out.size() == limits.max_stdout_bytes);

  run = run_student({"no-such-program-raycam"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::could_not_start);
  CHECK_THAT(run.error, Catch::Contains("no-such-program-raycam"));
}

TEST_CASE("the program runs in a fresh empty folder that is removed afterwards", "[check][process]") {
  const RunResult run =
      run_student({"sh", "-c", "pwd; ls -A | wc -l; touch mine"}, "", RunLimits{}, std::nullopt);
  REQUIRE(run.end == RunResult::End::exited);
  const std::string folder = run.out.substr(0, run.out.find('\n'));
  CHECK_THAT(folder, Catch::Contains("raycam-check-"));
  CHECK(run.out.substr(run.out.find('\n') + 1) == "0\n");
  CHECK(access(folder.c_str(), F_OK) != 0);
}

TEST_CASE("answers: shapes, sizes, ids and md are checked, with the field named", "[check][answer]") {
  ParsedAnswer a = parse_answer(R"({"ids": [-1, 0, 2.0, 1], "md": [[1,0,0],[0,1,0],[0,0,1]]})", 2, 1, 4, 3);
  CHECK(a.error.empty());
  REQUIRE(a.answer);
  CHECK(a.answer->ids == std::vector<int>{-1, 0, 2, 1});
  CHECK(a.answer->md->size() == 9);

  a = parse_answer(R"({"ids": [[0, 1], [1, -1], [0, 0]]})", 3, 3, 2, 2);
  CHECK(a.error.empty());
  CHECK(a.answer->ids == std::vector<int>{0, 1, 1, -1, 0, 0});

  a = parse_answer(R"({"ids": [0, 1, 1]})", 2, 1, 4, 3);
  CHECK(a.wrong_size);
  CHECK(a.answer);  // kept for the diagnosis (res_truncated)
  CHECK_THAT(a.error, Catch::Contains("expected 4 ids, got 3"));

  CHECK_THAT(parse_answer(R"({"ids": [0, 3]})", 2, 1, 2, 3).error,
             Catch::Contains("ids[1] = 3: expected an id in [-1, 2]"));
  CHECK_THAT(parse_answer(R"({"ids": [0, 0.5]})", 2, 1, 2, 3).error,
             Catch::Contains("ids[1]: expected an integer"));
  CHECK_THAT(parse_answer(R"({"ids": [[0], [0, 1]]})", 3, 2, 1, 3).error,
             Catch::Contains("ids[1]: 2 columns"));
  CHECK_THAT(parse_answer(R"({"ids": [0], "md": [[1, 2]]})", 2, 1, 1, 3).error,
             Catch::Contains("md: expected 3 rows"));
  CHECK_THAT(parse_answer("hello", 2, 1, 1, 3).error, Catch::Contains("not JSON"));
  CHECK_THAT(parse_answer("[1, 2]", 2, 1, 2, 3).error, Catch::Contains("\"ids\""));
  CHECK_FALSE(parse_answer("hello", 2, 1, 1, 3).answer);
}

TEST_CASE("answers: hostile output is a bad answer naming the field, never a crash", "[check][answer]") {
  // Numbers beyond a double: the reader names the field instead of letting nlohmann's exception escape.
  ParsedAnswer a = parse_answer(R"({"ids": [0, 1e999]})", 2, 1, 2, 3);
  CHECK_FALSE(a.answer);
  CHECK_THAT(a.error, Catch::Contains("ids[1]") && Catch::Contains("out of range"));
  a = parse_answer(R"({"ids": [0, 0], "md": [[1, 0, 0], [0, -1e999, 0], [0, 0, 1]]})", 2, 1, 2, 3);
  CHECK_THAT(a.error, Catch::Contains("md"));
  CHECK_THAT(parse_answer(R"({"ids": [99999999999999999999]})", 2, 1, 1, 3).error, Catch::Contains("ids[0]"));

  // Nesting 100 000 deep (200 KB): refused at the first level the protocol does not have.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  a = parse_answer("{\"ids\": " + deep + "}", 2, 1, 4, 3);
  CHECK_THAT(a.error, Catch::Contains("ids[0]: expected an integer id, got a list"));
  a = parse_answer("{\"ids\": " + deep + "}", 3, 2, 2, 3);
  CHECK_THAT(a.error, Catch::Contains("ids[0][0]: expected an integer id, got a list"));
  a = parse_answer("{\"notes\": " + deep + ", \"ids\": [0]}", 2, 1, 1, 3);
  CHECK_THAT(a.error, Catch::Contains("nested too deep"));

  // Millions of ids: refused as soon as they outnumber the case's pixels, nothing kept of them.
  std::string many = "{\"ids\": [0";
  for (int i = 0; i < 3000000; ++i) many += ",0";
  many += "]}";
  a = parse_answer(many, 2, 1, 37, 3);
  CHECK(a.wrong_size);
  CHECK_FALSE(a.answer);
  CHECK_THAT(a.error, Catch::Contains("expected 37 ids, got more"));
  std::string rows = "{\"ids\": [[0, 0]";
  for (int i = 0; i < 100000; ++i) rows += ", [0, 0]";
  a = parse_answer(rows + "]}", 3, 4, 2, 3);
  CHECK(a.wrong_size);
  CHECK_THAT(a.error, Catch::Contains("expected 4 rows of 2 ids, got more"));

  // Other bytes: not JSON, a string, an object where ids go.
  CHECK_THAT(parse_answer("\xff\xfe{", 2, 1, 1, 3).error, Catch::Contains("not JSON"));
  CHECK_THAT(parse_answer(R"({"ids": "0 1"})", 2, 1, 2, 3).error, Catch::Contains("ids: expected a list"));
  CHECK_THAT(parse_answer(R"({"ids": [{"id": 0}]})", 2, 1, 1, 3).error, Catch::Contains("ids[0]"));
  // Members the protocol does not know are still ignored.
  a = parse_answer(R"({"student": "x", "notes": [1, [2, {"a": null}]], "ids": [0, -1]})", 2, 1, 2, 3);
  CHECK(a.error.empty());
  CHECK(a.answer->ids == std::vector<int>{0, -1});
}

namespace {
SceneFile bar_case(std::vector<Circle> circles, int size) {
  SceneFile file;
  file.dimension = 2;
  file.scene2d.circles = std::move(circles);
  // The canonical camera itself: θ = 90°, d = 1, d_f = 1 puts the screen on y = 1, the eye at (0, 2).
  file.camera = {std::vector<double>{0, 0}, 1.0, 90.0, std::nullopt, 1.0, 1.0, std::vector<int>{size}, std::nullopt};
  return file;
}
}  // namespace

TEST_CASE("ambiguous pixels: a grazing centre ray and a tie, nothing else", "[check][ambiguous]") {
  // 4 pixels, centres at x = -0.75, -0.25, 0.25, 0.75 on the screen y = 1, eye (0, 2): pixel 3's ray
  // starts at (0.75, 1) along (0.75, -1)/1.25. A circle centred on the ray's normal at distance r touches it.
  const glm::dvec2 origin(0.75, 1.0), direction = glm::dvec2(0.75, -1.0) / 1.25, normal(0.8, 0.6);
  const glm::dvec2 touch = origin + 2.0 * direction;
  SceneFile grazing = bar_case({{touch + 0.5 * normal, 0.5, {}, ""}}, 4);
  CaseImage image = render_case(grazing);
  CHECK(image.ambiguous == std::vector<std::uint8_t>{0, 0, 0, 1});

  // The same circle pulled 1% of its radius away: no longer ambiguous.
  grazing.scene2d.circles[0].centre = touch + 0.505 * normal;
  CHECK(render_case(grazing).ambiguous == std::vector<std::uint8_t>{0, 0, 0, 0});

  // Two equal circles: every pixel that sees them ties; the lower index is the answer.
  SceneFile tie = bar_case({{{0, -3}, 3.5, {}, ""}, {{0, -3}, 3.5, {}, ""}}, 4);
  image = render_case(tie);
  CHECK(image.ids == std::vector<int>{0, 0, 0, 0});
  CHECK(image.ambiguous == std::vector<std::uint8_t>{1, 1, 1, 1});

  // A ray starting on a surface: the screen point (−0.25, 1) on a circle.
  SceneFile on_surface = bar_case({{{-0.25, 0.5}, 0.5, {}, ""}}, 4);
  CHECK(render_case(on_surface).ambiguous == std::vector<std::uint8_t>{0, 1, 0, 0});
}

TEST_CASE("grading: wrong pixels, the deepest one, ambiguous pixels forgiven, md compared",
          "[check][grading]") {
  CaseImage reference;
  reference.dimension = 2;
  reference.columns = 9;
  reference.ids = {-1, 0, 0, 0, 0, 0, 0, 0, -1};
  reference.ambiguous = {0, 1, 0, 0, 0, 0, 0, 0, 0};
  reference.md = {2, 0, 1, 0, 2, 0, 0, 0, 1};
  ParsedAnswer parsed;
  parsed.answer =
      Answer{1, 9, {-1, -1, 1, 0, 1, 0, 0, 0, -1}, std::vector<double>{2, 0, 1, 0, 2, 0, 0, 0, 1.0000001}};
  CaseResult result = grade_answer(reference, parsed);
  CHECK(result.status == CaseStatus::fail);
  CHECK(result.wrong_pixels == 2);  // pixel 1 is ambiguous and forgiven
  REQUIRE(result.worst);
  CHECK(result.worst->column == 4);  // three pixels from the nearest edge, against one for pixel 2
  CHECK(result.worst->expected == 0);
  CHECK(result.worst->got == 1);
  CHECK(result.md == "match");
  parsed.answer->md->at(2) = 1.1;
  CHECK(grade_answer(reference, parsed).md == "differs");
  parsed.answer->ids = reference.ids;
  parsed.answer->ids[1] = 3;  // only the ambiguous pixel differs
  CHECK(grade_answer(reference, parsed).status == CaseStatus::pass);
}

TEST_CASE("the worst pixel of an image is the wrong one farthest from any edge (Chebyshev)",
          "[check][grading]") {
  CaseImage reference;  // 7 × 7: columns 0-2 see object 0, columns 3-6 object 1; pixel (0, 6) is ambiguous
  reference.dimension = 3;
  reference.rows = reference.columns = 7;
  for (int r = 0; r < 7; ++r)
    for (int c = 0; c < 7; ++c) {
      reference.ids.push_back(c < 3 ? 0 : 1);
      reference.ambiguous.push_back(r == 0 && c == 6);
    }
  ParsedAnswer parsed;
  parsed.answer = Answer{7, 7, reference.ids, std::nullopt};
  auto wrong = [&](int r, int c) { parsed.answer->ids[std::size_t(r * 7 + c)] = 5; };
  wrong(3, 0);  // 3 columns from object 1 (column 3)
  wrong(6, 4);  // 2 columns from object 0 (column 2)
  wrong(3, 5);  // 3 columns from column 2, 3 rows from the ambiguous pixel
  wrong(4, 6);  // 4 columns from column 2, 4 rows from the ambiguous pixel: the deepest
  const CaseResult result = grade_answer(reference, parsed);
  CHECK(result.wrong_pixels == 4);
  REQUIRE(result.worst);
  CHECK(result.worst->row == 4);
  CHECK(result.worst->column == 6);
  CHECK(result.worst->depth == 4);
}

namespace {
// The depth the grader must report for pixel (r, c), by brute force from its definition: the Chebyshev
// distance to the nearest pixel whose reference id differs or that is ambiguous (0 on an ambiguous pixel),
// at most max(rows, columns) when the image holds no such pixel (the border is not an edge).
int brute_force_depth(const CaseImage& image, int r, int c) {
  const auto at = [&](int row, int column) { return std::size_t(row) * std::size_t(image.columns) + std::size_t(column); };
  int best = std::max(image.rows, image.columns);
  for (int rr = 0; rr < image.rows; ++rr)
    for (int cc = 0; cc < image.columns; ++cc)
      if (image.ambiguous[at(rr, cc)] || image.ids[at(rr, cc)] != image.ids[at(r, c)])
        best = std::min(best, std::max(std::abs(rr - r), std::abs(cc - c)));
  return best;
}

// A random reference: a few rectangles of ids painted over a background (regions several pixels deep),
// a few ambiguous pixels; 2D bars (one row) one time in three.
CaseImage random_reference(std::mt19937& random) {
  std::uniform_int_distribution<int> side(1, 14), id(-1, 3), percent(0, 99);
  CaseImage image;
  image.rows = percent(random) < 33 ? 1 : side(random);
  image.dimension = image.rows == 1 ? 2 : 3;
  image.columns = side(random) + (image.rows == 1 ? 10 : 0);
  image.ids.assign(std::size_t(image.rows * image.columns), id(random));
  for (int k = std::uniform_int_distribution<int>(0, 4)(random); k > 0; --k) {
    const int r0 = std::uniform_int_distribution<int>(0, image.rows - 1)(random);
    const int c0 = std::uniform_int_distribution<int>(0, image.columns - 1)(random);
    const int r1 = std::uniform_int_distribution<int>(r0, image.rows - 1)(random);
    const int c1 = std::uniform_int_distribution<int>(c0, image.columns - 1)(random);
    const int value = id(random);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) image.ids[std::size_t(r * image.columns + c)] = value;
  }
  for (std::size_t i = 0; i < image.ids.size(); ++i) image.ambiguous.push_back(percent(random) < 3);
  return image;
}
}  // namespace

TEST_CASE("the worst pixel's depth is the brute-force distance to the nearest edge, on random images",
          "[check][grading]") {
  std::mt19937 random(38);
  for (int trial = 0; trial < 300; ++trial) {
    const CaseImage reference = random_reference(random);
    INFO("trial " << trial << ": " << reference.rows << " x " << reference.columns);
    std::vector<int> depth;
    for (int r = 0; r < reference.rows; ++r)
      for (int c = 0; c < reference.columns; ++c) depth.push_back(brute_force_depth(reference, r, c));
    // Each pixel wrong alone: the grader's depth map read back pixel by pixel (row 0 and the last row too).
    for (std::size_t i = 0; i < reference.pixels(); ++i) {
      if (reference.ambiguous[i]) continue;  // forgiven: never wrong
      ParsedAnswer parsed;
      parsed.answer = Answer{reference.rows, reference.columns, reference.ids, std::nullopt};
      parsed.answer->ids[i] = reference.ids[i] + 7;
      const CaseResult result = grade_answer(reference, parsed);
      INFO("pixel " << i);
      REQUIRE(result.worst);
      CHECK(result.worst->row * reference.columns + result.worst->column == int(i));
      CHECK(result.worst->depth == depth[i]);
    }
    // A few wrong pixels at once: the worst is one of them, as deep as the deepest.
    ParsedAnswer parsed;
    parsed.answer = Answer{reference.rows, reference.columns, reference.ids, std::nullopt};
    int deepest = -1;
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = std::uniform_int_distribution<std::size_t>(0, reference.pixels() - 1)(random);
      parsed.answer->ids[i] = reference.ids[i] + 7;
      if (!reference.ambiguous[i]) deepest = std::max(deepest, depth[i]);
    }
    const CaseResult result = grade_answer(reference, parsed);
    if (deepest < 0) {
      CHECK_FALSE(result.worst);
      continue;
    }
    REQUIRE(result.worst);
    const std::size_t worst = std::size_t(result.worst->row * reference.columns + result.worst->column);
    CHECK(result.worst->depth == deepest);
    CHECK(depth[worst] == deepest);
    CHECK(parsed.answer->ids[worst] != reference.ids[worst]);
  }
}

TEST_CASE("a run's processes are capped, and a sandbox that cannot start is the checker's failure",
          "[check][sandbox]") {
  std::string why;
  const std::optional<Sandbox> sandbox = probe_sandbox(why);
  if (!sandbox) return;  // no sandbox here: the cap and the info pipe are the sandbox's
  const std::vector<std::string> forks = {"python3", MISBEHAVING_PY, "forks", "600"};
  RunLimits limits;
  limits.max_processes = 64;
  RunResult run = run_student(forks, "", limits, sandbox);
  REQUIRE(run.end == RunResult::End::exited);
  CHECK_FALSE(run.infrastructure_failure);
  int started = -1;
  std::sscanf(run.err.c_str() + run.err.find("started"), "started %d", &started);
  CHECK(started >= 0);
  CHECK(started < 64);
  // No process left for the program (bwrap's own two are counted on top): bwrap stops before it, the
  // checker's failure, not the student's crash.
  limits.max_processes = 0;
  run = run_student({"python3", "-c", "print(1)"}, "", limits, sandbox);
  CHECK(run.infrastructure_failure);
  // A program that only says "bwrap:" and fails is the program's failure.
  limits = RunLimits{};
  run = run_student({"python3", "-c", "import sys; print('bwrap: fake', file=sys.stderr); sys.exit(1)"}, "", limits,
                    sandbox);
  CHECK(run.end == RunResult::End::exited);
  CHECK_FALSE(run.infrastructure_failure);
}

TEST_CASE("a program that closes its stdout and goes on is stopped at the timeout", "[check][timeout]") {
  RunLimits limits;
  limits.timeout_seconds = 1.0;
  const RunResult run = run_student({"python3", MISBEHAVING_PY, "close-sleep"}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::timed_out);
  CHECK(run.seconds < 10.0);  // the deadline, not the program's 60 s
}

TEST_CASE("a program's answer counts when it exits, even if a detached child still holds its output",
          "[check][timeout]") {
  RunLimits limits;
  limits.timeout_seconds = 5.0;
  const std::string program =
      "import os, sys, time\n"
      "print('{\"ids\": [0]}', flush=True)\n"
      "if os.fork() == 0:\n"
      "    os.setsid()  # out of the run's process group, stdout still open\n"
      "    time.sleep(20)\n"
      "    os._exit(0)\n";
  const RunResult run = run_student({"python3", "-c", program}, "", limits, std::nullopt);
  CHECK(run.end == RunResult::End::exited);
  CHECK(run.exit_code == 0);
  CHECK(run.out == "{\"ids\": [0]}\n");
  CHECK(run.seconds < 3.0);
}
