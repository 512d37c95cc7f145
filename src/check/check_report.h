// What `check` writes: the table, score and diagnosis on the terminal (French or English), the --report JSON,
// a --batch CSV row, and the --diff-dir images.
#pragma once

#include <functional>

#include <string>
#include <vector>

#include "check/check_run.h"

namespace raycam::check {

struct ReportHeader {
  std::string mode;  // "2d", "3d", "both"
  unsigned long long seed = kDefaultSeed;
  bool two_res = false;  // --two-res: the battery asks the 3D case whose res is [res_c, res_l]
  bool sandboxed = false;
  std::string sandbox_note;  // why not, or what it isolates
  std::string limits_note;   // "memory not bounded per run: …" where no control group can be made
  Language language = Language::en;
};

// The terminal text: one line per case, the score, the diagnosis, then the stderr of failing runs.
std::string text_report(const ReportHeader& header, const std::vector<CheckCase>& cases, const StudentReport& report);

// A case's "worst pixel or reason" in the table: the worst pixel of a failing case, else the run's detail.
std::string case_reason(Language lang, const CaseResult& r);

// The line for a program whose only failing case is the two-resolution one (--two-res), in `lang`: the
// program most likely reads res as one number, which the handout allows. "" for any other report.
std::string two_res_note(Language lang, const std::vector<CheckCase>& cases, const StudentReport& report);

// --report: {"cases": N, "passed": P, "diagnosis": [{"mistake": ID, "explains": K, "text": ...}...],
//            "results": [{"case": i, "status": ..., "wrong_pixels": w, ...}...], plus seed, mode, protocol,
//            two_res, sandbox, and two_res_note when there is one}.
std::string json_report(const ReportHeader& header, const std::vector<CheckCase>& cases, const StudentReport& report);

// --batch --csv: the header line, and one row per student (the runs ended by each bound, the CPU seconds of
// all runs and the largest peak memory in MiB at the end of the row).
std::string csv_header();
std::string csv_row(const std::string& student, const StudentReport& report, bool sandboxed);

// --diff-dir: DIR/case_NN.png for every failing case with an answer: reference | student | difference (wrong
// pixels red, ambiguous ones yellow, agreeing ones dimmed); 2D bars in image order, drawn tall. Returns the
// paths written. Throws std::runtime_error naming a path that cannot be written.
// Writes `path` through `write_to(temporary)`: a new file beside it (mkstemp, so never a link a program left),
// then renamed over it: a link at `path` is replaced, not followed, and a failed write leaves `path` as it was.
void write_replacing(const std::string& path, const std::function<void(const std::string& temporary)>& write_to);
// write_replacing with `text` as the file's bytes.
void write_text_file(const std::string& path, const std::string& text);

std::vector<std::string> write_difference_images(const std::string& dir, const std::vector<CheckCase>& cases,
                                                 const std::vector<CaseImage>& references,
                                                 const StudentReport& report);

}  // namespace raycam::check
