// The page has no processes (fork() fails there before a child could call this), and its libc has no
// close_range: a stand-in for src/check/close_descriptors.cpp.
#include "close_descriptors.h"

namespace raycam::check {

void close_descriptors_from(int) {}

}  // namespace raycam::check
