#include "check/check_run.h"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <signal.h>
#include <sstream>
#include <thread>

#include "raycam/scene_file.h"

namespace raycam::check {

int StudentReport::passed() const { return count(CaseStatus::pass); }

int StudentReport::count(CaseStatus status) const {
  int n = 0;
  for (const CaseResult& r : results) n += r.status == status;
  return n;
}

std::vector<CaseImage> reference_images(const std::vector<CheckCase>& cases) {
  std::vector<CaseImage> references;
  for (const CheckCase& c : cases) references.push_back(render_case(c.file));
  return references;
}

namespace {
std::string numbered(const char* stem, int number, int count) {
  const int width = std::max(2, int(std::to_string(count).size()));
  char name[64];
  std::snprintf(name, sizeof name, "%s_%0*d.json", stem, width, number);
  return name;
}

std::string signal_text(int signal) {
#ifdef __GLIBC__
  const char* name = sigabbrev_np(signal);
#else
  const char* name = nullptr;  // the web page's libc has no signal names (and runs no programs)
#endif
  return "killed by signal " + std::to_string(signal) + (name ? std::string(" (SIG") + name + ")" : "");
}
}  // namespace

const char* limit_detail(const std::string& limit) {
  if (limit == kMemoryLimit) return "memory-limit: the run reached its memory bound (--memory), all its processes together";
  if (limit == kProcessLimit) return "process-limit: the run reached its bound on processes and threads (--processes)";
  if (limit == kDiskLimit) return "disk-limit: the run filled its writable folder (--disk)";
  return nullptr;
}

std::string case_file_name(int number, int count) { return numbered("case", number, count); }
std::string answer_file_name(int number, int count) { return numbered("answer", number, count); }

CaseResult result_of_run(int number, const CheckCase& c, const CaseImage& reference, const RunResult& run) {
  CaseResult result;
  switch (run.end) {
    case RunResult::End::exited:
      if (run.exit_code == 0) {
        result = grade_answer(reference, parse_answer(run.out, reference.dimension, reference.rows,
                                                      reference.columns, object_count(c.file)));
        break;
      }
      result.status = CaseStatus::crash;
      result.detail = "exit status " + std::to_string(run.exit_code);
      // A shell or the sandbox's init reports a signal as 128 + its number.
      if (run.exit_code > 128 && run.exit_code <= 128 + 64)
        result.detail += " (" + signal_text(run.exit_code - 128) + "?)";
      break;
    case RunResult::End::signalled:
      result.status = CaseStatus::crash;
      result.detail = signal_text(run.signal);
      break;
    case RunResult::End::timed_out:
      result.status = CaseStatus::timeout;
      result.detail = run.error == "CPU time" ? "CPU time over the timeout (all its processes together)"
                                             : "no answer within the timeout";
      break;
    case RunResult::End::output_too_large:
      result.status = CaseStatus::bad_output;
      result.detail = "more than " + std::to_string(run.out.size() >> 20) + " MiB on stdout: stopped";
      break;
    case RunResult::End::could_not_start:
      result.status = CaseStatus::crash;
      result.detail = run.error;
      break;
  }
  if (result.status != CaseStatus::pass && result.status != CaseStatus::fail && result.pixels == 0) {
    result.pixels = static_cast<long long>(reference.pixels());
    result.wrong_pixels = result.pixels;
  }
  if (const char* bound = limit_detail(run.limit); bound && result.status != CaseStatus::pass) result.detail = bound;
  result.limit = run.limit;
  result.cpu_seconds = run.cpu_seconds;
  result.peak_memory_bytes = run.peak_memory_bytes;
  result.number = number;
  result.dimension = c.file.dimension;
  result.stderr_text = run.err;
  result.seconds = run.seconds;
  return result;
}

RunResult read_answer_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  RunResult run;
  if (!in) {
    run.end = RunResult::End::could_not_start;
    run.error = path + ": cannot open the answer file";
    return run;
  }
  std::ostringstream text;
  text << in.rdbuf();
  run.end = RunResult::End::exited;
  run.out = text.str();
  return run;
}

CaseResult grade_answer_file(int number, const CheckCase& c, const CaseImage& reference, const std::string& path) {
  const RunResult run = read_answer_file(path);
  CaseResult result = result_of_run(number, c, reference, run);
  if (run.end == RunResult::End::could_not_start) result.status = CaseStatus::bad_output;
  return result;
}

StudentReport check_answer_files(const std::string& dir, const std::vector<CheckCase>& cases,
                                 const std::vector<CaseImage>& references) {
  StudentReport report;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const int number = int(i) + 1;
    const std::string path = dir + "/" + answer_file_name(number, int(cases.size()));
    report.results.push_back(grade_answer_file(number, cases[i], references[i], path));
  }
  report.diagnosis = diagnose(cases, report.results);
  return report;
}

std::vector<StudentReport> check_submissions(
    const std::vector<Submission>& submissions, const std::vector<CheckCase>& cases,
    const std::vector<CaseImage>& references, const RunLimits& limits, int threads,
    const std::function<void(std::size_t, std::size_t)>& on_run,
    const std::function<void(std::size_t, const StudentReport&)>& on_student) {
  std::vector<StudentReport> reports(submissions.size());
  for (StudentReport& report : reports) report.results.resize(cases.size());
  std::vector<std::size_t> remaining(submissions.size(), cases.size());
  std::vector<std::string> inputs;
  for (const CheckCase& c : cases) inputs.push_back(scene_to_json(c.file));
  const std::size_t total = submissions.size() * cases.size();
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex mutex;
  // Student-major order: the first students finish first and their rows appear while the others run.
  auto work = [&] {
    for (std::size_t item; (item = next++) < total;) {
      const std::size_t s = item / cases.size(), i = item % cases.size();
      RunResult run;
      if (!submissions[s].setup_error.empty()) {  // nothing to run: the checker's error, said per case
        run.error = submissions[s].setup_error;
        run.infrastructure_failure = true;
      } else if (!submissions[s].refusal.empty()) {  // nothing to run: the submission's own, said per case
        run.end = RunResult::End::could_not_start;
        run.error = submissions[s].refusal;
      } else {
        run = run_student(submissions[s].argv, inputs[i], limits, submissions[s].sandbox);
        if (run.infrastructure_failure)  // once more (a process table full for a moment), then the checker's error
          run = run_student(submissions[s].argv, inputs[i], limits, submissions[s].sandbox);
      }
      CaseResult result = result_of_run(int(i) + 1, cases[i], references[i], run);
      if (run.infrastructure_failure) {
        result.status = CaseStatus::checker_error;
        result.detail = "the checker could not run the program: " +
                        (run.error.empty() ? run.err.substr(0, 200) : run.error);
      }
      bool complete = false;
      {
        std::lock_guard<std::mutex> lock(mutex);
        reports[s].results[i] = std::move(result);
        ++done;
        if (on_run) on_run(done, total);
        complete = --remaining[s] == 0;
      }
      if (!complete) continue;
      reports[s].diagnosis = diagnose(cases, reports[s].results);  // no other thread touches reports[s] now
      std::lock_guard<std::mutex> lock(mutex);
      if (on_student) on_student(s, reports[s]);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, threads) && std::size_t(t) < total; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  return reports;
}

}  // namespace raycam::check
