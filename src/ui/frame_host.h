// One host interface for the app's frame, whatever shows it (Polyscope's engine idea): a GLFW window
// (src/app/glfw_host.cpp) or an OSMesa buffer (src/headless/headless_renderer.cpp). The frame itself, and
// the loop body that drives it, are the same code for both: run_frame below.
//
// Each host is its own executable's: libGL and OSMesa define the same GL symbols and must never meet in one
// binary, so this header names neither.
#pragma once

#include <string>

#include "session/app_state.h"
#include "ui/frame.h"
#include "gl/framebuffer_image.h"

namespace raycam::ui {

struct FramebufferSize {
  int width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

class FrameHost {
 public:
  virtual ~FrameHost() = default;
  // Waits for what the next frame needs (a window: events, or nothing when `state` or the `panels` have work
  // pending; a buffer: nothing) and starts the platform's ImGui frame. Returns the framebuffer's size; empty
  // when there is nothing to draw (minimised): the frame is skipped.
  virtual FramebufferSize begin(const session::AppState& state, const PanelState& panels) = 0;
  // Draws ImGui's frame into the framebuffer: GL hosts with the shared GL code (frame_host.cpp); the null
  // host draws nothing.
  virtual void draw(const FramebufferSize& size);
  // After the frame is drawn, before present(): a host that records the window reads the frame back here.
  virtual void frame_drawn(session::AppState&) {}
  // Shows the frame just drawn (a window swaps its buffers; a buffer finishes drawing).
  virtual void present() = 0;
  // The frame just drawn, read before present() (a window's back buffer), top row first.
  virtual gl::RgbaImage read_back() const = 0;
  // Framebuffer pixels per UI pixel (a page on a screen of pixel ratio 2: 2): the fonts are rasterised at it.
  // A host whose ratio is not 1 sets ImGui's DisplaySize in UI pixels and its DisplayFramebufferScale.
  virtual float pixel_density() const { return 1.0f; }
};

// A host with no GL at all: it runs a whole frame's logic (input, the panels, the views' geometry, the casts,
// ImGui's draw lists) and draws nothing, so the frame's tests also run where there is no GL context (the
// sanitizer build). Input is set on ImGui's IO directly.
class NullHost : public FrameHost {
 public:
  NullHost(int width, int height) : size_{width, height} {}
  FramebufferSize begin(const session::AppState& state, const PanelState& panels) override;
  void draw(const FramebufferSize&) override {}
  void present() override {}
  gl::RgbaImage read_back() const override { return {}; }

 private:
  FramebufferSize size_;
};

struct FrameResult {
  bool drawn = false;  // false: the host had nothing to draw (minimised)
  bool screenshot_failed = false;
  FrameLayout layout;
};

// The loop body, one frame: fonts, host.begin, the window built from `state` (and the frame's own panel
// state), ImGui rendered into the framebuffer, a requested screenshot saved (taken from state.requests),
// present.
FrameResult run_frame(FrameHost& host, FrameRenderer& frame, session::AppState& state);

// True while the window must keep drawing without waiting for input: the cameras changed, a coarse
// preview waits for its refinement, a request is waiting for the executable, a check's verdict is on its
// way (the panels say), a confirmation is counting down its seconds on screen. Anything that makes the image change with no input (a background cast) adds its
// condition here.
bool frame_needs_redraw(const session::AppState& state, const PanelState& panels);

}  // namespace raycam::ui
