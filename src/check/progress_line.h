// A long command's progress on stderr (`raycam-cli bench speed`, `bench accuracy`): what it is doing, how
// far along it is, and the time left at the pace so far, the estimate check --batch's bar gives (time_left).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace raycam::check {

// "bench speed: 3/120 (speed/cube/K:1000/side:256/threads:1/plain), 1 %, about 40 s left": step `done` + 1
// of `total` starting, `what` it does, `done` steps ended in `elapsed_seconds`. No estimate before the
// first step has ended; a `total` of 0 (not known) gives the step's number alone.
std::string progress_text(const std::string& command, std::size_t done, std::size_t total, const std::string& what,
                          double elapsed_seconds);

// progress_text as each step starts, on `out`: rewritten in place on a terminal, one line per step
// otherwise (a log stays readable), nothing at all when quiet. English, as the bench commands' tables.
class ProgressLine {
 public:
  ProgressLine(std::string command, std::size_t total, bool quiet, std::FILE* out = stderr);
  // The next step begins.
  void start(const std::string& what);
  // Wipes the line on a terminal, before other output to the same terminal (the next start draws it again).
  void clear();
  // Every step has ended: the last word, "COMMAND: N steps in T s", on its own line.
  void finish();

 private:
  void show(const std::string& line);
  std::string command_;
  std::size_t total_ = 0, started_ = 0, shown_width_ = 0;
  bool quiet_ = false, terminal_ = false;
  std::FILE* out_ = nullptr;
  std::chrono::steady_clock::time_point began_;
};

}  // namespace raycam::check
