#include "check/sandbox_policy.h"

#include <filesystem>

#include "check/shown_folders.h"

namespace raycam::check {

namespace fs = std::filesystem;

namespace {
// What a program needs from the system and nothing else: its programs and libraries (/usr and the root's
// links into it) and the few /etc files the dynamic loader and interpreters read. Not /opt: it holds
// other people's software and, on shared servers, other people's folders.
const char* const kSystemFolders[] = {"/usr"};
const char* const kRootLinks[] = {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};
const char* const kEtcFiles[] = {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives",
                                 "/etc/localtime", "/etc/mime.types"};

void add(std::vector<std::string>& words, std::initializer_list<std::string> more) {
  words.insert(words.end(), more.begin(), more.end());
}
}  // namespace

std::vector<std::string> bwrap_arguments(const SandboxPolicy& policy, const std::vector<std::string>& argv) {
  std::vector<std::string> words = {policy.bwrap};
  for (const std::string& path : policy.system) add(words, {"--ro-bind", path, path});
  for (const auto& [target, link] : policy.links) add(words, {"--symlink", target, link});
  add(words, {"--dev", "/dev", "--proc", "/proc", "--tmpfs", "/tmp"});
  for (const std::string& dir : policy.hidden) add(words, {"--tmpfs", dir});
  for (const std::string& dir : policy.shown)
    if (dir != "/") add(words, {"--ro-bind", dir, dir});
  add(words, {"--perms", "0555", "--file", std::to_string(kShimFd), kShimInSandbox});
  if (policy.filtered) add(words, {"--seccomp", std::to_string(kFilterFd)});
  add(words, {"--info-fd", std::to_string(kInfoFd), "--block-fd", std::to_string(kBlockFd)});
  add(words, {"--size", std::to_string(policy.disk_bytes), "--tmpfs", policy.work});
  add(words, {"--remount-ro", "/tmp", "--remount-ro", "/dev", "--unshare-all", "--unshare-user",
              "--disable-userns", "--uid", "65534", "--gid", "65534", "--die-with-parent", "--new-session",
              "--chdir", policy.work, "--", kShimInSandbox, std::to_string(kCheckpointFd)});
  words.insert(words.end(), argv.begin(), argv.end());
  return words;
}

std::vector<std::string> canonical_paths(std::vector<std::string> argv) {
  for (std::string& word : argv) {
    std::error_code error;
    if (word.rfind('/', 0) != 0 || !fs::exists(word, error)) continue;
    const fs::path real = fs::canonical(word, error);
    if (!error) word = real.string();
  }
  return argv;
}

SandboxPolicy sandbox_policy(const std::string& bwrap, const std::vector<std::string>& hidden,
                             const std::vector<std::string>& shown, const std::vector<std::string>& argv,
                             const std::string& work, long long disk_bytes) {
  SandboxPolicy policy;
  policy.bwrap = bwrap;
  std::error_code error;
  for (const char* folder : kSystemFolders)
    if (fs::exists(folder, error)) policy.system.push_back(folder);
  for (const char* link : kRootLinks) {
    if (fs::is_symlink(link, error))  // merged /usr: /bin -> usr/bin
      policy.links.emplace_back(fs::read_symlink(link, error).string(), link);
    else if (fs::is_directory(link, error))
      policy.system.push_back(link);
  }
  for (const char* file : kEtcFiles)
    if (fs::exists(file, error)) policy.system.push_back(file);
  for (const std::string& dir : hidden) policy.hidden.push_back(fs::weakly_canonical(dir, error).string());
  std::vector<std::string> folders = shown;
  for (const std::string& dir : folders_named(canonical_paths(argv))) folders.push_back(dir);
  for (const std::string& dir : folders) {
    const std::string real = fs::weakly_canonical(dir, error).string();
    bool seen = false;
    for (const std::string& known : policy.shown) seen |= known == real;
    if (!seen) policy.shown.push_back(real);
  }
  policy.work = work;
  policy.disk_bytes = disk_bytes;
  return policy;
}

}  // namespace raycam::check
