#include "gl/framebuffer_image.h"

#include <cstring>
#include <stdexcept>

#include "gl/gl.h"

namespace raycam::gl {

RgbaImage read_framebuffer(int width, int height) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  std::vector<std::uint8_t> bottom_up(std::size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  image.pixels.resize(bottom_up.size());
  const std::size_t row_bytes = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::memcpy(&image.pixels[std::size_t(y) * row_bytes], &bottom_up[std::size_t(height - 1 - y) * row_bytes], row_bytes);
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;  // the window is opaque
  return image;
}

}  // namespace raycam::gl
