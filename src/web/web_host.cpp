#include "web_host.h"

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "camera_check.h"
#include "downloads.h"
#include "raycam/scene_file.h"
#include "text.h"
#include "gl.h"
#include "renderer_backend.h"
#include "scene_loading.h"

namespace raycam::web {

namespace {
struct Page {
  GLFWwindow* window = nullptr;
  session::AppState* state = nullptr;
  WebHost* host = nullptr;
  ui::FrameRenderer* frame = nullptr;
  Downloads* downloads = nullptr;
  std::string downloaded_case;  // the JSON of Check my camera's last case download
};
Page page;

// emscripten 3.1.6's GLFW hands the scroll callback the browser's raw deltaX and deltaY: pixels (or lines, or
// pages), positive downwards, where the desktop's GLFW gives notches, positive upwards. One notch of a mouse
// (100 pixels in Chromium) took d from 8 to its limit, the wrong way. The page listens for the wheel itself:
// notches (100 pixels, 3 lines or a page each), the desktop's signs, and shift+wheel kept vertical (Chromium
// turns it into a horizontal scroll, where the desktop's shift+wheel changes d_f); then ImGui's callback, as
// GLFW would call it (it chains to the wake callback).
void listen_for_the_wheel() {
  EM_ASM({
    const canvas = Module.canvas;
    canvas.removeEventListener('wheel', GLFW.onMouseWheel, true);
    canvas.removeEventListener('mousewheel', GLFW.onMouseWheel, true);
    canvas.addEventListener('wheel', function(event) {
      const per_notch = [100, 3, 1][event.deltaMode] || 100;
      let x = -event.deltaX / per_notch, y = -event.deltaY / per_notch;
      if (event.shiftKey && y === 0) {
        y = x;
        x = 0;
      }
      Module.ccall('raycam_page_wheel', null, ['number', 'number'], [x, y]);
      event.preventDefault();  // the page itself does not scroll
    }, {capture: true, passive: false});
  });
}

ui::FrameLayout last_layout;  // the last frame's, for the browser tests (web_main.cpp)

void tick() {
  // A scene opening in steps (scene_loading.h) keeps the frames coming: each step is announced by a frame.
  if (scene_loading_step(*page.state)) page.host->note_event();
  if (!page.host->wants_frame(*page.state)) return;  // asleep until an event
  const ui::FrameResult result = ui::run_frame(*page.host, *page.frame, *page.state);
  if (!result.drawn) return;
  last_layout = result.layout;
  // Check my camera in the page: its case out as a download, its answer file asked of the browser.
  session::CheckRequest& request = page.frame->check().request();
  if (request.download_case) {
    request.download_case = false;
    try {
      const SceneFile downloaded = session::camera_case(*page.state);
      save_scene_file(downloaded, "raycam-case.json");
      page.downloaded_case = scene_to_json(downloaded);
    } catch (const std::exception& error) {
      session::set_message(*page.state, session::MessageSource::general, true, ui::tr_reason(error.what()));
    }
  }
  if (page.state->requests.take(session::HostRequestKind::pick_scene_file)) {  // the status line's button
    EM_ASM(document.getElementById('picker').click(););  // within the click's user activation
  }
  if (request.pick_answer) {
    request.pick_answer = false;
    EM_ASM(document.getElementById('answer-picker').click(););  // within the click's user activation
  }
  page.downloads->offer_new_files();  // Save as, PNGs, screenshots, the check's case become downloads
  page.state->requests.take(session::HostRequestKind::toggle_fullscreen);  // the browser's own (kPageHost)
  page.host->apply_title();  // the tab's title
}
}  // namespace

session::AppState& page_state() { return *page.state; }
const ui::FrameLayout& page_layout() { return last_layout; }
session::CameraCheck& page_check() { return page.frame->check(); }
bool camera_changed_since_case_download() {
  return !page.downloaded_case.empty() && scene_to_json(session::camera_case(*page.state)) != page.downloaded_case;
}
void wake_page() { page.host->note_event(); }

void WebHost::woken() {
  if (!sleeping_) return;
  sleeping_ = false;
  emscripten_resume_main_loop();
}

bool WebHost::wants_frame(const session::AppState& state) {
  if (has_work(state)) {
    spend_settle_frame();
    return true;
  }
  sleeping_ = true;
  emscripten_pause_main_loop();
  return false;
}

void WebHost::after_imgui_backend() { listen_for_the_wheel(); }

void run_page(session::AppState& state) {
  state.host = session::kPageHost;  // what the panels offer: the picker, answer files, no program to run
  if (!glfwInit()) {
    std::fprintf(stderr, "raycam: cannot start GLFW in this page\n");
    return;
  }
  // emscripten's glfwInit listens for gamepads, and while a page listens Chromium polls them on a thread of
  // its own forever (measured: 0.1 s of CPU every 10 s, most of the idle page's cost). The app takes no
  // gamepad input (ImGui's gamepad navigation is off), so the page stops listening.
  EM_ASM({
    window.removeEventListener("gamepadconnected", GLFW.onGamepadConnected, true);
    window.removeEventListener("gamepaddisconnected", GLFW.onGamepadDisconnected, true);
  });
  int width = EM_ASM_INT(return window.innerWidth;), height = EM_ASM_INT(return window.innerHeight;);
  GLFWwindow* window = glfwCreateWindow(std::max(width, 320), std::max(height, 240), "raycam", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "raycam: this browser gives no WebGL 2 context\n");
    return;
  }
  glfwMakeContextCurrent(window);
  // Objects of the page live as long as the page: the loop below never returns.
  static WebHost host(window, state);
  static Downloads downloads;
  page = Page{window, &state, &host, nullptr, &downloads};
  host.start_imgui();
  install_scene_reader();  // the picker's and the drop's files read in slices, with progress
  static ui::FrameRenderer frame;
  page.frame = &frame;
  emscripten_set_main_loop(tick, 0, false);
}

}  // namespace raycam::web

// The page's wheel listener (listen_for_the_wheel), in notches with the desktop's signs.
extern "C" EMSCRIPTEN_KEEPALIVE void raycam_page_wheel(double x, double y) {
  ImGui_ImplGlfw_ScrollCallback(raycam::web::page.window, x, y);
}
