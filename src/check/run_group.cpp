// Section index: files of a group · where groups can be made (v2, then v1) · one run's group.
#include "check/run_group.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <mutex>
#include <sstream>

namespace raycam::check {

namespace {
// ---- files of a group --------------------------------------------------------------------------------------
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes `text` with one write() (a control file takes one value per write); false with errno set on failure.
bool write_text(const std::string& path, const std::string& text) {
  const int fd = open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool written = write(fd, text.data(), text.size()) == ssize_t(text.size());
  const int saved = errno;
  close(fd);
  errno = saved;
  return written;
}

// The number after `key` in a "key value" file (memory.oom_control, pids.events, cpu.stat), or -1.
long long keyed_value(const std::string& text, const std::string& key) {
  std::istringstream lines(text);
  std::string name;
  long long value = 0;
  while (lines >> name >> value)
    if (name == key) return value;
  return -1;
}

long long number_in(const std::string& path) {
  try {
    return std::stoll(read_text(path));
  } catch (const std::exception&) {
    return 0;
  }
}

bool is_directory(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

// Kills every process listed in the groups until none is left (a run's forks race the kills: a few rounds).
void kill_members(const std::vector<std::string>& folders) {
  for (int round = 0; round < 500; ++round) {
    bool any = false;
    for (const std::string& folder : folders) {
      std::istringstream pids(read_text(folder + "/cgroup.procs"));
      for (long pid; pids >> pid;) {
        kill(pid_t(pid), SIGKILL);
        any = true;
      }
    }
    if (!any) return;
    usleep(1000);
  }
}

// ---- where groups can be made --------------------------------------------------------------------------------
// This process's group in the hierarchy holding `controller` ("" for v2's unified one), from /proc/self/cgroup.
std::string own_group(const std::string& controller) {
  std::istringstream lines(read_text("/proc/self/cgroup"));
  for (std::string line; std::getline(lines, line);) {
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string names = "," + line.substr(first + 1, second - first - 1) + ",";
    if (controller.empty() ? names == ",," : names.find("," + controller + ",") != std::string::npos)
      return line.substr(second + 1);
  }
  return {};
}

struct Hierarchy {
  bool v2 = false;
  std::vector<std::string> parents;  // where each run's folder is made (v1: memory, pids, cpuacct)
  std::string why;                   // empty when usable
};

const char* const kV1Controllers[] = {"memory", "pids", "cpuacct"};

// Which of `names` a controller list ("cpu memory pids", a cgroup.controllers or cgroup.subtree_control)
// lacks, as "memory, pids"; empty when it has them all.
std::string lacking(const std::string& list, std::initializer_list<const char*> names) {
  std::istringstream words(list);
  std::vector<std::string> present;
  for (std::string word; words >> word;) present.push_back(word);
  std::string missing;
  for (const char* name : names)
    if (std::find(present.begin(), present.end(), name) == present.end()) missing += (missing.empty() ? "" : ", ") + std::string(name);
  return missing;
}

// What this user may do in a group of its own: make folders, move processes, enable controllers.
bool writable_group(const std::string& folder) {
  return access(folder.c_str(), W_OK) == 0 && access((folder + "/cgroup.procs").c_str(), W_OK) == 0 &&
         access((folder + "/cgroup.subtree_control").c_str(), W_OK) == 0;
}

// The processes of a v2 group other than this one, as "PID COMMAND", the first few only (then "and N more").
std::string other_processes(const std::string& folder, int& count) {
  std::istringstream pids(read_text(folder + "/cgroup.procs"));
  std::string named;
  count = 0;
  for (long pid; pids >> pid;) {
    if (pid == long(getpid())) continue;
    if (++count > 4) continue;
    std::string command = read_text("/proc/" + std::to_string(pid) + "/comm");
    if (!command.empty() && command.back() == '\n') command.pop_back();
    named += (named.empty() ? "" : ", ") + std::to_string(pid) + " " + (command.empty() ? "?" : command);
  }
  if (count > 4) named += ", and " + std::to_string(count - 4) + " more";
  return named;
}

std::string uid_text() { return "uid " + std::to_string(geteuid()); }

// cgroup v2: the root (as root: a folder of this process's own under it, with the controllers on for its
// children), or this process's own group when delegated to this user: this process then moves into a leaf of
// its own beside the runs, since v2 lets a group enable controllers for its children only while it holds no
// process (the root aside). False with `found.why` saying exactly what is missing where v2 is the hierarchy.
bool find_v2(Hierarchy& found) {
  const std::string mount = is_directory("/sys/fs/cgroup/unified") ? "/sys/fs/cgroup/unified" : "/sys/fs/cgroup";
  const bool pure_v2 = mount == "/sys/fs/cgroup" && access("/sys/fs/cgroup/cgroup.controllers", F_OK) == 0;
  if (const std::string missing = lacking(read_text(mount + "/cgroup.controllers"), {"memory", "pids"}); !missing.empty()) {
    if (pure_v2) found.why = "this kernel's cgroup v2 has no " + missing + " controller";
    return false;  // hybrid: v2 holds no controller, v1 has them
  }
  const std::string own = own_group("");
  const std::string mine = "/raycam-check-" + std::to_string(getpid());
  std::string parent = mount + mine;  // as root, beside everything else
  if (mkdir(parent.c_str(), 0755) == 0) {
    static const std::string made = parent;  // removed at exit (its runs' folders are gone by then)
    std::atexit([] { rmdir(made.c_str()); });
    if (!write_text(parent + "/cgroup.subtree_control", "+memory +pids")) {
      found.why = "cannot enable memory and pids in " + parent + ": " + std::strerror(errno);
      return false;
    }
    write_text(parent + "/cgroup.subtree_control", "+cpu");  // optional: cpu.stat's usage is there without it
    found.v2 = true;
    found.parents = {parent};
    return true;
  }
  const std::string group = mount + (own == "/" ? "" : own);
  // Inside the leaf another check made for itself (a grader's test, or a script, running `raycam-cli check`):
  // its runs' parent, controllers already on, is this one's too; this process already sits beside the runs.
  const std::size_t slash = own.rfind('/');
  if (slash != std::string::npos && own.compare(slash, 14, "/raycam-check-") == 0) {
    const std::string shared = mount + own.substr(0, slash);
    if (writable_group(shared) && lacking(read_text(shared + "/cgroup.subtree_control"), {"memory", "pids"}).empty()) {
      found.v2 = true;
      found.parents = {shared};
      return true;
    }
  }
  const std::string shown = own.empty() ? "/" : own;
  if (!writable_group(group)) {
    found.why = "this user (" + uid_text() + ") cannot write its control group " + shown + " (not delegated to it)";
    return false;
  }
  if (const std::string missing = lacking(read_text(group + "/cgroup.controllers"), {"memory", "pids"}); !missing.empty()) {
    found.why = "the controllers " + missing + " are not delegated to its control group " + shown +
                " (missing from its cgroup.controllers: its parent's cgroup.subtree_control does not enable them)";
    return false;
  }
  // Checked before moving: a check that cannot use the group leaves it as it found it.
  int others = 0;
  const std::string named = other_processes(group, others);
  if (others > 0) {
    found.why = "its control group " + shown + " holds " + std::to_string(others) +
                (others == 1 ? " other process (" : " other processes (") + named +
                "): cgroup v2 enables controllers only in a group holding no process, and check moves only itself";
    return false;
  }
  const std::string leaf = group + mine;
  if (mkdir(leaf.c_str(), 0755) != 0 && errno != EEXIST) {
    found.why = "cannot make " + leaf + ": " + std::strerror(errno);
    return false;
  }
  if (!write_text(leaf + "/cgroup.procs", "0") || !write_text(group + "/cgroup.subtree_control", "+memory +pids")) {
    found.why = "cannot move into " + leaf + " and enable memory and pids in " + shown + ": " + std::strerror(errno);
    write_text(group + "/cgroup.procs", "0");  // back where it was, and no trace left
    rmdir(leaf.c_str());
    return false;
  }
  write_text(group + "/cgroup.subtree_control", "+cpu");
  found.v2 = true;
  found.parents = {group};
  return true;
}

// cgroup v1: a folder under this process's own group in each of the memory, pids and cpuacct hierarchies.
bool find_v1(Hierarchy& found) {
  for (const char* controller : kV1Controllers) {
    const std::string own = own_group(controller);
    const std::string parent = "/sys/fs/cgroup/" + std::string(controller) + (own == "/" ? "" : own);
    if (!is_directory(parent)) {
      found.why = "cgroup v1 has no " + std::string(controller) + " hierarchy mounted";
      return false;
    }
    if (access(parent.c_str(), W_OK) != 0) {
      found.why = "this user (" + uid_text() + ") cannot write its cgroup v1 group " + parent + " (not delegated to it)";
      return false;
    }
    found.parents.push_back(parent);
  }
  return true;
}

// The number in a stale-looking name: "raycam-run-PID-N" or "raycam-check-PID" (0 for any other name).
long checker_pid_in(const std::string& name) {
  for (const char* prefix : {"raycam-run-", "raycam-check-"}) {
    const std::size_t n = std::strlen(prefix);
    if (name.compare(0, n, prefix) == 0) return std::atol(name.c_str() + n);
  }
  return 0;
}

// Groups a check made and could not remove (killed by SIGKILL: no exit handler ran): under `folder`, those
// named after a checker pid that no longer runs, their own run groups first; what is left in them is killed.
void sweep_stale_groups(const std::string& folder) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const long pid = checker_pid_in(entry.path().filename().string());
    if (pid <= 0 || pid == long(getpid()) || !entry.is_directory(error) || kill(pid_t(pid), 0) == 0 || errno != ESRCH)
      continue;
    std::vector<std::string> stale;
    for (const auto& inner : std::filesystem::directory_iterator(entry.path(), error))
      if (inner.is_directory(error) && checker_pid_in(inner.path().filename().string()) > 0)
        stale.push_back(inner.path().string());
    stale.push_back(entry.path().string());
    remove_run_group(stale);
  }
}

const Hierarchy& hierarchy() {
  static const Hierarchy found = [] {
    Hierarchy h;
    if (find_v2(h)) {
      sweep_stale_groups(h.parents[0]);
      sweep_stale_groups(std::filesystem::path(h.parents[0]).parent_path().string());  // root's: beside its own
      return h;
    }
    const std::string v2_why = h.why;  // empty where v2 is not this machine's hierarchy
    h = Hierarchy{};
    if (find_v1(h)) {
      for (const std::string& parent : h.parents) sweep_stale_groups(parent);
      return h;
    }
    const std::string v1_why = h.why;
    h = Hierarchy{};
    // One line: what is missing, and what to type. systemd-run's scope is a group of the command's own;
    // -p Delegate=yes hands it (and memory, pids) to the user: without it nothing is delegated.
    h.why = v2_why.empty()
                ? "no control group can be made here: " + v1_why +
                      "; run check as root, or chown a group of cgroup v1's memory, pids and cpuacct to this user"
                : "no control group can be made here: " + v2_why +
                      "; run check as root, or as the only process of a delegated group: "
                      "systemd-run --user --scope -p Delegate=yes raycam-cli check ...";
    return h;
  }();
  return found;
}
}  // namespace

bool run_groups_available(std::string& why) {
  why = hierarchy().why;
  return why.empty();
}

bool join_run_group(const std::vector<int>& fds) {
  for (int fd : fds)
    if (write(fd, "0", 1) != 1) return false;
  return true;
}

// ---- one run's group -------------------------------------------------------------------------------------------
std::unique_ptr<RunGroup> RunGroup::create(const GroupLimits& limits, std::string& why) {
  const Hierarchy& h = hierarchy();
  if (!h.why.empty()) {
    why = h.why;
    return nullptr;
  }
  static std::atomic<unsigned> counter{0};
  const std::string name = "/raycam-run-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
  std::unique_ptr<RunGroup> group(new RunGroup);
  group->v2_ = h.v2;
  for (const std::string& parent : h.parents) {
    const std::string folder = parent + name;
    if (mkdir(folder.c_str(), 0755) != 0) {
      why = "cannot make the control group " + folder + ": " + std::strerror(errno);
      return nullptr;
    }
    group->folders_.push_back(folder);
  }
  const std::string memory = std::to_string(limits.memory_bytes), processes = std::to_string(limits.max_processes);
  const std::string& first = group->folders_[0];
  const bool limited =
      h.v2 ? write_text(first + "/memory.max", memory) && write_text(first + "/pids.max", processes)
           : write_text(first + "/memory.limit_in_bytes", memory) &&
                 write_text(group->folders_[1] + "/pids.max", processes);
  if (!limited) {
    why = "cannot set the bounds of the control group " + first + ": " + std::strerror(errno);
    return nullptr;
  }
  // No swap either (where the machine has it): the bound is on memory, not on what fits in memory and swap.
  if (h.v2) write_text(first + "/memory.swap.max", "0");
  else write_text(first + "/memory.memsw.limit_in_bytes", memory);
  for (const std::string& folder : group->folders_) {
    const int fd = open((folder + "/cgroup.procs").c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
      why = "cannot open " + folder + "/cgroup.procs: " + std::strerror(errno);
      return nullptr;
    }
    group->join_fds_.push_back(fd);
  }
  return group;
}

RunGroup::~RunGroup() {
  for (int fd : join_fds_) close(fd);
  remove_run_group(folders_);
}

void RunGroup::kill_all() const { kill_members(folders_); }

void remove_run_group(const std::vector<std::string>& folders) {
  kill_members(folders);
  // A killed process leaves its group a moment later (its exit runs after the signal): retry for a while.
  for (const std::string& folder : folders)
    for (int attempt = 0; attempt < 1000 && rmdir(folder.c_str()) != 0 && errno == EBUSY; ++attempt) usleep(1000);
}

double RunGroup::cpu_seconds() const {
  if (v2_) return double(keyed_value(read_text(folders_[0] + "/cpu.stat"), "usage_usec")) * 1e-6;
  return double(number_in(folders_[2] + "/cpuacct.usage")) * 1e-9;
}

GroupUsage RunGroup::usage() const {
  GroupUsage usage;
  usage.cpu_seconds = cpu_seconds();
  const std::string& memory = folders_[0];
  const std::string& pids = folders_[v2_ ? 0 : 1];
  usage.process_limit_hit = keyed_value(read_text(pids + "/pids.events"), "max") > 0;
  if (access((pids + "/pids.peak").c_str(), R_OK) == 0) usage.peak_processes = number_in(pids + "/pids.peak");
  if (v2_) {
    usage.peak_memory_bytes = number_in(memory + "/memory.peak");
    usage.memory_limit_hit = keyed_value(read_text(memory + "/memory.events"), "oom_kill") > 0;
  } else {
    usage.peak_memory_bytes = number_in(memory + "/memory.max_usage_in_bytes");
    const long long killed = keyed_value(read_text(memory + "/memory.oom_control"), "oom_kill");
    usage.memory_limit_hit = killed >= 0 ? killed > 0 : number_in(memory + "/memory.failcnt") > 0;
  }
  return usage;
}

}  // namespace raycam::check
