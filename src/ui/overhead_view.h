// The overhead views: the world seen from above (2D: the plane itself; 3D: looking down -z), with x to the
// right and y up, drawn with ImGui's draw list so that they look the same in a window and headless; the
// objects' discs are one cached image in that list (gl/disc_layer.h).
#pragma once

#include <imgui.h>

#include <glm/vec2.hpp>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "session/app_state.h"
#include "gl/disc_layer.h"
#include "session/inspection.h"
#include "ui/panel_state.h"

namespace raycam::ui {

// World xy ↦ screen pixels: uniform scale, y flipped (screen y grows downwards).
struct OverheadMapping {
  ImVec2 origin{0.0f, 0.0f};  // screen position of the world origin
  float scale = 1.0f;         // pixels per world unit
  ImVec2 to_screen(glm::dvec2 p) const { return {origin.x + scale * float(p.x), origin.y - scale * float(p.y)}; }
  glm::dvec2 to_world(ImVec2 s) const { return {(s.x - origin.x) / scale, (origin.y - s.y) / scale}; }
};

// Fits the world rectangle of the view (state.overhead_low/high) to the scene's objects near the target,
// the target and the camera (eye and screen). Called when a scene is loaded, the camera reset, on "fit",
// and when the camera or the target would leave the view; never every frame, so that the view holds still
// while the camera moves inside it.
void fit_overhead(const session::Lesson& state, session::Display& display);
// The mapping that shows the state's world rectangle centred in the screen rectangle, with a margin.
OverheadMapping overhead_mapping(const session::Display& display, ImVec2 top_left, ImVec2 size);
// Whether the camera (eye and screen) and the target are inside the view as it is now mapped.
bool camera_and_target_in_view(const session::Lesson& state, const session::Display& display, ImVec2 top_left,
                               ImVec2 size);

// The indices of `keys`, lowest key first, ties in index order (std::stable_sort's order), by a radix sort:
// overhead_discs' order for 10⁶ spheres in 42 ms where sorting through the objects took 225.
std::vector<std::uint32_t> lowest_first(const std::vector<double>& keys);

// Every object's disc seen from above, in drawing order (3D: from the lowest sphere top up, so the highest
// hides the others). Give it to a DiscLayer when the scene changes.
std::vector<gl::Disc> overhead_discs(const session::Lesson& state);

// Draws the view into `draw` (clipped by the caller). `inspected` highlights one ray. `discs` must hold
// overhead_discs(state); null (the null host): no disc texture. `label_rects` (the tests' hook, else null)
// gets where the 2D screen's end labels went.
void draw_overhead(ImDrawList* draw, const OverheadMapping& mapping, const session::Lesson& state,
                   const session::CastCache& cast,
                   const std::optional<session::InspectedRay>& inspected, gl::DiscLayer* discs,
                   WidgetRects* label_rects = nullptr);

// The object whose disc is under a screen point (topmost), or -1.
int object_under(const OverheadMapping& mapping, const session::Lesson& state, ImVec2 screen_point);

// A label's box on screen (top-left, size), and a disc on screen a label must not cover.
struct LabelBox {
  ImVec2 at, size;
};
struct ScreenDisc {
  ImVec2 centre;
  float radius = 0.0f;
};
std::vector<std::pair<ImVec2, ImVec2>> boxes_as_pairs(const std::vector<LabelBox>& boxes);
bool box_meets_disc(const LabelBox& box, const ScreenDisc& disc);

// Where (top-left) a label of `size` goes beside `anchor`, an end of the 2D screen segment (`outward`: the
// direction on screen away from the segment's other end): beyond the end, else turned from there by 30°,
// 60°, … either way, never reaching back past the end towards the other one; 4 px from the end, then half a
// line further for each of `rings` rings. The first spot inside [low, high] that covers no placed label and
// no disc of `avoid`; none when there is no such spot.
std::optional<ImVec2> label_beside(ImVec2 anchor, glm::dvec2 outward, ImVec2 size, ImVec2 low, ImVec2 high,
                                   const std::vector<LabelBox>& placed, const std::vector<ScreenDisc>& avoid,
                                   int rings);

// Where a label of `size` goes at `wanted` (its top-left) so that it stays inside [low, high] and off the
// labels already placed (top-left, size pairs): moved down, then up, a line at a time, past each it meets.
ImVec2 place_label(ImVec2 wanted, ImVec2 size, ImVec2 low, ImVec2 high,
                   const std::vector<std::pair<ImVec2, ImVec2>>& placed);

// Marker colours, shared with the tests that look for them.
inline constexpr ImU32 kEyeColour = IM_COL32(255, 255, 255, 255);
inline constexpr ImU32 kTargetColour = IM_COL32(255, 230, 0, 255);
inline constexpr ImU32 kScreenColour = IM_COL32(0, 230, 255, 255);
inline constexpr ImU32 kInspectedRayColour = IM_COL32(255, 0, 255, 255);
inline constexpr ImU32 kConstructionColour = IM_COL32(255, 150, 40, 255);
inline constexpr ImU32 kFirstPixelColour = IM_COL32(255, 200, 120, 255);  // k = 0 and the eye's left, in 2D
inline constexpr ImU32 kImageFrameColour = IM_COL32(170, 175, 190, 255);  // around the colour bar and image

}  // namespace raycam::ui
