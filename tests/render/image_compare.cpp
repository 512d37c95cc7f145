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

namespace {
bool is_masked(const ScreenshotRules& rules, int x, int y) {
  for (const MaskRect& r : rules.masked)
    if (x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h) return true;
  return false;
}
}  // namespace

ScreenshotDifference compare_screenshot(const gl::RgbaImage& actual, const gl::RgbaImage& reference,
                                        const ScreenshotRules& rules) {
  ScreenshotDifference d;
  if (actual.width != reference.width || actual.height != reference.height || actual.width == 0) {
    d.same_size = false;
    return d;
  }
  const int tiles_x = (actual.width + rules.tile - 1) / rules.tile;
  const int tiles_y = (actual.height + rules.tile - 1) / rules.tile;
  std::vector<int> per_tile(std::size_t(tiles_x) * std::size_t(tiles_y), 0);
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      if (is_masked(rules, x, y)) continue;
      ++d.compared;
      if (channel_difference(actual.at(x, y), reference.at(x, y)) <= rules.threshold) continue;
      ++d.differing;
      const std::size_t tile =
          std::size_t(y / rules.tile) * std::size_t(tiles_x) + std::size_t(x / rules.tile);
      if (++per_tile[tile] > d.worst_tile_count) {
        d.worst_tile_count = per_tile[tile];
        d.worst_tile_x = (x / rules.tile) * rules.tile;
        d.worst_tile_y = (y / rules.tile) * rules.tile;
      }
    }
  d.ok = d.worst_tile_count <= rules.max_per_tile &&
         double(d.differing) <= rules.max_fraction * double(d.compared);
  return d;
}

std::string ScreenshotDifference::summary() const {
  if (!same_size) return "the images differ in size (or the reference is missing)";
  return std::to_string(differing) + " of " + std::to_string(compared) +
         " compared pixels differ; the worst " + "block has " + std::to_string(worst_tile_count) + " at (" +
         std::to_string(worst_tile_x) + ", " + std::to_string(worst_tile_y) + ")";
}

ScreenshotDifference check_screenshot(const gl::RgbaImage& actual, const std::string& reference_path,
                                      const ScreenshotRules& rules, const std::string& name) {
  const gl::RgbaImage reference = load_png(reference_path);
  const ScreenshotDifference d = compare_screenshot(actual, reference, rules);
  if (d.ok) return d;
  gl::write_png(actual, name + ".actual.png");
  if (!d.same_size) return d;
  write_diff(actual, reference, rules.threshold, name + ".diff.png");
  gl::RgbaImage diff = load_png(name + ".diff.png");
  for (const MaskRect& r : rules.masked)
    for (int y = std::max(0, r.y); y < std::min(diff.height, r.y + r.h); ++y)
      for (int x = std::max(0, r.x); x < std::min(diff.width, r.x + r.w); ++x) {
        std::uint8_t* p = &diff.pixels[(std::size_t(y) * std::size_t(diff.width) + std::size_t(x)) * 4];
        p[2] = std::uint8_t(std::min(255, p[2] + 96));
      }
  gl::write_png(diff, name + ".diff.png");
  return d;
}

}  // namespace raycam::test
