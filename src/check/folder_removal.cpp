#include "check/folder_removal.h"

#include <sys/stat.h>

#include <filesystem>

namespace raycam::check {

namespace fs = std::filesystem;

namespace {
// Owner rights on every folder under `folder` (and itself), top down: a folder must be readable and crossable
// before its own sub-folders can be reached.
void make_folders_ours(const fs::path& folder) {
  chmod(folder.c_str(), S_IRWXU);
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.is_directory(error) && !entry.is_symlink(error)) make_folders_ours(entry.path());
}
}  // namespace

bool remove_folder_whatever_modes(const std::string& folder) {
  std::error_code error;
  fs::remove_all(folder, error);
  if (!fs::exists(fs::symlink_status(folder, error))) return true;
  make_folders_ours(folder);
  fs::remove_all(folder, error);
  return !fs::exists(fs::symlink_status(folder, error));
}

}  // namespace raycam::check
