#include "gl/disc_layer.h"

#include <algorithm>
#include <cmath>

namespace raycam::gl {

void rasterise_discs(const std::vector<Disc>& discs, const DiscPlacement& p,
                     std::vector<std::uint8_t>& rgba) {
  const int width = std::max(p.width, 0), height = std::max(p.height, 0);
  // Premultiplied while compositing ("over", in order), straight alpha at the end as ImGui blends it.
  std::vector<float> premultiplied(std::size_t(width) * height * 4, 0.0f);
  for (const Disc& disc : discs) {
    const float cx = p.origin.x + p.scale * float(disc.centre.x),
                cy = p.origin.y - p.scale * float(disc.centre.y);
    const float radius = std::max(1.0f, p.scale * float(disc.radius));
    const float reach = radius + 0.5f;  // coverage is zero beyond it
    const int x0 = std::max(0, int(std::floor(cx - reach))),
              x1 = std::min(width - 1, int(std::floor(cx + reach)));
    const int y0 = std::max(0, int(std::floor(cy - reach))),
              y1 = std::min(height - 1, int(std::floor(cy + reach)));
    if (x0 > x1 || y0 > y1) continue;  // wholly outside (also catches NaN and huge coordinates)
    const float r = disc.colour.r / 255.0f, g = disc.colour.g / 255.0f, b = disc.colour.b / 255.0f;
    for (int y = y0; y <= y1; ++y) {
      const float dy = float(y) + 0.5f - cy;
      float* row = premultiplied.data() + (std::size_t(y) * width) * 4;
      for (int x = x0; x <= x1; ++x) {
        const float dx = float(x) + 0.5f - cx;
        const float coverage = std::clamp(radius + 0.5f - std::sqrt(dx * dx + dy * dy), 0.0f, 1.0f);
        if (coverage <= 0.0f) continue;
        float* texel = row + std::size_t(x) * 4;
        const float keep = 1.0f - coverage;
        texel[0] = r * coverage + texel[0] * keep;
        texel[1] = g * coverage + texel[1] * keep;
        texel[2] = b * coverage + texel[2] * keep;
        texel[3] = coverage + texel[3] * keep;
      }
    }
  }
  rgba.resize(premultiplied.size());
  for (std::size_t i = 0; i < premultiplied.size(); i += 4) {
    const float alpha = premultiplied[i + 3];
    const float unpremultiply = alpha > 0.0f ? 255.0f / alpha : 0.0f;
    for (int c = 0; c < 3; ++c)
      rgba[i + std::size_t(c)] =
          std::uint8_t(std::min(255.0f, premultiplied[i + std::size_t(c)] * unpremultiply + 0.5f));
    rgba[i + 3] = std::uint8_t(alpha * 255.0f + 0.5f);
  }
}

DiscLayer::~DiscLayer() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void DiscLayer::set_discs(std::vector<Disc> discs) {
  discs_ = std::move(discs);
  stale_ = true;
}

GLuint DiscLayer::texture(const DiscPlacement& placement) {
  if (!texture_) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // one texel per framebuffer pixel
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  if (!stale_ && placement == drawn_) return texture_;
  rasterise_discs(discs_, placement, rgba_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (placement.width != texture_width_ || placement.height != texture_height_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, placement.width, placement.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba_.data());
    texture_width_ = placement.width;
    texture_height_ = placement.height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, placement.width, placement.height, GL_RGBA, GL_UNSIGNED_BYTE,
                    rgba_.data());
  }
  drawn_ = placement;
  stale_ = false;
  return texture_;
}

}  // namespace raycam::gl
