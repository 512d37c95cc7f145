// Section index: files of a group · where groups can be made (v2, then v1) · one run's group.
#include "run_group.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
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

// cgroup v2: the root (as root: a folder of this process's own under it, with the controllers on for its
// children) or this process's own group when delegated (then this process moves into a leaf of its own
// beside the runs: v2 lets only leaves hold processes once the controllers are on).
bool find_v2(Hierarchy& found) {
  const std::string mount = is_directory("/sys/fs/cgroup/unified") ? "/sys/fs/cgroup/unified" : "/sys/fs/cgroup";
  const std::string controllers = " " + read_text(mount + "/cgroup.controllers") + " ";
  if (controllers.find(" memory") == std::string::npos || controllers.find(" pids") == std::string::npos) return false;
  const std::string own = own_group("");
  const std::string mine = "/raycam-check-" + std::to_string(getpid());
  std::string parent = mount + mine;  // as root, beside everything else
  if (mkdir(parent.c_str(), 0755) == 0) {
    static const std::string made = parent;  // removed at exit (its runs' folders are gone by then)
    std::atexit([] { rmdir(made.c_str()); });
  } else {
    parent = mount + (own == "/" ? "" : own);
    const std::string leaf = parent + mine;
    if (mkdir(leaf.c_str(), 0755) != 0 && errno != EEXIST) return false;
    if (!write_text(leaf + "/cgroup.procs", "0")) return false;
  }
  if (!write_text(parent + "/cgroup.subtree_control", "+memory +pids")) return false;
  write_text(parent + "/cgroup.subtree_control", "+cpu");  // optional: cpu.stat's usage is there without it
  found.v2 = true;
  found.parents = {parent};
  return true;
}

// cgroup v1: a folder under this process's own group in each of the memory, pids and cpuacct hierarchies.
bool find_v1(Hierarchy& found) {
  for (const char* controller : kV1Controllers) {
    const std::string own = own_group(controller);
    const std::string parent = "/sys/fs/cgroup/" + std::string(controller) + (own == "/" ? "" : own);
    if (!is_directory(parent) || access(parent.c_str(), W_OK) != 0) return false;
    found.parents.push_back(parent);
  }
  return true;
}

const Hierarchy& hierarchy() {
  static const Hierarchy found = [] {
    Hierarchy h;
    if (find_v2(h)) return h;
    h = Hierarchy{};
    if (find_v1(h)) return h;
    h = Hierarchy{};
    h.why = "no control group can be made here (cgroup v2 with memory and pids delegated, or cgroup v1's "
            "memory, pids and cpuacct writable: run as root or in a delegated group, e.g. systemd-run --user "
            "--scope)";
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
