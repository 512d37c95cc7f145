// One run bounded as a whole, like a contest grader's control group: its memory (resident memory and the
// files it keeps in memory, every process together), its processes and threads, and its CPU time counted over
// all of them; what it used and which bound it hit read back at the end. A kernel control group per run:
// cgroup v2 where this process may make groups (root, or a delegated group it is the only process of, such as
// systemd-run --user --scope -p Delegate=yes gives), else cgroup v1's memory, pids and cpuacct controllers
// (writable by root, or delegated by chown).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace raycam::check {

struct GroupLimits {
  long long memory_bytes = 1LL << 30;
  int max_processes = 256;
};

// What a run used, as its group counted it.
struct GroupUsage {
  double cpu_seconds = 0;
  long long peak_memory_bytes = 0;  // 0 where the kernel does not keep the peak
  bool memory_limit_hit = false;    // the kernel killed a process of the run for its memory bound
  bool process_limit_hit = false;   // a fork or thread was refused at the process bound
  long long peak_processes = -1;    // most processes at once (-1 where the kernel does not keep it)
};

class RunGroup {
 public:
  // A new group with `limits`, or nullptr with `why` saying what this machine lacks.
  static std::unique_ptr<RunGroup> create(const GroupLimits& limits, std::string& why);
  ~RunGroup();  // kills what is left in it and removes it
  RunGroup(const RunGroup&) = delete;
  RunGroup& operator=(const RunGroup&) = delete;

  // Open cgroup.procs files (close-on-exec): a child writes "0" to each to join the group before exec.
  const std::vector<int>& join_fds() const { return join_fds_; }
  double cpu_seconds() const;
  GroupUsage usage() const;
  // Kills every process in the group (its own processes only: they all descend from the run).
  void kill_all() const;
  const std::vector<std::string>& folders() const { return folders_; }

 private:
  RunGroup() = default;
  bool v2_ = false;
  std::vector<std::string> folders_;  // v2: one; v1: memory, pids, cpuacct
  std::vector<int> join_fds_;
};

// Whether run groups can be made here (tried once per process); `why` says in one line what is missing when
// not (which group, which processes or controllers) and what to type.
bool run_groups_available(std::string& why);

// Kills what is left in a group's folders and removes them (also from an interrupted check's signal thread).
void remove_run_group(const std::vector<std::string>& folders);

// Writes "0" to each fd (async-signal-safe: for a child between fork and exec). False if one write failed.
bool join_run_group(const std::vector<int>& fds);

}  // namespace raycam::check
