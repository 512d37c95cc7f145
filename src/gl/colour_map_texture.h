// The camera's colour map as a GL texture (RGB8, nearest filtering so that pixels stay square and sharp).
// Texel row 0 is the map's row 0 (the top): show it with uv (0,0) at the top-left.
#pragma once

#include "gl/gl.h"
#include "raycam/colour_map.h"

namespace raycam::gl {

class ColourMapTexture {
 public:
  ColourMapTexture() = default;
  ~ColourMapTexture();
  ColourMapTexture(const ColourMapTexture&) = delete;
  ColourMapTexture& operator=(const ColourMapTexture&) = delete;

  void upload(const ColourMap& map);
  GLuint id() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GLuint texture_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace raycam::gl
