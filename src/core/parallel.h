// The casters' work sharing lives in the public raycam/parallel.h (the benchmarks use the same pool).
#pragma once

#include "raycam/parallel.h"
