// Writing images (raycam_io, on stb_image_write): the colour map as PNG and as ids text, and raw 8-bit pixels
// for the GL screenshots. stb's global flip flag is set here only, on every write.
#pragma once

#include <string>

#include "raycam/colour_map.h"

namespace raycam {

// PNG of the map; each map pixel becomes a block of scale_x × scale_y image pixels (a 2D bar is written
// n × 32 with scale_y = 32). Throws std::runtime_error naming the path if it cannot be written.
void write_png(const ColourMap& map, const std::string& path, int scale_x = 1, int scale_y = 1);
// Ids as text: one image row per line, space-separated integers, -1 for background.
void write_ids(const ColourMap& map, const std::string& path);
// Raw 8-bit pixels, `channels` per pixel (3 RGB, 4 RGBA), rows top-down unless `bottom_up` (OpenGL's read
// back). Throws std::runtime_error naming the path.
void write_png_pixels(const unsigned char* pixels, int width, int height, int channels, bool bottom_up,
                      const std::string& path);

}  // namespace raycam
