#include "check/process_calls.h"

#include <sys/wait.h>
#include <unistd.h>

namespace raycam::check {

void close_descriptors_from(int first) { close_range(unsigned(first), ~0U, 0); }

pid_t wait_with_usage(pid_t pid, int* status, int options, rusage* usage) {
  return wait4(pid, status, options, usage);
}

}  // namespace raycam::check
