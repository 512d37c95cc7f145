// Running one untrusted student program on one case: no shell, a fresh temporary directory, the case on
// stdin, a timeout, capped output, stderr kept, and (where it works) a bubblewrap sandbox.
//
// The sandbox's policy (what a run sees and may do, and the bwrap command line) is sandbox_policy.h's. Run
// by root, the program runs under an unprivileged uid of its own (never root's rights on what it sees); a
// fresh session keyring of its own, checked before anything of the student's runs. Each run is a control
// group of its own (run_group.h) bounding its memory, processes and CPU time as a whole; where none can be
// made, per-process limits (address space, RLIMIT_NPROC, RLIMIT_CPU). Without the sandbox the same limits
// apply except the isolation, the tmpfs, the filter and the uid.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace raycam::check {

// The command split like a shell word list, without a shell: words separated by blanks, '…' quotes
// literally, "…" quotes with \" \\ \$ \` escapes, \ escapes one character outside quotes. Nothing is
// expanded. Throws std::invalid_argument naming `field` on an unclosed quote or an empty command.
std::vector<std::string> split_command(const std::string& command, const std::string& field);

// Words naming an existing file or directory relative to the current directory become absolute paths:
// the program runs in a fresh directory, where "python3 camera.py" would find nothing.
std::vector<std::string> absolutise_paths(std::vector<std::string> words);

struct RunLimits {
  double timeout_seconds = 10.0;  // wall time
  double cpu_seconds = 0;         // CPU time of all the run's processes together; 0: timeout_seconds
  std::size_t max_stdout_bytes = std::size_t(16) << 20;  // over this the program is stopped: bad output
  std::size_t max_stderr_bytes = std::size_t(16) << 10;  // kept for the report; the rest is read and dropped
  // Memory of the run as a whole (its control group: resident memory and its files in memory); without a
  // group, each process's address space (RLIMIT_AS).
  long long memory_bytes = 1LL << 30;
  long long disk_bytes = 256LL << 20;   // the sandbox's writable folder (a tmpfs of this size)
  long long file_bytes = 64LL << 20;    // largest file it may write (RLIMIT_FSIZE)
  int max_processes = 256;  // processes and threads of the program (its control group; else RLIMIT_NPROC)
  // Files and folders in the sandbox's writable folder (its tmpfs's inodes, polled: an empty file costs the
  // kernel memory but no disk); 0: one per 4 KiB of disk_bytes.
  long long max_files = 0;
  bool use_run_groups = true;  // false: per-process limits only (the fallback, also for tests)
  // Set by the caller when it no longer wants the answer (the window's check: the camera moved on): the run
  // is stopped at its next poll (within 50 ms) and its result says cancelled.
  const std::atomic<bool>* cancel = nullptr;
};

// Which bound ended a run (isolate's meta file's "status"), as the report and the CSV name it.
inline constexpr const char* kMemoryLimit = "memory-limit";
inline constexpr const char* kProcessLimit = "process-limit";
inline constexpr const char* kDiskLimit = "disk-limit";
inline constexpr const char* kTimeLimit = "timeout";
inline constexpr const char* kOutputLimit = "output-limit";

struct Sandbox {
  std::string bwrap;  // absolute path of bwrap
  // Folders hidden behind an empty read-only tmpfs (a class's submissions), and those shown again
  // read-only inside them (this student's own).
  std::vector<std::string> hidden, shown;
};

struct RunResult {
  enum class End { exited, signalled, timed_out, output_too_large, could_not_start };
  // The checker's own failure, not the program's: the sandbox did not reach the program (classify_run) or
  // this process could not fork, make a folder or set the run up.
  bool infrastructure_failure = false;
  End end = End::could_not_start;
  int exit_code = 0;
  int signal = 0;
  std::string out, err;
  double seconds = 0;
  std::string error;  // could_not_start: why
  // What the run used (its control group's count; without one, the rusage of the processes waited for) and
  // the bound that ended it (one of the k…Limit names above), "" if none.
  double cpu_seconds = 0;
  long long peak_memory_bytes = 0;
  std::string limit;
  bool bounded_per_run = false;  // memory and processes counted for the run as a whole (a control group)
  bool cancelled = false;        // RunLimits::cancel stopped it (then ended as timed_out, limit "")
};

// Runs `argv` (argv[0] looked up in PATH if it has no '/') with `input` on stdin. Never throws for what the
// program does; SIGPIPE is ignored in this process from the first call.
RunResult run_student(const std::vector<std::string>& argv, const std::string& input, const RunLimits& limits,
                      const std::optional<Sandbox>& sandbox);

// Kills every run still going (its whole process group) and removes its temporary folder: at exit, and from
// raycam-cli check when SIGINT or SIGTERM interrupts a batch.
void stop_live_runs();
// The same, for a process about to end (raycam-cli check's interrupt): no run starts or ends afterwards, so
// that a worker whose run was just killed cannot finish the check first with its own exit status.
void stop_live_runs_for_good();

// Removes the folders TMPDIR/raycam-check-PID-… of checks that no longer run (killed by SIGKILL: nothing of
// theirs could clean up), this user's only. Called once per process, at its first run.
void sweep_stale_run_folders(const std::string& base);

// Whether bwrap exists and can start a sandbox here (checked once per process by running `true` in it).
// On failure `why` says what went wrong.
std::optional<Sandbox> probe_sandbox(std::string& why);

// The program found in PATH (or as given when it has a '/'); empty if none is executable (with `for_others`,
// by any user: the folders above it crossable and the file readable and runnable by others).
std::string find_program(const std::string& name, bool for_others = false);

}  // namespace raycam::check
