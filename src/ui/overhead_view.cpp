// Section index: fitting · primary-ray fan · drawing (2D, 3D) · picking.
#include "ui/overhead_view.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include <glm/trigonometric.hpp>

#include "session/construction_view.h"
#include "raycam/transform.h"
#include "ui/words.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
constexpr int kMaxFanRays = 160;       // rays drawn in the fan; more would be a grey smear
constexpr int kMaxFanLines = 48;       // up to this many, each ray is a line; more are drawn as beams
constexpr int kLabelRings = 7;         // a screen end's label is at most 4 px + 3 lines from it
constexpr double kConstructionAxisLength = 1.5;     // the 3D construction camera's axes, world units
constexpr std::size_t kDiscsAvoidedUpTo = 4096;     // the side view looks for a corner off the discs up to this many

ImU32 colour_of(Rgb8 c, int alpha = 255) { return IM_COL32(c.r, c.g, c.b, alpha); }
glm::dvec2 xy(glm::dvec3 p) { return {p.x, p.y}; }  // seen from above
glm::dvec2 xy(glm::dvec2 p) { return p; }

double camera_reach(const Lesson& state) {
  const auto orbit = active_orbit(state);
  return orbit.d + orbit.df;
}

// The camera's eye and screen corners in the world (2D: the two screen ends), seen from above.
template <class Matrix>
std::vector<glm::dvec2> camera_outline(const Matrix& world_from_camera, glm::dvec2* eye) {
  *eye = xy(eye_of(world_from_camera));
  std::vector<glm::dvec2> outline;
  for (const auto& corner : screen_corners_of(world_from_camera)) outline.push_back(xy(corner));
  return outline;
}
std::vector<glm::dvec2> camera_outline(const Lesson& state, glm::dvec2* eye) {
  return std::visit([&](const auto& view) { return camera_outline(view.camera.world_from_camera(), eye); },
                    state.view);
}
// How high an object reaches above the plane seen from above: discs are drawn low to high, and the mouse
// picks the one drawn last. A 2D scene is flat: its objects keep their order.
double top_of(const Circle&) { return 0.0; }
double top_of(const Sphere& sphere) { return sphere.centre.z + sphere.radius; }
}  // namespace

// ---- fitting -------------------------------------------------------------------------------------------
void fit_overhead(const Lesson& state, Display& display) {
  glm::dvec2 eye;
  std::vector<glm::dvec2> points = camera_outline(state, &eye);
  points.push_back(eye);
  const glm::dvec2 target = active_target_xy(state);
  points.push_back(target);
  // Objects near the action count; a huge "ground" sphere or a far outlier would shrink everything else.
  const double reach = 2.5 * camera_reach(state);
  auto include = [&](glm::dvec2 centre, double radius) {
    if (glm::length(centre - target) + radius > reach || radius > reach) return;
    points.push_back(centre - glm::dvec2(radius));
    points.push_back(centre + glm::dvec2(radius));
  };
  std::visit([&](const auto& view) {
    for (const auto& object : objects_of(view.scene)) include(xy(object.centre), object.radius);
  }, state.view);
  glm::dvec2 low = points[0], high = points[0];
  for (const glm::dvec2& p : points) low = glm::min(low, p), high = glm::max(high, p);
  display.overhead_low = low;
  display.overhead_high = high;
  display.overhead_fit_pending = false;
}

bool camera_and_target_in_view(const Lesson& state, const Display& display, ImVec2 top_left, ImVec2 size) {
  const OverheadMapping m = overhead_mapping(display, top_left, size);
  glm::dvec2 eye;
  std::vector<glm::dvec2> points = camera_outline(state, &eye);
  points.push_back(eye);
  points.push_back(active_target_xy(state));
  for (const glm::dvec2& p : points) {
    const ImVec2 s = m.to_screen(p);
    if (!(s.x >= top_left.x && s.y >= top_left.y && s.x <= top_left.x + size.x && s.y <= top_left.y + size.y))
      return false;
  }
  return true;
}

OverheadMapping overhead_mapping(const Display& display, ImVec2 top_left, ImVec2 size) {
  const glm::dvec2 low = display.overhead_low, high = display.overhead_high;
  const glm::dvec2 extent = glm::max(high - low, glm::dvec2(1e-9));
  const double margin = 0.08;
  OverheadMapping mapping;
  mapping.scale = float(std::min(size.x / extent.x, size.y / extent.y) * (1.0 - 2 * margin));
  const glm::dvec2 middle = 0.5 * (low + high);
  mapping.origin = {top_left.x + size.x * 0.5f - mapping.scale * float(middle.x),
                    top_left.y + size.y * 0.5f + mapping.scale * float(middle.y)};
  return mapping;
}

// ---- drawing -------------------------------------------------------------------------------------------
namespace {
void draw_cross(ImDrawList* draw, ImVec2 p, float size, ImU32 colour) {
  draw->AddLine({p.x - size, p.y}, {p.x + size, p.y}, colour, 2.0f);
  draw->AddLine({p.x, p.y - size}, {p.x, p.y + size}, colour, 2.0f);
}

using PlacedLabels = std::vector<std::pair<ImVec2, ImVec2>>;  // top-left, size: place_label's

// The axes through the world origin, each named inside the view at its end, whole at any font size: "x" left
// of the right edge, "y" under the top edge (a name is left out when its axis is out of the view). The names'
// rectangles go into `placed`, for the labels placed after them.
void draw_axes(ImDrawList* draw, const OverheadMapping& m, ImVec2 clip_min, ImVec2 clip_max, PlacedLabels& placed,
               WidgetRects* label_rects) {
  const ImU32 axis = IM_COL32(255, 255, 255, 40), name = IM_COL32(255, 255, 255, 90);
  draw->AddLine({clip_min.x, m.origin.y}, {clip_max.x, m.origin.y}, axis);
  draw->AddLine({m.origin.x, clip_min.y}, {m.origin.x, clip_max.y}, axis);
  const ImVec2 x_size = ImGui::CalcTextSize("x"), y_size = ImGui::CalcTextSize("y");
  if (m.origin.y >= clip_min.y && m.origin.y <= clip_max.y) {  // above its axis, below the top edge (14 px in at 1×)
    const ImVec2 at{clip_max.x - std::max(14.0f, x_size.x + 5), std::max(clip_min.y + 2, m.origin.y - x_size.y - 1)};
    draw->AddText(at, name, "x");
    placed.push_back({at, x_size});
    if (label_rects) (*label_rects)["###axis_x"] = {at.x, at.y, at.x + x_size.x, at.y + x_size.y};
  }
  if (m.origin.x >= clip_min.x && m.origin.x <= clip_max.x) {  // right of its axis, left of the right edge
    const ImVec2 at{std::min(m.origin.x + 4, clip_max.x - y_size.x - 2), clip_min.y + 2};
    draw->AddText(at, name, "y");
    placed.push_back({at, y_size});
    if (label_rects) (*label_rects)["###axis_y"] = {at.x, at.y, at.x + y_size.x, at.y + y_size.y};
  }
}

// Whether a label at `at`, `size` big, would print over one of `placed`.
bool overlaps_any(ImVec2 at, ImVec2 size, const PlacedLabels& placed) {
  for (const auto& [q, s] : placed)
    if (at.x < q.x + s.x && q.x < at.x + size.x && at.y < q.y + s.y && q.y < at.y + size.y) return true;
  return false;
}

// A label drawn into a view no wider than `width`: on one line, else on two (broken after its ": ", else at
// the space that makes the wider line narrowest), else on two lines in a smaller font (down to
// kMinLabelScale of the window's, still bigger than the 1× font at lecture sizes). `largest`: of the window's
// font, the largest size to use.
constexpr float kMinLabelScale = 0.5f;
constexpr float kInsetFontScale = 0.7f;  // the side view's lines above it: smaller, to hide less of the view
constexpr float kMinTitleWidth = 160.0f;  // those lines' width at least (a small frame: they go past it)
struct FittedLabel {
  std::string text;  // with '\n' where it is broken
  float font_size;
  ImVec2 size;
};
FittedLabel fit_label(const std::string& text, float width, float largest = 1.0f) {
  ImFont* font = ImGui::GetFont();
  const float full = ImGui::GetFontSize() * largest;
  auto measure = [&](const std::string& t, float size) { return font->CalcTextSizeA(size, FLT_MAX, 0.0f, t.c_str()); };
  if (measure(text, full).x <= width) return {text, full, measure(text, full)};
  std::string two = text;
  if (const std::size_t colon = text.find(": "); colon != std::string::npos) {
    two[colon + 1] = '\n';
  } else {
    float narrowest = FLT_MAX;
    for (std::size_t space = text.find(' '); space != std::string::npos; space = text.find(' ', space + 1)) {
      std::string broken = text;
      broken[space] = '\n';
      if (measure(broken, full).x < narrowest) narrowest = measure(broken, full).x, two = broken;
    }
  }
  const float size = std::clamp(full * width / measure(two, full).x, std::min(full, ImGui::GetFontSize() * kMinLabelScale), full);
  return {two, size, measure(two, size)};
}

// A line on screen as the small discs along it that a label must not cover (one every few pixels).
void mark_segment(std::vector<ScreenDisc>& marks, ImVec2 a, ImVec2 b, float radius = 3.0f) {
  const float length = std::hypot(b.x - a.x, b.y - a.y);
  const int steps = std::min(400, int(std::ceil(length / radius)));
  for (int i = 0; i <= steps; ++i) {
    const float f = steps ? float(i) / float(steps) : 0.0f;
    marks.push_back({{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)}, radius});
  }
}

// The camera (screen, eye, field-of-view edges) through a matrix: the final M_d or a construction step.
template <class Matrix>
void draw_camera(ImDrawList* draw, const OverheadMapping& m, const Matrix& world_from_camera, ImU32 colour,
                 double fov_length, bool draw_fov) {
  glm::dvec2 eye;
  const std::vector<glm::dvec2> corners = camera_outline(world_from_camera, &eye);
  const bool segment = corners.size() == 2;  // 2D: the screen is a segment
  for (std::size_t i = 0; i + (segment ? 1 : 0) < corners.size(); ++i)
    draw->AddLine(m.to_screen(corners[i]), m.to_screen(corners[(i + 1) % corners.size()]), colour,
                  segment ? 4.0f : 3.0f);
  if (draw_fov)
    for (const glm::dvec2& corner : corners) {
      const glm::dvec2 along = corner - eye;
      const double length = glm::length(along);
      if (length > 0) draw->AddLine(m.to_screen(eye), m.to_screen(eye + along * (fov_length / length)), (colour & 0x00FFFFFF) | 0x70000000, 1.0f);
    }
  draw->AddCircleFilled(m.to_screen(eye), 5.0f, colour == kScreenColour ? kEyeColour : colour);
}

// The 3D construction's intermediate camera seen from above (construction_view.h). Axes that point straight
// up or down (the view before R_y tilts it) shrink to a point: marked ⊗ (into the ground) or ⊙ (out of it).
void draw_construction_3d(ImDrawList* draw, const OverheadMapping& m, const glm::dmat4& world_from_camera,
                          const PlacedLabels& placed, const std::vector<ScreenDisc>& avoid,
                          const std::vector<ScreenDisc>& discs, Language language, WidgetRects* label_rects) {
  constexpr double kAxisLength = kConstructionAxisLength;
  auto colour = [](ConstructionPart part) {
    const glm::vec4 c = construction_colour(part);
    return IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), int(c.a * 255));
  };
  const std::vector<ConstructionSegment> segments = construction_camera(world_from_camera, kAxisLength);
  for (const ConstructionSegment& segment : segments)  // a dark halo first: readable over any disc
    if (segment.part != ConstructionPart::field_edge)
      draw->AddLine(m.to_screen(xy(segment.from)), m.to_screen(xy(segment.to)), IM_COL32(0, 0, 0, 200), 5.0f);
  for (const ConstructionSegment& segment : segments) {
    const ImVec2 from = m.to_screen(xy(segment.from)), to = m.to_screen(xy(segment.to));
    const bool axis = segment.part == ConstructionPart::right_axis ||
                      segment.part == ConstructionPart::up_axis ||
                      segment.part == ConstructionPart::view_axis;
    const float width = segment.part == ConstructionPart::top_edge ? 4.0f
                        : axis                                     ? 2.5f
                        : segment.part == ConstructionPart::screen ? 3.0f
                                                                   : 1.0f;
    draw->AddLine(from, to, colour(segment.part), width);
    if (!axis) continue;
    const double projected = glm::length(xy(segment.to - segment.from)) / kAxisLength;
    if (projected > 0.2) {
      draw->AddCircleFilled(to, 3.5f, colour(segment.part));  // the arrow's head
    } else {  // (almost) vertical: a circle with a cross (down, away from the viewer) or a dot (up)
      draw->AddCircle(from, 8.0f, colour(segment.part), 16, 2.0f);
      if (segment.to.z < segment.from.z) {
        draw->AddLine({from.x - 5, from.y - 5}, {from.x + 5, from.y + 5}, colour(segment.part), 2.0f);
        draw->AddLine({from.x - 5, from.y + 5}, {from.x + 5, from.y - 5}, colour(segment.part), 2.0f);
      } else {
        draw->AddCircleFilled(from, 3.0f, colour(segment.part));
      }
    }
  }
  // From above, H (the eye pushed back along z) only shows in numbers: a side view (x right, z up) in a
  // corner shows it, and the tilt, at a fixed scale. The eye's height is written beside the eye where a spot
  // off the cameras, the target and the axes' names is near it; else (narrow views at lecture sizes) under
  // the side view's title, which goes inside its frame where it fits there, else on lines of its own above
  // it, as wide as the view.
  const ImVec2 clip_min = draw->GetClipRectMin(), clip_max = draw->GetClipRectMax();
  const glm::dvec3 eye = eye_of(world_from_camera);
  const ImVec2 at = m.to_screen(xy(eye));
  draw->AddCircleFilled(at, 5.0f, kConstructionColour);
  const std::string height = trf(language, "eye E: z = %.2f", eye.z);
  const ImVec2 height_size = ImGui::CalcTextSize(height.c_str());
  std::vector<LabelBox> taken;
  for (const auto& [q, size] : placed) taken.push_back({q, size});
  const std::optional<ImVec2> height_spot =
      label_beside(at, {1.0, -1.0}, height_size, clip_min, clip_max, taken, avoid, kLabelRings);
  const bool beside_eye = height_spot.has_value();
  const ImVec2 height_at = height_spot.value_or(ImVec2{});
  if (beside_eye) taken.push_back({height_at, height_size});

  // The side view with its title: in the first corner (bottom-left, bottom-right, top-left, top-right) or
  // edge's middle, at full size, then smaller, that covers no camera, no target, no axis name and not the eye's label, and of
  // those the first that covers no disc either (from above, a ground's disc may cover the whole view).
  const std::string side_title = beside_eye ? tr(language, "side view: x →, z ↑") : std::string(tr(language, "side view: x →, z ↑")) + "\n" + height;
  struct SideBox {
    ImVec2 low, high, title_at;
    FittedLabel title;
    bool title_inside;
    LabelBox whole() const {
      const ImVec2 top{std::min(low.x, title_at.x - 2), std::min(low.y, title_at.y - 1)};
      return {top, {std::max(high.x, title_at.x + title.size.x + 2) - top.x, high.y - top.y}};
    }
  };
  const float largest_side = std::min(170.0f, 0.4f * std::min(clip_max.x - clip_min.x, clip_max.y - clip_min.y));
  // Spots along the view's edges: the four corners, then the middles of the edges. fx, fy: 0 left / top,
  // 1 right / bottom.
  static constexpr std::pair<float, float> kSpots[] = {{0, 1}, {1, 1}, {0, 0}, {1, 0}, {0.5f, 1}, {0.5f, 0}, {0, 0.5f}, {1, 0.5f}};
  auto side_box = [&](float side, int spot) {
    SideBox box;
    const auto [fx, fy] = kSpots[spot];
    const bool right = fx > 0.75f;
    box.title_inside = ImGui::CalcTextSize(side_title.c_str()).x <= side - 8;
    // Above the frame: as wide as the frame (smaller, on two lines), so that the pair takes one corner.
    box.title = fit_label(side_title, box.title_inside ? side - 8 : std::max(side, kMinTitleWidth),
                          box.title_inside ? 1.0f : kInsetFontScale);
    const float above = box.title_inside ? 0.0f : box.title.size.y + 4;  // the title's lines over the frame
    const float x = clip_min.x + 6 + fx * (clip_max.x - clip_min.x - 12 - side);
    const float y = clip_min.y + 6 + above + fy * (clip_max.y - clip_min.y - 12 - above - side);
    box.low = {x, y};
    box.high = {x + side, y + side};
    const float title_x = std::clamp(box.title_inside || !right ? x + 4 : x + side - 4 - box.title.size.x,
                                     clip_min.x + 4, std::max(clip_min.x + 4, clip_max.x - 4 - box.title.size.x));
    box.title_at = box.title_inside ? ImVec2{x + 4, y + 2} : ImVec2{title_x, y - box.title.size.y - 4};
    return box;
  };
  auto meets = [](const LabelBox& box, const std::vector<ScreenDisc>& marks) {
    return std::any_of(marks.begin(), marks.end(), [&](const ScreenDisc& d) { return box_meets_disc(box, d); });
  };
  auto covers_label = [&](const LabelBox& box) {
    return std::any_of(taken.begin(), taken.end(), [&](const LabelBox& q) {
      return box.at.x < q.at.x + q.size.x && q.at.x < box.at.x + box.size.x && box.at.y < q.at.y + q.size.y &&
             q.at.y < box.at.y + box.size.y;
    });
  };
  std::optional<SideBox> chosen, clear_of_marks;
  for (const float part : {1.0f, 0.8f, 0.6f, 0.45f}) {
    for (int spot = 0; spot < int(std::size(kSpots)) && !chosen; ++spot) {
      const SideBox box = side_box(part * largest_side, spot);
      const LabelBox whole = box.whole();
      if (whole.at.y < clip_min.y || covers_label(whole) || meets(whole, avoid)) continue;
      if (!clear_of_marks) clear_of_marks = box;
      if (!meets(whole, discs)) chosen = box;
    }
    if (chosen) break;
  }
  // Nowhere clear (a view smaller than the camera's drawing): the bottom-left corner at full size.
  const SideBox box = chosen ? *chosen : clear_of_marks ? *clear_of_marks : side_box(largest_side, 0);
  const ImVec2 low = box.low, high = box.high, title_at = box.title_at;
  const float side = high.x - low.x;
  const bool title_inside = box.title_inside;
  const FittedLabel& title = box.title;
  if (label_rects) {
    const LabelBox whole = box.whole();
    (*label_rects)["###label_side_view"] = {whole.at.x, whole.at.y, whole.at.x + whole.size.x, whole.at.y + whole.size.y};
    if (beside_eye)
      (*label_rects)["###label_eye_height"] = {height_at.x, height_at.y, height_at.x + height_size.x,
                                               height_at.y + height_size.y};
  }
  draw->AddRectFilled(low, high, IM_COL32(15, 15, 22, 230));
  draw->AddRect(low, high, IM_COL32(170, 175, 190, 255));
  // Above the frame the lines lie over the construction (discs, the camera): a dark backing keeps them readable.
  const auto backing = [&](ImVec2 at, ImVec2 size) {
    draw->AddRectFilled({at.x - 2, at.y - 1}, {at.x + size.x + 2, at.y + size.y + 1}, IM_COL32(15, 15, 22, 215));
  };
  if (!title_inside) backing(title_at, title.size);
  draw->AddText(ImGui::GetFont(), title.font_size, title_at, IM_COL32(200, 200, 210, 255), title.text.c_str());
  if (beside_eye) {
    backing(height_at, height_size);
    draw->AddText(height_at, kConstructionColour, height.c_str());
  }

  double reach = 1.0;
  for (const ConstructionSegment& segment : segments)
    reach = std::max({reach, std::abs(segment.from.x), std::abs(segment.from.z), std::abs(segment.to.x),
                      std::abs(segment.to.z)});
  reach = std::pow(2.0, std::ceil(std::log2(reach)));  // steps of the scale, so that it rarely changes
  const float scale = 0.45f * side / float(reach);
  const ImVec2 centre{0.5f * (low.x + high.x), 0.5f * (low.y + high.y) + 6};
  auto side_point = [&](glm::dvec3 p) {
    return ImVec2{centre.x + scale * float(p.x), centre.y - scale * float(p.z)};
  };
  draw->PushClipRect(low, high, true);
  draw->AddLine({low.x, centre.y}, {high.x, centre.y}, IM_COL32(255, 255, 255, 40));
  for (const ConstructionSegment& segment : segments)
    draw->AddLine(side_point(segment.from), side_point(segment.to), colour(segment.part),
                  segment.part == ConstructionPart::field_edge ? 1.0f : 2.0f);
  draw->AddCircleFilled(side_point(eye), 4.0f, kConstructionColour);
  draw->PopClipRect();
}

// What the view's labels must leave in sight, as small discs on screen: the camera (its screen and eye), the
// target, and during the construction the intermediate camera (its screen, eye and axes).
std::vector<ScreenDisc> content_marks(const OverheadMapping& m, const Lesson& state) {
  std::vector<ScreenDisc> marks;
  auto outline = [&](const auto& world_from_camera) {
    glm::dvec2 eye;
    const std::vector<glm::dvec2> corners = camera_outline(world_from_camera, &eye);
    for (std::size_t i = 0; i + (corners.size() == 2 ? 1 : 0) < corners.size(); ++i)
      mark_segment(marks, m.to_screen(corners[i]), m.to_screen(corners[(i + 1) % corners.size()]));
    marks.push_back({m.to_screen(eye), 7.0f});
  };
  std::visit([&](const auto& view) { outline(view.camera.world_from_camera()); }, state.view);
  marks.push_back({m.to_screen(active_target_xy(state)), 9.0f});
  if (shows_construction(state))
    std::visit(overloaded{[&](const View2D& view) {
                            outline(construction_pose(view.camera.placement(), state.construction_step,
                                                      state.construction_fraction));
                          },
                          [&](const View3D& view) {
                            const glm::dmat4 pose = construction_pose(view.camera.placement(), state.construction_step,
                                                                      state.construction_fraction);
                            for (const ConstructionSegment& segment : construction_camera(pose, kConstructionAxisLength))
                              if (segment.part != ConstructionPart::field_edge)
                                mark_segment(marks, m.to_screen(xy(segment.from)), m.to_screen(xy(segment.to)));
                            marks.push_back({m.to_screen(xy(eye_of(pose))), 9.0f});
                          }},
               state.view);
  return marks;
}

// The 2D screen segment's landmarks: pixel k = 0 (the handout's first pixel, at canonical x near -1: the
// eye's right) and the other end, the eye's left, where the colour bar's column 0 is; and, when the pixels
// are few enough to tell apart, their edges as ticks (the rays leave from the centres between them, or from
// the ticks under the "pixel edges" mistake). Each label sits beside its own end, whatever the font's size:
// its long text where it fits, else its short one, off the discs, the markers and the other label.
void mark_screen_segment(ImDrawList* draw, const OverheadMapping& m, const Lesson& state, const Camera2D& camera,
                         const PlacedLabels& names, const std::vector<ScreenDisc>& marks, WidgetRects* label_rects) {
  const glm::dmat3& world_from_camera = camera.world_from_camera();
  auto at = [&](double x) { return m.to_screen(transform_point(world_from_camera, glm::dvec2(x, 0.0))); };
  const int n = camera.pixel_count();
  const ImVec2 minus = at(-1.0), plus = at(1.0);
  glm::dvec2 along{plus.x - minus.x, plus.y - minus.y};
  const double length = glm::length(along);
  if (length < 1.0) return;
  along /= length;
  const glm::dvec2 normal{-along.y, along.x};
  if (n <= 64 && length / n >= 4.0)
    for (int i = 0; i <= n; ++i) {
      const ImVec2 p = at(-1.0 + 2.0 * i / n);
      draw->AddLine({p.x - float(5 * normal.x), p.y - float(5 * normal.y)},
                    {p.x + float(5 * normal.x), p.y + float(5 * normal.y)}, kScreenColour, 1.5f);
    }
  const ImVec2 first = at(camera.canonical_pixel(0).x);
  draw->AddCircleFilled(first, 5.0f, kFirstPixelColour);

  // What a label must not cover: every disc, the cameras, the target, both ends' markers and the axes' names.
  std::vector<ScreenDisc> avoid = marks;
  for (const gl::Disc& disc : overhead_discs(state)) avoid.push_back({m.to_screen(disc.centre), float(disc.radius) * m.scale});
  avoid.push_back({first, 6.0f});
  std::vector<LabelBox> placed;
  for (const auto& [q, size] : names) placed.push_back({q, size});
  auto label = [&](ImVec2 end, glm::dvec2 outward, const char* long_text, const char* short_text, const char* id) {
    // The long text only right at the end (far from it, it would read as the other end's); else the short.
    const char* text = long_text;
    std::optional<ImVec2> spot = label_beside(end, outward, ImGui::CalcTextSize(long_text), draw->GetClipRectMin(),
                                              draw->GetClipRectMax(), placed, avoid, 2);
    if (!spot) {
      text = short_text;
      spot = label_beside(end, outward, ImGui::CalcTextSize(short_text), draw->GetClipRectMin(),
                          draw->GetClipRectMax(), placed, avoid, kLabelRings);
    }
    if (!spot)  // farther out, rather than on a disc: the line to its end says whose it is
      spot = label_beside(end, outward, ImGui::CalcTextSize(short_text), draw->GetClipRectMin(),
                          draw->GetClipRectMax(), placed, avoid, 4 * kLabelRings);
    const ImVec2 size = ImGui::CalcTextSize(text);
    // Nowhere free (a view smaller than the text): beyond the end, kept inside the view and off the other.
    const ImVec2 top_left =
        spot ? *spot
             : place_label({end.x + float(outward.x * 12.0) - (outward.x < 0 ? size.x : 0.0f), end.y - 0.5f * size.y},
                           size, draw->GetClipRectMin(), draw->GetClipRectMax(), boxes_as_pairs(placed));
    // Pushed away from its end by discs: a thin line from the end to the label says whose it is.
    const ImVec2 nearest{std::clamp(end.x, top_left.x, top_left.x + size.x), std::clamp(end.y, top_left.y, top_left.y + size.y)};
    if (std::hypot(nearest.x - end.x, nearest.y - end.y) > 0.6f * size.y)
      draw->AddLine(end, nearest, (kFirstPixelColour & 0x00FFFFFF) | 0xA0000000, 1.0f);
    draw->AddText(top_left, kFirstPixelColour, text);
    placed.push_back({top_left, size});
    if (label_rects) (*label_rects)[id] = {top_left.x, top_left.y, top_left.x + size.x, top_left.y + size.y};
  };
  label(minus, -along, tr(state.language, "k = 0 (eye's right)"), tr(state.language, "k = 0"), "###label_k0");
  label(plus, along, tr(state.language, "column 0 (eye's left)"), tr(state.language, "column 0"), "###label_column0");
}

// Primary rays of the 2D bar (or of the middle image row in 3D): the same rays as the caster's, each drawn to
// the hit the caster found, in the colour it returned; misses faint, to the edge of the view. A few rays are
// lines; many are drawn as translucent wedges between neighbours that hit the same object, so that a dense
// fan reads as a beam instead of hatching over the discs.
void draw_fan(ImDrawList* draw, const OverheadMapping& m, const Lesson& state, const CastCache& cast,
              double far_length) {
  const std::vector<InspectedRay> fan = primary_ray_fan(state, cast, kMaxFanRays);
  const Rgb8 miss_colour{200, 200, 200};
  auto colour = [&](const InspectedRay& ray) {
    return ray.hit.id >= 0 ? cast.map.colour_at(ray.pixel.row, ray.pixel.column) : miss_colour;
  };
  auto from = [&](const InspectedRay& ray) { return m.to_screen(xy(ray.origin)); };
  auto to = [&](const InspectedRay& ray) { return m.to_screen(xy(ray.end(far_length))); };
  if (fan.size() <= std::size_t(kMaxFanLines)) {
    for (const InspectedRay& ray : fan) {
      const bool missed = ray.hit.id < 0;
      draw->AddLine(from(ray), to(ray), colour_of(colour(ray), missed ? 70 : 230), missed ? 1.0f : 1.5f);
      if (!missed) draw->AddCircleFilled(to(ray), 2.5f, colour_of(colour(ray)));
    }
    return;
  }
  // Without anti-aliased edges: the faint seams between neighbouring wedges would themselves read as
  // hatching.
  const ImDrawListFlags flags = draw->Flags;
  draw->Flags &= ~ImDrawListFlags_AntiAliasedFill;
  for (std::size_t i = 0; i + 1 < fan.size(); ++i) {
    const InspectedRay &a = fan[i], &b = fan[i + 1];
    if (a.hit.id != b.hit.id) continue;
    const int alpha = a.hit.id < 0 ? 14 : 70;
    draw->AddTriangleFilled(from(a), to(a), to(b), colour_of(colour(a), alpha));
    draw->AddTriangleFilled(from(a), to(b), from(b), colour_of(colour(a), alpha));
  }
  draw->Flags = flags;
  for (std::size_t i = 0; i < fan.size(); ++i) {  // the edges of each beam, where the object changes
    const bool edge = i == 0 || i + 1 == fan.size() || fan[i - 1].hit.id != fan[i].hit.id ||
                      fan[i + 1].hit.id != fan[i].hit.id;
    if (edge)
      draw->AddLine(from(fan[i]), to(fan[i]), colour_of(colour(fan[i]), fan[i].hit.id < 0 ? 60 : 200), 1.0f);
  }
}
}  // namespace

std::vector<std::pair<ImVec2, ImVec2>> boxes_as_pairs(const std::vector<LabelBox>& boxes) {
  std::vector<std::pair<ImVec2, ImVec2>> pairs;
  for (const LabelBox& box : boxes) pairs.push_back({box.at, box.size});
  return pairs;
}

bool box_meets_disc(const LabelBox& box, const ScreenDisc& disc) {
  const float x = std::clamp(disc.centre.x, box.at.x, box.at.x + box.size.x);
  const float y = std::clamp(disc.centre.y, box.at.y, box.at.y + box.size.y);
  const float dx = x - disc.centre.x, dy = y - disc.centre.y;
  return dx * dx + dy * dy < disc.radius * disc.radius;
}

std::optional<ImVec2> label_beside(ImVec2 anchor, glm::dvec2 outward, ImVec2 size, ImVec2 low, ImVec2 high,
                                   const std::vector<LabelBox>& placed, const std::vector<ScreenDisc>& avoid,
                                   int rings) {
  const glm::dvec2 o = glm::length(outward) > 0 ? glm::normalize(outward) : glm::dvec2(1, 0);
  // Half the box's extent along a unit direction: a box centred at anchor + v·(gap + extent(v)) starts gap
  // pixels from the anchor along v.
  const auto extent = [&](glm::dvec2 v) { return std::abs(v.x) * 0.5 * size.x + std::abs(v.y) * 0.5 * size.y; };
  const glm::dvec2 a{anchor.x, anchor.y};
  const auto overlaps = [](const LabelBox& p, const LabelBox& q) {
    return p.at.x < q.at.x + q.size.x && q.at.x < p.at.x + p.size.x && p.at.y < q.at.y + q.size.y &&
           q.at.y < p.at.y + p.size.y;
  };
  // Beyond the end first, then turning away from that direction either way, 30° at a time.
  constexpr double kTurns[] = {0, 30, -30, 60, -60, 90, -90, 120, -120, 150, -150};
  for (int ring = 0; ring < rings; ++ring) {
    const double gap = 4.0 + ring * 0.5 * size.y;  // half a line further each time
    for (const double turn : kTurns) {
      const double c = std::cos(glm::radians(turn)), s = std::sin(glm::radians(turn));
      const glm::dvec2 v{c * o.x - s * o.y, s * o.x + c * o.y};
      glm::dvec2 centre = a + v * (gap + extent(v));
      // Never reaching back past the anchor towards the segment's other end (it would read as that end's).
      const double back = glm::dot(centre - a, o) - extent(o);
      if (back < -4.0) centre += o * (-4.0 - back);
      const LabelBox box{{float(centre.x - 0.5 * size.x), float(centre.y - 0.5 * size.y)}, size};
      const bool inside = box.at.x >= low.x + 2 && box.at.y >= low.y + 2 && box.at.x + size.x <= high.x - 2 &&
                          box.at.y + size.y <= high.y - 2;
      if (!inside) continue;
      if (std::any_of(placed.begin(), placed.end(), [&](const LabelBox& other) { return overlaps(box, other); }))
        continue;
      if (std::any_of(avoid.begin(), avoid.end(), [&](const ScreenDisc& d) { return box_meets_disc(box, d); })) continue;
      return box.at;
    }
  }
  return std::nullopt;
}

ImVec2 place_label(ImVec2 wanted, ImVec2 size, ImVec2 low, ImVec2 high,
                   const std::vector<std::pair<ImVec2, ImVec2>>& placed) {
  // Inside the view, never cut.
  const auto inside = [&](ImVec2 p) {
    return ImVec2{std::clamp(p.x, low.x + 2, std::max(low.x + 2, high.x - size.x - 2)),
                  std::clamp(p.y, low.y + 2, std::max(low.y + 2, high.y - size.y - 2))};
  };
  const auto overlaps = [&](ImVec2 p) { return overlaps_any(p, size, placed); };
  const ImVec2 start = inside(wanted);
  const int lines = int((high.y - low.y) / (size.y + 2)) + 1;  // every line of the view, both ways
  for (int step = 0; step <= 2 * lines; ++step) {
    const float shift = float((step + 1) / 2) * (size.y + 2) * (step % 2 ? 1.0f : -1.0f);  // 0, +1, -1, +2…
    const ImVec2 p = inside({start.x, start.y + shift});
    if (!overlaps(p)) return p;
  }
  return start;  // nowhere free: where it was wanted
}

// A least-significant-digit radix sort on the doubles' bits, 11 at a time (stable, so ties keep their order),
// skipping a digit every key shares. Not std::stable_sort through the objects: a cache miss a comparison,
// 225 ms for 10⁶ spheres (a std::sort of (key, index) pairs: 88 ms), a frame's worth of the page's first image
// after opening them.
std::vector<std::uint32_t> lowest_first(const std::vector<double>& keys) {
  const std::size_t n = keys.size();
  std::vector<std::uint64_t> bits(n), bits_next(n);
  std::vector<std::uint32_t> order(n), order_next(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double key = keys[i] == 0.0 ? 0.0 : keys[i];  // -0 ties with +0, as under <
    std::uint64_t b;
    std::memcpy(&b, &key, sizeof b);
    // Order-preserving: the negatives' bits reversed, below the positives' (no NaN in a valid scene).
    bits[i] = b >> 63 ? ~b : b | (std::uint64_t(1) << 63);
    order[i] = std::uint32_t(i);
  }
  constexpr int kDigitBits = 11;  // 2048 counters: in L1, and cheap to clear for the few discs of a 2D bar
  constexpr std::uint64_t kDigit = (1u << kDigitBits) - 1;
  std::vector<std::size_t> start(kDigit + 2);
  for (int shift = 0; shift < 64; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0);
    for (std::size_t i = 0; i < n; ++i) ++start[((bits[i] >> shift) & kDigit) + 1];
    if (n == 0 || *std::max_element(start.begin(), start.end()) == n) continue;  // one digit for all
    for (std::size_t d = 0; d <= kDigit; ++d) start[d + 1] += start[d];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t at = start[(bits[i] >> shift) & kDigit]++;
      bits_next[at] = bits[i];
      order_next[at] = order[i];
    }
    bits.swap(bits_next);
    order.swap(order_next);
  }
  return order;
}

std::vector<gl::Disc> overhead_discs(const Lesson& state) {
  std::vector<gl::Disc> discs;
  std::visit(
      [&](const auto& view) {
        const auto& objects = objects_of(view.scene);
        std::vector<double> tops(objects.size());
        for (std::size_t i = 0; i < objects.size(); ++i) tops[i] = top_of(objects[i]);
        const std::vector<std::uint32_t> order = lowest_first(tops);
        discs.reserve(order.size());
        for (std::uint32_t i : order) discs.push_back({xy(objects[i].centre), objects[i].radius, objects[i].colour});
      },
      state.view);
  return discs;
}

void draw_overhead(ImDrawList* draw, const OverheadMapping& m, const Lesson& state, const CastCache& cast,
                   const std::optional<InspectedRay>& inspected, gl::DiscLayer* discs, WidgetRects* label_rects) {
  const ImVec2 clip_min = draw->GetClipRectMin(), clip_max = draw->GetClipRectMax();
  draw->AddRectFilled(clip_min, clip_max, colour_of(std::visit([](const auto& view) { return view.scene.background; }, state.view)));
  PlacedLabels placed;  // the labels drawn so far: the next ones go beside them
  draw_axes(draw, m, clip_min, clip_max, placed, label_rects);
  const double far_length = 3.0 * camera_reach(state);

  // One texel per framebuffer pixel (a HiDPI window has more of them than UI pixels).
  const ImVec2 density = ImGui::GetIO().DisplayFramebufferScale;
  gl::DiscPlacement placement;
  placement.origin = {(m.origin.x - clip_min.x) * density.x, (m.origin.y - clip_min.y) * density.y};
  placement.scale = m.scale * density.x;
  placement.width = int(std::lround((clip_max.x - clip_min.x) * density.x));
  placement.height = int(std::lround((clip_max.y - clip_min.y) * density.y));
  if (discs && placement.width > 0 && placement.height > 0)  // none: the null host draws no texture
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(discs->texture(placement))), clip_min,
                   clip_max);

  const bool final_camera = !shows_construction(state);
  if (final_camera) draw_fan(draw, m, state, cast, far_length);
  std::visit([&](const auto& view) {
    draw_camera(draw, m, view.camera.world_from_camera(), kScreenColour, far_length, true);
  }, state.view);
  // The handout's frames: the canonical camera after the first `step` factors (a: none … d: all).
  const int step = state.construction_step;
  const std::vector<ScreenDisc> marks = content_marks(m, state);
  std::visit(overloaded{[&](const View2D& view) {
                          mark_screen_segment(draw, m, state, view.camera, placed, marks, label_rects);
                          if (!final_camera)
                            draw_camera(draw, m, construction_pose(view.camera.placement(), step, state.construction_fraction),
                                        kConstructionColour, far_length * 0.3, true);
                        },
                        [&](const View3D& view) {  // a frame of axes: the 3D steps turn it
                          if (!final_camera) {
                            // The discs a corner's side view would rather not cover (up to a few thousand: the
                            // check is per frame).
                            std::vector<ScreenDisc> discs;
                            if (view.scene.spheres.size() <= kDiscsAvoidedUpTo)
                              for (const Sphere& sphere : view.scene.spheres)
                                discs.push_back({m.to_screen(xy(sphere.centre)), float(sphere.radius) * m.scale});
                            draw_construction_3d(draw, m, construction_pose(view.camera.placement(), step, state.construction_fraction), placed,
                                                 marks, discs, state.language, label_rects);
                          }
                        }},
             state.view);
  const glm::dvec2 target = active_target_xy(state);
  draw_cross(draw, m.to_screen(target), 7.0f, kTargetColour);

  if (inspected) {
    const ImVec2 end = m.to_screen(xy(inspected->end(far_length)));
    draw->AddLine(m.to_screen(xy(inspected->origin)), end, kInspectedRayColour, 3.0f);
    if (inspected->hit.id >= 0) draw->AddCircle(end, 6.0f, kInspectedRayColour, 16, 2.0f);
  }
}

// ---- picking -------------------------------------------------------------------------------------------
int object_under(const OverheadMapping& m, const Lesson& state, ImVec2 screen_point) {
  const glm::dvec2 p = m.to_world(screen_point);
  int best = -1;
  double best_top = -1e300;
  std::visit([&](const auto& view) {
    const auto& objects = objects_of(view.scene);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const double top = top_of(objects[i]);
      // >=: of discs as high, the later one is drawn over the others (overhead_discs' stable order)
      if (glm::length(xy(objects[i].centre) - p) <= objects[i].radius && top >= best_top) best = int(i), best_top = top;
    }
  }, state.view);
  return best;
}

}  // namespace raycam::ui
