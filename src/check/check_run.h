// Grading one student: run the program on every case (or read answer files), grade, diagnose. And grading a
// class: every (student, case) run on a pool of threads, each student's report as soon as it is complete.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check/battery.h"
#include "check/case_image.h"
#include "check/grading.h"
#include "check/student_process.h"

namespace raycam::check {

struct StudentReport {
  std::vector<CaseResult> results;     // one per case, in case order
  std::vector<Explanation> diagnosis;  // sorted (grading.h)
  int passed() const;
  // Count of results with `status`.
  int count(CaseStatus status) const;
};

// The references of a battery (the right images with their ambiguous pixels), computed once.
std::vector<CaseImage> reference_images(const std::vector<CheckCase>& cases);

// What one run of the program says about case `number` (1-based), with what it used and the bound that
// ended it.
CaseResult result_of_run(int number, const CheckCase& c, const CaseImage& reference, const RunResult& run);

// The file names of case i (1-based) in --write-cases and --answers folders: case_01.json, answer_01.json.
std::string case_file_name(int number, int count);
std::string answer_file_name(int number, int count);

// An answer file read as if a program had printed it (could_not_start, with a message naming the file,
// when it cannot be read).
RunResult read_answer_file(const std::string& path);
// Case `number` graded from the answer file at `path`: one that is missing or unreadable is a bad output (no
// answer given), not a crash of a program that never ran.
CaseResult grade_answer_file(int number, const CheckCase& c, const CaseImage& reference, const std::string& path);

// Grades DIR/answer_NN.json for every case (a missing or unreadable file is a bad output).
StudentReport check_answer_files(const std::string& dir, const std::vector<CheckCase>& cases,
                                 const std::vector<CaseImage>& references);

struct Submission {
  std::string name;               // the student (a folder name in --batch)
  std::vector<std::string> argv;  // the command, already split
  std::optional<Sandbox> sandbox;
  // Why the checker cannot run this submission at all (a folder the sandbox's user cannot read): every case
  // is then the checker's error, never the student's crash. "" when it can.
  std::string setup_error;
  // Why this submission is refused (submission_refusal: a link out of its folder, a folder for a program):
  // every case is then "could not start" with this reason, in its own row; the class goes on. "" when none.
  std::string refusal;
};

// The report's sentence for a run ended by its memory, process or disk bound (`limit` as RunResult::limit),
// nullptr for another limit or none.
const char* limit_detail(const std::string& limit);

// Runs every submission on every case, `threads` runs at once (a hanging program holds one thread for its
// timeout; the others go on). `on_run` is called after each run (progress), `on_student` once per submission
// when its report is complete, both under one lock (never concurrently). Reports come back in input order.
std::vector<StudentReport> check_submissions(
    const std::vector<Submission>& submissions, const std::vector<CheckCase>& cases,
    const std::vector<CaseImage>& references, const RunLimits& limits, int threads,
    const std::function<void(std::size_t done, std::size_t total)>& on_run = {},
    const std::function<void(std::size_t submission, const StudentReport&)>& on_student = {});

}  // namespace raycam::check
