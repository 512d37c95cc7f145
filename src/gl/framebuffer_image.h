// Reading the current framebuffer back into an image (row 0 at the top), and writing it as PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raycam::gl {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // RGBA, row 0 at the top
  const std::uint8_t* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * 4]; }
};

// glReadPixels of the bound framebuffer (GL rows are bottom-up; the image is flipped to top-down).
RgbaImage read_framebuffer(int width, int height);
// Throws std::runtime_error naming the path if it cannot be written.
void write_png(const RgbaImage& image, const std::string& path);

}  // namespace raycam::gl
