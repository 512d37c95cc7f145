// The page has no processes (fork() fails there before a child could exist), and its libc has neither
// close_range nor wait4: stand-ins for src/check/process_calls.cpp.
#include <cerrno>

#include "process_calls.h"

namespace raycam::check {

void close_descriptors_from(int) {}

pid_t wait_with_usage(pid_t, int*, int, rusage*) {
  errno = ECHILD;  // no child can exist
  return -1;
}

}  // namespace raycam::check
