// Section index: splitting a command · finding programs · the child (after fork: async-signal-safe calls
// only) · the parent's poll loop · the sandbox.
#include "student_process.h"

#include "close_descriptors.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
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
#include <mutex>
#include <stdexcept>

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

// The bwrap command line around `argv` (see the header for what each part isolates).
std::vector<std::string> sandboxed(const Sandbox& sandbox, const std::string& work, const std::vector<std::string>& argv) {
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
  // The student's own folder, and the folders of the files its command names (its program, its script).
  std::vector<std::string> shown = sandbox.shown;
  for (const std::string& word : argv) {
    std::error_code error;
    if (word.rfind('/', 0) == 0 && fs::exists(word, error) && word.rfind("/usr/", 0) != 0)
      shown.push_back(fs::is_directory(word, error) ? word : fs::path(word).parent_path().string());
  }
  for (const std::string& dir : shown)
    if (dir != "/") words.insert(words.end(), {"--ro-bind", dir, dir});
  // bwrap writes its "child-pid" JSON on fd 4 once the sandbox is up: no bytes there means it never started.
  words.insert(words.end(), {"--info-fd", "4"});
  words.insert(words.end(), {"--bind", work, work, "--remount-ro", "/tmp", "--remount-ro", "/dev", "--unshare-all",
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
struct LiveRuns {
  std::mutex mutex;
  std::map<std::string, pid_t> folders;  // folder -> process group (0 before the fork)
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

void stop_live_runs() {
  LiveRuns& r = live_runs();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (const auto& [folder, group] : r.folders) {
    if (group > 0) kill(-group, SIGKILL);
    std::error_code ignored;
    fs::remove_all(folder, ignored);
  }
  r.folders.clear();
}

namespace {
void track(const std::string& folder, pid_t group) {
  LiveRuns& r = live_runs();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.folders[folder] = group;
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
[[noreturn]] void exec_child(const char* program, char* const* argv, char* const* envp, const char* work, int in,
                             int out, int err, int report, int info, const RunLimits& limits, uid_t run_uid,
                             rlim_t max_processes) {
  setpgid(0, 0);
  sigset_t none;  // raycam-cli check blocks SIGINT and SIGTERM for its signal thread: not the student's
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (run_uid != 0 && (setgroups(0, nullptr) != 0 || setgid(gid_t(run_uid)) != 0 || setuid(run_uid) != 0)) {
    const int code = errno;
    ssize_t ignored = write(report, &code, sizeof code);
    (void)ignored;
    _exit(127);
  }
  const rlimit processes{max_processes, max_processes};
  setrlimit(RLIMIT_NPROC, &processes);
  signal(SIGPIPE, SIG_DFL);  // ignored in raycam-cli; an ignored signal would stay ignored across exec
  const rlimit memory{rlim_t(limits.memory_bytes), rlim_t(limits.memory_bytes)};
  const rlimit file{rlim_t(limits.file_bytes), rlim_t(limits.file_bytes)};
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_AS, &memory);
  setrlimit(RLIMIT_FSIZE, &file);
  setrlimit(RLIMIT_CORE, &no_core);
  if (dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0 || dup2(report, 3) < 0 ||
      (info >= 0 && dup2(info, 4) < 0))
    _exit(127);
  fcntl(3, F_SETFD, FD_CLOEXEC);
  close_descriptors_from(info >= 0 ? 5 : 4);  // nothing else of ours leaks into the student's program
  if (chdir(work) == 0) execve(program, argv, envp);
  const int code = errno;
  ssize_t ignored = write(3, &code, sizeof code);
  (void)ignored;
  _exit(127);
}
}  // namespace

// ---- the parent's poll loop ------------------------------------------------------------------------------
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
    result.error = unprivileged && !find_program(argv[0]).empty()
                       ? "'" + argv[0] + "' is found only where an unprivileged user cannot run it (" +
                             find_program(argv[0]) + "): sandboxed runs do not have root's rights; install it "
                             "for every user or give a path others can read"
                       : "cannot find an executable program '" + argv[0] + "'";
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
  // Sandboxed under root: the run's own uid (see next_run_uid), which must own its folder to write there.
  const uid_t run_uid = unprivileged ? next_run_uid() : 0;
  if (run_uid != 0 && chown(work.c_str(), run_uid, gid_t(run_uid)) != 0) {
    result.error = "cannot give the run its temporary directory: " + std::string(std::strerror(errno));
    std::error_code ignored;
    fs::remove_all(work, ignored);
    untrack(work);
    return result;
  }
  const rlim_t max_processes =
      rlim_t(limits.max_processes) + rlim_t(run_uid != 0 ? 0 : processes_of(geteuid()));
  std::vector<std::string> command = sandbox ? sandboxed(*sandbox, work, argv) : argv;
  std::vector<std::string> environment = child_environment(work);
  std::vector<char*> c_argv = c_strings(command), c_envp = c_strings(environment);

  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.timeout_seconds));
  try {
    Pipe in, out, err, report, info;
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) exec_child(c_argv[0], c_argv.data(), c_envp.data(), work.c_str(), in.read, out.write, err.write,
                             report.write, sandbox ? info.write : -1, limits, run_uid, max_processes);
    setpgid(pid, pid);  // also here: whichever runs first, the group exists before we may signal it
    track(work, pid);
    in.close_read();
    out.close_write();
    err.close_write();
    report.close_write();
    info.close_write();
    int exec_errno = 0;
    if (read(report.read, &exec_errno, sizeof exec_errno) == sizeof exec_errno) {
      waitpid(pid, nullptr, 0);
      result.error = "cannot run '" + argv[0] + "': " + std::strerror(exec_errno);
      std::error_code ignored;
      fs::remove_all(work, ignored);
      untrack(work);
      return result;
    }
    fcntl(in.write, F_SETFL, O_NONBLOCK);
    std::size_t written = 0;
    if (input.empty()) in.close_write();
    bool too_large = false, timed_out = false;
    char buffer[65536];
    // The program itself may end while something it started still holds its output open (a setsid child,
    // out of its process group): its answer counts once it has exited, after a short drain of what it wrote.
    int status = 0;
    bool exited = false;
    Clock::time_point drained_by = deadline;
    while (out.read >= 0 || err.read >= 0) {
      const auto now = Clock::now();
      if (now >= deadline && !exited) {
        timed_out = true;
        break;
      }
      if (!exited && waitpid(pid, &status, WNOHANG) == pid) {
        exited = true;
        drained_by = std::min(deadline, now + std::chrono::milliseconds(200));
      }
      if (exited && now >= drained_by) break;
      pollfd fds[3];
      int count = 0;
      if (in.write >= 0) fds[count++] = {in.write, POLLOUT, 0};
      if (out.read >= 0) fds[count++] = {out.read, POLLIN, 0};
      if (err.read >= 0) fds[count++] = {err.read, POLLIN, 0};
      // Short waits until the program has exited (its exit is noticed above), then until the drain ends.
      const int wait_ms = exited ? int(std::chrono::duration_cast<std::chrono::milliseconds>(drained_by - now).count()) + 1
                                 : std::min(50, int(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1);
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
    while (!exited && !timed_out && !too_large && (done = waitpid(pid, &status, WNOHANG)) == 0) {
      if (Clock::now() >= deadline) timed_out = true;
      else usleep(2000);
    }
    if (timed_out || too_large) {
      stop(pid);
      waitpid(pid, &status, 0);
      result.end = timed_out ? RunResult::End::timed_out : RunResult::End::output_too_large;
    } else if (WIFEXITED(status)) {
      result.end = RunResult::End::exited;
      result.exit_code = WEXITSTATUS(status);
    } else {
      result.end = RunResult::End::signalled;
      result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    kill(-pid, SIGKILL);  // anything it left behind in its group
    if (sandbox) {  // see RunResult::infrastructure_failure
      fcntl(info.read, F_SETFL, O_NONBLOCK);
      char started[64];
      result.infrastructure_failure = read(info.read, started, sizeof started) <= 0;
    }
  } catch (const std::exception& error) {  // fork or pipe failed: the machine, not the program
    result.end = RunResult::End::could_not_start;
    result.error = error.what();
    result.infrastructure_failure = true;
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::error_code ignored;
  fs::remove_all(work, ignored);
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
