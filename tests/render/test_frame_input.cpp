// The window driven through its own input path (mouse and keys sent to ImGui's IO, as the GLFW backend
// sends them), checked in the very frame that follows: same-frame truth, the keyboard, the window title,
// messages that stay visible, lecture mode's layout.
#include <imgui.h>
#include <imgui_internal.h>

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "gl/gl.h"
#include "headless/headless_renderer.h"
#include "ui/panels.h"
#include "raycam/ray_caster.h"

using namespace raycam;

namespace {

session::AppState state_for(const std::vector<std::string>& args) {
  session::AppOptions options;
  options.language = raycam::Language::en;
  return session::make_app_state(flags::parse_app_options(args, options));
}

// The image region of the frame holds exactly `expected`, sampled at pixel centres.
int wrong_pixels(const gl::RgbaImage& image, const ui::Rect& r, const ColourMap& expected) {
  REQUIRE(r.w >= 2 * expected.width);
  REQUIRE(r.h >= 2 * expected.height);
  int wrong = 0;
  for (int row = 0; row < expected.height; ++row)
    for (int column = 0; column < expected.width; ++column) {
      const std::uint8_t* p = image.at(int(r.x + (column + 0.5) * r.w / expected.width),
                                       int(r.y + (row + 0.5) * r.h / expected.height));
      wrong += Rgb8{p[0], p[1], p[2]} != expected.colour_at(row, column);
    }
  return wrong;
}

// The frame just rendered agrees with the core for the state's current parameters: the M_d the table
// showed is the core's placement matrix, and the image is the core's colour map (both computed here).
void check_frame_agrees_with_core(headless::HeadlessRenderer& renderer, const session::AppState& state) {
  const gl::RgbaImage image = renderer.read_back();
  const ui::FrameLayout& layout = renderer.layout();
  const Orbit3D& o = view3d(state).orbit;
  Camera3D camera(64, 64);
  camera.set_orbit({o.target, o.d, o.theta, o.phi, o.df});
  const glm::dmat4 expected = camera.world_from_camera();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) CHECK(layout.shown.placement[c][r] == Approx(expected[c][r]).margin(1e-12));
  CHECK(layout.shown.map_version == state.map_version);
  CHECK(wrong_pixels(image, layout.image, cast_primary_rays(camera, view3d(state).scene)) == 0);
}

// A key pressed for one frame and released the next, as fingers do.
void tap(headless::HeadlessRenderer& renderer, session::AppState& state, int key) {
  renderer.press_key(key);
  renderer.run_frame(state);
  renderer.run_frame(state);
}

// A click as a hand makes it: hover, press (with ctrl held for a Ctrl+click), release, a frame each.
void click(headless::HeadlessRenderer& renderer, session::AppState& state, ImVec2 at, bool ctrl = false) {
  renderer.move_mouse(at.x, at.y);
  renderer.run_frame(state);
  ImGui::GetIO().KeyCtrl = ctrl;
  renderer.set_mouse_button(0, true);
  renderer.run_frame(state);
  renderer.set_mouse_button(0, false);
  ImGui::GetIO().KeyCtrl = false;
  renderer.run_frame(state);
}
// Ctrl+click, as ImGui's sliders take it to type a value.
void ctrl_click(headless::HeadlessRenderer& renderer, session::AppState& state, ImVec2 at) {
  click(renderer, state, at, true);
}

ImVec2 centre(const std::pair<ImVec2, ImVec2>& r) {
  return {(r.first.x + r.second.x) / 2, (r.first.y + r.second.y) / 2};
}

// Where the panels drew the labelled widget "###id" (the panels' test hook, PanelState::widget_rects).
std::optional<std::pair<ImVec2, ImVec2>> widget_rect(const ui::WidgetRects& rects, const std::string& id) {
  const auto found = rects.find(id);
  if (found == rects.end()) return std::nullopt;
  const ui::WidgetRect& r = found->second;
  return std::pair<ImVec2, ImVec2>{{r.x0, r.y0}, {r.x1, r.y1}};
}
// Opens the panel's section "###id" (as a click on its header does); the panel window, for its scroll.
ImGuiWindow* open_panel_section(const char* id) {
  ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
  REQUIRE(panel);
  panel->StateStorage.SetInt(panel->GetID(id), 1);
  return panel;
}
}  // namespace

TEST_CASE("the page's host offers its file picker at the status line's end, the desktop's does not",
          "[render][host]") {
  for (const bool page : {false, true}) {
    session::AppState state = state_for({"--size", "64x64"});
    state.host = page ? session::kPageHost : session::kDesktopHost;
    ui::WidgetRects rects;
    headless::HeadlessRenderer renderer(1280, 720);
    renderer.panels().widget_rects = &rects;
    renderer.render_settled(state);
    const auto open = widget_rect(rects, "###open_scene_file");
    CHECK(open.has_value() == page);
    const auto status = widget_rect(rects, "###status_text");
    REQUIRE(status);
    if (open) CHECK(open->first.x >= status->second.x);  // after the text, never over it
  }
}

TEST_CASE("a slider dragged with the mouse: image and M_d table match the core in that very frame",
          "[render][input][same-frame]") {
  session::AppState state = state_for({"--size", "64x64"});
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.panels().widget_rects = &rects;
  renderer.render_settled(state);
  const auto theta = widget_rect(rects, "###theta");
  REQUIRE(theta);
  const float y = centre(*theta).y;
  const double before = view3d(state).orbit.theta;
  renderer.move_mouse(theta->first.x + 0.8f * (theta->second.x - theta->first.x),
                      y);  // hover first, as a hand does
  renderer.run_frame(state);
  renderer.set_mouse_button(0, true);  // the slider jumps to the mouse: this frame changes θ
  renderer.run_frame(state);
  CHECK(std::abs(view3d(state).orbit.theta - before) > glm::radians(30.0));
  check_frame_agrees_with_core(renderer, state);
  // ... and while dragging, every frame.
  for (float x : {0.3f, 0.55f, 0.1f}) {
    renderer.move_mouse(theta->first.x + x * (theta->second.x - theta->first.x), y);
    renderer.run_frame(state);
    check_frame_agrees_with_core(renderer, state);
  }
  renderer.set_mouse_button(0, false);
  renderer.run_frame(state);
}

TEST_CASE("a mistake toggled in the panel shows in the image and the table of the same frame",
          "[render][input][same-frame]") {
  session::AppState state = state_for({"--size", "64x64", "--theta", "10", "--phi", "75"});
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.render_settled(state);
  state.mistakes.printed_rotation_sign = true;  // what the checkbox sets (the section is closed here)
  state.cameras_dirty = true;
  renderer.run_frame(state);
  Camera3D camera(64, 64);
  camera.set_mistakes(state.mistakes);
  camera.set_orbit(view3d(state).orbit);
  CHECK(renderer.layout().shown.placement == camera.world_from_camera());
  CHECK(wrong_pixels(renderer.read_back(), renderer.layout().image,
                     cast_primary_rays(camera, view3d(state).scene)) == 0);
}

TEST_CASE("a drag in the overhead view orbits the camera, and the frame agrees with the core",
          "[render][input]") {
  session::AppState state = state_for({"--size", "64x64"});
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.render_settled(state);
  const ui::Rect view = renderer.layout().overhead;
  const ImVec2 target = renderer.layout().overhead_mapping.to_screen(glm::dvec2(view3d(state).orbit.target));
  renderer.move_mouse(view.x + view.w - 10, target.y);  // to the right of the target: θ = 0 there
  renderer.run_frame(state);
  renderer.set_mouse_button(0, true);
  renderer.run_frame(state);
  renderer.move_mouse(target.x, view.y + 10);  // straight above the target: θ = 90°
  renderer.run_frame(state);
  CHECK(view3d(state).orbit.theta ==
        Approx(glm::radians(90.0)).margin(glm::radians(1.0)));  // within a screen pixel
  check_frame_agrees_with_core(renderer, state);
  renderer.set_mouse_button(0, false);
  renderer.run_frame(state);
}

TEST_CASE(
    "Tab always switches 2D/3D, also from a text field, and arrows move the camera unless a field is edited",
    "[render][input][keyboard]") {
  session::AppState state = state_for({});
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.panels().widget_rects = &rects;
  renderer.render_settled(state);
  CHECK(state.window_title == "raycam — 3D — demo scene");
  for (int dimension : {2, 3, 2, 3}) {
    tap(renderer, state, ImGuiKey_Tab);
    CHECK(session::dimension(state) == dimension);
    CHECK(state.window_title == "raycam — " + std::to_string(dimension) + "D — demo scene");
    CHECK_FALSE(ui::editing_text());  // Tab never puts a field into text editing
  }
  // Right arrow: θ + 5°.
  const double theta = view3d(state).orbit.theta;
  tap(renderer, state, ImGuiKey_RightArrow);
  CHECK(view3d(state).orbit.theta == Approx(theta + glm::radians(5.0)));
  // Ctrl+click the d slider: it becomes a text field; arrows and + then edit the text, not the camera.
  const auto d_slider = widget_rect(rects, "###d");
  REQUIRE(d_slider);
  ctrl_click(renderer, state, centre(*d_slider));
  REQUIRE(ui::editing_text());
  const double d = view3d(state).orbit.d, theta_editing = view3d(state).orbit.theta;
  tap(renderer, state, ImGuiKey_LeftArrow);
  renderer.type_text("+");
  renderer.run_frame(state);
  CHECK(view3d(state).orbit.theta == theta_editing);
  // Esc leaves the field (the typed text is dropped), and the arrows act on the camera again.
  tap(renderer, state, ImGuiKey_Escape);
  CHECK_FALSE(ui::editing_text());
  CHECK(view3d(state).orbit.d == d);
  tap(renderer, state, ImGuiKey_LeftArrow);
  CHECK(view3d(state).orbit.theta == Approx(theta_editing - glm::radians(5.0)));
  // Tab from inside a text field: leaves it and switches.
  ctrl_click(renderer, state, centre(*d_slider));
  REQUIRE(ui::editing_text());
  tap(renderer, state, ImGuiKey_Tab);
  CHECK(dimension(state) == 2);
  CHECK_FALSE(ui::editing_text());
}

TEST_CASE("a message stays on screen, wrapped inside the window, until dismissed or replaced",
          "[render][messages]") {
  session::AppState state = state_for({});
  headless::HeadlessRenderer renderer(1280, 800);
  renderer.render_settled(state);
  CHECK_FALSE(session::open_scene(state, "no/such/scene_file_for_the_test.json"));
  for (int frame = 0; frame < 30; ++frame) renderer.run_frame(state);  // stays
  const ui::FrameLayout& layout = renderer.layout();
  REQUIRE(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains("no/such/scene_file_for_the_test.json"));
  // The Scene file section is closed: the message is read at the panel's foot, in view.
  CHECK(layout.message.w > 0);
  // Opened, the section shows it, in view: nothing at the panel's foot.
  open_panel_section("###files");
  for (int frame = 0; frame < 3; ++frame) renderer.run_frame(state);
  CHECK(renderer.layout().message.w == 0);
  // At 3× the section's message is below the panel's fold: the panel's foot shows it again
  // (a screenshot's confirmation used to land there, out of sight).
  state.font_scale = 3.0f;
  for (int frame = 0; frame < 3; ++frame) renderer.run_frame(state);
  CHECK(renderer.layout().message.w > 0);
  state.font_scale = 1.0f;
  // A message whose section is closed (here: none) is read at the panel's foot, tall enough for its wrapped
  // text at 3× font, inside the window and beside the views (never over them).
  state.font_scale = 3.0f;
  session::set_message(state, session::MessageSource::general, true,
                  "a long message that cannot fit on one line of the right-hand side at three times the font size, "
                  "so it wraps: /a/long/path/to/a/scene/file/lesson3.json");
  for (int frame = 0; frame < 3; ++frame) renderer.run_frame(state);
  const ui::FrameLayout big = renderer.layout();  // a copy: the next frames replace the renderer's
  REQUIRE(big.message.w > 0);
  const float line = ImGui::GetTextLineHeightWithSpacing();
  CHECK(big.message.h >= 3 * line);  // wrapped over at least two lines, plus the Dismiss button
  CHECK(big.message.y >= 0);
  CHECK(big.message.y + big.message.h <= 800.5f);
  CHECK(big.message.y >= big.panel.y + big.panel.h - 0.5f);      // under the panel, which gave it the room
  CHECK(big.message.x + big.message.w <= big.panel.w + 0.5f);    // in the panel's column: no view's room
  CHECK(big.panel.w <= 0.4f * 1280 + 0.5f);
  CHECK(big.status.x + big.status.w <= 1280.5f);
  // Replaced by the next message; cleared by Dismiss (what the button does).
  session::set_message(state, session::MessageSource::general, false, "done");
  renderer.run_frame(state);
  CHECK(renderer.layout().message.h < big.message.h);
  state.message.clear();
  renderer.run_frame(state);
  CHECK(renderer.layout().message.w == 0);
}

TEST_CASE("a section's message shows in one place: wholly in its section, or at the panel's foot",
          "[render][messages]") {
  // At 3× a message cut by the panel's bottom edge showed twice (QA): cut in its section, whole elsewhere.
  session::AppState state = state_for({});
  state.font_scale = 3.0f;
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1280, 800);
  renderer.panels().widget_rects = &rects;
  renderer.render_settled(state);
  CHECK_FALSE(session::open_scene(state, "no/such/folder/for/this/test/scene_file_for_the_test.json"));
  ImGuiWindow* panel = open_panel_section("###files");
  renderer.run_frame(state);
  int in_section = 0, on_line = 0;
  // Every scroll of the panel, a few pixels at a time: the message passes the bottom edge, is in view, then
  // passes the top edge.
  for (float scroll = 0; scroll <= panel->ScrollMax.y + 1; scroll += 11) {
    ImGui::SetScrollY(panel, scroll);
    renderer.run_frame(state);  // the scroll applies
    rects.clear();
    renderer.run_frame(state);
    const auto section = widget_rect(rects, "###message/section");
    const bool line = renderer.layout().message.w > 0;
    INFO("scroll " << scroll << " of " << panel->ScrollMax.y);
    CHECK(section.has_value() != line);  // one place, never both, never neither
    if (section) {
      ++in_section;
      // Whole inside the panel's window, below its title bar.
      CHECK(section->first.y >= panel->InnerClipRect.Min.y - 0.5f);
      CHECK(section->second.y <= panel->InnerClipRect.Max.y + 0.5f);
    }
    on_line += line;
  }
  CHECK(in_section > 0);  // scrolled into view, the section shows it
  CHECK(on_line > 0);     // below the fold or scrolled past, the line does
  REQUIRE(state.message_is_error);
}

TEST_CASE("lecture mode: at 1×, 1.5×, 2× and 3× the image keeps half the window and the panel 40% at most",
          "[render][lecture]") {
  for (const auto& [width, height] : {std::pair{1280, 800}, std::pair{1024, 768}})  // a laptop, a projector
    for (const char* language : {"en", "fr"})
      for (const char* view : {"3d", "2d"})
        for (const float scale : {1.0f, 1.5f, 2.0f, 3.0f}) {
          session::AppState state = state_for({"--view", view, "--lang", language});
          ui::WidgetRects rects;
          state.font_scale = scale;
          headless::HeadlessRenderer renderer(width, height);
          renderer.panels().widget_rects = &rects;
          renderer.render_settled(state);
          const ui::FrameLayout& layout = renderer.layout();
          INFO(width << "×" << height << " " << language << " " << view << " at " << scale << "×");
          CHECK(ImGui::GetFontSize() == Approx(std::round(15.0f * scale)));  // rasterised at the size, not stretched
          CHECK(ImGui::GetIO().FontGlobalScale == 1.0f);
          CHECK(layout.panel.w <= 0.4f * width + 0.5f);
          // At 1280×800 (at 1024×768 the 3D image keeps 364 of 768 px: the panel's 40% and the overhead view
          // beside it take the width).
          if (width == 1280 && std::string(view) == "3d") CHECK(std::min(layout.image.w, layout.image.h) >= 0.5f * height);
          else if (std::string(view) == "2d") CHECK(layout.image.w >= 0.5f * width);  // the bar spans the right-hand side
          // The status line's one line fits its area.
          CHECK(layout.status.x + layout.status.w <= width + 0.5f);
          // Every labelled widget of the panel lies inside the panel (its label beside it or above it).
          for (const char* id : {"###df", "###d", "###theta", "###res", "###target"}) {
            const auto rect = widget_rect(rects, id);
            REQUIRE(rect);
            CHECK(rect->second.x <= layout.panel.x + layout.panel.w);
          }
          // The target's fields each show a coordinate such as -10.00 whole (they were cut to "0.0" at 3×): side
          // by side, or one a line.
          const int fields = std::string(view) == "3d" ? 3 : 2;
          const float coordinate = ImGui::CalcTextSize("-10.00").x;
          if (const auto first = widget_rect(rects, "###target0")) {
            for (int i = 0; i < fields; ++i) {
              const auto field = widget_rect(rects, "###target" + std::to_string(i));
              REQUIRE(field);
              CHECK(field->second.x - field->first.x >= coordinate);
              CHECK(field->second.x <= layout.panel.x + layout.panel.w);
            }
          } else {
            const auto target = widget_rect(rects, "###target");
            CHECK(target->second.x - target->first.x >= fields * coordinate);
          }
        }
}

TEST_CASE("lecture mode: after a change of font scale its slider is still in view", "[render][lecture]") {
  session::AppState state = state_for({"--view", "3d", "--lang", "fr"});
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1024, 768);
  renderer.panels().widget_rects = &rects;
  renderer.render_settled(state);
  ImGuiWindow* panel = open_panel_section("###lecture");  // Lecture mode opened
  renderer.render_settled(state);
  const auto in_view = [&] {
    const auto slider = widget_rect(rects, "###font_scale");
    REQUIRE(slider);
    INFO("slider from y = " << slider->first.y << " to " << slider->second.y << ", panel " << panel->InnerRect.Min.y
                            << " to " << panel->InnerRect.Max.y);
    return slider->first.y >= panel->InnerRect.Min.y && slider->second.y <= panel->InnerRect.Max.y;
  };
  REQUIRE(in_view());
  for (const float scale : {3.0f, 2.0f, 1.5f, 1.0f}) {
    state.font_scale = scale;  // as the slider sets it when released
    renderer.render_settled(state);
    INFO("at " << scale << "×");
    CHECK(in_view());
  }
}

TEST_CASE("lecture mode: a font scale changed in a running window draws what a window started at it draws",
          "[render][lecture]") {
  // The fonts are rebuilt in the running window (the backend restarted): the frame at 3× must be the frame of
  // a window that started at 3×, pixel for pixel, with no GL error on the way (Dear ImGui 1.86's
  // DestroyDeviceObjects left buffers without storage: in the page a blank frame, under Mesa GL errors).
  gl::RgbaImage after_change;
  GLenum error_after_change = GL_NO_ERROR;
  {
    session::AppState changed = state_for({"--view", "3d"});
    headless::HeadlessRenderer renderer(1024, 768);
    renderer.render_settled(changed);
    changed.font_scale = 3.0f;
    after_change = renderer.render_settled(changed);
    error_after_change = glGetError();
  }
  session::AppState started = state_for({"--view", "3d", "--font-scale", "3"});
  headless::HeadlessRenderer fresh(1024, 768);
  const gl::RgbaImage from_start = fresh.render_settled(started);
  const ui::Rect status = fresh.layout().status;  // the frame and cast times there are measured: they differ
  CHECK(error_after_change == GL_NO_ERROR);
  REQUIRE(after_change.pixels.size() == from_start.pixels.size());
  int differing = 0, compared = 0;
  for (int y = 0; y < from_start.height; ++y)
    for (int x = 0; x < from_start.width; ++x) {
      if (y >= status.y && y < status.y + status.h) continue;
      ++compared;
      differing += !std::equal(from_start.at(x, y), from_start.at(x, y) + 4, after_change.at(x, y));
    }
  CHECK(compared > 0.8 * from_start.width * from_start.height);
  CHECK(differing == 0);
}

// QA: Export colour map said "wrote raycam-colour-map.png" (the name as typed, relative to a folder the
// student does not see) where the screenshot and the figure exports name the whole path.
TEST_CASE("Export colour map names the file it wrote by its whole path", "[render][files]") {
  const test::ScratchDir scratch("export-colour-map");
  struct InFolder {  // the default name is relative: written into the scratch folder, whatever happens
    std::filesystem::path before = std::filesystem::current_path();
    explicit InFolder(const std::filesystem::path& dir) { std::filesystem::current_path(dir); }
    ~InFolder() { std::filesystem::current_path(before); }
  } in_folder(scratch.dir);
  session::AppState state = state_for({"--size", "32x32"});
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.panels().widget_rects = &rects;
  renderer.run_frame(state);
  open_panel_section("###files");  // the Scene file section open
  renderer.render_settled(state);
  const auto button = widget_rect(rects, "###export_png");
  REQUIRE(button);
  click(renderer, state, centre(*button));
  const std::string written = (scratch.dir / renderer.panels().export_path).lexically_normal().string();
  CHECK(std::filesystem::exists(written));
  CHECK_FALSE(state.message_is_error);
  INFO(state.message);
  CHECK(state.message.find(written) != std::string::npos);
}

// QA: Export colour map wrote over the file of the last export without a word (the 3D map was replaced by
// the 2D bar). Like Save as and Export figure, it asks; Cancel keeps the file, Replace writes it.
TEST_CASE("Export colour map asks before replacing a file: Cancel keeps it, Replace writes it", "[render][files]") {
  const test::ScratchDir scratch("export-colour-map-replace");
  session::AppState state = state_for({"--size", "32x32"});
  ui::WidgetRects rects;
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.panels().widget_rects = &rects;
  renderer.panels().export_path = (scratch.dir / "lecture-map.png").string();
  renderer.run_frame(state);
  open_panel_section("###files");
  renderer.render_settled(state);
  auto press = [&](const char* id) {
    renderer.render_settled(state);
    const auto button = widget_rect(rects, id);
    REQUIRE(button);
    click(renderer, state, centre(*button));
    renderer.move_mouse(-FLT_MAX, -FLT_MAX);  // off the panel, so that the next widget rects are fresh
  };
  press("###export_png");
  const std::string path = renderer.panels().export_path;
  REQUIRE(std::filesystem::exists(path));
  auto bytes = [&] {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string first = bytes();
  view3d(state).orbit.theta += 1.0;  // another picture
  state.cameras_dirty = true;
  press("###export_png");
  CHECK((bytes() == first));  // not written: asked (parenthesised: no PNG bytes in a failure's report)
  rects.clear();
  renderer.render_settled(state);
  REQUIRE(widget_rect(rects, "###colour_map_replace"));
  press("###colour_map_cancel");
  CHECK((bytes() == first));
  rects.clear();
  renderer.render_settled(state);
  CHECK_FALSE(widget_rect(rects, "###colour_map_replace"));  // the question is gone
  press("###export_png");
  press("###colour_map_replace");
  CHECK((bytes() != first));  // the new picture
  CHECK_FALSE(state.message_is_error);
  CHECK(state.message.find(path) != std::string::npos);
}

// The wheel over the image zooms it as the camera does in the other views: d closer (shift: d_f larger, the
// field narrower), and the image of that very frame is the core's for the new camera (it did nothing there).
TEST_CASE("the wheel over the image moves the camera closer, shift+wheel lengthens d_f", "[render][input]") {
  session::AppState state = state_for({"--size", "64x64"});
  headless::HeadlessRenderer renderer(1280, 720);
  renderer.render_settled(state);
  const ui::Rect image = renderer.layout().image;
  renderer.move_mouse(image.x + image.w / 2, image.y + image.h / 2);
  renderer.run_frame(state);
  const double d = view3d(state).orbit.d, df = view3d(state).orbit.df;
  renderer.scroll(1.0f);
  renderer.run_frame(state);
  CHECK(view3d(state).orbit.d == Approx(d * 0.9));
  CHECK(view3d(state).orbit.df == Approx(df));
  check_frame_agrees_with_core(renderer, state);
  ImGui::GetIO().KeyShift = true;
  renderer.scroll(1.0f);
  renderer.run_frame(state);
  ImGui::GetIO().KeyShift = false;
  CHECK(view3d(state).orbit.df == Approx(df * 1.1));
  check_frame_agrees_with_core(renderer, state);
}

// The status line gives the frame's time as well as the cast's at every lecture size (at 3× on 1024 px it
// kept the cast's alone), never wider than its room; its tooltip wraps inside the window (it ran past the
// right edge at 1024 px).
TEST_CASE("the status line shows the frame time at 3x and its tooltip stays in the window", "[render][lecture]") {
  for (const auto& [width, height] : {std::pair{1024, 768}, std::pair{1280, 800}})
    for (const char* language : {"fr", "en"})
      for (const float scale : {1.0f, 2.0f, 3.0f}) {
        session::AppState state = state_for({"--lang", language});
        state.font_scale = scale;
        ui::WidgetRects rects;
        headless::HeadlessRenderer renderer(width, height);
        renderer.panels().widget_rects = &rects;
        renderer.render_settled(state);
        const float room = renderer.layout().status.w - 2 * ImGui::GetStyle().WindowPadding.x;
        const std::string line = ui::status_timing_line(state.language, 16.7, 0.42, "stable", false, room);
        INFO(width << "x" << height << " at " << scale << "x, " << language << ": '" << line << "' in " << room << " px");
        // The numbers in the window's language: a decimal comma in French.
        const bool french = std::string(language) == "fr";
        CHECK((line.find("17") != std::string::npos || line.find(french ? "16,7" : "16.7") != std::string::npos));
        CHECK(line.find(french ? "0,4" : "0.4") != std::string::npos);
        CHECK(line.find(french ? "0.4" : "0,4") == std::string::npos);
        CHECK(ImGui::CalcTextSize(line.c_str()).x <= room);
        // The tooltip, under the mouse on the line.
        REQUIRE(rects.count("###status_text") == 1);
        const ui::WidgetRect& text = rects.at("###status_text");
        renderer.move_mouse(text.x0 + 5, (text.y0 + text.y1) / 2);
        renderer.render_settled(state, 40);  // past the hover delay
        const ImGuiWindow* tooltip = nullptr;
        for (ImGuiWindow* window : GImGui->Windows)
          if (window->WasActive && (window->Flags & ImGuiWindowFlags_Tooltip)) tooltip = window;
        REQUIRE(tooltip);
        INFO("tooltip at " << tooltip->Pos.x << "," << tooltip->Pos.y << " " << tooltip->Size.x << "x" << tooltip->Size.y);
        CHECK(tooltip->Pos.x >= 0.0f);
        CHECK(tooltip->Pos.x + tooltip->Size.x <= float(width));
        CHECK(tooltip->Pos.y >= 0.0f);
        CHECK(tooltip->Pos.y + tooltip->Size.y <= float(height));
      }
}
