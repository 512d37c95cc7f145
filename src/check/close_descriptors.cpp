#include "close_descriptors.h"

#include <unistd.h>

namespace raycam::check {

void close_descriptors_from(int first) { close_range(unsigned(first), ~0U, 0); }

}  // namespace raycam::check
