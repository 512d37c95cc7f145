// The progress line of the long commands (bench speed, bench accuracy): its text from the steps done and the
// time spent, and what it writes where it is not a terminal (a log: one line a step) or is told to be quiet.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

#include "check/check_texts.h"
#include "check/progress_line.h"

using raycam::Language;
using raycam::check::progress_text;
using raycam::check::ProgressLine;
using raycam::check::time_left;

namespace {
// Everything written to a temporary file (not a terminal).
std::string written(std::FILE* file) {
  std::string text;
  std::rewind(file);
  for (int c; (c = std::fgetc(file)) != EOF;) text += char(c);
  return text;
}
}  // namespace

TEST_CASE("progress text: the step starting, its share done and the time left at the pace so far",
          "[check][progress]") {
  using raycam::check::Progress;
  // 2 of 12 steps in 20 s: 10 s a step, 10 steps left, 100 s (+1, rounded up as check --batch rounds).
  CHECK(progress_text("bench speed", Progress{2, 12, 2, 12}, "cube K=1e5", 20.0) ==
        "bench speed: 3/12 (cube K=1e5), 16 %, about 1 min 41 s left");
  CHECK(progress_text("bench accuracy", Progress{0, 63, 0, 63}, "2d-classic reference", 0.2) ==
        "bench accuracy: 1/63 (2d-classic reference), 0 %");  // no pace before a step has ended
  CHECK(progress_text("bench speed", Progress{11, 12, 11, 12}, "", 11.0) == "bench speed: 12/12, 91 %, about 2 s left");
  CHECK(progress_text("bench speed", Progress{3, 0, 3, 0}, "x", 9.0) == "bench speed: 4 (x)");  // a total not known
  // Steps of unequal work: the share and the pace are the work's, not the steps' (4 steps of 63 ended,
  // 3 of them the long references: 30 % of the work in 6 s, 14 s left, +1).
  CHECK(progress_text("bench accuracy", Progress{4, 63, 300, 1000}, "3d-far reference", 6.0) ==
        "bench accuracy: 5/63 (3d-far reference), 30 %, about 15 s left");
  CHECK(progress_text("bench speed", Progress{5, 6, 1200, 1000}, "x", 9.0) == "bench speed: 6/6 (x), 100 %");  // work over
  // The estimate is check --batch's own, word for word.
  const std::string text = progress_text("bench speed", Progress{7, 40, 7, 40}, "x", 33.0);
  const std::string left = time_left(Language::en, 7, 40, 33.0);
  REQUIRE_FALSE(left.empty());
  CHECK(text.size() > left.size());
  CHECK(text.compare(text.size() - left.size(), left.size(), left) == 0);
}

TEST_CASE("progress line: one line a step off a terminal, the total kept, the share by work, nothing when quiet",
          "[check][progress]") {
  std::FILE* log = std::tmpfile();
  REQUIRE(log != nullptr);
  {
    ProgressLine line("bench speed", 2, false, log);
    line.start("first");
    line.clear();  // off a terminal nothing to wipe
    line.start("second");
    line.start("third");  // past the total: shown without a share over 100 %
    line.finish();
  }
  const std::string text = written(log);
  std::fclose(log);
  CHECK(text.rfind("bench speed: 1/2 (first), 0 %\nbench speed: 2/2 (second), 50 %", 0) == 0);
  CHECK(text.find("\nbench speed: 3 (third)\nbench speed: 3 steps in ") != std::string::npos);
  CHECK(text.find('\r') == std::string::npos);
  CHECK(text.back() == '\n');

  std::FILE* weighed = std::tmpfile();
  REQUIRE(weighed != nullptr);
  {
    ProgressLine line("bench accuracy", 3, false, weighed, 100);
    line.start("long", 90);
    line.start("short", 5);
    line.start("short", 5);
  }
  const std::string weighed_text = written(weighed);
  std::fclose(weighed);
  CHECK(weighed_text.find("bench accuracy: 2/3 (short), 90 %") != std::string::npos);
  CHECK(weighed_text.find("bench accuracy: 3/3 (short), 95 %") != std::string::npos);

  std::FILE* quiet_log = std::tmpfile();
  REQUIRE(quiet_log != nullptr);
  ProgressLine quiet("bench speed", 2, true, quiet_log);
  quiet.start("first");
  quiet.finish();
  CHECK(written(quiet_log).empty());
  std::fclose(quiet_log);
}
