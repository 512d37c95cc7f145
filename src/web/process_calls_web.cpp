// The page has no processes (fork() fails there before a child could exist), and its libc has neither
// close_range nor wait4, and no libseccomp: stand-ins for src/check/process_calls.cpp and syscall_filter.cpp.
#include <cerrno>

#include "check/process_calls.h"
#include "check/syscall_filter.h"

namespace raycam::check {

void close_descriptors_from(int) {}

pid_t wait_with_usage(pid_t, int*, int, rusage*) {
  errno = ECHILD;  // no child can exist
  return -1;
}

const std::vector<std::string>& refused_system_calls() {
  static const std::vector<std::string> none;
  return none;
}

const std::string& syscall_filter_program(std::string& why) {
  static const std::string none;
  why = "a page runs no program";
  return none;
}

}  // namespace raycam::check
