// A long command's progress on stderr (`raycam-cli bench speed`, `bench accuracy`): what it is doing, how
// far along it is, and the time left at the pace so far, the estimate check --batch's bar gives (time_left).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace raycam::check {

// Where a run stands as a step starts: its number and the work done before it, of the whole.
struct Progress {
  std::size_t step = 0, steps = 0;  // the step starting (from 0) of `steps` (0: a total not known)
  std::size_t done = 0, work = 0;   // work ended before it and in all, in any one unit (by default a step each)
};

// "bench speed: 3/120 (speed/cube/K:1000/side:256/threads:1/plain), 1 %, about 40 s left": the step
// starting, `what` it does, the share of the work done and the time left at the pace of `elapsed_seconds`
// (time_left). No estimate before any work has ended; without a total, the step's number alone.
std::string progress_text(const std::string& command, const Progress& progress, const std::string& what,
                          double elapsed_seconds);

// progress_text as each step starts, on `out`: rewritten in place on a terminal, one line per step
// otherwise (a log stays readable), nothing at all when quiet. English, as the bench commands' tables.
class ProgressLine {
 public:
  // `work`: the steps' work together, when they differ (each start() then says its own); 0: a step each.
  ProgressLine(std::string command, std::size_t steps, bool quiet, std::FILE* out = stderr, std::size_t work = 0);
  // The next step begins; `work` is its share, in the unit of the constructor's.
  void start(const std::string& what, std::size_t work = 1);
  // Wipes the line on a terminal, before other output to the same terminal (the next start draws it again).
  void clear();
  // Every step has ended: the last word, "COMMAND: N steps in T s", on its own line (none if no step ran).
  void finish();

 private:
  void show(const std::string& line);
  std::string command_;
  Progress progress_;
  std::size_t shown_width_ = 0;
  bool quiet_ = false, terminal_ = false;
  std::FILE* out_ = nullptr;
  std::chrono::steady_clock::time_point began_;
};

}  // namespace raycam::check
