// The null host (ui/frame_host.h): whole frames with no GL context, as the sanitizer build can run them.
#include <catch2/catch.hpp>
#include <imgui.h>

#include "../session/app_state_for.h"
#include "ui/frame_host.h"
#include "imgui_context_scope.h"
#include "raycam/ray_caster.h"

using namespace raycam;

using test::ImGuiContextScope;

TEST_CASE("the null host runs whole frames without GL: the cast, the panels and the views follow the camera",
          "[ui][null-host]") {
  session::AppState state = test::state_for({"--size", "48x32"});
  const ImGuiContextScope imgui;
  ui::NullHost host(1280, 720);
  ui::FrameRenderer frame(ui::FrameRenderer::Graphics::none);
  ui::FrameResult result;
  for (int i = 0; i < 3; ++i) result = ui::run_frame(host, frame, state);
  REQUIRE(result.drawn);
  CHECK(state.map.width == 48);
  CHECK(state.map.height == 32);
  // The image the frame shows is the camera's, cast by the frame itself.
  CHECK(state.map.ids == cast_primary_rays(session::view3d(state).camera, session::view3d(state).scene).ids);
  CHECK(result.layout.shown.map_version == state.map_version);
  CHECK(result.layout.image.w > 0);
  CHECK(result.layout.observer.w > 0);  // 3D: the observer view is laid out (not drawn)

  session::view3d(state).orbit.theta += 0.5;  // as a slider would
  state.cameras_dirty = true;
  result = ui::run_frame(host, frame, state);
  CHECK(state.map.ids == cast_primary_rays(session::view3d(state).camera, session::view3d(state).scene).ids);

  session::switch_dimension(state, 2);  // the bar, no observer
  for (int i = 0; i < 2; ++i) result = ui::run_frame(host, frame, state);
  CHECK(state.map.height == 1);
  CHECK(result.layout.observer.w == 0);
  CHECK(state.map.ids == cast_primary_rays(session::view2d(state).camera, session::view2d(state).scene).ids);
}
