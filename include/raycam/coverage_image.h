// An image for accuracy work: per pixel, the id seen by the ray through the pixel centre and the
// coverage-weighted mean colour (what an infinitely supersampled box filter would show).
//
// Image order as ColourMap: row-major, row 0 at the top, column 0 at the eye's left; id -1 is background.
// Colours are 8-bit sRGB values averaged linearly in those 8-bit units (no gamma decoding: the error metric
// compares like with like, and a flat-coloured scene has no lighting to get wrong).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "raycam/colour_map.h"
#include "raycam/scene.h"

namespace raycam {

struct CoverageImage {
  int width = 0;
  int height = 0;
  std::vector<int> ids;             // centre-ray id per pixel
  std::vector<glm::dvec3> colours;  // mean colour per pixel, 8-bit units in [0, 255]
};

// Rounded colours and ids as a ColourMap (for PNG output and the app's texture).
ColourMap to_colour_map(const CoverageImage& image);

// Fraction of pixels whose id differs. Throws std::invalid_argument if the sizes differ.
double id_disagreement(const CoverageImage& image, const CoverageImage& reference);
// Mean over pixels and channels of |colour - reference colour|, in 8-bit units. Throws on size mismatch.
double mean_colour_error(const CoverageImage& image, const CoverageImage& reference);

inline glm::dvec3 to_dvec3(Rgb8 c) { return {double(c.r), double(c.g), double(c.b)}; }

}  // namespace raycam
