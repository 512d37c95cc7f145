#include "raycam/coverage_image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raycam {

namespace {
void require_same_size(const CoverageImage& a, const CoverageImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image size " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " differs from reference size " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
}

std::uint8_t to_byte(double value) { return std::uint8_t(std::clamp(std::lround(value), 0L, 255L)); }
}  // namespace

ColourMap to_colour_map(const CoverageImage& image) {
  ColourMap map(image.width, image.height, Rgb8{});
  for (std::size_t i = 0; i < map.colours.size(); ++i) {
    const glm::dvec3 c = image.colours[i];
    map.colours[i] = Rgb8{to_byte(c.x), to_byte(c.y), to_byte(c.z)};
    map.ids[i] = image.ids[i];
  }
  return map;
}

double id_disagreement(const CoverageImage& image, const CoverageImage& reference) {
  require_same_size(image, reference);
  if (image.ids.empty()) return 0.0;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < image.ids.size(); ++i) differing += image.ids[i] != reference.ids[i];
  return double(differing) / double(image.ids.size());
}

double mean_colour_error(const CoverageImage& image, const CoverageImage& reference) {
  require_same_size(image, reference);
  if (image.colours.empty()) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < image.colours.size(); ++i) {
    const glm::dvec3 d = image.colours[i] - reference.colours[i];
    sum += std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  }
  return sum / (3.0 * double(image.colours.size()));
}

}  // namespace raycam
