// Section index: view input · theme · layout and build · image window · overhead window · observer window.
//
// One frame, in the order that keeps everything it shows true to one state (same-frame truth):
//   1. input: keys, then the mouse on the views (hit-tested on last frame's windows, as ImGui does);
//   2. the panel's controls (camera, mistakes, caster, files, lecture) change the state;
//   3. the cast (only if something changed);
//   4. everything derived is drawn from that state: the M_d tables, the ray inspector, the image and views.
#include "ui/frame.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImGui::FindWindowByName, the hovered window

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "session/camera_ranges.h"
#include "session/construction_view.h"
#include "ui/fonts.h"
#include "ui/image_header.h"
#include "session/inspection.h"
#include "session/mistake_lessons.h"
#include "gl/observer_renderer.h"
#include "session/observer_view.h"
#include "ui/panels.h"
#include "raycam/transform.h"
#include "ui/words.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
constexpr int kObserverFanRays = 24;                   // rays of the middle row drawn in the observer view
const ImVec4 kMistakeHeader{0.65f, 0.1f, 0.1f, 1.0f};  // the image's header while a mistake is on
const ImVec4 kPassHeader{0.08f, 0.4f, 0.15f, 1.0f};     // while the check passes
constexpr ImGuiWindowFlags kFixedWindow =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

// The first of `candidates` (longest first) whose shown part fits a title bar `width` wide; the last one
// whatever: a title is never cut.
std::string first_fitting(const std::vector<std::string>& candidates, float width) {
  const float room = title_room(width);
  for (const std::string& c : candidates)
    if (ImGui::CalcTextSize(c.substr(0, c.find("##")).c_str()).x <= room) return c;
  return candidates.back();
}

// The long title if it fits the window's width, else the short one.
std::string fitting_title(const std::string& full, const std::string& brief, float width) {
  return first_fitting({full, brief}, width);
}

bool begin_fixed_window(const char* title, const Rect& r, ImGuiWindowFlags extra = 0) {
  ImGui::SetNextWindowPos({r.x, r.y});
  ImGui::SetNextWindowSize({r.w, r.h});
  return ImGui::Begin(title, nullptr, kFixedWindow | extra);
}

// A double-click on the title bar of the window just begun (Begin's last item) makes its view fill the views'
// area, or gives the others back.
void maximise_on_double_click(Display& display, ShownView view) {
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) toggle_maximised(display, view);
}

// Is the mouse over this window's drawing area? ImGui decided the hovered window at NewFrame from last
// frame's windows; the area is last frame's too. So the input pass needs no window of its own this frame.
bool view_hovered(const char* window_id, const Rect& area) {
  const ImGuiWindow* window = ImGui::FindWindowByName(window_id);
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  return window && GImGui->HoveredWindow == window && area.w > 0 && mouse.x >= area.x && mouse.y >= area.y &&
         mouse.x < area.x + area.w && mouse.y < area.y + area.h;
}

// The image widget shows the canonical screen: in 3D the square [-1, 1]² with +y up; in 2D the segment
// with canonical +x at the left (column 0 is the eye's left). fx, fy: the mouse in the widget, 0…1. The
// pixel comes from the core's pixel <-> screen pair, as the caster's pixel centres do.
PixelIndex pixel_under(const Lesson& state, double fx, double fy) {
  auto pixel_of = [](double raster, int count) { return std::clamp(int(std::floor(raster)), 0, count - 1); };
  PixelIndex pixel;
  std::visit(overloaded{[&](const View2D& view) {  // the bar: canonical +x at the left
                          const Camera2D& camera = view.camera;
                          pixel.column = camera.column_of_pixel(
                              pixel_of(camera.raster_from_screen(1.0 - 2.0 * fx), camera.pixel_count()));
                        },
                        [&](const View3D& view) {
                          const Camera3D& camera = view.camera;
                          const glm::dvec2 raster = camera.raster_from_screen({2.0 * fx - 1.0, 1.0 - 2.0 * fy});
                          pixel.column = pixel_of(raster.x, camera.columns());
                          pixel.row = pixel_of(raster.y, camera.rows());
                        }},
             state.view);
  return pixel;
}

// Mouse on the overhead or observer view: drag orbits the camera, the wheel changes d (shift: d_f),
// a double-click on an object makes it the target.
void orbit_with_mouse(AppState& state, bool hovered, bool dragging, bool drag_turns_around_target,
                      const OverheadMapping* mapping, const ObserverCamera* observer = nullptr) {
  ImGuiIO& io = ImGui::GetIO();
  double& theta = active_orbit(state).theta;
  if (dragging && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f) &&
      (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    if (drag_turns_around_target && mapping) {  // the camera follows the mouse around the target
      const glm::dvec2 target = active_target_xy(state);
      const glm::dvec2 towards = mapping->to_world(io.MousePos) - target;
      if (glm::length(towards) > 0) theta = std::atan2(towards.y, towards.x);
    } else if (observer) {  // the camera goes the way the mouse goes, seen by the observer
      drag_camera_in_observer(state, *observer, io.MouseDelta.x, io.MouseDelta.y);
    }
    state.cameras_dirty = true;
  }
  if (hovered && io.MouseWheel != 0.0f && !io.KeyCtrl) {
    const SharedOrbit<double> orbit = active_orbit(state);
    double &d = orbit.d, &df = orbit.df;
    if (io.KeyShift) df = kFocalRange.clamp(df * std::pow(1.1, io.MouseWheel));
    else d = kDistanceRange.clamp(d * std::pow(0.9, io.MouseWheel));
    state.cameras_dirty = true;
  }
  if (mapping && hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    const int id = object_under(*mapping, state, io.MousePos);
    if (id >= 0) {
      std::visit([&](auto& view) { view.orbit.target = objects_of(view.scene)[std::size_t(id)].centre; },
                 state.view);
      state.cameras_dirty = true;
    }
  }
}
}  // namespace

// ---- theme ---------------------------------------------------------------------------------------------
void apply_theme(const Display& display, AppliedTheme& applied) {
  if (applied.context != ImGui::GetCurrentContext() || applied.font_scale != display.font_scale ||
      applied.high_contrast != display.high_contrast) {
    ImGui::GetStyle() = make_style(display.high_contrast, display.font_scale);
    set_current_theme(display.high_contrast);
    applied = {display.high_contrast, display.font_scale, ImGui::GetCurrentContext()};
  }
}

// The room a message needs at the panel's foot (wrapped at the panel's width, its Dismiss button under it),
// when no section showed it in the last frame; else 0. At most half the window (a longer one scrolls).
float message_room(const Messages& messages, const HostLink& link, float panel_width, float window_height) {
  if (messages.message.empty() || messages.message_shown_frame == link.frame_count - 1) return 0.0f;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float wrap = panel_width - 2 * style.WindowPadding.x;
  const float text = ImGui::CalcTextSize(messages.message.c_str(), nullptr, false, wrap).y;
  const float room = text + style.ItemSpacing.y + ImGui::GetTextLineHeight() + 2 * style.WindowPadding.y + 2.0f;
  return std::min(std::ceil(room), std::floor(0.5f * window_height));
}

void prepare_frame(const Display& display, float pixel_density) {
  update_fonts(display.font_scale, pixel_density);
  take_tab_key();
}

// ---- layout and build ----------------------------------------------------------------------------------
FrameRenderer::FrameRenderer(Graphics graphics) {
  if (graphics == Graphics::none) return;  // the views' geometry is computed, their textures are not drawn
  observer_ = std::make_unique<gl::ObserverRenderer>();
  discs_ = std::make_unique<gl::DiscLayer>();
}
FrameRenderer::~FrameRenderer() = default;

Rect FrameRenderer::layout_areas(const Lesson& state, const Display& display, int width, int height,
                                 FrameLayout& layout) const {
  const float scale = display.font_scale;
  const float status_height = ImGui::GetFontSize() + 2 * ImGui::GetStyle().WindowPadding.y + 4;
  // The panel never takes more than 40% of the width: the image and the views keep the rest at any scale
  // (labels that do not fit beside their widget go above it: panel_widgets.cpp, labelled()).
  // Hidden (P), the panel gives the views its whole width.
  const float panel_w =
      display.panel_hidden ? 0.0f : std::clamp(390.0f * scale, std::min(300.0f, width * 0.4f), width * 0.4f);
  layout.panel = {0, 0, panel_w, float(height)};
  const float right_x = layout.panel.w, right_w = width - layout.panel.w, body_h = height - status_height;
  if (image_is_bar(state.view)) {
    const float bar_h = std::min(body_h * 0.3f, 60.0f * scale + 2 * ImGui::GetFrameHeightWithSpacing());
    image_area_ = {right_x, 0, right_w, bar_h};
    overhead_area_ = {right_x, bar_h, right_w, body_h - bar_h};
    observer_area_ = {};
  } else {
    // The image keeps at least half the window's height at every font scale (the views give way). With the
    // panel hidden it keeps just that, so that the overhead view under it keeps a usable height.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float top_h =
        display.panel_hidden
            ? std::ceil(0.5f * float(height) + ImGui::GetFrameHeight() + 2 * style.WindowPadding.y + 2.0f)
            : body_h * std::min(0.75f, 0.6f + 0.05f * (scale - 1.0f));
    const float image_w = std::min(right_w * 0.6f, top_h - ImGui::GetFrameHeightWithSpacing() + 16.0f);
    image_area_ = {right_x, 0, image_w, top_h};
    if (display.panel_hidden) {
      // The panel's width goes to the observer, as a column of the window's height beside the image and the
      // overhead view under it: under them all it stayed a strip (at 3× on 1024×768, 117 px tall, the
      // ground 35 px), the one view that shows where the camera is.
      overhead_area_ = {right_x, top_h, image_w, body_h - top_h};
      observer_area_ = {right_x + image_w, 0, right_w - image_w, body_h};
    } else {
      overhead_area_ = {right_x + image_w, 0, right_w - image_w, top_h};
      observer_area_ = {right_x, top_h, right_w, body_h - top_h};
    }
  }
  // A maximised view (1, 2, 3 or a double-click on its title) takes the whole views' area, the others are
  // not drawn; the observer only where there is one.
  layout.views = {right_x, 0, right_w, body_h};
  Rect* maximised = display.maximised == ShownView::image      ? &image_area_
                    : display.maximised == ShownView::overhead ? &overhead_area_
                    : display.maximised == ShownView::observer && has_observer(state.view) ? &observer_area_
                                                                                           : nullptr;
  if (maximised) {
    image_area_ = overhead_area_ = observer_area_ = {};
    *maximised = layout.views;
  }
  return {right_x, body_h, right_w, status_height};
}

void FrameRenderer::view_input(AppState& state) {
  ImGuiIO& io = ImGui::GetIO();
  const bool over_overhead = view_hovered("###overhead", last_.overhead);
  const bool over_observer = has_observer(state.view) && view_hovered("###observer", last_.observer);
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    left_drag_ = over_overhead ? Drag::overhead : over_observer ? Drag::observer : Drag::none;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) right_drag_observer_ = over_observer;
  if (!io.MouseDown[ImGuiMouseButton_Left]) left_drag_ = Drag::none;
  if (!io.MouseDown[ImGuiMouseButton_Right]) right_drag_observer_ = false;
  orbit_with_mouse(state, over_overhead, left_drag_ == Drag::overhead, true, &last_.overhead_mapping);
  // Over the image the wheel zooms it as it does the camera in the other views: d (shift: d_f, the field of
  // view); it did nothing there. A click there pins a pixel (hover_image), a drag does nothing.
  orbit_with_mouse(state, view_hovered("###image", last_.image), false, false, nullptr);
  if (!has_observer(state.view)) return;
  orbit_with_mouse(state, over_observer, left_drag_ == Drag::observer, false, nullptr, &observer_view_);
  if (right_drag_observer_ && ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
    state.observer.yaw_deg -= io.MouseDelta.x * 0.4f;
    state.observer.pitch_deg = std::clamp(state.observer.pitch_deg + io.MouseDelta.y * 0.4f, -89.0f, 89.0f);
  }
  if (over_observer && io.KeyCtrl && io.MouseWheel != 0.0f)
    state.observer.zoom = std::clamp(state.observer.zoom * std::pow(0.9f, io.MouseWheel), 0.05f, 20.0f);
}

void FrameRenderer::hover_image(Lesson& state, const CastCache& cast) {
  state.hovered_pixel.reset();
  const Rect& r = last_.image;
  if (cast.map.width <= 0 || !view_hovered("###image", r)) return;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const PixelIndex pixel = pixel_under(state, (mouse.x - r.x) / r.w, (mouse.y - r.y) / r.h);
  state.hovered_pixel = pixel;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) state.pinned_pixel = pixel;
}

FrameLayout FrameRenderer::build(AppState& state, int width, int height) {
  apply_theme(state, applied_theme_);
  // 1. input (a scene file may have opened since the last frame: dropped, or the page's picker)
  follow_scene_shown(state, panels_);
  follow_default_names(state, panels_);
  handle_shortcuts(state);
  view_input(state);
  // A confirmation goes by itself after a few seconds; an error stays until read (Dismiss, or the next one).
  age_message(state, ImGui::GetTime());
  // 2. the panel's controls
  FrameLayout layout;
  layout_areas(state, state, width, height, layout);
  // A message no section showed last frame is read at the panel's foot: the panel gives it its room, the
  // views keep theirs (over them it hid the observer's title and a third of the image at 3×).
  const bool panel_shown = !state.panel_hidden;
  const float message_h = panel_shown ? message_room(state, state, layout.panel.w, float(height)) : 0.0f;
  layout.panel.h -= message_h;
  const bool panel_open = panel_shown && begin_fixed_window("raycam###panel", layout.panel);
  if (panel_open) {
    camera_section(state, panels_);
    mistakes_section(state, panels_);
    caster_section(state, panels_);
    files_section(state, panels_);
    lecture_section(state, panels_);
  }
  // 3. the cast, once every control had its say (a control may also have switched 2D/3D or opened a file)
  recast_if_needed(state, ImGui::IsAnyMouseDown());
  const Rect status_area = layout_areas(state, state, width, height, layout);
  layout.panel.h -= message_h;
  hover_image(state, state);
  // 4. what is derived from the state, all after the cast
  if (!panels_.check_command.empty()) {  // --check CMD: the panel's program from the command line
    check_.set_command(panels_.check_command, false);
    panels_.check_command.clear();
  }
  check_.update(state, state, ImGui::GetTime());
  panels_.check_waiting = check_.waiting();
  if (panel_open) {
    construction_section(state, panels_);
    inspector_section(state);
    check_section(check_, state.host, ImGui::GetTime(), state.language, mistakes_on(state));
    // A verdict scrolled into view moves the panel at the next frame: the window draws it (an idle window
    // would leave the verdict below the fold until the next event).
    const ImGuiWindow* panel = ImGui::GetCurrentWindow();
    panels_.check_waiting |= panel->ScrollTarget.x < FLT_MAX || panel->ScrollTarget.y < FLT_MAX;
  }
  if (panel_shown) ImGui::End();
  if (draws_textures() && state.map_version != uploaded_map_version_) {
    texture_.upload(state.map);
    uploaded_map_version_ = state.map_version;
  }
  if (observer_ && has_observer(state.view) && state.scene_version != uploaded_scene_version_) {
    observer_->set_spheres(view3d(state).scene.spheres);
    uploaded_scene_version_ = state.scene_version;
  }
  if (discs_ && (state.scene_version != uploaded_disc_version_ || dimension(state) != uploaded_disc_dimension_)) {
    discs_->set_discs(overhead_discs(state));
    uploaded_disc_version_ = state.scene_version;
    uploaded_disc_dimension_ = dimension(state);
  }
  if (image_area_.w > 0) image_window(state, image_area_, layout);
  if (overhead_area_.w > 0) overhead_window(state, overhead_area_, layout);
  if (has_observer(state.view) && observer_area_.w > 0) observer_window(state, observer_area_, layout);
  shown_.placement = panels_.shown_matrix;
  shown_.map_version = state.map_version;
  layout.shown = shown_;

  // The message, if no open section showed it: at the panel's foot, in the room the panel left it, wrapped,
  // never clipped (a message set during this frame waits for the next one's room). With the panel hidden,
  // the status line says it (status_line).
  layout.status = status_area;
  if (!state.message.empty() && !message_shown_this_frame(state, state) && message_h > 0) {
    layout.message = {layout.panel.x, layout.panel.y + layout.panel.h, layout.panel.w, message_h};
    // Capped at half the window, a long one scrolls: its scroll bar from the first frame, so that the text
    // wraps at the width it is drawn in.
    const bool scrolls = message_h >= std::floor(0.5f * float(height));
    if (begin_fixed_window("##message", layout.message,
                           ImGuiWindowFlags_NoTitleBar | (scrolls ? ImGuiWindowFlags_AlwaysVerticalScrollbar : 0)))
      show_message_line(state, panels_);
    ImGui::End();
  }
  if (begin_fixed_window("##status", layout.status, ImGuiWindowFlags_NoTitleBar)) {
    status_line(state, panels_);
    if (state.panel_hidden && !state.message.empty()) layout.message = layout.status;
  }
  ImGui::End();
  help_overlay(state, state.language);
  state.window_title = window_title(state);
  ++state.frame_count;
  last_ = layout;
  return layout;
}

// ---- image window --------------------------------------------------------------------------------------
void FrameRenderer::image_window(AppState& state, const Rect& area, FrameLayout& layout) {
  const bool is_bar = image_is_bar(state.view);
  auto shown = [](const std::string& label) { return label.substr(0, label.find("###")); };
  const std::string full =
      shown(is_bar ? trf(state.language, "Colour bar: n = %d {{pixel|pixels}}, column 0 = the eye's left###image", state.map.width)
                   : trf(state.language, "Image: %d × %d###image", state.map.width, state.map.height));
  const std::string brief = shown(is_bar ? trf(state.language, "Colour bar: n = %d###image", state.map.width)
                                         : trf(state.language, "%d × %d###image", state.map.width, state.map.height));
  // A mistake that is on is named in the header, in red, whether the mistakes panel is open or not, and so
  // is the check's verdict: where the eye is. One line whatever it says (image_header.h): the picture under
  // it keeps its height, so that turning a mistake on changes the picture, not its size.
  const std::string mistakes = mistakes_on(state);
  const CheckHeader check = check_header(state.language, check_.progress(), mistakes, !state.host.runs_programs);
  const bool mistake_part = !mistakes.empty() && !check.names_mistake;  // else the verdict names it
  const ImageHeader header =
      fit_image_header({check.forms, mistake_part ? trf(state.language, "MISTAKE ON: %s", mistakes.c_str()) : "",
                        mistake_part ? tr(state.language, "MISTAKE ON") : "", {full, brief}},
                       area.w);
  const bool alarm = mistake_part || (!check.forms.empty() && !check.passed);
  const int header_colours = alarm || !check.forms.empty() ? 3 : 0;
  if (header_colours) {
    ImGui::PushStyleColor(ImGuiCol_TitleBg, alarm ? kMistakeHeader : kPassHeader);
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, alarm ? kMistakeHeader : kPassHeader);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 1, 1, 1));  // white on both (7:1), in either theme
  }
  const bool open = begin_fixed_window((header.title + "###image").c_str(), area, ImGuiWindowFlags_NoScrollbar);
  ImGui::PopStyleColor(header_colours);
  layout.image_header = {area.x, area.y, area.w, ImGui::GetFrameHeight()};
  layout.image_title = header.title;
  maximise_on_double_click(state, ShownView::image);
  // Begin()'s last item is the title bar: what the line left out, whole, under the mouse.
  if (!header.tooltip.empty() && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(0.5f * ImGui::GetIO().DisplaySize.x);  // a long name wraps on the screen
    ImGui::TextUnformatted(header.tooltip.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  if (open) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // 3D: the canonical screen is square, so the image is shown square (pixels are square when nbc = nbl).
    const ImVec2 size = is_bar ? ImVec2(std::floor(avail.x), std::floor(std::max(8.0f, avail.y)))
                              : ImVec2(std::floor(std::min(avail.x, avail.y)), std::floor(std::min(avail.x, avail.y)));
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_.id())), size, {0, 0}, {1, 1});
    const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
    layout.image = {low.x, low.y, high.x - low.x, high.y - low.y};
    // A frame just outside the image, so that where the background ends shows against the window.
    ImGui::GetWindowDrawList()->AddRect({low.x - 2, low.y - 2}, {high.x + 2, high.y + 2}, kImageFrameColour,
                                        0, 0, 1.0f);
    check_overlay(check_, state, state, ImGui::GetWindowDrawList(), low.x, low.y, high.x,
                  high.y);                         // the student's wrong pixels
    if (const auto pixel = active_pixel(state, state)) {  // outline the inspected pixel
      const float cw = (high.x - low.x) / state.map.width, ch = (high.y - low.y) / state.map.height;
      const ImVec2 a{low.x + pixel->column * cw, low.y + pixel->row * ch};
      // The pixel's outline, and around it a frame as big as the font at least (a 3D pixel is a few screen
      // pixels: its outline alone was 4 px at 3×, lost from the back row), a tenth of the font thick.
      const float thickness = std::max(2.0f, 0.1f * ImGui::GetFontSize());
      const float side = std::max({cw, ch, ImGui::GetFontSize()});
      const ImVec2 middle{a.x + 0.5f * cw, a.y + 0.5f * ch};
      const ImVec2 m0{middle.x - 0.5f * side - thickness, middle.y - 0.5f * side - thickness},
          m1{middle.x + 0.5f * side + thickness, middle.y + 0.5f * side + thickness};
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddRect({a.x - 1, a.y - 1}, {a.x + cw + 1, a.y + ch + 1}, kInspectedRayColour, 0, 0, 2.0f);
      draw->AddRect(m0, m1, kInspectedRayColour, 0, 0, thickness);
      if (panels_.widget_rects) (*panels_.widget_rects)["###pinned_marker"] = {m0.x, m0.y, m1.x, m1.y};
    }
  }
  ImGui::End();
}

// ---- overhead window -----------------------------------------------------------------------------------
void FrameRenderer::overhead_window(AppState& state, const Rect& area, FrameLayout& layout) {
  const std::string title = first_fitting({dimension(state) == 2 ? tr(state.language, "Overhead view: the plane, the camera and its rays###overhead")
                                                                : tr(state.language, "Overhead view: looking down the z axis###overhead"),
                                            tr(state.language, "Overhead view###overhead"), tr(state.language, "Overhead###overhead")},
                                           area.w);
  const bool open = begin_fixed_window(title.c_str(), area, ImGuiWindowFlags_NoScrollbar);
  maximise_on_double_click(state, ShownView::overhead);
  if (open) {
    // A short view (under the image, panel hidden, at 3×) gives the button's row to the drawing: F fits it.
    const bool short_view = ImGui::GetContentRegionAvail().y < 5 * ImGui::GetFrameHeightWithSpacing();
    const char* fit = tr(state.language, "Fit view (F)");  // shorter where the view is narrow (1024 px at 3×)
    if (ImGui::CalcTextSize(fit).x + 2 * ImGui::GetStyle().FramePadding.x > ImGui::GetContentRegionAvail().x)
      fit = tr(state.language, "Fit (F)###fit");
    if (!short_view) {
      if (ImGui::SmallButton(fit)) state.overhead_fit_pending = true;
      // The hint on the rest of the line when it fits there (large fonts: in the button's tooltip instead).
      const char* hint = tr(state.language, "holds still while the camera moves; drag: the camera around C");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", hint);
      ImGui::SameLine();
      if (ImGui::CalcTextSize(hint).x <= ImGui::GetContentRegionAvail().x) ImGui::TextDisabled("%s", hint);
      else ImGui::NewLine();
    }
    const ImVec2 top_left = ImGui::GetCursorScreenPos(), size = ImGui::GetContentRegionAvail();
    if (size.x > 4 && size.y > 4) {
      ImGui::InvisibleButton("##overhead_input", size);
      layout.overhead = {top_left.x, top_left.y, size.x, size.y};
      // On load, reset, "fit", or when the camera or the target would leave the view: else it holds still.
      if (state.overhead_fit_pending || !camera_and_target_in_view(state, state, top_left, size)) fit_overhead(state, state);
      layout.overhead_mapping = overhead_mapping(state, top_left, size);
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->PushClipRect(top_left, {top_left.x + size.x, top_left.y + size.y}, true);
      std::optional<InspectedRay> inspected;
      if (const auto pixel = active_pixel(state, state)) inspected = inspect_pixel(state, state, *pixel);
      draw_overhead(draw, layout.overhead_mapping, state, state, inspected, discs_.get(), panels_.widget_rects);
      draw->PopClipRect();
    }
  }
  ImGui::End();
}

// ---- observer window -----------------------------------------------------------------------------------
void FrameRenderer::observer_window(AppState& state, const Rect& area, FrameLayout& layout) {
  const std::string title =
      fitting_title(tr(state.language, "Observer: the camera among the spheres (left drag: orbit the camera, right drag: "
                       "turn the observer, ctrl+wheel: zoom)###observer"),
                    fitting_title(tr(state.language, "Observer: the camera among the spheres###observer"),
                                  tr(state.language, "Observer###observer"), area.w),
                    area.w);
  const bool open = begin_fixed_window(title.c_str(), area, ImGuiWindowFlags_NoScrollbar);
  maximise_on_double_click(state, ShownView::observer);
  if (open) {
    const ImVec2 top_left = ImGui::GetCursorScreenPos(), size = ImGui::GetContentRegionAvail();
    if (size.x > 4 && size.y > 4) {
      ImGui::InvisibleButton("##observer_input", size);
      layout.observer = {top_left.x, top_left.y, size.x, size.y};
      const double aspect = double(size.x) / double(size.y);

      const Camera3D& camera = view3d(state).camera;
      const glm::dvec3 target = view3d(state).orbit.target;
      const double reach = view3d(state).orbit.d + view3d(state).orbit.df;
      const ObserverCamera observer = observer_camera(state, state, aspect);
      layout.observer_camera = observer_view_ = observer;
      const glm::mat4 view = observer.view, projection = observer.projection;

      gl::ObserverFrame frame;
      frame.view_projection = projection * view;
      frame.observer_eye = glm::vec3(observer.eye);
      frame.background = view3d(state).scene.background;
      const glm::dvec3 eye = camera.eye();
      const std::array<glm::dvec3, 4> corners = camera.screen_corners();
      const glm::vec4 cyan{0, 0.9f, 1, 1}, faint_cyan{0, 0.9f, 1, 0.45f};
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 corner = corners[i], next = corners[(i + 1) % corners.size()];
        frame.screen_corners[i] = glm::vec3(corner);
        frame.lines.push_back({glm::vec3(corner), glm::vec3(next), cyan});
        frame.lines.push_back({glm::vec3(eye), glm::vec3(eye + glm::normalize(corner - eye) * (1.4 * reach)), faint_cyan});
      }
      frame.image_texture = texture_.id();
      const float axis = float(reach * 0.3);
      frame.lines.push_back({{0, 0, 0}, {axis, 0, 0}, {1, 0.3f, 0.3f, 1}});
      frame.lines.push_back({{0, 0, 0}, {0, axis, 0}, {0.3f, 1, 0.3f, 1}});
      frame.lines.push_back({{0, 0, 0}, {0, 0, axis}, {0.4f, 0.5f, 1, 1}});
      const glm::vec3 t(target);
      const float cross = float(reach * 0.05);
      const glm::vec4 yellow{1, 0.9f, 0, 1};
      for (int a = 0; a < 3; ++a) {
        glm::vec3 offset(0.0f);
        offset[a] = cross;
        frame.lines.push_back({t - offset, t + offset, yellow});
      }
      // The same rays as the image and the overhead view (the middle row), to where the caster hit.
      const bool constructing = shows_construction(state);
      for (const InspectedRay& ray : primary_ray_fan(state, state, constructing ? 0 : kObserverFanRays)) {
        const Rgb8 c =
            ray.hit.id >= 0 ? state.map.colour_at(ray.pixel.row, ray.pixel.column) : Rgb8{200, 200, 200};
        frame.lines.push_back({glm::vec3(ray.origin),
                               glm::vec3(ray.end(2.0 * reach)),
                               {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, ray.hit.id >= 0 ? 0.9f : 0.25f}});
      }
      if (const auto pixel = active_pixel(state, state)) {
        const InspectedRay ray = inspect_pixel(state, state, *pixel);
        frame.lines.push_back({glm::vec3(eye), glm::vec3(ray.origin), {1, 0, 1, 0.6f}});
        frame.lines.push_back({glm::vec3(ray.origin), glm::vec3(ray.end(2.0 * reach)), {1, 0, 1, 1}});
      }
      if (constructing)  // the handout's frames; GL lines are one pixel wide, so the key parts get a band
        for (const ConstructionSegment& segment :
             construction_camera(construction_pose(camera.placement(), state.construction_step, state.construction_fraction), 1.5)) {
          const glm::vec4 colour = construction_colour(segment.part);
          frame.overlay_lines.push_back({glm::vec3(segment.from), glm::vec3(segment.to), colour});
          if (segment.part == ConstructionPart::screen || segment.part == ConstructionPart::field_edge)
            continue;
          const glm::dvec3 along = glm::normalize(segment.to - segment.from);
          const glm::dvec3 side =
              glm::normalize(std::abs(along.z) < 0.9 ? glm::cross(along, glm::dvec3(0, 0, 1))
                                                     : glm::cross(along, glm::dvec3(1, 0, 0)));
          const glm::dvec3 other = glm::cross(along, side);
          for (const glm::dvec3& offset : {side, -side, other, -other}) {
            const glm::dvec3 shift = 0.004 * observer.distance * offset;  // about a pixel
            frame.overlay_lines.push_back(
                {glm::vec3(segment.from + shift), glm::vec3(segment.to + shift), colour});
          }
        }
      // One texel per framebuffer pixel (a screen of pixel ratio 2 has twice as many in each direction).
      const ImVec2 density = ImGui::GetIO().DisplayFramebufferScale;
      const GLuint texture =
          observer_ ? observer_->render(frame, int(std::lround(size.x * density.x)), int(std::lround(size.y * density.y)))
                    : 0;
      // GL textures are bottom-up: flip v.
      ImGui::GetWindowDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), top_left,
                                           {top_left.x + size.x, top_left.y + size.y}, {0, 1}, {1, 0});
    }
  }
  ImGui::End();
}

}  // namespace raycam::ui
