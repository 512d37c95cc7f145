// Key presses and releases that arrive between two frames, spread over frames. Dear ImGui 1.86 reads a key's
// state once a frame (io.KeysDown), so a key pressed and released between two frames was never seen: a
// quick BackSpace or Return in a text field was lost about half the time. A host forwards a key's first
// change since the last frame at once and holds its later changes, in order, one per frame.
#pragma once

#include <algorithm>
#include <vector>

namespace raycam::ui {

class KeyEventQueue {
 public:
  struct Event {
    int key;
    bool press;
  };
  // A key event from the window system: true to forward it now, false when it is held for a later frame.
  bool arrive(int key, bool press) {
    if (!changed(key) && !waiting(key)) {
      changed_.push_back(key);
      return true;
    }
    held_.push_back({key, press});
    return false;
  }
  // At the start of a frame, before the window system's events: the held events to forward now (each key's
  // earliest); the others wait for the next frame.
  std::vector<Event> start_frame() {
    changed_.clear();
    std::vector<Event> now, later;
    for (const Event& e : held_) {
      if (changed(e.key)) {
        later.push_back(e);
      } else {
        changed_.push_back(e.key);
        now.push_back(e);
      }
    }
    held_ = std::move(later);
    return now;
  }
  // Events are waiting: the host must draw another frame, even if nothing else happens.
  bool holding() const { return !held_.empty(); }

 private:
  bool changed(int key) const { return std::find(changed_.begin(), changed_.end(), key) != changed_.end(); }
  bool waiting(int key) const {
    return std::any_of(held_.begin(), held_.end(), [key](const Event& e) { return e.key == key; });
  }
  std::vector<int> changed_;  // keys whose state changed since the last frame started
  std::vector<Event> held_;
};

}  // namespace raycam::ui
