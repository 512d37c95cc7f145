// PNG loading and tolerant comparison for the screenshot tests. A failed comparison writes the actual image
// and a diff image (differing pixels in magenta over a dimmed copy) next to the build.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl/framebuffer_image.h"

namespace raycam::test {

// Loads a PNG as RGBA (stb_image from Debian's libstb); an empty image if it cannot be read.
gl::RgbaImage load_png(const std::string& path);

struct Difference {
  long differing = 0;  // pixels whose largest channel difference exceeds the threshold
  long compared = 0;
};

// Compares the two images outside the rows [ignore_top, ignore_bottom) (the status line shows timings).
Difference compare(const gl::RgbaImage& a, const gl::RgbaImage& b, int threshold, int ignore_top = -1,
                   int ignore_bottom = -1);
void write_diff(const gl::RgbaImage& actual, const gl::RgbaImage& expected, int threshold, const std::string& path);

// Reference screenshots: strict enough that one changed digit in a panel fails, lenient only where the
// renderer may differ by a stray pixel. The same llvmpipe build renders bit-identical frames, so any real
// change is a cluster of differing pixels (a glyph is ~7×13 pixels and a changed digit moves ≥ 10 of them),
// while rasteriser noise between Mesa builds is isolated pixels.
struct MaskRect {
  int x = 0, y = 0, w = 0, h = 0;
};
struct ScreenshotRules {
  int threshold = 8;             // largest channel difference that still counts as equal
  int tile = 8;                  // differences are counted per tile × tile block
  int max_per_tile = 2;          // more differing pixels than this in one block: a real change
  double max_fraction = 5e-4;    // isolated differing pixels allowed over the whole compared area
  std::vector<MaskRect> masked;  // never compared: ONLY what cannot repeat from run to run (timings)
};
struct ScreenshotDifference {
  long differing = 0, compared = 0;
  int worst_tile_count = 0, worst_tile_x = 0, worst_tile_y = 0;  // the block with most differing pixels
  bool same_size = true;
  bool ok = false;
  std::string summary() const;
};
ScreenshotDifference compare_screenshot(const gl::RgbaImage& actual, const gl::RgbaImage& reference,
                                        const ScreenshotRules& rules);
// The same, and on failure NAME.actual.png and NAME.diff.png (masked regions shown in blue) in the
// working directory.
ScreenshotDifference check_screenshot(const gl::RgbaImage& actual, const std::string& reference_path,
                                      const ScreenshotRules& rules, const std::string& name);

}  // namespace raycam::test
