// What the session asks of the executable that shows it (only it knows about windows and files of pixels):
// a small queue the host takes its requests from after each frame. A request asked twice before the host
// took it is kept once (the newest screenshot path).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace raycam::session {

enum class HostRequestKind {
  screenshot,         // write the frame to `path` (request_screenshot() picks it)
  toggle_fullscreen,  // F11 or the button
  quit,               // Ctrl+Q
  pick_scene_file,    // the page: the status line's button asks the browser for a scene file
  toggle_recording,   // F9 or the Record button: start recording the window, or stop and save
};

struct HostRequest {
  HostRequestKind kind;
  std::string path;  // screenshot: the file to write
};

class HostRequests {
 public:
  void ask(HostRequestKind kind, std::string path = {}) {
    take(kind);
    queue_.push_back({kind, std::move(path)});
  }
  bool pending(HostRequestKind kind) const { return find(kind) != nullptr; }
  const HostRequest* find(HostRequestKind kind) const {
    const auto found = std::find_if(queue_.begin(), queue_.end(), [&](const HostRequest& r) { return r.kind == kind; });
    return found == queue_.end() ? nullptr : &*found;
  }
  // The host takes a request it handles (nothing if none is waiting).
  std::optional<HostRequest> take(HostRequestKind kind) {
    const auto found = std::find_if(queue_.begin(), queue_.end(), [&](const HostRequest& r) { return r.kind == kind; });
    if (found == queue_.end()) return std::nullopt;
    HostRequest request = std::move(*found);
    queue_.erase(found);
    return request;
  }

 private:
  std::vector<HostRequest> queue_;
};

}  // namespace raycam::session
