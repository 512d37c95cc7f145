// A key pressed and released between two frames reaches a text field (KeyEventQueue): Dear ImGui reads the
// keys' state once a frame, so forwarded together the press and release cancel out before the frame reads
// them. Driven through a real ImGui context and InputText, as the GLFW host drives it.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <catch2/catch.hpp>
#include <string>

#include "key_queue.h"

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
