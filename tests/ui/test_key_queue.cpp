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

// Taps BackSpace `taps` times, each press and release between the same two frames, forwarded to ImGui as the
// host does (through the queue, or straight), and returns what the field holds after.
std::string tap_backspace(int taps, bool queued) {
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
  const auto forward = [&](int key, bool press) { io.KeysDown[key] = press; };
  // All the taps between two frames (a fast typist, a slow frame), then frames until the queue is empty.
  for (int tap = 0; tap < taps; ++tap)
    for (bool press : {true, false})
      if (!queued || queue.arrive(kBackspace, press)) forward(kBackspace, press);
  for (int frames = 0; frames < 4 * taps + 2; ++frames) {
    frame(text);
    for (const ui::KeyEventQueue::Event& e : queue.start_frame()) forward(e.key, e.press);  // the host, before its events
  }
  ImGui::DestroyContext(context);
  return text;
}
}  // namespace

TEST_CASE("a key pressed and released between two frames reaches the text field", "[ui][keys]") {
  CHECK(tap_backspace(5, true) == "scene");
  // Forwarded straight, the press and release cancel out before the frame reads the keys: the bug it fixes.
  CHECK(tap_backspace(5, false) == "scene.json");
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
