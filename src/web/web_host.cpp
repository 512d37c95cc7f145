#include "web/web_host.h"

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>

#include "session/camera_check.h"
#include "web/downloads.h"
#include "raycam/scene_file.h"
#include "session/text.h"
#include "gl/gl.h"
#include "web/page_recording.h"
#include "ui/renderer_backend.h"
#include "web/scene_loading.h"

namespace raycam::web {

namespace {
struct Page {
  GLFWwindow* window = nullptr;
  session::AppState* state = nullptr;
  WebHost* host = nullptr;
  ui::FrameRenderer* frame = nullptr;
  Downloads* downloads = nullptr;
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

// The canvas's drawing buffer is its CSS box × the screen's pixel ratio, whenever either changes: a resize
// or the browser's zoom (the CSS box; ResizeObserver), a move to a screen of another ratio (the ratio alone: a
// media query on the current one, armed again after each change). emscripten's GLFW kept the size it had at
// load and the browser stretched it (spheres drawn as ellipses). The window's size as GLFW reports it
// (glfwGetWindowSize and glfwGetFramebufferSize are the same in emscripten 3.1.6) is the buffer's; the host
// lays the UI out in CSS pixels (frame_started).
void follow_the_canvas_size() {
  EM_ASM({
    const canvas = Module.canvas;
    let armed_for = 0;
    const fit = function() {
      const ratio = window.devicePixelRatio || 1;
      if (ratio !== armed_for) {
        armed_for = ratio;
        window.matchMedia('(resolution: ' + ratio + 'dppx)').addEventListener('change', fit, {once: true});
      }
      const box = canvas.getBoundingClientRect();
      const width = Math.max(1, Math.round(box.width * ratio));
      const height = Math.max(1, Math.round(box.height * ratio));
      if (canvas.width === width && canvas.height === height && Module.raycam_pixel_ratio === ratio) return;
      canvas.width = width;
      canvas.height = height;
      GLFW.active.width = width;
      GLFW.active.height = height;
      Module.raycam_pixel_ratio = ratio;
      Module.ccall('raycam_page_resized', null, ['number'], [ratio]);
    };
    // The device-pixel box also changes with the ratio alone; browsers without it observe the CSS box.
    try {
      new ResizeObserver(fit).observe(canvas, {box: 'device-pixel-content-box'});
    } catch (error) {
      new ResizeObserver(fit).observe(canvas);
    }
    fit();
  });
}

// F1 (help), F9 (record), F11 (full screen) and F12 (screenshot) are the app's while the canvas has the focus: not the
// browser's help, its own full screen (which a page cannot leave) or its developer tools. Escape leaves the
// app's full screen (browsers do it themselves; this also covers those that pass the key on).
void keep_the_app_keys() {
  EM_ASM({
    Module.canvas.addEventListener('keydown', function(event) {
      if (event.key === 'F1' || event.key === 'F9' || event.key === 'F11' || event.key === 'F12') event.preventDefault();
      if (event.key === 'Escape' && document.fullscreenElement) document.exitFullscreen().catch(function() {});
    });
  });
}

// F11 or the panel's button: the browser's Fullscreen API on the whole page (the canvas then follows its new
// size). Asked within the key's or the click's user activation; a refusal (a frame without allowfullscreen)
// is said on the status line.
void toggle_fullscreen() {
  EM_ASM({
    if (document.fullscreenElement) {
      document.exitFullscreen().catch(function() {});
      return;
    }
    const page = document.documentElement;
    if (!page.requestFullscreen) {
      Module.ccall('raycam_page_fullscreen_refused', null, [], []);
      return;
    }
    page.requestFullscreen().catch(function() { Module.ccall('raycam_page_fullscreen_refused', null, [], []); });
  });
}

ui::FrameLayout last_layout;  // the last frame's, for the browser tests (web_main.cpp)

EM_JS(int, page_in_fullscreen, (), { return document.fullscreenElement ? 1 : 0; });

void tick() {
  // A scene opening in steps (scene_loading.h) keeps the frames coming: each step is announced by a frame.
  if (scene_loading_step(*page.state)) page.host->note_event();
  if (!page.host->wants_frame(*page.state, page.frame->panels())) return;  // asleep until an event
  page.state->in_fullscreen = page_in_fullscreen() != 0;  // the panel's button says Leave there
  const ui::FrameResult result = ui::run_frame(*page.host, *page.frame, *page.state);
  if (!result.drawn) return;  // (a frame drawn gave ImGui the keys held since: WebHost::frame_drawn)
  last_layout = result.layout;
  // Check my camera in the page: its case out as a download, its answer file asked of the browser.
  session::CheckRequest& request = page.frame->check().request();
  if (request.download_case) {
    request.download_case = false;
    try {
      save_scene_file(page.frame->check().case_for_download(*page.state), "raycam-case.json");
    } catch (const std::exception& error) {
      session::set_message(*page.state, session::MessageSource::general, true, session::tr_reason(page.state->language, error.what()));
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
  if (page.state->requests.take(session::HostRequestKind::toggle_fullscreen)) toggle_fullscreen();
  if (page.state->requests.take(session::HostRequestKind::toggle_recording)) toggle_page_recording(*page.state);
  update_page_recording(*page.state);
  page.host->apply_title();  // the tab's title
}
}  // namespace

session::AppState& page_state() { return *page.state; }
const ui::FrameLayout& page_layout() { return last_layout; }
session::CameraCheck& page_check() { return page.frame->check(); }
const ui::PanelState& page_panels() { return page.frame->panels(); }
void wake_page() { page.host->note_event(); }

void WebHost::woken() {
  if (!sleeping_) return;
  sleeping_ = false;
  emscripten_resume_main_loop();
}

bool WebHost::wants_frame(const session::AppState& state, const ui::PanelState& panels) {
  // Recording, the page draws every animation frame: the canvas's stream and the status line's clock move.
  if (has_work(state, panels) || state.recording) {
    spend_settle_frame();
    return true;
  }
  sleeping_ = true;
  emscripten_pause_main_loop();
  return false;
}

void WebHost::after_imgui_backend() {
  listen_for_the_wheel();
  follow_the_canvas_size();
  keep_the_app_keys();
}

void WebHost::resized(double pixel_ratio) {
  pixel_ratio_ = float(pixel_ratio);
  note_event();
}

// GLFW's window, its framebuffer and its mouse are in the canvas's device pixels; the UI is laid out in CSS
// pixels and drawn at the ratio (ImGui's DisplayFramebufferScale), so it keeps its size to the eye.
void WebHost::frame_started() {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(size_.width) / pixel_ratio_, float(size_.height) / pixel_ratio_);
  io.DisplayFramebufferScale = ImVec2(pixel_ratio_, pixel_ratio_);
  if (io.MousePos.x > -FLT_MAX / 2) io.MousePos = ImVec2(io.MousePos.x / pixel_ratio_, io.MousePos.y / pixel_ratio_);
}

void run_page(session::AppState& state, const ui::PanelState& panels) {
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
  frame.panels() = panels;
  page.frame = &frame;
  emscripten_set_main_loop(tick, 0, false);
}

}  // namespace raycam::web

// The page's canvas listener (follow_the_canvas_size): the buffer has its new size, at this pixel ratio.
extern "C" EMSCRIPTEN_KEEPALIVE void raycam_page_resized(double pixel_ratio) {
  if (raycam::web::page.host) raycam::web::page.host->resized(pixel_ratio);
}

extern "C" EMSCRIPTEN_KEEPALIVE void raycam_page_fullscreen_refused() {
  raycam::session::set_message(*raycam::web::page.state, raycam::session::MessageSource::general, true,
                               raycam::session::tr(raycam::web::page.state->language, "The browser refused full screen for this page."));
  raycam::web::wake_page();
}

// For the browser tests: the UI's size (CSS pixels), the pixel ratio, the text's size in UI pixels and the
// pixels its glyphs are rasterised at.
extern "C" EMSCRIPTEN_KEEPALIVE const char* raycam_page_display() {
  static std::string json;
  const ImGuiIO& io = ImGui::GetIO();
  const ImFont* font = io.Fonts->Fonts.empty() ? nullptr : io.Fonts->Fonts[0];
  char text[256];
  std::snprintf(text, sizeof text, "{\"ui\": [%.3f, %.3f], \"ratio\": %g, \"font\": %.4f, \"font_raster\": %g}",
                io.DisplaySize.x, io.DisplaySize.y, double(raycam::web::page.host->pixel_density()),
                font ? double(font->FontSize * io.FontGlobalScale) : 0.0, font ? double(font->FontSize) : 0.0);
  json = text;
  return json.c_str();
}

// The page's wheel listener (listen_for_the_wheel), in notches with the desktop's signs.
extern "C" EMSCRIPTEN_KEEPALIVE void raycam_page_wheel(double x, double y) {
  ImGui_ImplGlfw_ScrollCallback(raycam::web::page.window, x, y);
}
