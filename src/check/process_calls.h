// The two process calls that running a student's program needs and a page's libc lacks (close_range,
// wait4). Their own file so that a platform without processes (the web page, src/web) builds a stand-in.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>

namespace raycam::check {

// Closing every file descriptor from `first` up, in a forked child before exec (async-signal-safe).
void close_descriptors_from(int first);

// waitpid() that also gives the child's resource usage (its CPU time: the per-process fallback's clock).
pid_t wait_with_usage(pid_t pid, int* status, int options, rusage* usage);

}  // namespace raycam::check
