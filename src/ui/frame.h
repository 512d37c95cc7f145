// The whole window, built the same way inside a GLFW window or an OSMesa buffer: only the executable's main
// knows which. Call FrameRenderer::build between ImGui::NewFrame() and ImGui::Render().
//
// Layout (framebuffer pixels, origin top-left): a control panel on the left; on the right the colour bar
// (2D) or image (3D) at the top, the overhead view below or beside it, and in 3D the observer's view.
#pragma once

#include <cstdint>
#include <memory>

#include "app_state.h"
#include "colour_map_texture.h"
#include "overhead_view.h"

namespace raycam::gl {
class ObserverRenderer;
}

namespace raycam::ui {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
};

// Where things were drawn this frame: tests sample the screenshot there.
struct FrameLayout {
  Rect panel;
  Rect image;     // the colour bar or texture, exactly
  Rect image_header;  // the image window's title bar (names a classic mistake that is on)
  Rect overhead;  // the overhead view's drawing area
  OverheadMapping overhead_mapping;
  Rect observer;  // 3D only
  Rect status;    // the status line (frame time, work done and skipped)
};

class FrameRenderer {
 public:
  FrameRenderer();  // needs a current GL 3.3 context and an ImGui context
  ~FrameRenderer();
  FrameLayout build(AppState& state, int width, int height);

 private:
  void image_window(AppState& state, const Rect& area, FrameLayout& layout);
  void overhead_window(AppState& state, const Rect& area, FrameLayout& layout);
  void observer_window(AppState& state, const Rect& area, FrameLayout& layout);

  gl::ColourMapTexture texture_;
  std::unique_ptr<gl::ObserverRenderer> observer_;
  std::unique_ptr<gl::DiscLayer> discs_;
  std::uint64_t uploaded_map_version_ = 0, uploaded_scene_version_ = 0, uploaded_disc_version_ = 0;
  int uploaded_disc_dimension_ = 0;
};

// Call before the renderer backend's NewFrame, outside ImGui::NewFrame/Render: rebuilds the font atlas at
// the state's font scale when it changed (fonts.h). Both hosts (GLFW window, OSMesa) call it every frame.
void prepare_frame(const AppState& state);

// Dark or high-contrast theme and the font scale (lecture mode).
void apply_theme(const AppState& state);

}  // namespace raycam::ui
