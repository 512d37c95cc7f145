// Files as the student knows them. On the desktop a path is the student's own and is shown whole; in the
// page (HostCapabilities::files_are_downloads) files live in the page's own folders, so a message names a
// file by its name alone, and what the app writes is a download named after the scene.
#pragma once

#include <string>
#include <vector>

#include "session/app_state.h"

namespace raycam::session {

// `path` as a message shows it: the whole path, or in the page its file name.
std::string shown_file_name(const HostCapabilities& host, const std::string& path);

// `text` (a message, an error's reason) with every `path` in it shown as shown_file_name() shows it.
std::string with_file_shown(const HostCapabilities& host, std::string text, const std::string& path);

// What a message says of a file just written: "wrote PATH" on the desktop; in the page "asked the browser to
// save NAME": the page hands the file to the browser, which may ask, or refuse, and never tells the page what
// arrived.
std::string written_message(const HostCapabilities& host, Language language, const std::string& path);

// The page's downloads of several files at once (every construction step's figure): a browser asks before a
// page downloads several files, and drops the later ones while it waits, so in the page they become ONE
// download, a zip archive (stored, raycam/zip_archive.h) named `archive_name` beside the first file; the
// files themselves are removed (only the archive is offered). Returns the archive's path. Throws
// std::runtime_error when a file cannot be read or the archive written.
std::string as_one_download(const std::vector<std::string>& files, const std::string& archive_name);

// A download's name after the scene on screen: "many3d" + suffix ("many3d.json", "many3d.png"); the demo
// scene is "raycam-demo-3d".
std::string named_after_scene(const Lesson& state, const std::string& suffix);

// What an export writes by default, named as the page names its downloads and with the dimension too where
// the scene's name does not say it (2D and 3D never share a name: the 2D bar replaced the 3D map), the
// words in the window's language: "raycam-demo-3d-colour-map.png", "lesson-2d-carte-des-couleurs.png",
// "many3d-figure.svg".
enum class ExportKind { colour_map, figure };
std::string default_export_name(const Lesson& state, ExportKind kind);

// Where the window's next recording goes: the first free "raycam-demo-3d-recording-NNN.mp4" (in French
// "…-enregistrement-NNN.mp4"), NNN from 001, in `directory`: a recording never replaces a file.
std::string next_recording_path(const Lesson& state, const std::string& directory = ".");

}  // namespace raycam::session
