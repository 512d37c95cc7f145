// Whose fault a run's failure is, and which bound ended it, decided from what the checker itself saw (the
// exec checkpoint's byte, bwrap's info and block pipes, the group's counters, its own stops): never from what
// the student's program printed. One pure function, so that every status decision can be read and tested in
// one place (tests/check/test_sandbox_policy.cpp) without running anything.
#pragma once

#include <string>

#include "check/student_process.h"

namespace raycam::check {

// What the checker itself saw of one run: facts, never what the program printed. classify_run turns them
// into the result's end, its bound and whose fault a failure is.
struct RunFacts {
  bool sandboxed = false;
  // The child failed before it could exec (joining the run's group, dropping to the run's uid, a keyring of
  // its own): the checker's error, with why.
  std::string setup_failure;
  int exec_errno = 0;  // the exec of the program (unsandboxed) or of bwrap (sandboxed) failed with this
  // Sandboxed: bwrap named its child on its info fd (the namespaces exist), read the byte on its block fd
  // (its mounts are done), and what the exec checkpoint wrote ("": never reached; "S": the program was
  // exec'd; "S" then an errno: its exec failed).
  bool sandbox_named_child = false, sandbox_setup_done = false;
  std::string checkpoint;
  enum class Stop { none, timeout, cpu_time, output, cancelled, files };
  Stop stopped = Stop::none;  // the checker stopped the run, and why
  int wait_status = 0;        // as waitpid gave it (when not stopped)
  bool memory_limit_hit = false, process_limit_hit = false, disk_full = false;
  bool cpu_over_limit = false;  // per-process fallback: the kernel's CPU limit killed it (SIGXCPU/SIGKILL past it)
};

// The end, the bound and the fault of a run from its facts (RunResult's end, exit_code, signal, limit,
// infrastructure_failure and, for could_not_start, error).
void classify_run(const RunFacts& facts, RunResult& result);

}  // namespace raycam::check
