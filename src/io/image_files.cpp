#include "raycam/image_files.h"

#include <stb_image_write.h>  // implementation provided by Debian's libstb

#include <fstream>
#include <stdexcept>
#include <vector>

namespace raycam {

void write_png(const ColourMap& map, const std::string& path, int scale_x, int scale_y) {
  if (map.width <= 0 || map.height <= 0)
    throw std::runtime_error(path + ": cannot write an empty colour map");
  if (scale_x < 1 || scale_y < 1) throw std::invalid_argument("write_png: scale must be >= 1");
  const int width = map.width * scale_x, height = map.height * scale_y;
  std::vector<unsigned char> pixels(std::size_t(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Rgb8 c = map.colour_at(y / scale_y, x / scale_x);
      unsigned char* out = &pixels[(std::size_t(y) * width + x) * 3];
      out[0] = c.r;
      out[1] = c.g;
      out[2] = c.b;
    }
  }
  write_png_pixels(pixels.data(), width, height, 3, false, path);
}

void write_png_pixels(const unsigned char* pixels, int width, int height, int channels, bool bottom_up,
                      const std::string& path) {
  stbi_flip_vertically_on_write(bottom_up ? 1 : 0);  // global in stb: set on every write, and only here
  if (!stbi_write_png(path.c_str(), width, height, channels, pixels, width * channels))
    throw std::runtime_error(path + ": cannot write PNG (does the directory exist and is it writable?)");
}

void write_ids(const ColourMap& map, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  for (int row = 0; row < map.height; ++row) {
    for (int column = 0; column < map.width; ++column) {
      if (column) out << ' ';
      out << map.id_at(row, column);
    }
    out << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace raycam
