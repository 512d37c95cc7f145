// The accuracy knobs (README, "Accuracy"): precision, intersection formula, samples per pixel, frame,
// placement route, the exact 2D bar. The command line sets them through src/flags' caster option group; when
// needs_reference_caster() says so (or the placement route is not the orbit), a command renders with
// render_with_accuracy() instead of cast_primary_rays().
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
};

// The colour map with the knobs applied: the camera re-placed by the chosen route (same P, C, d_f), cast by
// reference_cast (colours are the samples' mean, rounded; ids from the pixel-centre ray) or, with --exact in
// 2D, the exact bar. Throws std::invalid_argument for --exact in 3D or a non-square --spp in 3D.
ColourMap render_with_accuracy(const ViewSetup& setup, const AccuracyFlags& flags);
// The same for a camera already placed (the app's): the knobs but the placement route.
ColourMap render_with_accuracy(const Camera2D& camera, const Scene2D& scene, const AccuracyFlags& flags);
ColourMap render_with_accuracy(const Camera3D& camera, const Scene3D& scene, const AccuracyFlags& flags);

}  // namespace raycam
