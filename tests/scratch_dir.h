// A folder of its own under the system's temporary folder, removed when the test is done: the tests write
// nowhere else (never the current folder, never the source tree). CTest runs test cases as parallel
// processes, so the process id keeps their folders apart.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace raycam::test {

struct ScratchDir {
  std::filesystem::path dir;
  explicit ScratchDir(const std::string& name)
      : dir(std::filesystem::temp_directory_path() / ("raycam-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~ScratchDir() { std::filesystem::remove_all(dir); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  // The path of `file` inside the folder.
  std::string path(const std::string& file) const { return (dir / file).string(); }
};

}  // namespace raycam::test
