#include "check/case_verdict.h"

#include <algorithm>
#include <optional>

#include "check/check_run.h"
#include "raycam/scene_file.h"

namespace raycam::check {

CaseVerdict grade_case(const CheckCase& checked, const CaseSource& source) {
  const CaseImage reference = render_case(checked.file);
  std::string why;
  const bool reads_file = source.argv.empty();
  const std::optional<Sandbox> sandbox = reads_file ? std::nullopt : probe_sandbox(why);
  CaseVerdict verdict;
  verdict.sandboxed = bool(sandbox);
  if (reads_file) {
    verdict.result = grade_answer_file(1, checked, reference, source.answer_path);
  } else {
    RunLimits limits;
    limits.timeout_seconds = source.timeout_seconds;
    limits.cancel = source.cancel;
    const RunResult run = run_student(source.argv, scene_to_json(checked.file), limits, sandbox);
    if (run.cancelled) return verdict;  // nobody waits for it: no grading, no diagnosis
    verdict.result = result_of_run(1, checked, reference, run);
  }
  verdict.dimension = reference.dimension;
  verdict.rows = reference.rows;
  verdict.columns = reference.columns;
  const CaseResult& r = verdict.result;
  verdict.wrong =
      r.answer ? wrong_pixel_mask(reference, *r.answer) : std::vector<std::uint8_t>(reference.pixels(), 0);
  const double tests = double(reference.pixels()) * std::max(1, object_count(checked.file));
  if (r.answer && r.status != CaseStatus::pass && tests <= source.diagnosis_budget) {
    std::vector<CaseResult> results = {verdict.result};
    verdict.diagnosis = diagnose({checked}, results);
    verdict.diagnosed = true;
  }
  return verdict;
}

}  // namespace raycam::check
