// The ray behind one pixel, with every quantity of the handout's exercise 2, for the ray inspector.
#pragma once

#include <glm/vec3.hpp>

#include "app_state.h"

namespace raycam::ui {

struct InspectedRay {
  PixelIndex pixel;                     // image row and column
  int k = 0;                            // 2D: the handout's pixel index (column = n-1-k)
  glm::dvec3 canonical_pixel{0.0};      // P_k^0 (z = 0; 2D uses x, y)
  glm::dvec3 canonical_direction{0.0};  // u_k^0 = P_k^0 - E0
  glm::dvec3 origin{0.0};               // P_k = M_d·P_k^0
  glm::dvec3 direction{0.0};            // u_k (unit)
  Hit hit;                              // nearest object and t
};

// The pixel must be inside the current image.
InspectedRay inspect_pixel(const AppState& state, PixelIndex pixel);
// The pixel to inspect this frame: hovered, else pinned (if still inside the image).
std::optional<PixelIndex> active_pixel(const AppState& state);

}  // namespace raycam::ui
