// Key presses, releases and typed characters that arrive between two frames, spread over frames. Dear ImGui
// 1.86 reads a key's state once a frame (io.KeysDown), so a key pressed and released between two frames was
// never seen: a quick BackSpace or Return in a text field was lost about half the time. A host forwards an
// event at once when nothing is waiting, and otherwise holds it; held events go in arrival order, each key
// changing at most once a frame, and a character never overtakes the keys typed before it ("12", BackSpace,
// BackSpace, "5" gives "5", not "1").
// Mouse buttons go through it too, as keys: ImGui ignores a text field's keys in the frame its click activates
// it (ActiveIdIsJustActivated), so a Ctrl+A or Home that arrived with the click was dropped (the path typed
// next was spliced into the old one); and two clicks in one frame were one click, never a double-click. A
// click's release is held to the next frame, and what came after it with it.
// And a chord is seen whole: xdotool's Ctrl+A is Ctrl down, A down, Ctrl up, A up, and with A down and Ctrl up
// in one frame ImGui saw a plain A (3 Ctrl+A in 20 lost under Xvfb at 3×): a modifier (Ctrl, Shift, Alt,
// Super) changes in a frame only before any other key is pressed in it.
#pragma once

#include <algorithm>
#include <vector>

namespace raycam::ui {

class KeyEventQueue {
 public:
  struct Event {
    int key = -1;               // a key event: the key; -1 for a character or a mouse button
    bool press = false;         // a key or button event: pressed or released
    unsigned int character = 0; // a character event: its code point
    int button = -1;            // a mouse button event: the button (0 left); -1 otherwise
    bool modifier = false;      // a key event of Ctrl, Shift, Alt or Super
  };
  // A key event from the window system: true to forward it now, false when it is held for a later frame.
  // `modifier`: the key is Ctrl, Shift, Alt or Super (the host knows its key numbers).
  bool arrive(int key, bool press, bool modifier = false) { return arrive(Event{key, press, 0, -1, modifier}); }
  // A typed character: the same.
  bool arrive_character(unsigned int character) { return arrive(Event{-1, false, character}); }
  // A mouse button pressed or released: the same.
  bool arrive_button(int button, bool press) { return arrive(Event{-1, press, 0, button}); }

  // At the start of a frame, before the window system's events: the held events to forward now, in order,
  // up to the first that would change a key (or a button) a second time in this frame.
  std::vector<Event> start_frame() {
    changed_.clear();
    pressed_key_ = false;
    std::vector<Event> now;
    std::size_t taken = 0;
    for (; taken < held_.size(); ++taken) {
      const Event& e = held_[taken];
      if (must_wait(e)) break;
      note(e);
      now.push_back(e);
    }
    held_.erase(held_.begin(), held_.begin() + std::ptrdiff_t(taken));
    return now;
  }
  // Events are waiting: the host must draw another frame, even if nothing else happens.
  bool holding() const { return !held_.empty(); }

 private:
  static constexpr int kFirstButtonId = 1 << 20;  // past every key number: buttons share the key bookkeeping
  static bool changes_a_key(const Event& e) { return e.key >= 0 || e.button >= 0; }
  static int id_of(const Event& e) { return e.button >= 0 ? kFirstButtonId + e.button : e.key; }
  bool arrive(const Event& e) {
    if (held_.empty() && !must_wait(e)) {
      note(e);
      return true;
    }
    held_.push_back(e);
    return false;
  }
  // `e` would change a key or button a second time in this frame, or a modifier after another key's press.
  bool must_wait(const Event& e) const {
    return (changes_a_key(e) && changed(id_of(e))) || (e.modifier && pressed_key_);
  }
  void note(const Event& e) {  // `e` goes to ImGui in this frame
    if (changes_a_key(e)) changed_.push_back(id_of(e));
    if (e.key >= 0 && e.press && !e.modifier) pressed_key_ = true;
  }
  bool changed(int id) const { return std::find(changed_.begin(), changed_.end(), id) != changed_.end(); }
  std::vector<int> changed_;  // keys and buttons whose state changed since the last frame started
  bool pressed_key_ = false;  // a key other than a modifier was pressed in this frame
  std::vector<Event> held_;
};

}  // namespace raycam::ui
