// The overhead view's discs (2D circles, 3D spheres seen from above) as one cached image layer: rasterised on
// the CPU when the view's placement or the scene changes, uploaded as one texture and drawn as one quad.
// Through ImGui's draw lists 10⁵ discs were millions of vertices tessellated and uploaded every frame, and
// as GL instances llvmpipe still paid about a microsecond per disc (docs/speed.md).
//
// Layer pixels: origin at the layer's top-left, y down; pixel (i, j) has its centre at (i + ½, j + ½).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "gl/gl.h"
#include "raycam/scene.h"

namespace raycam::gl {

struct Disc {
  glm::dvec2 centre{0.0};  // world xy
  double radius = 1.0;     // world units
  Rgb8 colour{};
};

// World xy ↦ layer pixels: uniform scale, y flipped (as OverheadMapping).
struct DiscPlacement {
  glm::vec2 origin{0.0f};  // layer pixel of the world origin
  float scale = 1.0f;      // layer pixels per world unit
  int width = 0, height = 0;
  friend bool operator==(const DiscPlacement& a, const DiscPlacement& b) {
    return a.origin == b.origin && a.scale == b.scale && a.width == b.width && a.height == b.height;
  }
};

// Straight-alpha RGBA8, row 0 at the top: each disc, in order (later ones on top), with at least one pixel
// of radius and a one-pixel anti-aliased edge (the coverage of the pixel by the disc, from its centre's
// distance to the circle); transparent elsewhere.
void rasterise_discs(const std::vector<Disc>& discs, const DiscPlacement& placement,
                     std::vector<std::uint8_t>& rgba);

class DiscLayer {
 public:
  DiscLayer() = default;
  ~DiscLayer();
  DiscLayer(const DiscLayer&) = delete;
  DiscLayer& operator=(const DiscLayer&) = delete;

  // Keeps the discs, drawn in this order; call only when the scene changed.
  void set_discs(std::vector<Disc> discs);
  // The layer's texture for this placement, rasterised again only if the placement or the discs changed.
  GLuint texture(const DiscPlacement& placement);

 private:
  std::vector<Disc> discs_;
  std::vector<std::uint8_t> rgba_;
  DiscPlacement drawn_;
  bool stale_ = true;
  GLuint texture_ = 0;
  int texture_width_ = 0, texture_height_ = 0;
};

}  // namespace raycam::gl
