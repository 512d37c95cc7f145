// The accuracy knobs (docs/accuracy.md): precision, intersection formula, samples per pixel, frame,
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
#include "raycam/camera2d.h"
#include "raycam/camera3d.h"

namespace raycam {

enum class PlacementRoute { orbit, arccos, stable };

struct AccuracyFlags {
  ReferenceOptions options;                          // scalar, formula, spp, frame
  PlacementRoute placement = PlacementRoute::orbit;  // arccos/stable: free placement from P and C
  bool exact = false;                                // 2D only: exact coverage instead of samples
};

// The colour map with the knobs applied to a placed camera (the placement route is applied by raycam_io's
// render_with_accuracy(ViewSetup)): cast by reference_cast (colours are the samples' mean, rounded; ids from
// the pixel-centre ray) or, with exact in 2D, the exact bar. Throws std::invalid_argument for exact in 3D or a
// non-square spp in 3D.
ColourMap render_with_accuracy(const Camera2D& camera, const Scene2D& scene, const AccuracyFlags& flags);
ColourMap render_with_accuracy(const Camera3D& camera, const Scene3D& scene, const AccuracyFlags& flags);

}  // namespace raycam
