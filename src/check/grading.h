// Grading one case, and the diagnosis over the failing ones.
//
// Pass rule: every pixel equals the reference, except pixels the reference marks ambiguous (case_image.h).
// Diagnosis: for each failing case with a well-formed answer (a wrong size included: res_truncated makes
// one), the case is rendered again with each classic mistake on, alone and in pairs, and a candidate is kept
// when its image equals the answer at every pixel it does not itself mark ambiguous (and its M_d equals the
// answer's "md", when given). A pair is kept only when it reproduces a case neither of its mistakes alone
// reproduces. Explanations are sorted by the number of failing cases they reproduce, most first, then single
// mistakes before pairs, then the table's order (so in 3D upside_down comes before mirrored+rows_flipped).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "check/answer.h"
#include "check/battery.h"
#include "check/case_image.h"
#include "raycam/classic_mistakes.h"

namespace raycam::check {

// checker_error: the checker could not run the program (the sandbox did not start, no process could be
// forked), twice: not counted against the student, who is to be checked again.
enum class CaseStatus { pass, fail, crash, timeout, bad_output, checker_error };
const char* status_name(CaseStatus status);  // "pass", "fail", "crash", "timeout", "bad-output", "checker-error"

// The wrong pixel deepest inside a region where the reference is one id (the clearest error to look at).
struct WorstPixel {
  int row = 0, column = 0;  // 2D: row 0, column = pixel k
  int expected = -1, got = -1;
  int depth = 0;  // pixels to the nearest reference edge or ambiguous pixel
};

struct CaseResult {
  int number = 0;  // 1-based, as the case files
  int dimension = 2;
  CaseStatus status = CaseStatus::pass;
  long long pixels = 0, wrong_pixels = 0, ambiguous_pixels = 0;
  std::optional<WorstPixel> worst;
  std::string md = "absent";  // "absent", "match", "differs"
  std::string detail;         // why a case crashed, timed out or gave a bad output
  std::string stderr_text;    // the program's stderr (capped)
  double seconds = 0;
  double cpu_seconds = 0;           // the run's CPU time, all its processes (student_process.h)
  long long peak_memory_bytes = 0;  // the run's peak memory (0: not measured)
  std::string limit;                // the bound that ended the run ("memory-limit"…), "" if none
  std::optional<Answer> answer;           // kept for the diagnosis and the difference images
  std::vector<std::string> explained_by;  // explanation IDs reproducing this case
};

// 1 at each pixel where `answer` is wrong (pixel_is_wrong), in protocol order; all 0 when the answer is not the
// reference's size.
std::vector<std::uint8_t> wrong_pixel_mask(const CaseImage& reference, const Answer& answer);

// The verdict on an answer (the program exited 0 and printed `parsed`).
CaseResult grade_answer(const CaseImage& reference, const ParsedAnswer& parsed);

struct Explanation {
  std::vector<const MistakeInfo*> mistakes;  // one or two
  std::vector<int> cases;                    // the case numbers it reproduces
  std::string id() const;                    // "mirrored" or "mirrored+rows_flipped"
  std::string text(Language language) const;
};

std::vector<Explanation> diagnose(const std::vector<CheckCase>& cases, std::vector<CaseResult>& results);

}  // namespace raycam::check
