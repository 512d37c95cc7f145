// The system calls a student's program is refused, in the spirit of Docker's default seccomp profile: what a
// camera program never needs and what reaches past the sandbox's namespaces or the checker's accounting.
// Refused calls fail with EPERM (ENOSYS for clone3, whose flags a filter cannot read: libc then falls back
// to clone, whose flags it can); calls of another architecture's ABI (32-bit, x32) kill the process.
#pragma once

#include <string>
#include <vector>

namespace raycam::check {

// The refused calls, by name: keyrings (keyctl, add_key, request_key: keyrings are not namespaced),
// io_uring, new namespaces (unshare, setns, clone with a CLONE_NEW* flag), ptrace and process_vm_*,
// bpf, perf_event_open, userfaultfd, mounts of every kind, and the machine's own (modules, kexec, reboot,
// swap, acct, syslog, handles to files by number).
const std::vector<std::string>& refused_system_calls();

// The filter compiled to BPF, as bwrap's --seccomp reads it (built once). Empty, with `why`, where
// libseccomp cannot build it.
const std::string& syscall_filter_program(std::string& why);

}  // namespace raycam::check
