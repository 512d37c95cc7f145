// The classic mistakes students make building the handout's camera, reproducible on purpose: the app's
// toggles show what each does to the image, and `raycam-cli check` renders a case again with them switched
// on (alone and in pairs) to name the mistake a student's program made. One definition serves both.
//
// Each mistake has a stable ID (the names in docs/check.md and in `check --report`, never renamed), the
// dimensions it exists in, and a label and one-line explanation in every language that point to the
// handout's step. The cameras apply the flags (camera2d.cpp, camera3d.cpp) and the plain caster the
// intersection one (ray_caster.cpp); only the mistakes that only move the camera keep the accelerated casters.
#pragma once

#include <cstddef>
#include <string_view>

#include "raycam/languages.h"

namespace raycam {

struct ClassicMistakes {
  bool printed_rotation_sign = false;  // rotation angle from the view vector PC, as printed: looks away
  bool pixel_edges = false;            // P_k^0 = -1 + 2k/n as printed: left pixel edges, image shifts
  bool skip_renormalise = false;       // u_k left scaled by H; the intersection assumes |u| = 1
  bool mirrored = false;               // 2D: pixel k stored at n-1-k; 3D: columns reversed
  bool upside_down = false;            // 3D: roll ψ0 = -π/2 as printed: the image turned half a turn
  bool rows_flipped = false;           // 3D: row 0 at the bottom
  bool degrees_as_radians = false;     // the angles' degree values passed to cos/sin as radians
  bool no_focal_scale = false;         // H(1, d_f) forgotten: the camera acts as d_f = 1
  bool direction_translated = false;   // u_k = M_d·(P_k^0 - E0) transformed as a point (translation added)
  bool eye_origin = false;             // rays start at the eye, not on the screen: objects behind it show
  bool no_t_min = false;               // hits with t < 0 accepted: the smaller root wins, whatever its sign
  bool theta_phi_swapped = false;      // 3D: θ used as φ and φ as θ
  bool res_truncated = false;          // n = floor(res·N) instead of round(res·N)
  bool square_pixels = false;          // 3D: screen stretched to the image's aspect (a look-at camera's habit)
};

// Only the printed rotation sign, as `on` says (the placement's older boolean form).
inline ClassicMistakes rotation_mistake_only(bool on) {
  ClassicMistakes mistakes;
  mistakes.printed_rotation_sign = on;
  return mistakes;
}

// Where a mistake acts: the placement M_d, a pixel's ray (which pixel, where it lies on the canonical screen,
// the ray built from it, the pixel count n), or the caster's hit rule. tests/core/test_classic_mistakes.cpp
// checks each row's hook against what the mistake really changes.
enum class MistakeHook { placement, pixel, hit_rule };

// One row per mistake: everything raycam knows about it, declared once. Adding a mistake takes this row, its
// flag in ClassicMistakes, its effect where its hook is (camera2d.cpp / camera3d.cpp / ray_caster.cpp) and
// its lesson (src/session/mistake_lessons.cpp); docs/architecture.md, "Adding a classic mistake".
struct MistakeInfo {
  const char* id;  // stable: "printed_rotation_sign", …
  bool ClassicMistakes::*flag;
  bool in_2d, in_3d;
  MistakeHook hook;
  // It changes only M_d or n, so the accelerated casters, whose bounds come from the camera's own M_d and
  // pixel count, stay exact with it on (mistakes_change_only_placement).
  bool only_moves_camera;
  // What a check case needs to reveal it (English, for whoever designs the battery: src/check/battery.cpp
  // lists it in such a case's "reveals", and tests/check/test_battery.cpp names this when none does).
  const char* battery_needs;
  LocalText label;        // short, for a checkbox
  LocalText explanation;  // one line, cites the handout's step
};

inline constexpr std::size_t kClassicMistakeCount = 14;
// Every mistake, in the order the app lists them and the diagnosis breaks ties.
extern const MistakeInfo kClassicMistakes[kClassicMistakeCount];

// Whether the mistake exists in a 2D or a 3D camera (`dimension` 2 or 3).
inline bool exists_in(const MistakeInfo& mistake, int dimension) { return dimension == 2 ? mistake.in_2d : mistake.in_3d; }
// nullptr when `id` names no mistake.
const MistakeInfo* find_mistake(std::string_view id);
bool any_mistake(const ClassicMistakes& mistakes);
// True when every mistake that is on only changes M_d or n (the accelerated casters stay exact for them).
bool mistakes_change_only_placement(const ClassicMistakes& mistakes);

}  // namespace raycam
