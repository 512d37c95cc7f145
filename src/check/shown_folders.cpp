#include "check/shown_folders.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace raycam::check {

namespace fs = std::filesystem;

namespace {
// Whether `inner` is `outer` or inside it (both absolute, compared by components after normalising).
bool inside(const fs::path& inner, const fs::path& outer) {
  const fs::path a = inner.lexically_normal(), b = outer.lexically_normal();
  auto i = a.begin();
  for (auto o = b.begin(); o != b.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == a.end() || *i != *o) return false;
  }
  return true;
}
}  // namespace

std::vector<std::string> folders_named(const std::vector<std::string>& argv) {
  std::vector<std::string> folders;
  for (const std::string& word : argv) {
    std::error_code error;
    if (word.rfind('/', 0) == 0 && fs::exists(word, error) && word.rfind("/usr/", 0) != 0)
      folders.push_back(fs::is_directory(word, error) ? word : fs::path(word).parent_path().string());
  }
  return folders;
}

void refuse_exposed_folders(const std::vector<std::string>& shown, const std::string& home,
                            const std::vector<std::string>& protected_paths, const std::string& flag) {
  for (const std::string& folder : shown) {
    const fs::path dir = fs::weakly_canonical(folder);
    std::string what;
    if (dir == dir.root_path()) what = "the whole machine (/)";
    else if (!home.empty() && inside(fs::weakly_canonical(home), dir)) what = "your home folder " + home + " as a whole";
    for (const std::string& path : protected_paths)
      if (what.empty() && !path.empty() && inside(fs::weakly_canonical(fs::absolute(path)), dir))
        what = "a folder holding " + path;
    if (!what.empty())
      throw std::invalid_argument(flag + ": the command names a file in " + dir.string() +
                                  ", so the sandboxed program would see " + what +
                                  "; give the program a folder of its own (e.g. ~/grading/alice/)");
  }
}

std::string submission_refusal(const std::string& folder, const std::string& root, const std::vector<std::string>& argv) {
  std::error_code error;
  const fs::path name = fs::path(folder).filename();
  if (fs::is_symlink(folder, error))
    return "the submission folder " + name.string() + " is a symbolic link (to " +
           fs::read_symlink(folder, error).string() + "): only real folders inside the batch are graded";
  const fs::path real = fs::canonical(folder, error), real_root = fs::canonical(root, error);
  if (error || !inside(real, real_root))
    return "the submission folder " + name.string() + " leads out of the batch's folder: only real folders inside it are graded";
  for (const std::string& word : argv) {
    if (word.empty() || word[0] != '/' || !inside(fs::path(word), fs::path(folder)) || fs::path(word) == fs::path(folder))
      continue;
    const std::string shown = fs::path(word).lexically_relative(folder).string();
    if (!fs::exists(fs::symlink_status(word, error))) continue;  // missing: the run says so (cannot find)
    const fs::path target = fs::weakly_canonical(word, error);
    if (!inside(target, real))
      return shown + " leads out of the student's folder (to " + target.string() +
             "): a submission's program must be its own files";
    if (&word == &argv[0] && fs::is_directory(target, error)) return shown + " is a folder, not a program";
  }
  return {};
}

std::string unreadable_by_others(const std::string& folder) {
  struct stat info {};
  if (stat(folder.c_str(), &info) != 0 || (info.st_mode & (S_IROTH | S_IXOTH)) != (S_IROTH | S_IXOTH))
    return folder + " is not readable by other users (the sandboxed program has no rights of yours): "
                    "chmod -R o+rX " + folder;
  for (fs::path dir = fs::path(folder).parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
    if (stat(dir.c_str(), &info) != 0 || !(info.st_mode & S_IXOTH))
      return dir.string() + " cannot be crossed by other users (the sandboxed program has no rights of yours): "
                            "chmod o+x " + dir.string();
  return {};
}

std::string launch_hint(const std::vector<std::string>& argv) {
  for (const std::string& word : argv) {
    std::error_code error;
    if (word.find('/') == std::string::npos || !fs::is_regular_file(word, error)) continue;
    std::ifstream in(word, std::ios::binary);
    std::string first_line;
    std::getline(in, first_line);
    if (!first_line.empty() && first_line.back() == '\r')
      return word + " has Windows line ends (CRLF): convert it (dos2unix " + word + ")";
    if (&word == &argv[0] && access(word.c_str(), X_OK) != 0)
      return word + " is not executable (no run bit): chmod +x " + word;
  }
  return {};
}

}  // namespace raycam::check
