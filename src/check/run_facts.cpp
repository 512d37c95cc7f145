#include "check/run_facts.h"

#include <signal.h>
#include <sys/wait.h>

#include <cstring>

namespace raycam::check {

void classify_run(const RunFacts& f, RunResult& r) {
  r.infrastructure_failure = false;
  r.limit.clear();
  r.error.clear();
  if (!f.setup_failure.empty()) {
    r.end = RunResult::End::could_not_start;
    r.infrastructure_failure = true;
    r.error = f.setup_failure;
    return;
  }
  using Stop = RunFacts::Stop;
  switch (f.stopped) {
    case Stop::timeout: case Stop::cpu_time: case Stop::cancelled:
      r.end = RunResult::End::timed_out;
      r.limit = f.stopped == Stop::cancelled ? "" : kTimeLimit;
      r.cancelled = f.stopped == Stop::cancelled;
      if (f.stopped == Stop::cpu_time) r.error = "CPU time";
      break;
    case Stop::output: r.end = RunResult::End::output_too_large; r.limit = kOutputLimit; break;
    case Stop::files: r.end = RunResult::End::signalled; r.signal = SIGKILL; r.limit = kDiskLimit; break;
    case Stop::none:
      if (WIFEXITED(f.wait_status)) {
        r.end = RunResult::End::exited;
        r.exit_code = WEXITSTATUS(f.wait_status);
      } else {
        r.end = RunResult::End::signalled;
        r.signal = WIFSIGNALED(f.wait_status) ? WTERMSIG(f.wait_status) : 0;
      }
  }
  // Whose fault: sandboxed, the program ran only if the exec checkpoint wrote its byte; before that every
  // failure is the sandbox's, after it every failure is the program's, whatever either printed.
  const bool program_started = f.sandboxed ? !f.checkpoint.empty() : f.exec_errno == 0;
  if (f.sandboxed && !program_started) {
    if (f.stopped == Stop::cancelled) return;  // nobody's: the caller gave up
    r.infrastructure_failure = true;
    r.end = RunResult::End::could_not_start;
    r.error = f.exec_errno ? "cannot start bwrap: " + std::string(std::strerror(f.exec_errno))
              : !f.sandbox_named_child ? "the sandbox did not start (bwrap named no child)"
              : !f.sandbox_setup_done  ? "the sandbox's set-up did not finish"
                                       : "the sandbox failed after its set-up, before the program started";
    r.limit.clear();
    return;
  }
  int exec_errno = f.exec_errno;
  if (f.sandboxed && f.checkpoint.size() >= 1 + sizeof(int)) std::memcpy(&exec_errno, f.checkpoint.data() + 1, sizeof(int));
  if (exec_errno != 0) {  // the program itself cannot be exec'd: the submission's (no run bit, CRLF, …)
    r.end = RunResult::End::could_not_start;
    r.error = std::strerror(exec_errno);
    r.limit.clear();
    return;
  }
  if (r.limit.empty() && f.memory_limit_hit) r.limit = kMemoryLimit;
  else if (r.limit.empty() && f.process_limit_hit) r.limit = kProcessLimit;
  else if (r.limit.empty() && f.cpu_over_limit) r.limit = kTimeLimit;
  if (r.limit.empty() && f.disk_full) r.limit = kDiskLimit;
}

}  // namespace raycam::check
