// PNG output of an RgbaImage; kept apart from the GL readback so that image tools need no GL library.
#include <stdexcept>

#include <stb_image_write.h>  // implementation provided by Debian's libstb

#include "framebuffer_image.h"

namespace raycam::gl {

void write_png(const RgbaImage& image, const std::string& path) {
  stbi_flip_vertically_on_write(0);
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4))
    throw std::runtime_error(path + ": cannot write PNG (does the directory exist and is it writable?)");
}

}  // namespace raycam::gl
