// A key pressed and released between two frames reaches a text field (KeyEventQueue): Dear ImGui reads the
// keys' state once a frame, so forwarded together the press and release cancel out before the frame reads
// them. Driven through a real ImGui context and InputText, as the GLFW host drives it.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <catch2/catch.hpp>
#include <string>

#include "ui/key_queue.h"

using namespace raycam;

namespace {
constexpr int kBackspace = 259, kEnd = 269;  // GLFW's numbers: the hosts' key numbers index io.KeysDown

// A frame with one focused text field, as the window's path boxes are.
void frame(std::string& text) {
  ImGui::NewFrame();
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize({400, 200});
  ImGui::Begin("keys");
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::InputText("##path", &text);
  ImGui::End();
  ImGui::Render();
}

// Sends `events` (key changes and characters) all between the same two frames, forwarded to ImGui as the
// host does (through the queue, or straight), then runs frames until the queue is empty, and returns what a
// focused text field that held "scene.json" (the cursor at its end) holds after.
std::string type_into_field(const std::vector<ui::KeyEventQueue::Event>& events, bool queued) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = {800, 600};
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  io.KeyMap[ImGuiKey_Backspace] = kBackspace;
  io.KeyMap[ImGuiKey_End] = kEnd;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  std::string text = "scene.json";
  ui::KeyEventQueue queue;
  frame(text);
  frame(text);  // focused, its text selected whole
  io.KeysDown[kEnd] = true;  // End, held over a frame: the cursor at the end, nothing selected
  frame(text);
  io.KeysDown[kEnd] = false;
  frame(text);
  const auto forward = [&](const ui::KeyEventQueue::Event& e) {
    if (e.key >= 0) io.KeysDown[e.key] = e.press;
    else io.AddInputCharacter(e.character);
  };
  for (const ui::KeyEventQueue::Event& e : events) {
    const bool now = !queued || (e.key >= 0 ? queue.arrive(e.key, e.press) : queue.arrive_character(e.character));
    if (now) forward(e);
  }
  for (int frames = 0; frames < 4 * int(events.size()) + 2; ++frames) {
    frame(text);
    for (const ui::KeyEventQueue::Event& e : queue.start_frame()) forward(e);  // the host, before its events
  }
  ImGui::DestroyContext(context);
  return text;
}

std::vector<ui::KeyEventQueue::Event> backspace_taps(int taps) {
  std::vector<ui::KeyEventQueue::Event> events;
  for (int tap = 0; tap < taps; ++tap) {
    events.push_back({kBackspace, true, 0});
    events.push_back({kBackspace, false, 0});
  }
  return events;
}
}  // namespace

TEST_CASE("a key pressed and released between two frames reaches the text field", "[ui][keys]") {
  CHECK(type_into_field(backspace_taps(5), true) == "scene");
  // Forwarded straight, the press and release cancel out before the frame reads the keys: the bug it fixes.
  CHECK(type_into_field(backspace_taps(5), false) == "scene.json");
}

TEST_CASE("characters typed after quick keys do not overtake them", "[ui][keys]") {
  // "12", BackSpace, BackSpace, "5", all between two frames: the field ends in "5" (a character let through
  // at once would be typed before the BackSpaces run, which would then delete it: "scene.json1").
  std::vector<ui::KeyEventQueue::Event> events = {{-1, false, '1'}, {-1, false, '2'}};
  for (const ui::KeyEventQueue::Event& e : backspace_taps(2)) events.push_back(e);
  events.push_back({-1, false, '5'});
  CHECK(type_into_field(events, true) == "scene.json5");
}

TEST_CASE("the key queue lets each key change once a frame, in order", "[ui][keys]") {
  ui::KeyEventQueue queue;
  CHECK(queue.arrive(1, true));
  CHECK(queue.arrive(2, false));  // another key: its own first change
  CHECK_FALSE(queue.arrive(1, false));
  CHECK_FALSE(queue.arrive(1, true));
  CHECK(queue.holding());
  std::vector<ui::KeyEventQueue::Event> now = queue.start_frame();
  REQUIRE(now.size() == 1);
  CHECK((now[0].key == 1 && !now[0].press));
  CHECK_FALSE(queue.arrive(1, false));  // key 1 changed this frame already: after the held press
  now = queue.start_frame();
  REQUIRE(now.size() == 1);
  CHECK((now[0].key == 1 && now[0].press));
  now = queue.start_frame();
  REQUIRE(now.size() == 1);
  CHECK((now[0].key == 1 && !now[0].press));
  CHECK_FALSE(queue.holding());
  CHECK(queue.start_frame().empty());
  CHECK(queue.arrive(1, true));
}

// ---- keys and clicks together (xdotool: click, then Ctrl+A or Home, then the new path) ----
namespace {
constexpr int kHome = 268, kControl = 341, kA = 65;  // GLFW's numbers

struct ClickedField {
  ImVec2 low, high;  // where the field is, from the frame before the events
};

// A frame with one text field that is not focused until it is clicked, as the window's path boxes are.
void unfocused_frame(std::string& text, ClickedField& field) {
  ImGui::NewFrame();
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize({400, 200});
  ImGui::Begin("keys");
  ImGui::InputText("##path", &text);
  field = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
  ImGui::End();
  ImGui::Render();
}

// The field holds `before`; `events` (keys, characters and left-button changes with the mouse over the field at
// `click_at` characters into the text) arrive between two frames (or more: next_frame()), forwarded as the
// GLFW host does: through
// the queue, or straight. ImGui's GLFW backend keeps a press for one frame and otherwise reads the button's
// state as it is now (so a whole click seen by the frame is one frame down). Returns the field's text after.
std::string edit_after_click(const std::string& before, const char* click_at,
                             const std::vector<ui::KeyEventQueue::Event>& events, bool queued) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = {800, 600};
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  io.KeyMap[ImGuiKey_Home] = kHome;
  io.KeyMap[ImGuiKey_End] = kEnd;
  io.KeyMap[ImGuiKey_A] = kA;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  std::string text = before;
  ClickedField field;
  bool button_down = false, just_pressed = false;
  const auto frame = [&] {
    io.MouseDown[0] = just_pressed || button_down;
    just_pressed = false;
    unfocused_frame(text, field);
  };
  frame();
  frame();
  io.MousePos = {field.low.x + ImGui::GetStyle().FramePadding.x + ImGui::CalcTextSize(click_at).x,
                 0.5f * (field.low.y + field.high.y)};
  frame();
  ui::KeyEventQueue queue;
  const auto forward = [&](const ui::KeyEventQueue::Event& e) {
    if (e.key >= 0) {
      io.KeysDown[e.key] = e.press;
      io.KeyCtrl = io.KeysDown[kControl];  // as the backend does
    } else if (e.button >= 0) {
      just_pressed |= e.press;
    } else {
      io.AddInputCharacter(e.character);
    }
  };
  for (const ui::KeyEventQueue::Event& e : events) {
    if (e.key < 0 && e.button < 0 && e.character == 0) {  // next_frame()
      frame();
      for (const ui::KeyEventQueue::Event& held : queue.start_frame()) forward(held);
      continue;
    }
    if (e.button >= 0) button_down = e.press;  // the window system's state, whatever was forwarded
    const bool now = !queued || (e.key >= 0      ? queue.arrive(e.key, e.press, e.modifier)
                                 : e.button >= 0 ? queue.arrive_button(e.button, e.press)
                                                 : queue.arrive_character(e.character));
    if (now) forward(e);
  }
  for (int frames = 0; frames < 4 * int(events.size()) + 2; ++frames) {
    frame();
    for (const ui::KeyEventQueue::Event& e : queue.start_frame()) forward(e);
  }
  ImGui::DestroyContext(context);
  return text;
}

using Events = std::vector<ui::KeyEventQueue::Event>;
Events click() { return {{-1, true, 0, 0}, {-1, false, 0, 0}}; }
Events tap(int key) { return {{key, true, 0}, {key, false, 0}}; }
Events chord(int modifier, int key) {
  return {{modifier, true, 0, -1, true}, {key, true, 0}, {key, false, 0}, {modifier, false, 0, -1, true}};
}
// xdotool's order: the modifier is released before the key.
Events xdotool_chord(int modifier, int key) {
  return {{modifier, true, 0, -1, true}, {key, true, 0}, {modifier, false, 0, -1, true}, {key, false, 0}};
}
Events next_frame() { return {{-1, false, 0, -1}}; }
Events typed(const char* text) {
  Events events;
  for (const char* c = text; *c; ++c) events.push_back({-1, false, static_cast<unsigned char>(*c)});
  return events;
}
Events operator+(Events a, const Events& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
}  // namespace

TEST_CASE("Ctrl+A, Home and a double-click that arrive with the click that focuses a field are not lost",
          "[ui][keys]") {
  const std::string old_path = "old/scene.json";
  // Click in the middle of the old path, Ctrl+A, the new path: replaced whole.
  CHECK(edit_after_click(old_path, "old/sc", click() + chord(kControl, kA) + typed("new.json"), true) == "new.json");
  // Click, Home, a prefix: at the start.
  CHECK(edit_after_click(old_path, "old/sc", click() + tap(kHome) + typed("../"), true) == "../old/scene.json");
  // Two clicks on a word: the word selected, then replaced.
  CHECK(edit_after_click("alpha beta", "alpha be", click() + click() + typed("gamma"), true) == "alpha gamma");
  // Forwarded straight, ImGui drops the keys of the frame whose click focuses the field (the new path was
  // spliced into the old one) and two presses in one frame are one click: the bugs the queue fixes.
  CHECK(edit_after_click(old_path, "old/sc", click() + chord(kControl, kA) + typed("new.json"), false) ==
        "old/scnew.jsonene.json");
  CHECK(edit_after_click(old_path, "old/sc", click() + tap(kHome) + typed("../"), false) == "old/sc../ene.json");
  CHECK(edit_after_click("alpha beta", "alpha be", click() + click() + typed("gamma"), false) == "alpha begammata");
}

TEST_CASE("a chord whose modifier is released before its key, in the frame the key went down, is seen whole",
          "[ui][keys]") {
  // The walk's trace: Ctrl down in one frame; A down, Ctrl up, A up and the new path in the next.
  const Events chord = xdotool_chord(kControl, kA);
  const Events ctrl_down = {chord[0]}, rest(chord.begin() + 1, chord.end());
  const Events walk = click() + next_frame() + ctrl_down + next_frame() + rest + typed("new.json");
  CHECK(edit_after_click("old/scene.json", "old/sc", walk, true) == "new.json");
  // Forwarded straight (or without the modifier rule), the frame saw A down with Ctrl up: a plain A, the
  // new path spliced into the old one.
  CHECK(edit_after_click("old/scene.json", "old/sc", walk, false) == "old/scnew.jsonene.json");
  // All in one frame, too.
  CHECK(edit_after_click("old/scene.json", "old/sc", click() + xdotool_chord(kControl, kA) + typed("x"), true) == "x");
}
