// PNG output of an RgbaImage; kept apart from the GL readback so that image tools need no GL library.
#include "gl/framebuffer_image.h"
#include "raycam/image_files.h"

namespace raycam::gl {

void write_png(const RgbaImage& image, const std::string& path) {
  write_png_pixels(image.pixels.data(), image.width, image.height, 4, false, path);  // already top-down
}

}  // namespace raycam::gl
