// Section index: splitting a command · finding programs · the child (after fork: async-signal-safe calls
// only) · the parent's poll loop · the sandbox.
#include "check/student_process.h"

#include "check/process_calls.h"

#include <fcntl.h>
#if __has_include(<linux/keyctl.h>)
#include <linux/keyctl.h>
#endif
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <grp.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "check/folder_removal.h"
#include "check/run_facts.h"
#include "check/run_group.h"
#include "check/sandbox_policy.h"
#include "check/shown_folders.h"
#include "check/syscall_filter.h"

namespace raycam::check {

namespace fs = std::filesystem;

// ---- splitting a command ---------------------------------------------------------------------------------
std::vector<std::string> split_command(const std::string& command, const std::string& field) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  for (std::size_t i = 0; i < command.size(); ++i) {
    const char c = command[i];
    if (c == ' ' || c == '\t' || c == '\n') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else if (c == '\'') {
      const std::size_t end = command.find('\'', i + 1);
      if (end == std::string::npos) throw std::invalid_argument(field + ": unclosed ' in \"" + command + "\"");
      word += command.substr(i + 1, end - i - 1);
      in_word = true;
      i = end;
    } else if (c == '"') {
      in_word = true;
      for (++i;; ++i) {
        if (i >= command.size()) throw std::invalid_argument(field + ": unclosed \" in \"" + command + "\"");
        if (command[i] == '"') break;
        if (command[i] == '\\' && i + 1 < command.size() && std::strchr("\"\\$`", command[i + 1])) ++i;
        word += command[i];
      }
    } else if (c == '\\' && i + 1 < command.size()) {
      word += command[++i];
      in_word = true;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  if (words.empty()) throw std::invalid_argument(field + ": expected a command, got an empty string");
  return words;
}

std::vector<std::string> absolutise_paths(std::vector<std::string> words) {
  for (std::string& word : words) {
    if (word.empty() || word[0] == '/' || word[0] == '-') continue;
    std::error_code error;
    if (fs::exists(word, error)) word = fs::absolute(word, error).lexically_normal().string();
  }
  return words;
}

// ---- finding programs ------------------------------------------------------------------------------------
// Whether any user may run `path`: every folder above it can be crossed by others, and the file read and
// run by them (a sandboxed run under root has no more rights than that).
bool others_can_run(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0 || (info.st_mode & (S_IXOTH | S_IROTH)) != (S_IXOTH | S_IROTH)) return false;
  for (fs::path dir = fs::path(path).parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
    if (stat(dir.c_str(), &info) != 0 || !(info.st_mode & S_IXOTH)) return false;
  return true;
}

std::string find_program(const std::string& name, bool for_others) {
  if (name.empty()) return {};
  if (name.find('/') != std::string::npos)
    return access(name.c_str(), X_OK) == 0 && (!for_others || others_can_run(name)) ? name : std::string();
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = dirs.substr(start, end - start);
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    struct stat info;
    if (stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) && access(candidate.c_str(), X_OK) == 0 &&
        (!for_others || others_can_run(candidate)))
      return candidate;
    start = end + 1;
  }
  return {};
}

namespace {
using Clock = std::chrono::steady_clock;

struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    read = fds[0];
    write = fds[1];
  }
  ~Pipe() {
    close_read();
    close_write();
  }
  void close_read() {
    if (read >= 0) ::close(read);
    read = -1;
  }
  void close_write() {
    if (write >= 0) ::close(write);
    write = -1;
  }
};

// A NULL-terminated char* array over strings that outlive it (built before fork: no allocation after).
std::vector<char*> c_strings(std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  for (std::string& s : strings) pointers.push_back(s.data());
  pointers.push_back(nullptr);
  return pointers;
}

std::vector<std::string> child_environment(const std::string& work) {
  const char* path = std::getenv("PATH");
  return {"PATH=" + std::string(path ? path : "/usr/local/bin:/usr/bin:/bin"), "HOME=" + work, "TMPDIR=" + work,
          "LANG=C.UTF-8", "LC_ALL=C.UTF-8", "PYTHONDONTWRITEBYTECODE=1"};
}

// raycam-exec (exec_checkpoint.cpp): beside the running program, as every executable of a build; else
// where this build put it.
std::string exec_checkpoint_path() {
  std::error_code error;
  const fs::path beside = fs::read_symlink("/proc/self/exe", error).parent_path() / "raycam-exec";
  if (!error && access(beside.c_str(), X_OK) == 0) return beside.string();
#ifdef RAYCAM_EXEC_CHECKPOINT
  if (access(RAYCAM_EXEC_CHECKPOINT, X_OK) == 0) return RAYCAM_EXEC_CHECKPOINT;
#endif
  return {};
}

// Run as root, a sandboxed program would keep root's rights on every file bwrap shows it (a user namespace
// maps its "nobody" back to root). So the child drops to an unprivileged uid of its own before starting
// bwrap: one per run, from a range no account uses, so that the process cap below counts this run only.
constexpr uid_t kFirstRunUid = 2'000'000'000u;  // below 2^31: the kernel maps no uid above into a user namespace
uid_t next_run_uid() {
  static std::atomic<unsigned> counter{0};
  return kFirstRunUid + uid_t(getpid() % 100000) * 1000u + (counter++ % 1000u);
}

// Processes (threads included) of `uid` now: the cap is set this many above, for a user who is not root.
int processes_of(uid_t uid) {
  int count = 0;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator("/proc", error)) {
    struct stat info {};
    if (std::isdigit(static_cast<unsigned char>(entry.path().filename().string()[0])) &&
        stat(entry.path().c_str(), &info) == 0 && info.st_uid == uid)
      ++count;
  }
  return count;
}

}  // namespace
void stop_live_runs();
namespace {

// Runs still going when the process exits (a detached worker of the app's panel, a test that ends while a
// program hangs): their programs are killed and their folders removed at exit, not left behind.
struct LiveRun {
  pid_t group = 0;                          // process group (0 before the fork)
  std::vector<std::string> control_groups;  // its run group's folders (run_group.h)
};
struct LiveRuns {
  std::mutex mutex;
  std::map<std::string, LiveRun> folders;  // temporary folder -> the run
};
LiveRuns& live_runs() {
  static LiveRuns* runs = [] {
    auto* created = new LiveRuns;  // never destroyed: the exit handler below still needs it
    std::atexit(stop_live_runs);
    return created;
  }();
  return *runs;
}
}  // namespace

namespace {
void stop_runs(bool for_good) {
  LiveRuns& r = live_runs();
  std::unique_lock<std::mutex> lock(r.mutex);
  if (for_good) lock.release();  // kept locked until the process ends
  for (const auto& [folder, run] : r.folders) {
    if (run.group > 0) kill(-run.group, SIGKILL);
    remove_run_group(run.control_groups);
    remove_folder_whatever_modes(folder);
  }
  r.folders.clear();
}
}  // namespace

void stop_live_runs() { stop_runs(false); }
void stop_live_runs_for_good() { stop_runs(true); }

namespace {
// A sandboxed run's processes that are not the program's: bwrap's launcher outside and its pid 1 inside.
constexpr int kSandboxProcesses = 2;
}  // namespace

void sweep_stale_run_folders(const std::string& base) {
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(base, error)) {
    const std::string name = entry.path().filename().string();
    const std::string prefix = "raycam-check-";
    if (name.rfind(prefix, 0) != 0) continue;
    const std::size_t dash = name.find('-', prefix.size());
    if (dash == std::string::npos) continue;
    const long pid = std::atol(name.substr(prefix.size(), dash - prefix.size()).c_str());
    if (pid <= 0 || pid == getpid() || kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;
    struct stat info {};
    if (lstat(entry.path().c_str(), &info) == 0 && S_ISDIR(info.st_mode) &&
        (geteuid() == 0 || info.st_uid == geteuid()))  // root's runs chown theirs to the run's uid
      remove_folder_whatever_modes(entry.path().string());
  }
}

namespace {

void track(const std::string& folder, pid_t group, const RunGroup* control = nullptr) {
  LiveRuns& r = live_runs();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.folders[folder] = {group, control ? control->folders() : std::vector<std::string>()};
}
void untrack(const std::string& folder) {
  LiveRuns& r = live_runs();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.folders.erase(folder);
}

void stop(pid_t pid) {
  kill(-pid, SIGKILL);  // the process group: whatever it started (bwrap's namespace dies with its first child)
  kill(pid, SIGKILL);
}

// A run's temporary folder, TMPDIR/raycam-check-PID-XXXXXX (tracked; "" with result's error when it cannot be
// made). The checker's pid in the name lets a later check sweep the folders of one that was killed.
std::string make_run_folder(RunResult& result) {
  const char* tmp = std::getenv("TMPDIR");
  const std::string base = tmp && *tmp ? tmp : "/tmp";
  static std::once_flag swept;
  std::call_once(swept, [&] { sweep_stale_run_folders(base); });
  std::string pattern = base + "/raycam-check-" + std::to_string(getpid()) + "-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    result.error = "cannot create a temporary directory: " + std::string(std::strerror(errno));
    result.infrastructure_failure = true;
    return {};
  }
  track(pattern, 0);
  return pattern;
}

// ---- the child (after fork: async-signal-safe calls only) -------------------------------------------------
// What the child needs besides its command, prepared before the fork. Descriptors are the parent's; the
// child moves them to 0–2, 3 (its report) and, sandboxed, to sandbox_policy.h's numbers.
struct ChildSetup {
  const char* work = nullptr;
  int in = -1, out = -1, err = -1, report = -1;
  int info = -1, block = -1, checkpoint = -1, filter = -1, shim = -1;  // sandboxed only
  const RunLimits* limits = nullptr;
  uid_t run_uid = 0;
  rlim_t max_processes = 0;                      // RLIMIT_NPROC, 0: none (a run group bounds the processes)
  const std::vector<int>* join_group = nullptr;  // the run group's cgroup.procs, or nullptr
};

// The child's report to the parent (its fd 3, closed on exec): which step failed, and errno.
enum ChildStep : int { kSetupStep = 1, kExecStep = 2 };
[[noreturn]] void fail_in_child(int report, int step) {
  const int message[2] = {step, errno};
  ssize_t ignored = write(report, message, sizeof message);
  (void)ignored;
  _exit(127);
}

[[noreturn]] void exec_child(const char* program, char* const* argv, char* const* envp, const ChildSetup& c) {
  setpgid(0, 0);
  // Into the run's group first, while still allowed to (its files belong to the checker's user).
  if (c.join_group && !join_run_group(*c.join_group)) fail_in_child(c.report, kSetupStep);
  sigset_t none;  // raycam-cli check blocks SIGINT and SIGTERM for its signal thread: not the student's
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (c.run_uid != 0 && (setgroups(0, nullptr) != 0 || setgid(gid_t(c.run_uid)) != 0 || setuid(c.run_uid) != 0))
    fail_in_child(c.report, kSetupStep);
  // Keyrings are not namespaced: a fresh, empty session keyring, so that no key of the checker's session or
  // of an earlier run is within reach. Checked: if it cannot be made (a key quota filled), the run does not
  // start rather than share the checker's (the filter then refuses keyctl to the program).
#ifdef KEYCTL_JOIN_SESSION_KEYRING
  if (syscall(SYS_keyctl, KEYCTL_JOIN_SESSION_KEYRING, nullptr) < 0) fail_in_child(c.report, kSetupStep);
#endif
  if (c.max_processes > 0) {
    const rlimit processes{c.max_processes, c.max_processes};
    setrlimit(RLIMIT_NPROC, &processes);
  }
  signal(SIGPIPE, SIG_DFL);  // ignored in raycam-cli; an ignored signal would stay ignored across exec
  const RunLimits& limits = *c.limits;
  if (!c.join_group) {  // no group bounds the run's memory as a whole: each process's address space
    const rlimit memory{rlim_t(limits.memory_bytes), rlim_t(limits.memory_bytes)};
    setrlimit(RLIMIT_AS, &memory);
  }
  const rlim_t cpu = rlim_t(limits.cpu_seconds > 0 ? limits.cpu_seconds : limits.timeout_seconds) + 1;
  const rlimit cpu_time{cpu, cpu};  // a backstop per process; the run's own count is polled by the parent
  const rlimit file{rlim_t(limits.file_bytes), rlim_t(limits.file_bytes)};
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CPU, &cpu_time);
  setrlimit(RLIMIT_FSIZE, &file);
  setrlimit(RLIMIT_CORE, &no_core);
  // The report first to a number above every target, so that no dup2 below overwrites it.
  const int report = fcntl(c.report, F_DUPFD_CLOEXEC, 16);
  if (report < 0) _exit(127);
  const std::pair<int, int> moves[] = {{c.in, 0},          {c.out, 1},          {c.err, 2},
                                       {c.info, kInfoFd},  {c.block, kBlockFd}, {c.checkpoint, kCheckpointFd},
                                       {c.filter, kFilterFd}, {c.shim, kShimFd}};
  for (const auto& [from, to] : moves)
    if (from >= 0 && dup2(from, to) < 0) fail_in_child(report, kSetupStep);
  if (dup2(report, 3) < 0) fail_in_child(report, kSetupStep);
  fcntl(3, F_SETFD, FD_CLOEXEC);
  close_descriptors_from(c.info >= 0 ? kShimFd + 1 : 4);  // nothing else of ours leaks into the sandbox
  if (chdir(c.work) != 0) fail_in_child(3, kSetupStep);
  execve(program, argv, envp);
  fail_in_child(3, kExecStep);
}
}  // namespace

// ---- launching, waiting --------------------------------------------------------------------------------
namespace {
// The pid bwrap's info fd names ("child-pid": N), or 0.
pid_t child_pid_in(const std::string& info) {
  const std::size_t at = info.find("\"child-pid\"");
  if (at == std::string::npos) return 0;
  const std::size_t colon = info.find(':', at);
  return colon == std::string::npos ? 0 : pid_t(std::atol(info.c_str() + colon + 1));
}

// The run's tmpfs, seen through the sandbox's root once it is up (a tmpfs of exactly its size: never the
// host's folder of the same name), kept open so that it can be measured during and after the run. -1 if not.
int open_run_disk(pid_t child, const std::string& work, long long disk_bytes) {
  const std::string path = "/proc/" + std::to_string(child) + "/root" + work;
  const int fd = open(path.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  struct statfs info {};
  if (fd >= 0 && fstatfs(fd, &info) == 0 && (long long)info.f_blocks * (long long)info.f_bsize == disk_bytes)
    return fd;
  if (fd >= 0) close(fd);
  return -1;
}

bool disk_full(int fd) {
  struct statfs info {};
  return fd >= 0 && fstatfs(fd, &info) == 0 && info.f_bavail == 0;
}

long long files_in(int fd) {
  struct statfs info {};
  return fd >= 0 && fstatfs(fd, &info) == 0 ? (long long)info.f_files - (long long)info.f_ffree : 0;
}

// A program writing into a full disk says so on stderr: the one fact a run that ended before its disk could
// be measured leaves (it only ever names the disk bound, never whose fault a failure is).
bool says_disk_full(const std::string& err) {
  return err.find("No space left on device") != std::string::npos || err.find("[Errno 28]") != std::string::npos;
}

void drain_into(int fd, std::string& text) {
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
}

// A started run: the child's pid and the parent's ends of its pipes.
struct Launched {
  pid_t pid = 0;
  Pipe in, out, err, report, info, block, checkpoint, filter;
  int shim = -1;
  ~Launched() {
    if (shim >= 0) ::close(shim);
  }
};

// Forks and execs the run's command (bwrap's or the program). Throws on the machine's failures (pipes, fork).
void launch(Launched& run, std::vector<char*>& c_argv, std::vector<char*>& c_envp, const std::string& work,
            const RunLimits& limits, uid_t run_uid, rlim_t max_processes, const RunGroup* group,
            const std::string* filter, const std::string& shim_path) {
  const bool sandboxed = !shim_path.empty();
  if (write(run.block.write, "x", 1) != 1) throw std::runtime_error("pipe: cannot write");
  if (sandboxed && filter) {  // bwrap reads the filter to its end: written whole, then closed
    if (write(run.filter.write, filter->data(), filter->size()) != ssize_t(filter->size()))
      throw std::runtime_error("pipe: cannot write the system-call filter");
    run.filter.close_write();
  }
  if (sandboxed && (run.shim = open(shim_path.c_str(), O_RDONLY | O_CLOEXEC)) < 0)
    throw std::runtime_error("cannot open " + shim_path + ": " + std::strerror(errno));
  ChildSetup setup;
  setup.work = work.c_str();
  setup.in = run.in.read;
  setup.out = run.out.write;
  setup.err = run.err.write;
  setup.report = run.report.write;
  if (sandboxed) {
    setup.info = run.info.write;
    setup.block = run.block.read;
    setup.checkpoint = run.checkpoint.write;
    setup.filter = filter ? run.filter.read : -1;
    setup.shim = run.shim;
  }
  setup.limits = &limits;
  setup.run_uid = run_uid;
  setup.max_processes = max_processes;
  setup.join_group = group ? &group->join_fds() : nullptr;
  run.pid = fork();
  if (run.pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (run.pid == 0) exec_child(c_argv[0], c_argv.data(), c_envp.data(), setup);
  setpgid(run.pid, run.pid);  // also here: whichever runs first, the group exists before we may signal it
  for (Pipe* pipe : {&run.out, &run.err, &run.report, &run.info, &run.block, &run.checkpoint}) pipe->close_write();
  run.in.close_read();
  run.filter.close_read();
}

// Feeds the input, collects the output and polls the bounds until the run ends or is stopped; fills the
// facts and the result's output. The program's own exit counts once it has exited, after a short drain of
// what it wrote (something it started may still hold its output open: a setsid child).
void wait_for(Launched& run, const std::string& input, const RunLimits& limits, const RunGroup* group,
              const std::string& work, bool sandboxed, RunFacts& facts, RunResult& result, rusage& usage,
              int& disk) {
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.timeout_seconds));
  const double cpu_limit = limits.cpu_seconds > 0 ? limits.cpu_seconds : limits.timeout_seconds;
  const long long max_files = limits.max_files > 0 ? limits.max_files : std::max(1LL, limits.disk_bytes >> 12);
  using Stop = RunFacts::Stop;
  auto cancelled = [&] { return limits.cancel && limits.cancel->load(); };
  fcntl(run.in.write, F_SETFL, O_NONBLOCK);
  fcntl(run.info.read, F_SETFL, O_NONBLOCK);
  std::size_t written = 0;
  if (input.empty()) run.in.close_write();
  std::string info_text;
  pid_t sandbox_child = 0;
  char buffer[65536];
  bool exited = false;
  Clock::time_point drained_by = deadline;
  // The bounds the checker itself polls: wall time, a cancel, CPU time (a group's count), files on disk.
  auto over_a_bound = [&](Clock::time_point now) {
    if (now >= deadline) return Stop::timeout;
    if (cancelled()) return Stop::cancelled;
    if (group && group->cpu_seconds() > cpu_limit) return Stop::cpu_time;
    if (files_in(disk) > max_files) return Stop::files;
    return Stop::none;
  };
  while (run.out.read >= 0 || run.err.read >= 0) {
    const auto now = Clock::now();
    if (!exited && (facts.stopped = over_a_bound(now)) != Stop::none) break;
    if (!exited && wait_with_usage(run.pid, &facts.wait_status, WNOHANG, &usage) == run.pid) {
      exited = true;
      drained_by = std::min(deadline, now + std::chrono::milliseconds(200));
    }
    if (exited && now >= drained_by) break;
    if (sandboxed && run.info.read >= 0) {  // bwrap names its child once the namespaces exist
      const ssize_t n = read(run.info.read, buffer, sizeof buffer);
      if (n > 0) info_text.append(buffer, std::size_t(n));
      else if (n == 0) run.info.close_read();
      if (!sandbox_child) sandbox_child = child_pid_in(info_text);
    }
    if (sandbox_child && disk < 0 && !exited) disk = open_run_disk(sandbox_child, work, limits.disk_bytes);
    pollfd fds[3];
    int count = 0;
    if (run.in.write >= 0) fds[count++] = {run.in.write, POLLOUT, 0};
    if (run.out.read >= 0) fds[count++] = {run.out.read, POLLIN, 0};
    if (run.err.read >= 0) fds[count++] = {run.err.read, POLLIN, 0};
    // Short waits until the program has exited (its exit is noticed above), then until the drain ends;
    // shorter while the run's disk is still to be found.
    const int step = sandbox_child && disk < 0 ? 5 : 50;
    const int wait_ms = exited ? int(std::chrono::duration_cast<std::chrono::milliseconds>(drained_by - now).count()) + 1
                               : std::min(step, int(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1);
    if (poll(fds, nfds_t(count), wait_ms) < 0 && errno != EINTR) break;
    bool too_large = false;
    for (int i = 0; i < count; ++i) {
      if (!fds[i].revents) continue;
      if (fds[i].fd == run.in.write) {
        const ssize_t n = write(run.in.write, input.data() + written, input.size() - written);
        if (n > 0) written += std::size_t(n);
        if (n < 0 && errno != EAGAIN) run.in.close_write();  // EPIPE: the program does not read its input
        if (written == input.size()) run.in.close_write();
        continue;
      }
      const bool is_out = fds[i].fd == run.out.read;
      const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
      if (n <= 0) {
        if (n == 0 || errno != EAGAIN) (is_out ? run.out : run.err).close_read();
        continue;
      }
      std::string& sink = is_out ? result.out : result.err;
      const std::size_t cap = is_out ? limits.max_stdout_bytes : limits.max_stderr_bytes;
      sink.append(buffer, std::min(std::size_t(n), cap - std::min(cap, sink.size())));
      if (is_out && result.out.size() >= limits.max_stdout_bytes) too_large = true;
    }
    if (too_large) {
      facts.stopped = Stop::output;
      break;
    }
  }
  // Output closed: wait for the exit, still under the bounds (a program may close stdout and go on).
  while (!exited && facts.stopped == Stop::none && wait_with_usage(run.pid, &facts.wait_status, WNOHANG, &usage) == 0)
    if ((facts.stopped = over_a_bound(Clock::now())) == Stop::none) usleep(2000);
  if (facts.stopped != Stop::none) {
    stop(run.pid);
    if (group) group->kill_all();
    wait_with_usage(run.pid, &facts.wait_status, 0, &usage);
    // A cancel after the deadline, or with the CPU spent, is that bound's.
    if (facts.stopped == Stop::cancelled && Clock::now() >= deadline) facts.stopped = Stop::timeout;
  }
  kill(-run.pid, SIGKILL);  // anything it left behind in its process group
  if (group) group->kill_all();
  if (sandboxed) {
    if (run.info.read >= 0) drain_into(run.info.read, info_text);
    int unread = 0;  // bwrap's set-up reads the byte on its --block-fd when it is done
    ioctl(run.block.read, FIONREAD, &unread);
    facts.sandbox_named_child = child_pid_in(info_text) != 0;
    facts.sandbox_setup_done = unread == 0;
    // Every holder of the checkpoint's pipe is gone once bwrap has ended: read to its end.
    fcntl(run.checkpoint.read, F_SETFL, O_NONBLOCK);
    drain_into(run.checkpoint.read, facts.checkpoint);
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
}
}  // namespace

RunResult run_student(const std::vector<std::string>& argv_in, const std::string& input, const RunLimits& limits,
                      const std::optional<Sandbox>& sandbox) {
  static std::once_flag ignore_sigpipe;
  std::call_once(ignore_sigpipe, [] { signal(SIGPIPE, SIG_IGN); });  // a student closing stdin early
  RunResult result;
  if (argv_in.empty()) {
    result.error = "empty command";
    return result;
  }
  // Sandboxed, the program sees only real paths (sandbox_policy.h): a link in its command is resolved.
  std::vector<std::string> argv = sandbox ? canonical_paths(argv_in) : argv_in;
  // Sandboxed under root the run has no rights of root's: its program comes from where anyone may run it
  // (/usr/bin/python3, not a shim in root's home).
  const bool unprivileged = sandbox && geteuid() == 0;
  const std::string program = find_program(argv[0], unprivileged);
  if (program.empty()) {
    const std::string hint = launch_hint(argv);
    result.error = unprivileged && !find_program(argv[0]).empty()
                       ? "'" + argv[0] + "' is found only where an unprivileged user cannot run it (" +
                             find_program(argv[0]) + "): sandboxed runs do not have root's rights; install it "
                             "for every user or give a path others can read"
                       : !hint.empty() ? hint : "cannot find an executable program '" + argv[0] + "'";
    return result;
  }
  argv[0] = program;
  std::string shim, no_filter;
  const std::string* filter = nullptr;
  if (sandbox) {
    shim = exec_checkpoint_path();
    const std::string& compiled = syscall_filter_program(no_filter);
    if (!compiled.empty()) filter = &compiled;
    if (shim.empty() || !filter) {
      result.infrastructure_failure = true;
      result.error = shim.empty() ? "raycam-exec (the sandbox's exec checkpoint) is not beside this program"
                                  : "no system-call filter: " + no_filter;
      return result;
    }
  }

  const std::string work = make_run_folder(result);
  if (work.empty()) return result;
  auto give_up = [&](const std::string& why) {
    result.error = why;
    result.infrastructure_failure = true;
    remove_folder_whatever_modes(work);
    untrack(work);
    return result;
  };
  // Sandboxed under root: the run's own uid (see next_run_uid), which must own its folder to write there.
  const uid_t run_uid = unprivileged ? next_run_uid() : 0;
  if (run_uid != 0 && chown(work.c_str(), run_uid, gid_t(run_uid)) != 0)
    return give_up("cannot give the run its temporary directory: " + std::string(std::strerror(errno)));
  // bwrap's own two processes (its launcher outside, its pid 1 inside) are not the program's: counted on top.
  const int overhead = sandbox ? kSandboxProcesses : 0;
  std::string no_group;
  std::unique_ptr<RunGroup> group;
  if (limits.use_run_groups && run_groups_available(no_group)) {
    group = RunGroup::create({limits.memory_bytes, limits.max_processes + overhead}, no_group);
    if (!group) return give_up(no_group);
  }
  result.bounded_per_run = bool(group);
  // Without a group the process cap counts per uid: a run's own uid under root, else this user's processes
  // now plus the run's.
  const rlim_t max_processes =
      group ? 0 : rlim_t(limits.max_processes + overhead) + rlim_t(run_uid != 0 ? 0 : processes_of(geteuid()));
  std::vector<std::string> command =
      sandbox ? bwrap_arguments(sandbox_policy(sandbox->bwrap, sandbox->hidden, sandbox->shown, argv, work,
                                               limits.disk_bytes),
                                argv)
              : argv;
  std::vector<std::string> environment = child_environment(work);
  std::vector<char*> c_argv = c_strings(command), c_envp = c_strings(environment);

  RunFacts facts;
  facts.sandboxed = bool(sandbox);
  rusage usage{};
  int disk = -1;  // the run's tmpfs (open_run_disk)
  try {
    Launched run;
    launch(run, c_argv, c_envp, work, limits, run_uid, max_processes, group.get(), filter, shim);
    track(work, run.pid, group.get());
    int message[2] = {0, 0};
    if (read(run.report.read, message, sizeof message) == sizeof message) {  // the child failed before exec
      waitpid(run.pid, nullptr, 0);
      if (message[0] == kSetupStep) facts.setup_failure = std::string("cannot set the run up: ") + std::strerror(message[1]);
      else facts.exec_errno = message[1];
    } else {
      wait_for(run, input, limits, group.get(), work, bool(sandbox), facts, result, usage, disk);
    }
  } catch (const std::exception& error) {  // pipes or fork failed: the machine, not the program
    facts.setup_failure = error.what();
  }
  if (group) {
    const GroupUsage counted = group->usage();
    result.cpu_seconds = counted.cpu_seconds;
    result.peak_memory_bytes = counted.peak_memory_bytes;
    facts.memory_limit_hit = counted.memory_limit_hit;
    facts.process_limit_hit = counted.process_limit_hit;
  } else {
    result.cpu_seconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    result.peak_memory_bytes = (long long)usage.ru_maxrss << 10;
    const int signal = WIFSIGNALED(facts.wait_status) ? WTERMSIG(facts.wait_status) : 0;
    const double cpu_limit = limits.cpu_seconds > 0 ? limits.cpu_seconds : limits.timeout_seconds;
    facts.cpu_over_limit = (signal == SIGXCPU || signal == SIGKILL) && result.cpu_seconds >= cpu_limit;
  }
  facts.disk_full = sandbox && (disk_full(disk) || says_disk_full(result.err));
  classify_run(facts, result);
  if (result.end == RunResult::End::could_not_start && !result.infrastructure_failure) {
    // The program cannot be exec'd: the submission's, with a hint where one applies (CRLF, no run bit).
    const std::string hint = launch_hint(argv);
    result.error = hint.empty() ? "cannot run '" + argv[0] + "': " + result.error : hint;
  }
  // "#!/usr/bin/env python3\r" starts env, which then finds no 'python3\r' and exits 127: the script's line
  // ends (read from the file, not from what the run printed), as when the kernel finds no interpreter.
  if (result.end == RunResult::End::exited && result.exit_code == 127 && !result.infrastructure_failure)
    if (const std::string hint = launch_hint(argv); hint.find("(CRLF)") != std::string::npos) {
      result.end = RunResult::End::could_not_start;
      result.error = hint;
    }
  if (disk >= 0) close(disk);
  group.reset();
  remove_folder_whatever_modes(work);
  untrack(work);
  return result;
}

// ---- the sandbox ---------------------------------------------------------------------------------------
std::optional<Sandbox> probe_sandbox(std::string& why) {
  static std::mutex mutex;
  static bool probed = false;
  static std::optional<Sandbox> found;
  static std::string reason;
  std::lock_guard<std::mutex> lock(mutex);
  if (!probed) {
    probed = true;
    const std::string bwrap = find_program("bwrap");
    if (bwrap.empty()) {
      reason = "bwrap not found (Debian package bubblewrap)";
    } else {
      RunLimits limits;
      limits.timeout_seconds = 10;
      const RunResult probe = run_student({"true"}, "", limits, Sandbox{bwrap, {}, {}});
      if (probe.end == RunResult::End::exited && probe.exit_code == 0) found = Sandbox{bwrap, {}, {}};
      else
        reason = "bwrap cannot start a sandbox here: " +
                 (probe.err.empty() ? probe.error : probe.err.substr(0, probe.err.find('\n')));
    }
  }
  why = reason;
  return found;
}

}  // namespace raycam::check
