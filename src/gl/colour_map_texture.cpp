#include "gl/colour_map_texture.h"

namespace raycam::gl {

ColourMapTexture::~ColourMapTexture() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void ColourMapTexture::upload(const ColourMap& map) {
  if (!texture_) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 3-byte texels are not 4-aligned
  if (map.width != width_ || map.height != height_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, map.width, map.height, 0, GL_RGB, GL_UNSIGNED_BYTE, map.colours.data());
    width_ = map.width;
    height_ = map.height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, map.width, map.height, GL_RGB, GL_UNSIGNED_BYTE, map.colours.data());
  }
}

}  // namespace raycam::gl
