// Section index: splitting a command · finding programs · the child (after fork: async-signal-safe calls
// only) · the parent's poll loop · the sandbox.
#include "student_process.h"

#include "process_calls.h"

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

#include "folder_removal.h"
#include "run_group.h"
#include "shown_folders.h"

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

// What a program needs to run and nothing else: the system's programs and libraries (/usr and the root's
// links into it), the few /etc files the dynamic loader and interpreters read, /opt; not /home, /root, /etc's
// other files, the instructor's output folders, other submissions nor anything else of the machine.
const char* const kSystemFolders[] = {"/usr", "/opt"};
const char* const kRootLinks[] = {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};
const char* const kEtcFiles[] = {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives",
                                 "/etc/localtime", "/etc/mime.types"};

// The bwrap command line around `argv` (see the header for what each part isolates). bwrap reads a byte on
// fd 5 once its set-up is done (the byte left unread: the sandbox failed, not the program).
std::vector<std::string> sandboxed(const Sandbox& sandbox, const std::string& work, long long disk_bytes,
                                   const std::vector<std::string>& argv) {
  std::vector<std::string> words = {sandbox.bwrap};
  for (const char* folder : kSystemFolders) words.insert(words.end(), {"--ro-bind-try", folder, folder});
  for (const char* link : kRootLinks) {
    std::error_code error;
    if (fs::is_symlink(link, error))  // merged /usr: /bin -> usr/bin
      words.insert(words.end(), {"--symlink", fs::read_symlink(link, error).string(), link});
    else if (fs::is_directory(link, error))
      words.insert(words.end(), {"--ro-bind", link, link});
  }
  for (const char* file : kEtcFiles) words.insert(words.end(), {"--ro-bind-try", file, file});
  words.insert(words.end(), {"--dev", "/dev", "--proc", "/proc", "--tmpfs", "/tmp"});
  // A class's folder is hidden even where a system folder holds it (a batch under /opt).
  for (const std::string& dir : sandbox.hidden) words.insert(words.end(), {"--tmpfs", dir});
  // The student's own folder, and the folders of the files its command names (its program, its script).
  std::vector<std::string> shown = sandbox.shown;
  for (const std::string& dir : folders_named(argv)) shown.push_back(dir);
  for (const std::string& dir : shown)
    if (dir != "/") words.insert(words.end(), {"--ro-bind", dir, dir});
  // bwrap writes its "child-pid" JSON on fd 4 once the sandbox is up: no bytes there means it never started.
  words.insert(words.end(), {"--info-fd", "4", "--block-fd", "5"});
  // The only writable folder: a tmpfs of its own, so a full disk is this run's failure, never the machine's.
  words.insert(words.end(), {"--size", std::to_string(disk_bytes), "--tmpfs", work});
  words.insert(words.end(), {"--remount-ro", "/tmp", "--remount-ro", "/dev", "--unshare-all",
                             "--unshare-user", "--uid", "65534", "--gid", "65534", "--die-with-parent",
                             "--new-session", "--chdir", work, "--"});
  words.insert(words.end(), argv.begin(), argv.end());
  return words;
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

// ---- the child (after fork: async-signal-safe calls only) -------------------------------------------------
// What the child needs besides its command, prepared before the fork.
struct ChildSetup {
  const char* work;
  int in, out, err, report, info, block;  // block: bwrap's --block-fd (-1 without the sandbox)
  const RunLimits* limits;
  uid_t run_uid;
  rlim_t max_processes;                // RLIMIT_NPROC, 0: none (a run group bounds the processes)
  const std::vector<int>* join_group;  // the run group's cgroup.procs, or nullptr
};

[[noreturn]] void fail_in_child(int report) {
  const int code = errno;
  ssize_t ignored = write(report, &code, sizeof code);
  (void)ignored;
  _exit(127);
}

[[noreturn]] void exec_child(const char* program, char* const* argv, char* const* envp, const ChildSetup& c) {
  setpgid(0, 0);
  // Into the run's group first, while still allowed to (its files belong to the checker's user).
  if (c.join_group && !join_run_group(*c.join_group)) fail_in_child(c.report);
  sigset_t none;  // raycam-cli check blocks SIGINT and SIGTERM for its signal thread: not the student's
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (c.run_uid != 0 && (setgroups(0, nullptr) != 0 || setgid(gid_t(c.run_uid)) != 0 || setuid(c.run_uid) != 0))
    fail_in_child(c.report);
  // Keyrings are not namespaced: a fresh, empty session keyring, so that no key of the checker's session or
  // of an earlier run is within reach.
#ifdef KEYCTL_JOIN_SESSION_KEYRING
  syscall(SYS_keyctl, KEYCTL_JOIN_SESSION_KEYRING, nullptr);
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
  if (dup2(c.in, 0) < 0 || dup2(c.out, 1) < 0 || dup2(c.err, 2) < 0 || dup2(c.report, 3) < 0 ||
      (c.info >= 0 && dup2(c.info, 4) < 0) || (c.block >= 0 && dup2(c.block, 5) < 0))
    _exit(127);
  fcntl(3, F_SETFD, FD_CLOEXEC);
  close_descriptors_from(c.block >= 0 ? 6 : 4);  // nothing else of ours leaks into the student's program
  if (chdir(c.work) == 0) execve(program, argv, envp);
  fail_in_child(3);
}
}  // namespace

// ---- the parent's poll loop ------------------------------------------------------------------------------
namespace {
// The pid bwrap's info fd names ("child-pid": N), or 0.
pid_t child_pid_in(const std::string& info) {
  const std::size_t at = info.find("\"child-pid\"");
  if (at == std::string::npos) return 0;
  const std::size_t colon = info.find(':', at);
  return colon == std::string::npos ? 0 : pid_t(std::atol(info.c_str() + colon + 1));
}

// The run's tmpfs, seen through the sandbox's root once it is up (a tmpfs of exactly its size: never the
// host's folder of the same name), kept open so that it can be measured after the run has ended. -1 if not.
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

// A program writing into a full disk says so on stderr; a run that ended before its disk could be measured.
bool says_disk_full(const std::string& err) {
  return err.find("No space left on device") != std::string::npos || err.find("[Errno 28]") != std::string::npos;
}

// A sandbox that failed after its set-up's checkpoint ("bwrap: Can't fork for pid 1"): bwrap's own message,
// and never more than bwrap's two processes in the run's group, so the program never started (a program
// printing "bwrap: …" itself ran as a third). Without a group's count (peak_processes < 0), that one message.
bool bwrap_failed_late(const RunResult& r, long long peak_processes) {
  return r.end == RunResult::End::exited && r.exit_code == 1 && r.err.rfind("bwrap: ", 0) == 0 &&
         (peak_processes >= 0 ? peak_processes <= 2 : r.err.rfind("bwrap: Can't fork for pid 1", 0) == 0);
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
  std::vector<std::string> argv = argv_in;
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

  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/raycam-check-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    result.error = "cannot create a temporary directory: " + std::string(std::strerror(errno));
    result.infrastructure_failure = true;
    return result;
  }
  const std::string work = pattern;
  track(work, 0);
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
  std::string no_group;
  std::unique_ptr<RunGroup> group;
  if (limits.use_run_groups && run_groups_available(no_group)) {
    group = RunGroup::create({limits.memory_bytes, limits.max_processes}, no_group);
    if (!group) return give_up(no_group);
  }
  result.bounded_per_run = bool(group);
  // Without a group the process cap counts per uid: a run's own uid under root, else this user's processes
  // now plus the run's.
  const rlim_t max_processes =
      group ? 0 : rlim_t(limits.max_processes) + rlim_t(run_uid != 0 ? 0 : processes_of(geteuid()));
  std::vector<std::string> command = sandbox ? sandboxed(*sandbox, work, limits.disk_bytes, argv) : argv;
  std::vector<std::string> environment = child_environment(work);
  std::vector<char*> c_argv = c_strings(command), c_envp = c_strings(environment);
  const double cpu_limit = limits.cpu_seconds > 0 ? limits.cpu_seconds : limits.timeout_seconds;

  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.timeout_seconds));
  int disk = -1;  // the run's tmpfs (open_run_disk)
  try {
    Pipe in, out, err, report, info, block;
    if (write(block.write, "x", 1) != 1) throw std::runtime_error("pipe: cannot write");
    const ChildSetup setup{work.c_str(), in.read, out.write, err.write, report.write, sandbox ? info.write : -1,
                           sandbox ? block.read : -1, &limits, run_uid, max_processes,
                           group ? &group->join_fds() : nullptr};
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) exec_child(c_argv[0], c_argv.data(), c_envp.data(), setup);
    setpgid(pid, pid);  // also here: whichever runs first, the group exists before we may signal it
    track(work, pid, group.get());
    in.close_read();
    out.close_write();
    err.close_write();
    report.close_write();
    info.close_write();
    block.close_write();
    int exec_errno = 0;
    if (read(report.read, &exec_errno, sizeof exec_errno) == sizeof exec_errno) {
      waitpid(pid, nullptr, 0);
      const std::string hint = launch_hint(argv);
      result.error = hint.empty() ? "cannot run '" + argv[0] + "': " + std::strerror(exec_errno) : hint;
      group.reset();
      remove_folder_whatever_modes(work);
      untrack(work);
      return result;
    }
    fcntl(in.write, F_SETFL, O_NONBLOCK);
    fcntl(info.read, F_SETFL, O_NONBLOCK);
    std::size_t written = 0;
    if (input.empty()) in.close_write();
    bool too_large = false, timed_out = false, cpu_out = false;
    std::string info_text;
    pid_t sandbox_child = 0;
    char buffer[65536];
    // The program itself may end while something it started still holds its output open (a setsid child,
    // out of its process group): its answer counts once it has exited, after a short drain of what it wrote.
    int status = 0;
    rusage usage {};
    bool exited = false;
    Clock::time_point drained_by = deadline;
    auto cancelled = [&] { return limits.cancel && limits.cancel->load(); };
    while (out.read >= 0 || err.read >= 0) {
      const auto now = Clock::now();
      if ((now >= deadline || cancelled()) && !exited) {
        timed_out = true;
        break;
      }
      if (group && !exited && group->cpu_seconds() > cpu_limit) {
        timed_out = cpu_out = true;
        break;
      }
      if (!exited && wait_with_usage(pid, &status, WNOHANG, &usage) == pid) {
        exited = true;
        drained_by = std::min(deadline, now + std::chrono::milliseconds(200));
      }
      if (exited && now >= drained_by) break;
      if (sandbox && info.read >= 0) {  // bwrap names its child once the namespaces exist
        const ssize_t n = read(info.read, buffer, sizeof buffer);
        if (n > 0) info_text.append(buffer, std::size_t(n));
        else if (n == 0) info.close_read();
        if (!sandbox_child) sandbox_child = child_pid_in(info_text);
      }
      if (sandbox_child && disk < 0 && !exited) disk = open_run_disk(sandbox_child, work, limits.disk_bytes);
      pollfd fds[3];
      int count = 0;
      if (in.write >= 0) fds[count++] = {in.write, POLLOUT, 0};
      if (out.read >= 0) fds[count++] = {out.read, POLLIN, 0};
      if (err.read >= 0) fds[count++] = {err.read, POLLIN, 0};
      // Short waits until the program has exited (its exit is noticed above), then until the drain ends;
      // shorter while the run's disk is still to be found.
      const int step = sandbox_child && disk < 0 ? 5 : 50;
      const int wait_ms = exited ? int(std::chrono::duration_cast<std::chrono::milliseconds>(drained_by - now).count()) + 1
                                 : std::min(step, int(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1);
      if (poll(fds, nfds_t(count), wait_ms) < 0 && errno != EINTR) break;
      for (int i = 0; i < count; ++i) {
        if (!fds[i].revents) continue;
        if (fds[i].fd == in.write) {
          const ssize_t n = write(in.write, input.data() + written, input.size() - written);
          if (n > 0) written += std::size_t(n);
          if (n < 0 && errno != EAGAIN) in.close_write();  // EPIPE: the program does not read its input
          if (written == input.size()) in.close_write();
          continue;
        }
        const bool is_out = fds[i].fd == out.read;
        const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
        if (n <= 0) {
          if (n == 0 || errno != EAGAIN) (is_out ? out : err).close_read();
          continue;
        }
        std::string& sink = is_out ? result.out : result.err;
        const std::size_t cap = is_out ? limits.max_stdout_bytes : limits.max_stderr_bytes;
        sink.append(buffer, std::min(std::size_t(n), cap - std::min(cap, sink.size())));
        if (is_out && result.out.size() >= limits.max_stdout_bytes) too_large = true;
      }
      if (too_large) break;
    }
    // Output closed: wait for the exit, still under the deadline (a program may close stdout and go on).
    pid_t done = exited ? pid : 0;
    while (!exited && !timed_out && !too_large && (done = wait_with_usage(pid, &status, WNOHANG, &usage)) == 0) {
      if (Clock::now() >= deadline || cancelled()) timed_out = true;
      else if (group && group->cpu_seconds() > cpu_limit) timed_out = cpu_out = true;
      else usleep(2000);
    }
    if (timed_out || too_large) {
      stop(pid);
      if (group) group->kill_all();
      wait_with_usage(pid, &status, 0, &usage);
      result.end = timed_out ? RunResult::End::timed_out : RunResult::End::output_too_large;
      result.limit = timed_out ? kTimeLimit : kOutputLimit;
      if (timed_out && !cpu_out && Clock::now() < deadline && cancelled()) {
        result.cancelled = true;  // no bound ended it: the caller gave up
        result.limit.clear();
      }
      if (cpu_out) result.error = "CPU time";
    } else if (WIFEXITED(status)) {
      result.end = RunResult::End::exited;
      result.exit_code = WEXITSTATUS(status);
    } else {
      result.end = RunResult::End::signalled;
      result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    kill(-pid, SIGKILL);  // anything it left behind in its group
    if (group) group->kill_all();
    if (sandbox) {  // see RunResult::infrastructure_failure
      if (info.read >= 0) {
        const ssize_t n = read(info.read, buffer, sizeof buffer);
        if (n > 0) info_text.append(buffer, std::size_t(n));
      }
      int unread = 0;  // bwrap's set-up reads the byte on its --block-fd when it is done
      ioctl(block.read, FIONREAD, &unread);
      result.infrastructure_failure = info_text.empty() || unread > 0 ||
                                      bwrap_failed_late(result, group ? group->usage().peak_processes : -1);
    }
    if (group) {
      const GroupUsage counted = group->usage();
      result.cpu_seconds = counted.cpu_seconds;
      result.peak_memory_bytes = counted.peak_memory_bytes;
      if (result.limit.empty() && counted.memory_limit_hit) result.limit = kMemoryLimit;
      else if (result.limit.empty() && counted.process_limit_hit) result.limit = kProcessLimit;
    } else {
      result.cpu_seconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
      result.peak_memory_bytes = (long long)usage.ru_maxrss << 10;
      if (result.end == RunResult::End::signalled && (result.signal == SIGXCPU || result.signal == SIGKILL) &&
          result.cpu_seconds >= cpu_limit)
        result.limit = kTimeLimit;
    }
    if (result.limit.empty() && sandbox && (disk_full(disk) || says_disk_full(result.err))) result.limit = kDiskLimit;
    // The sandbox is up but the program cannot start (bwrap says "execvp"): the submission's, with a hint.
    if (sandbox && !result.infrastructure_failure && result.err.rfind("bwrap: execvp ", 0) == 0) {
      const std::string hint = launch_hint(argv);
      result.end = RunResult::End::could_not_start;
      result.error = hint.empty() ? "cannot run '" + argv[0] + "': " + result.err.substr(result.err.rfind(": ") + 2)
                                  : hint;
      if (!result.error.empty() && result.error.back() == '\n') result.error.pop_back();
    }
    // "#!/usr/bin/env python3\r" starts env, which then finds no 'python3\r' (exit 127, its message quoting
    // the \r as "\\r"): the script's line ends, as when the kernel finds no interpreter.
    if (!result.infrastructure_failure && result.end == RunResult::End::exited && result.exit_code == 127 &&
        (result.err.find('\r') != std::string::npos || result.err.find("\\r") != std::string::npos)) {
      if (const std::string hint = launch_hint(argv); hint.find("(CRLF)") != std::string::npos) {
        result.end = RunResult::End::could_not_start;
        result.error = hint;
      }
    }
  } catch (const std::exception& error) {  // fork or pipe failed: the machine, not the program
    result.end = RunResult::End::could_not_start;
    result.error = error.what();
    result.infrastructure_failure = true;
  }
  if (disk >= 0) close(disk);
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
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
