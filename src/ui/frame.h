// The whole window, built the same way inside a GLFW window or an OSMesa buffer: only the executable's main
// knows which. Call FrameRenderer::build between ImGui::NewFrame() and ImGui::Render().
//
// Layout (framebuffer pixels, origin top-left): a control panel on the left; on the right the colour bar
// (2D) or image (3D) at the top, the overhead view below or beside it, and in 3D the observer's view.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <memory>

#include "session/app_state.h"
#include "ui/check_panel.h"
#include "gl/colour_map_texture.h"
#include "session/observer_view.h"
#include "ui/overhead_view.h"
#include "ui/panel_state.h"

namespace raycam::gl {
class ObserverRenderer;
}

namespace raycam::ui {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
};

// What the frame showed, for the tests that check it agrees with the core in that very frame.
struct ShownValues {
  glm::dmat4 placement{1.0};      // the M_d the construction table showed (2D: embedded in a 4×4)
  std::uint64_t map_version = 0;  // the colour map the image texture held
};

// Where things were drawn this frame: tests sample the screenshot there.
struct FrameLayout {
  Rect panel;
  Rect views;     // the room the views share (all of it for a maximised one)
  Rect image;     // the colour bar or texture, exactly
  Rect image_header;  // the image window's title bar (names a classic mistake that is on)
  std::string image_title;  // what that title bar says (ImGui keeps a window's first name, not the shown one)
  Rect overhead;  // the overhead view's drawing area
  OverheadMapping overhead_mapping;
  Rect observer;  // 3D only
  session::ObserverCamera observer_camera;  // the observer's viewpoint drawn this frame
  Rect status;    // the status line (frame time, work done and skipped)
  Rect message;   // where the message was read when no open panel section showed it: the panel's foot, or
                  // the status line while the panel is hidden (never a view's room)
  ShownValues shown;
};

// The theme and font scale last applied to an ImGui context's style.
struct AppliedTheme {
  bool high_contrast = false;
  float font_scale = 0.0f;
  const ImGuiContext* context = nullptr;  // a new context starts with the default style
};

class FrameRenderer {
 public:
  // What the frame draws its textures with: GL (a current GL 3.3 context), or nothing (the null host).
  enum class Graphics { gl, none };
  explicit FrameRenderer(Graphics graphics = Graphics::gl);  // needs an ImGui context
  ~FrameRenderer();
  FrameLayout build(session::AppState& state, int width, int height);
  session::CameraCheck& check() { return check_; }  // for a host: the page hands the check its answer files
  // The panels' own widget state (the session never reads it): a host sets it from its options
  // (panel_state_for), a test sets its widget_rects hook.
  PanelState& panels() { return panels_; }
  const PanelState& panels() const { return panels_; }

 private:
  enum class Drag { none, overhead, observer };
  bool draws_textures() const { return observer_ != nullptr; }  // false with Graphics::none
  // Sets the panel's rectangle and the views' areas; returns the status line's.
  Rect layout_areas(const session::Lesson& state, const session::Display& display, int width, int height,
                    FrameLayout& layout) const;
  void view_input(session::AppState& state);
  void hover_image(session::Lesson& state, const session::CastCache& cast);
  void image_window(session::AppState& state, const Rect& area, FrameLayout& layout);
  void overhead_window(session::AppState& state, const Rect& area, FrameLayout& layout);
  void observer_window(session::AppState& state, const Rect& area, FrameLayout& layout);

  gl::ColourMapTexture texture_;  // with Graphics::none: never uploaded, id 0
  std::unique_ptr<gl::ObserverRenderer> observer_;
  std::unique_ptr<gl::DiscLayer> discs_;
  std::uint64_t uploaded_map_version_ = 0, uploaded_scene_version_ = 0, uploaded_disc_version_ = 0;
  int uploaded_disc_dimension_ = 0;
  FrameLayout last_;  // last frame's rectangles: where the mouse input of this frame lands
  mutable Rect image_area_, overhead_area_, observer_area_;
  Drag left_drag_ = Drag::none;
  bool right_drag_observer_ = false;
  ShownValues shown_;
  session::ObserverCamera observer_view_;  // last frame's, for the mouse
  session::CameraCheck check_;             // "Check my camera": runs on its own thread, never blocks a frame
  AppliedTheme applied_theme_;
  PanelState panels_;
};

// Call before the renderer backend's NewFrame, outside ImGui::NewFrame/Render: rebuilds the font atlas at
// the state's font scale when it changed (fonts.h), at the host's pixel density (FrameHost::pixel_density).
// Both hosts (GLFW window, OSMesa) call it every frame.
void prepare_frame(const session::Display& display, float pixel_density = 1.0f);

// Dark or high-contrast theme and the font scale (lecture mode), when they differ from `applied`.
void apply_theme(const session::Display& display, AppliedTheme& applied);

}  // namespace raycam::ui
