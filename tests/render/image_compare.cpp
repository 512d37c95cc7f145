#include "image_compare.h"

#include <algorithm>
#include <cstdlib>

#include <stb_image.h>  // implementation provided by Debian's libstb

namespace raycam::test {

gl::RgbaImage load_png(const std::string& path) {
  gl::RgbaImage image;
  int channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
  if (!pixels) return {};
  image.pixels.assign(pixels, pixels + std::size_t(image.width) * image.height * 4);
  stbi_image_free(pixels);
  return image;
}

namespace {
int channel_difference(const std::uint8_t* p, const std::uint8_t* q) {
  return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
}
}  // namespace

Difference compare(const gl::RgbaImage& a, const gl::RgbaImage& b, int threshold, int ignore_top, int ignore_bottom) {
  Difference d;
  if (a.width != b.width || a.height != b.height) return {1, 1};
  for (int y = 0; y < a.height; ++y) {
    if (y >= ignore_top && y < ignore_bottom) continue;
    for (int x = 0; x < a.width; ++x) {
      ++d.compared;
      if (channel_difference(a.at(x, y), b.at(x, y)) > threshold) ++d.differing;
    }
  }
  return d;
}

void write_diff(const gl::RgbaImage& actual, const gl::RgbaImage& expected, int threshold, const std::string& path) {
  gl::RgbaImage diff = actual;
  if (actual.width == expected.width && actual.height == expected.height)
    for (int y = 0; y < actual.height; ++y)
      for (int x = 0; x < actual.width; ++x) {
        std::uint8_t* p = &diff.pixels[(std::size_t(y) * actual.width + x) * 4];
        const bool differs = channel_difference(actual.at(x, y), expected.at(x, y)) > threshold;
        for (int c = 0; c < 3; ++c) p[c] = differs ? (c == 1 ? 0 : 255) : std::uint8_t(p[c] / 4);
      }
  gl::write_png(diff, path);
}

}  // namespace raycam::test
