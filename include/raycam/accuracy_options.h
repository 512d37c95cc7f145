// The accuracy knobs as command-line flags, for any subcommand that renders (`render`, `bench accuracy`):
//   --precision float|double|long-double   --intersect naive|stable   --spp N   --frame world|relative
//   --placement orbit|arccos|stable        --exact (2D: the exact, area-weighted bar)
// A subcommand calls parse_accuracy_flag() in its argument loop (like parse_view_flag) and, when any knob was
// given, renders with render_with_accuracy() instead of cast_primary_rays(). Without knobs nothing changes.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "raycam/colour_map.h"
#include "raycam/reference_caster.h"
#include "raycam/view_setup.h"

namespace raycam {

enum class PlacementRoute { orbit, arccos, stable };

struct AccuracyFlags {
  ReferenceOptions options;                          // scalar, formula, spp, frame
  PlacementRoute placement = PlacementRoute::orbit;  // arccos/stable: free placement from P and C
  bool exact = false;                                // 2D only: exact coverage instead of samples
  bool given = false;                                // any accuracy flag seen
};

// If args[i] is an accuracy flag, consumes it and its value (advancing i) and returns true; otherwise
// returns false and leaves i. Throws std::invalid_argument naming the flag and the accepted values.
bool parse_accuracy_flag(const std::vector<std::string>& args, std::size_t& i, AccuracyFlags& flags);

const char* accuracy_flags_help();

// The colour map with the knobs applied: the camera re-placed by the chosen route (same P, C, d_f), cast by
// reference_cast (colours are the samples' mean, rounded; ids from the pixel-centre ray) or, with --exact in
// 2D, the exact bar. Throws std::invalid_argument for --exact in 3D or a non-square --spp in 3D.
ColourMap render_with_accuracy(const ViewSetup& setup, const AccuracyFlags& flags);
// The same for a camera already placed (the app's): the knobs but the placement route.
ColourMap render_with_accuracy(const Camera2D& camera, const Scene2D& scene, const AccuracyFlags& flags);
ColourMap render_with_accuracy(const Camera3D& camera, const Scene3D& scene, const AccuracyFlags& flags);

}  // namespace raycam
