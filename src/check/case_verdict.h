// One case graded on its own, the way the app's "Check my camera" shows it: the student's program (or an
// answer file) on the case, the verdict of `raycam-cli check`'s grading, the mask of the wrong pixels, and
// the diagnosis when it is affordable.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "check/battery.h"
#include "check/grading.h"

namespace raycam::check {

struct CaseVerdict {
  CaseResult result;
  std::vector<Explanation> diagnosis;
  bool diagnosed = false;  // the diagnosis ran (it may have found nothing)
  int rows = 0, columns = 0, dimension = 2;
  std::vector<std::uint8_t> wrong;  // 1 at a wrong pixel (wrong_pixel_mask), protocol order
  bool sandboxed = false;           // the program ran under bubblewrap
};

struct CaseSource {
  std::vector<std::string> argv;  // the program, already split; empty: read `answer_path`
  std::string answer_path;
  double timeout_seconds = 10.0;
  // Above this many ray-object tests (pixels × objects) the case is graded but not diagnosed: the diagnosis
  // renders it again 91 times.
  double diagnosis_budget = 2e7;
  // The caller gave up (RunLimits::cancel): the run stops within 50 ms, the verdict is not diagnosed and is
  // of no use.
  const std::atomic<bool>* cancel = nullptr;
};

// Runs (or reads) `source` on `checked` and grades it. Throws std::invalid_argument on a camera the core
// refuses.
CaseVerdict grade_case(const CheckCase& checked, const CaseSource& source);

}  // namespace raycam::check
