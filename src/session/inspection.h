// The rays behind the pixels, with every quantity of the handout's exercise 2: the ray inspector and the fans
// of rays drawn in the overhead and observer views. Hits are the ones the caster found (the colour map's
// ids), with t from the caster's intersection formula on the very same ray, so that every view draws what the
// image shows, classic mistakes included (a missed ray in a view is a background pixel in the image).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "session/app_state.h"

namespace raycam::session {

struct InspectedRay {
  PixelIndex pixel;                     // image row and column
  int k = 0;                            // 2D: the handout's pixel index (column = n-1-k)
  glm::dvec3 canonical_pixel{0.0};      // P_k^0 (z = 0; 2D uses x, y)
  glm::dvec3 canonical_direction{0.0};  // u_k^0 = P_k^0 - E0
  glm::dvec3 origin{0.0};               // P_k = M_d·P_k^0
  glm::dvec3 direction{0.0};            // u_k (unit, unless the "forgot to renormalise" mistake is on)
  Hit hit;                              // the map's object and t along `direction` (the caster's formula)
  glm::dvec3 end(double miss_length) const {  // the hit point as the caster computed it, or a far point
    return origin +
           direction * (hit.id >= 0 && hit.t < kNoHit<double> ? hit.t : miss_length / glm::length(direction));
  }
};

// The pixel must be inside the current image.
InspectedRay inspect_pixel(const Lesson& state, const CastCache& cast, PixelIndex pixel);
// The pixel to inspect this frame: hovered, else pinned (if still inside the image).
std::optional<PixelIndex> active_pixel(const Lesson& state, const CastCache& cast);

// The rays of the 2D bar, or of the middle image row in 3D, at most `max_rays` of them evenly sampled, in
// column order (column 0 = the eye's left). The overhead and the observer views draw these same rays.
std::vector<InspectedRay> primary_ray_fan(const Lesson& state, const CastCache& cast, int max_rays);

}  // namespace raycam::session
