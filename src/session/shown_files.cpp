#include "session/shown_files.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "raycam/zip_archive.h"
#include "session/text.h"

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

std::string written_message(const HostCapabilities& host, Language language, const std::string& path) {
  return trf(language, host.files_are_downloads ? "asked the browser to save %s" : "wrote %s",
                 shown_file_name(host, path).c_str());
}

std::string as_one_download(const std::vector<std::string>& files, const std::string& archive_name) {
  std::vector<ZipEntry> entries;
  for (const std::string& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    if (!in || !(bytes << in.rdbuf())) throw std::runtime_error(file + ": cannot read the file");
    entries.push_back({std::filesystem::path(file).filename().string(), bytes.str()});
  }
  const std::filesystem::path folder = files.empty() ? std::filesystem::path(".") : std::filesystem::path(files.front()).parent_path();
  const std::string archive = (folder / archive_name).string();
  write_zip(archive, entries);
  std::error_code ignored;
  for (const std::string& file : files) std::filesystem::remove(file, ignored);
  return archive;
}

std::string named_after_scene(const Lesson& state, const std::string& suffix) {
  const std::string& path = scene_path(state);
  if (path.empty()) return "raycam-demo-" + std::to_string(dimension(state)) + "d" + suffix;
  return std::filesystem::path(path).stem().string() + suffix;
}

namespace {
// The scene's name with the dimension where it does not say it: "raycam-demo-3d", "lesson-2d", "many3d".
std::string export_base(const Lesson& state) {
  const std::string dimension = std::to_string(session::dimension(state)) + "d";
  std::string base = scene_path(state).empty() ? "raycam-demo" : std::filesystem::path(scene_path(state)).stem().string();
  std::string lower = base;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower.size() < dimension.size() || lower.compare(lower.size() - dimension.size(), dimension.size(), dimension) != 0)
    base += "-" + dimension;  // "lesson-3d", but "many3d" as it is
  return base;
}
}  // namespace

std::string default_export_name(const Lesson& state, ExportKind kind) {
  return export_base(state) + (kind == ExportKind::colour_map ? tr(state.language, "-colour-map.png") : "-figure.svg");
}

std::string next_recording_path(const Lesson& state, const std::string& directory) {
  for (int i = 1;; ++i) {
    char number[16];
    std::snprintf(number, sizeof number, "-%03d.mp4", i);
    const std::filesystem::path path =
        std::filesystem::path(directory) / (export_base(state) + tr(state.language, "-recording") + number);
    if (!std::filesystem::exists(path) || i >= 99999) return path.lexically_normal().string();
  }
}

}  // namespace raycam::session
