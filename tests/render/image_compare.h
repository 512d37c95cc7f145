// PNG loading and tolerant comparison for the screenshot tests. A failed comparison writes the actual image
// and a diff image (differing pixels in magenta over a dimmed copy) next to the build.
#pragma once

#include <cstdint>
#include <string>

#include "framebuffer_image.h"

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

}  // namespace raycam::test
