// Key presses, releases and typed characters that arrive between two frames, spread over frames. Dear ImGui
// 1.86 reads a key's state once a frame (io.KeysDown), so a key pressed and released between two frames was
// never seen: a quick BackSpace or Return in a text field was lost about half the time. A host forwards an
// event at once when nothing is waiting, and otherwise holds it; held events go in arrival order, each key
// changing at most once a frame, and a character never overtakes the keys typed before it ("12", BackSpace,
// BackSpace, "5" gives "5", not "1").
#pragma once

#include <algorithm>
#include <vector>

namespace raycam::ui {

class KeyEventQueue {
 public:
  struct Event {
    int key = -1;               // a key event: the key; -1 for a character
    bool press = false;         // a key event: pressed or released
    unsigned int character = 0; // a character event: its code point
  };
  // A key event from the window system: true to forward it now, false when it is held for a later frame.
  bool arrive(int key, bool press) { return arrive(Event{key, press, 0}); }
  // A typed character: the same.
  bool arrive_character(unsigned int character) { return arrive(Event{-1, false, character}); }

  // At the start of a frame, before the window system's events: the held events to forward now, in order,
  // up to the first that would change a key a second time in this frame.
  std::vector<Event> start_frame() {
    changed_.clear();
    std::vector<Event> now;
    std::size_t taken = 0;
    for (; taken < held_.size(); ++taken) {
      const Event& e = held_[taken];
      if (e.key >= 0 && changed(e.key)) break;
      if (e.key >= 0) changed_.push_back(e.key);
      now.push_back(e);
    }
    held_.erase(held_.begin(), held_.begin() + std::ptrdiff_t(taken));
    return now;
  }
  // Events are waiting: the host must draw another frame, even if nothing else happens.
  bool holding() const { return !held_.empty(); }

 private:
  bool arrive(const Event& e) {
    if (held_.empty() && (e.key < 0 || !changed(e.key))) {
      if (e.key >= 0) changed_.push_back(e.key);
      return true;
    }
    held_.push_back(e);
    return false;
  }
  bool changed(int key) const { return std::find(changed_.begin(), changed_.end(), key) != changed_.end(); }
  std::vector<int> changed_;  // keys whose state changed since the last frame started
  std::vector<Event> held_;
};

}  // namespace raycam::ui
