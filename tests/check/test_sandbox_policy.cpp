// The sandbox one can audit (sandbox_policy.h): its bwrap argument list read as a list of mounts, without
// bwrap; the statuses decided from facts (classify_run), never from what a program prints; and, where a
// sandbox starts here, what a hostile program meets: the system-call filter, no /opt, no descriptor of the
// checker's, a bound on files, bwrap's processes not counted against the program's.
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "../scratch_dir.h"
#include "check/run_facts.h"
#include "check/run_group.h"
#include "check/sandbox_policy.h"
#include "check/student_process.h"
#include "check/syscall_filter.h"

namespace fs = std::filesystem;
using namespace raycam::check;

namespace {
// The mounts an argument list makes, in order: (option, source, destination); "--tmpfs" has no source.
struct Mount {
  std::string option, source, destination;
};
std::vector<Mount> mounts_of(const std::vector<std::string>& words) {
  std::vector<Mount> mounts;
  for (std::size_t i = 1; i < words.size() && words[i] != "--"; ++i) {
    const std::string& w = words[i];
    if (w == "--ro-bind" || w == "--bind" || w == "--dev-bind" || w == "--ro-bind-try" || w == "--bind-try" ||
        w == "--symlink") {
      mounts.push_back({w, words[i + 1], words[i + 2]});
      i += 2;
    } else if (w == "--tmpfs" || w == "--dev" || w == "--proc" || w == "--remount-ro") {
      mounts.push_back({w, "", words[i + 1]});
      i += 1;
    } else if (w == "--file") {
      mounts.push_back({w, words[i + 1], words[i + 2]});
      i += 2;
    } else if (w == "--size" || w == "--perms" || w == "--info-fd" || w == "--block-fd" || w == "--seccomp" ||
               w == "--uid" || w == "--gid" || w == "--chdir") {
      i += 1;
    }
  }
  return mounts;
}

bool has(const std::vector<std::string>& words, const std::string& word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

SandboxPolicy example_policy() {
  SandboxPolicy p;
  p.bwrap = "/usr/bin/bwrap";
  p.system = {"/usr", "/etc/ld.so.cache"};
  p.links = {{"usr/bin", "/bin"}};
  p.hidden = {"/srv/class"};
  p.shown = {"/srv/class/alice"};
  p.work = "/tmp/raycam-check-1-abc";
  p.disk_bytes = 1 << 20;
  return p;
}

// `sh -c SCRIPT` in the sandbox, with `limits`.
RunResult in_sandbox(const std::string& script, const std::optional<Sandbox>& sandbox, RunLimits limits = {}) {
  return run_student({"/bin/sh", "-c", script}, "", limits, sandbox);
}
}  // namespace

TEST_CASE("sandbox policy: the argument list shows read-only what the policy names, writes only the run's tmpfs",
          "[check][sandbox][policy]") {
  const SandboxPolicy policy = example_policy();
  const std::vector<std::string> argv = {"/usr/bin/python3", "/srv/class/alice/camera.py"};
  const std::vector<std::string> words = bwrap_arguments(policy, argv);
  REQUIRE(words.front() == policy.bwrap);
  std::set<std::string> tmpfs;
  std::size_t hidden_at = 0, shown_at = 0;
  const std::vector<Mount> mounts = mounts_of(words);
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    const Mount& m = mounts[i];
    INFO(m.option << " " << m.source << " " << m.destination);
    CHECK(m.option != "--bind");  // nothing of the host writable
    CHECK(m.option != "--dev-bind");
    CHECK(m.option != "--bind-try");
    if (m.option == "--ro-bind") {
      CHECK(m.source == m.destination);  // shown where it is: the paths the guard checked
      const bool named = std::count(policy.system.begin(), policy.system.end(), m.source) +
                         std::count(policy.shown.begin(), policy.shown.end(), m.source);
      CHECK(named);
      if (m.source == "/srv/class/alice") shown_at = i;
    }
    if (m.option == "--tmpfs") {
      tmpfs.insert(m.destination);
      if (m.destination == "/srv/class") hidden_at = i;
    }
    if (m.option == "--file") CHECK(m.destination == kShimInSandbox);
  }
  CHECK(tmpfs == std::set<std::string>{"/tmp", "/srv/class", policy.work});
  CHECK(hidden_at < shown_at);  // the student's folder shown again inside the hidden class
  // /tmp and /dev read-only once made; the size belongs to the run's tmpfs.
  CHECK(has(words, "--remount-ro"));
  const auto size = std::find(words.begin(), words.end(), "--size");
  REQUIRE(size + 3 < words.end());
  CHECK(size[1] == std::to_string(policy.disk_bytes));
  CHECK(size[2] == "--tmpfs");
  CHECK(size[3] == policy.work);
  for (const char* option : {"--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent",
                             "--new-session", "--seccomp", "--info-fd", "--block-fd"})
    CHECK(has(words, option));
  // The command: the exec checkpoint with its descriptor, then the program, word for word.
  const auto end = std::find(words.begin(), words.end(), "--");
  REQUIRE(end != words.end());
  const std::vector<std::string> command(end + 1, words.end());
  const std::vector<std::string> expected = {kShimInSandbox, std::to_string(kCheckpointFd), argv[0], argv[1]};
  CHECK(command == expected);
  SandboxPolicy unfiltered = policy;
  unfiltered.filtered = false;
  CHECK_FALSE(has(bwrap_arguments(unfiltered, argv), "--seccomp"));
}

TEST_CASE("sandbox policy: this machine's policy hides /opt and the home, and binds real paths only",
          "[check][sandbox][policy]") {
  const raycam::test::ScratchDir scratch("policy");
  fs::create_directories(scratch.dir / "class" / "alice");
  std::ofstream(scratch.path("class/alice/camera.py")) << "print(1)\n";
  fs::create_directory_symlink(scratch.dir / "class" / "alice", scratch.dir / "link-to-alice");
  const std::string real_alice = fs::canonical(scratch.dir / "class" / "alice").string();
  const std::string through_link = scratch.path("link-to-alice/camera.py");
  const SandboxPolicy policy = sandbox_policy("/usr/bin/bwrap", {scratch.path("class")}, {scratch.path("link-to-alice")},
                                              {"/usr/bin/python3", through_link}, "/tmp/work", 1 << 20);
  CHECK(policy.shown == std::vector<std::string>{real_alice});  // the link and the script's folder: one real folder
  const char* home = std::getenv("HOME");
  for (const Mount& m : mounts_of(bwrap_arguments(policy, {"/usr/bin/true"}))) {
    INFO(m.option << " " << m.source);
    if (m.option != "--ro-bind") continue;
    if (m.source.rfind("/etc/", 0) != 0) CHECK(m.source == fs::weakly_canonical(m.source).string());
    CHECK(m.source.rfind("/opt", 0) != 0);
    CHECK(m.source.rfind("/home", 0) != 0);
    CHECK(m.source != "/");
    if (home && std::string(home) != "/") CHECK(m.source != fs::weakly_canonical(home).string());
  }
  // The command's paths are the real ones too, so that the program finds them where they are shown.
  CHECK(canonical_paths({"/usr/bin/python3", through_link})[1] == real_alice + "/camera.py");
}

TEST_CASE("run facts: whose fault a failure is comes from the checkpoint, never from what the program printed",
          "[check][sandbox][facts][bounds]") {
  RunFacts started;
  started.sandboxed = true;
  started.sandbox_named_child = started.sandbox_setup_done = true;
  started.checkpoint = "S";
  started.wait_status = 1 << 8;  // exit 1
  RunResult r;
  r.err = "bwrap: Can't fork for pid 1: Resource temporarily unavailable\n";  // printed by the program
  classify_run(started, r);
  CHECK(r.end == RunResult::End::exited);
  CHECK(r.exit_code == 1);
  CHECK_FALSE(r.infrastructure_failure);

  // The same exit and message with no checkpoint byte: bwrap never reached the program.
  RunFacts failed = started;
  failed.checkpoint.clear();
  RunResult f;
  classify_run(failed, f);
  CHECK(f.infrastructure_failure);
  CHECK(f.end == RunResult::End::could_not_start);
  CHECK_THAT(f.error, Catch::Contains("after its set-up"));
  failed.sandbox_setup_done = false;
  classify_run(failed, f);
  CHECK_THAT(f.error, Catch::Contains("set-up did not finish"));
  failed.sandbox_named_child = false;
  classify_run(failed, f);
  CHECK_THAT(f.error, Catch::Contains("did not start"));

  // The checkpoint ran but the program's exec failed: the submission's, not the checker's.
  RunFacts no_exec = started;
  const int code = ENOEXEC;
  no_exec.checkpoint = "S" + std::string(reinterpret_cast<const char*>(&code), sizeof code);
  RunResult n;
  classify_run(no_exec, n);
  CHECK(n.end == RunResult::End::could_not_start);
  CHECK_FALSE(n.infrastructure_failure);
  CHECK(n.error == std::strerror(ENOEXEC));

  // The checker's own set-up failing (a keyring, a group, a uid) is the checker's, before anything ran.
  RunFacts setup;
  setup.sandboxed = true;
  setup.setup_failure = "cannot set the run up: Disk quota exceeded";
  RunResult s;
  classify_run(setup, s);
  CHECK(s.infrastructure_failure);

  // A cancel before the program started is nobody's; bounds name themselves once the program ran.
  RunFacts cancelled = failed;
  cancelled.stopped = RunFacts::Stop::cancelled;
  RunResult c;
  classify_run(cancelled, c);
  CHECK_FALSE(c.infrastructure_failure);
  CHECK(c.cancelled);
  RunFacts memory = started;
  memory.wait_status = SIGKILL;
  memory.memory_limit_hit = true;
  RunResult m;
  classify_run(memory, m);
  CHECK(m.limit == kMemoryLimit);
  RunFacts files = started;
  files.stopped = RunFacts::Stop::files;
  RunResult d;
  classify_run(files, d);
  CHECK(d.limit == kDiskLimit);
  CHECK_FALSE(d.infrastructure_failure);
}

TEST_CASE("sandbox: a program printing bwrap's own failures is the program's crash", "[check][sandbox][facts][bounds]") {
  std::string why;
  const std::optional<Sandbox> sandbox = probe_sandbox(why);
  if (!sandbox) return;  // no sandbox here
  for (const char* message : {"bwrap: Can't fork for pid 1: Resource temporarily unavailable",
                              "bwrap: execvp /x: No such file or directory", "bwrap: Creating new namespace failed"}) {
    INFO(message);
    const RunResult run = run_student({"/bin/sh", "-c", "echo \"$0\" >&2; exit 1", message}, "", RunLimits{}, sandbox);
    CHECK(run.end == RunResult::End::exited);
    CHECK(run.exit_code == 1);
    CHECK_FALSE(run.infrastructure_failure);
  }
}

TEST_CASE("sandbox: the system-call filter refuses what reaches past the sandbox", "[check][sandbox][filter][bounds]") {
  std::string why;
  const std::optional<Sandbox> sandbox = probe_sandbox(why);
  if (!sandbox || find_program("python3").empty()) return;
  // Each call made with harmless arguments through libc's syscall(): EPERM from the filter, or ENOSYS for
  // clone3. Unfiltered, keyctl, add_key, io_uring_setup, ptrace and clone3 succeed or fail otherwise here.
  const std::string script = R"(
import ctypes, json, os
libc = ctypes.CDLL(None, use_errno=True)
calls = {"keyctl": (250, 0, -3), "add_key": (248, 0, 0), "request_key": (249, 0, 0),
         "io_uring_setup": (425, 1, 0), "unshare": (272, 0x10000000), "setns": (308, -1, 0),
         "ptrace": (101, 0, 0), "bpf": (321, 0, 0, 0), "perf_event_open": (298, 0, 0, -1, -1, 0),
         "userfaultfd": (323, 0), "mount": (165, 0, 0, 0, 0, 0), "clone_newuser": (56, 0x10000000 | 17, 0),
         "clone3": (435, 0, 0)}
out = {}
for name, args in calls.items():
    ctypes.set_errno(0)
    r = libc.syscall(*[ctypes.c_long(a) for a in args])
    out[name] = ctypes.get_errno() if r == -1 else 0
print(json.dumps(out))
)";
  const RunResult run = run_student({"python3", "-c", script}, "", RunLimits{}, sandbox);
  INFO(run.out << run.err);
  REQUIRE(run.end == RunResult::End::exited);
  REQUIRE(run.exit_code == 0);
  for (const char* name : {"keyctl", "add_key", "request_key", "io_uring_setup", "unshare", "setns", "ptrace", "bpf",
                           "perf_event_open", "userfaultfd", "mount", "clone_newuser"}) {
    INFO(name);
    CHECK_THAT(run.out, Catch::Contains("\"" + std::string(name) + "\": " + std::to_string(EPERM) + ","));
  }
  CHECK_THAT(run.out, Catch::Contains("\"clone3\": " + std::to_string(ENOSYS) + "}"));
  // Ordinary work goes on: threads, a fork, a pipe.
  const RunResult ordinary = run_student(
      {"python3", "-c", "import threading, os, subprocess; t = threading.Thread(target=print); t.start(); t.join(); "
                        "print(subprocess.run(['echo', 'forked'], capture_output=True).stdout.decode().strip())"},
      "", RunLimits{}, sandbox);
  CHECK(ordinary.exit_code == 0);
  CHECK_THAT(ordinary.out, Catch::Contains("forked"));
  CHECK(refused_system_calls().size() >= 30);
}

TEST_CASE("sandbox: no /opt, no descriptor of the checker's, only the run's folder writable", "[check][sandbox][bounds]") {
  std::string why;
  const std::optional<Sandbox> sandbox = probe_sandbox(why);
  if (!sandbox) return;
  const RunResult opt = in_sandbox("ls -d /opt /home /root /srv /var 2>/dev/null; echo done", sandbox);
  CHECK(opt.out == "done\n");
  const RunResult fds = in_sandbox("ls /proc/self/fd", sandbox);  // ls's own: 0 1 2 and the folder it reads
  CHECK(fds.out == "0\n1\n2\n3\n");
  const RunResult writes = in_sandbox("touch ok && echo wrote; touch /tmp/x /usr/x 2>/dev/null || echo refused", sandbox);
  CHECK(writes.out == "wrote\nrefused\n");
}

TEST_CASE("sandbox: the files of a run's folder are bounded, and bwrap's processes are not the program's",
          "[check][sandbox][bounds][disk][processes]") {
  std::string why;
  const std::optional<Sandbox> sandbox = probe_sandbox(why);
  if (!sandbox) return;
  RunLimits limits;
  limits.max_files = 500;
  limits.timeout_seconds = 30;
  const RunResult files = in_sandbox("i=0; while :; do : > f$i; i=$((i+1)); done", sandbox, limits);
  CHECK(files.limit == kDiskLimit);
  CHECK_FALSE(files.infrastructure_failure);
  CHECK(files.seconds < 20);
  // A program may use every process it is allowed: here 3 (the shell and two sleeps at once).
  limits = RunLimits{};
  limits.max_processes = 3;
  const RunResult three = in_sandbox("sleep 0.3 & sleep 0.3 & wait; echo ok", sandbox, limits);
  CHECK(three.out == "ok\n");
  CHECK(three.limit.empty());
  // No process left at all for the program: bwrap stops before it (no checkpoint): the checker's error.
  // Only where the count is the run's own (a group, or root's uid per run): an ordinary user's per-user
  // count moves with whatever else that user runs.
  std::string no_group;
  if (!run_groups_available(no_group) && geteuid() != 0) return;
  limits.max_processes = 0;
  const RunResult none = in_sandbox("echo ran", sandbox, limits);
  CHECK(none.infrastructure_failure);
  CHECK(none.out.empty());
}

TEST_CASE("a killed check's temporary folders are swept by the next check", "[check][cleanup]") {
  // A pid that no longer runs: a child that has exited and been waited for.
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  REQUIRE(dead > 0);
  waitpid(dead, nullptr, 0);
  const raycam::test::ScratchDir scratch("sweep");
  const fs::path stale = scratch.dir / ("raycam-check-" + std::to_string(dead) + "-abcdef");
  const fs::path live = scratch.dir / ("raycam-check-" + std::to_string(getppid()) + "-abcdef");
  const fs::path other = scratch.dir / "raycam-checklist";
  fs::create_directories(stale / "inner");
  fs::permissions(stale / "inner", fs::perms::none);  // whatever modes the run left
  fs::create_directories(live);
  fs::create_directories(other);
  sweep_stale_run_folders(scratch.dir.string());
  CHECK_FALSE(fs::exists(stale));
  CHECK(fs::exists(live));  // its checker still runs
  CHECK(fs::exists(other));
}
