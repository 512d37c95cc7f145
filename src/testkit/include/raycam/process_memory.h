// This process's memory, as /proc/self/status reports it: for the soak and the benchmarks' peak figures.
#pragma once

#include <fstream>
#include <string>

namespace raycam::testkit {

// A field such as "VmRSS:" (resident now) or "VmHWM:" (peak resident), in kB; -1 when it cannot be read.
inline long resident_kb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field, 0) == 0) return std::stol(line.substr(std::string(field).size()));
  return -1;
}

}  // namespace raycam::testkit
