// One sandbox policy, readable in one place: what a student's program sees, what it may write, which bounds
// and namespaces hold it, and the exact bwrap argument list that says so. `bwrap_arguments` is a pure
// function of the policy (tests read its output without bwrap); `sandbox_policy` reads the machine once
// (which root folders are links into /usr, the real paths of the student's folders) to fill a policy in.
//
// What a run sees, read-only: /usr and the root's links into it, the dynamic loader's few /etc files, and
// the real (canonical) paths of its own folder and of the folders its command names. Nothing else of the
// machine: not /opt, /home, /root, /srv, /var, /etc's other files, the instructor's outputs, other
// submissions (a class's folder is hidden behind an empty tmpfs even where a shown folder holds it).
// Writable: one tmpfs of `disk_bytes`, the run's own folder; /tmp and /dev read-only. New user, PID, IPC,
// UTS, network (no loopback) and cgroup namespaces; no further user namespaces; a system-call filter
// (syscall_filter.h); its own session; it dies with the checker. The program is started through the exec
// checkpoint (raycam-exec, copied into the sandbox), which writes one byte on a pipe just before it execs
// the program: the fact that tells the sandbox's failures from the program's.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace raycam::check {

// File descriptors the run's child hands to bwrap (numbers inside the child, fixed so that the policy is
// a pure function of its fields).
inline constexpr int kInfoFd = 4;        // bwrap writes {"child-pid": N} here once the namespaces exist
inline constexpr int kBlockFd = 5;       // bwrap reads one byte here when its set-up is done
inline constexpr int kCheckpointFd = 6;  // raycam-exec writes 'S' here just before exec (then errno if exec failed)
inline constexpr int kFilterFd = 7;      // the system-call filter, compiled (BPF)
inline constexpr int kShimFd = 8;        // raycam-exec's bytes, copied into the sandbox
// Where the exec checkpoint sits inside the sandbox (a file of the sandbox's own root, not a host path).
inline constexpr const char* kShimInSandbox = "/.raycam-exec";

struct SandboxPolicy {
  std::string bwrap;                                      // absolute path of bwrap
  std::vector<std::pair<std::string, std::string>> links;  // (target, link): the root's links into /usr
  std::vector<std::string> system;  // folders and files of the system shown read-only (those that exist)
  std::vector<std::string> hidden;  // folders behind an empty read-only tmpfs (a class's submissions)
  std::vector<std::string> shown;   // the student's folders, canonical, shown read-only (after `hidden`)
  std::string work;                 // the run's folder: the only writable place, a tmpfs
  long long disk_bytes = 0;         // the tmpfs's size
  bool filtered = true;             // the system-call filter on kFilterFd
};

// The bwrap command line that runs `argv` (absolute program path first) under `policy`.
std::vector<std::string> bwrap_arguments(const SandboxPolicy& policy, const std::vector<std::string>& argv);

// The policy for one run: the system part read from this machine; `hidden` and `shown` (the batch's folder,
// the student's) and the folders `argv` names made canonical (a link is shown as what it points to, and
// the guard that refuses exposed folders checks the same real paths bwrap binds).
SandboxPolicy sandbox_policy(const std::string& bwrap, const std::vector<std::string>& hidden,
                             const std::vector<std::string>& shown, const std::vector<std::string>& argv,
                             const std::string& work, long long disk_bytes);

// `argv` with every absolute path that exists replaced by its canonical path (a link resolved), so that the
// program finds inside the sandbox the files it names: only real paths are shown there.
std::vector<std::string> canonical_paths(std::vector<std::string> argv);

}  // namespace raycam::check
