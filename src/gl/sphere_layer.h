// The observer view's spheres cast on the CPU into a colour and depth layer, for scenes with so many spheres
// that llvmpipe's cost per primitive dominates (10⁵ impostors: ~90 ms of rasterising a frame;
// docs/speed.md). The same picture as sphere.vert/sphere.frag: the nearest hit of the observer's ray through each
// pixel centre, lightly shaded, its window depth kept so that the lines and the screen drawn afterwards are
// hidden by the spheres in front of them.
//
// Pixel (i, j) in GL order: row j = 0 at the bottom; its centre at NDC ((2i + 1)/width − 1, (2j + 1)/height −
// 1).
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "raycam/scene.h"

namespace raycam::gl {

struct SphereLayerView {
  glm::dmat4 view_projection{1.0};
  glm::dvec3 eye{0.0};                        // where view_projection looks from
  glm::dvec3 light_direction{0.0, 0.0, 1.0};  // unit
  int width = 0, height = 0;
  friend bool operator==(const SphereLayerView& a, const SphereLayerView& b) {
    return a.view_projection == b.view_projection && a.eye == b.eye && a.light_direction == b.light_direction &&
           a.width == b.width && a.height == b.height;
  }
};

struct PixelRect {  // a closed range of pixels, empty when x0 > x1 or y0 > y1
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
};

struct SphereLayer {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // alpha 0 where no sphere is seen
  std::vector<float> depth;        // window depth in [0, 1], as gl_FragDepth
  std::vector<int> ids;            // the sphere seen, -1 for none
  std::vector<PixelRect> rects;    // scratch: each sphere's pixels
  std::vector<double> nearest;     // scratch: t of the hit seen, along the unit ray
};

// Keeps the memory of `layer` between calls. Runs on the casters' worker pool (raycam/parallel.h).
void cast_sphere_layer(const std::vector<Sphere>& spheres, const SphereLayerView& view, SphereLayer& layer);

}  // namespace raycam::gl
