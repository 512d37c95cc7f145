#include "shown_files.h"

#include <filesystem>

namespace raycam::session {

std::string shown_file_name(const HostCapabilities& host, const std::string& path) {
  if (!host.files_are_downloads) return path;
  const std::string name = std::filesystem::path(path).filename().string();
  return name.empty() ? path : name;
}

std::string with_file_shown(const HostCapabilities& host, std::string text, const std::string& path) {
  const std::string shown = shown_file_name(host, path);
  if (path.empty() || shown == path) return text;
  for (std::size_t at = text.find(path); at != std::string::npos; at = text.find(path, at + shown.size()))
    text.replace(at, path.size(), shown);
  return text;
}

std::string named_after_scene(const Lesson& state, const std::string& suffix) {
  const std::string& path = scene_path(state);
  if (path.empty()) return "raycam-demo-" + std::to_string(dimension(state)) + "d" + suffix;
  return std::filesystem::path(path).stem().string() + suffix;
}

}  // namespace raycam::session
