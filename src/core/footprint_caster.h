// The accelerated casters (CastMethod culled, footprint, binned). Same ids as the plain loop: each pixel
// runs the camera's own primary_ray and the same nearest_hit_t over a superset of the objects that can hit
// it, in any order, with the plain loop's answer on a tie (nearer_hit: the lower index).
#pragma once

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/cast_options.h"
#include "raycam/colour_map.h"
#include "raycam/scene.h"

namespace raycam::detail {

// Crossover measured by `raycam-cli bench speed` (docs/speed.md): below it, scanning every visible
// object's box per band beats sorting the objects into bands first.
inline constexpr int kBinnedCrossover = 64;

void cast_accelerated(const Camera2D& camera, const Scene2D& scene, ColourMap& out,
                      const CastOptions& options, CastStats& stats);
void cast_accelerated(const Camera3D& camera, const PackedScene3D& scene, ColourMap& out,
                      const CastOptions& options, CastStats& stats);
// The first stage alone (culling and projection, into the same reused memory); returns the survivors.
int project_visible(const Camera3D& camera, const PackedScene3D& scene, const CastOptions& options);

}  // namespace raycam::detail
