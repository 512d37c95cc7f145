#include "check/syscall_filter.h"

#include <sched.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <mutex>

namespace raycam::check {

const std::vector<std::string>& refused_system_calls() {
  static const std::vector<std::string> names = {
      // keyrings: shared by every process of a user, so a run could read or fill the instructor's
      "keyctl", "add_key", "request_key",
      // io_uring: its own path to files and sockets, a frequent source of kernel flaws
      "io_uring_setup", "io_uring_enter", "io_uring_register",
      // namespaces: the run's are set up once; new ones would let it rearrange what it sees
      "unshare", "setns",
      // other processes' memory and the kernel's tracing and programs
      "ptrace", "process_vm_readv", "process_vm_writev", "kcmp", "bpf", "perf_event_open", "userfaultfd",
      // mounts of every kind
      "mount", "umount2", "pivot_root", "move_mount", "open_tree", "fsopen", "fsmount", "fsconfig", "fspick",
      "mount_setattr",
      // the machine's own
      "init_module", "finit_module", "delete_module", "kexec_load", "kexec_file_load", "reboot", "swapon",
      "swapoff", "acct", "syslog", "name_to_handle_at", "open_by_handle_at", "quotactl", "lookup_dcookie"};
  return names;
}

namespace {
// Builds the filter; "" and `why` on failure.
std::string build_program(std::string& why) {
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> context(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!context) {
    why = "libseccomp: seccomp_init failed";
    return {};
  }
  scmp_filter_ctx ctx = context.get();
  // Another ABI's calls (int 0x80, x32) would dodge rules written for the native numbers.
  seccomp_attr_set(ctx, SCMP_FLTATR_ACT_BADARCH, SCMP_ACT_KILL_PROCESS);
  for (const std::string& name : refused_system_calls()) {
    const int number = seccomp_syscall_resolve_name(name.c_str());
    if (number == __NR_SCMP_ERROR) continue;  // a call this kernel's headers do not know
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), number, 0) != 0) {
      why = "libseccomp: cannot refuse " + name;
      return {};
    }
  }
  // clone: threads and forks yes, new namespaces no (the flags are its first argument on x86-64).
  const unsigned long namespaces[] = {CLONE_NEWUSER, CLONE_NEWNS,  CLONE_NEWPID,   CLONE_NEWNET,
                                      CLONE_NEWIPC,  CLONE_NEWUTS, CLONE_NEWCGROUP};
  for (const unsigned long flag : namespaces)
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)) != 0) {
      why = "libseccomp: cannot filter clone's flags";
      return {};
    }
  // clone3 passes its flags in memory, out of a filter's sight: ENOSYS makes libc use clone instead.
  const int clone3 = seccomp_syscall_resolve_name("clone3");
  if (clone3 != __NR_SCMP_ERROR) seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), clone3, 0);
  // Exported through a file in memory (seccomp_export_bpf writes to a descriptor).
  const int fd = memfd_create("raycam-syscall-filter", MFD_CLOEXEC);
  if (fd < 0) {
    why = std::string("cannot hold the filter in memory: ") + std::strerror(errno);
    return {};
  }
  std::string program;
  if (seccomp_export_bpf(ctx, fd) == 0 && lseek(fd, 0, SEEK_SET) == 0) {
    char buffer[4096];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) program.append(buffer, std::size_t(n));
  }
  close(fd);
  if (program.empty()) why = "libseccomp: cannot export the filter";
  return program;
}
}  // namespace

const std::string& syscall_filter_program(std::string& why) {
  static std::string reason;
  static const std::string program = build_program(reason);
  why = reason;
  return program;
}

}  // namespace raycam::check
