#include "gl/sphere_layer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>

#include "raycam/camera2d.h"  // raster_from_screen
#include "raycam/intersect.h"
#include "raycam/parallel.h"

namespace raycam::gl {

namespace {
constexpr int kBandRows = 16;                   // rows a worker casts at a time
constexpr std::size_t kSpheresPerChunk = 8192;  // spheres a worker projects at a time

// Pixels whose centre can see the sphere: the projection of the square that holds the circle where the
// tangent cone from the eye meets the plane through the centre across the view (sphere.vert's quad).
// Every pixel when the eye is inside the sphere or the square reaches behind the eye; none when it is
// wholly behind.
PixelRect pixels_of(const Sphere& sphere, const SphereLayerView& view) {
  const PixelRect all{0, view.width - 1, 0, view.height - 1};
  const glm::dvec3 towards = sphere.centre - view.eye;
  const double distance2 = glm::dot(towards, towards), r2 = sphere.radius * sphere.radius;
  if (distance2 <= r2 * (1.0 + 1e-9)) return all;
  const glm::dvec3 w = towards / std::sqrt(distance2);
  const glm::dvec3 u =
      glm::normalize(glm::cross(std::abs(w.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0), w));
  const glm::dvec3 v = glm::cross(w, u);
  const double half_width = sphere.radius * std::sqrt(distance2 / (distance2 - r2));
  double low_x = 1e300, high_x = -1e300, low_y = 1e300, high_y = -1e300;
  int behind = 0;
  for (const double a : {-1.0, 1.0})
    for (const double b : {-1.0, 1.0}) {
      const glm::dvec4 clip =
          view.view_projection * glm::dvec4(sphere.centre + half_width * (a * u + b * v), 1.0);
      if (clip.w <= 0.0) {
        ++behind;
        continue;
      }
      low_x = std::min(low_x, clip.x / clip.w), high_x = std::max(high_x, clip.x / clip.w);
      low_y = std::min(low_y, clip.y / clip.w), high_y = std::max(high_y, clip.y / clip.w);
    }
  if (behind == 4) return PixelRect{};
  if (behind > 0) return all;
  // NDC x ↦ pixel index: the core's raster coordinate, where pixel i's centre is i + 1/2.
  constexpr double kSlack = 1e-3;  // of a pixel, far above the rounding here
  const auto first = [](double ndc, int count) {
    return std::max(0, int(std::ceil(raster_from_screen(ndc, count) - 0.5 - kSlack)));
  };
  const auto last = [](double ndc, int count) {
    return std::min(count - 1, int(std::floor(raster_from_screen(ndc, count) - 0.5 + kSlack)));
  };
  if (!(high_x >= -2.0 && low_x <= 2.0 && high_y >= -2.0 && low_y <= 2.0))
    return PixelRect{};  // off screen (or NaN)
  return PixelRect{first(low_x, view.width), last(high_x, view.width), first(low_y, view.height),
                   last(high_y, view.height)};
}
}  // namespace

void cast_sphere_layer(const std::vector<Sphere>& spheres, const SphereLayerView& view, SphereLayer& layer) {
  const int width = std::max(view.width, 0), height = std::max(view.height, 0);
  const std::size_t pixels = std::size_t(width) * height;
  layer.width = width;
  layer.height = height;
  layer.ids.assign(pixels, -1);
  std::vector<double>& nearest = layer.nearest;
  nearest.assign(pixels, std::numeric_limits<double>::infinity());
  layer.depth.resize(pixels);
  layer.rgba.resize(pixels * 4);

  // The ray through NDC (x, y) points at inverse(view_projection)·(x, y, 1, 1) = (H, h): direction
  // H − eye·h, linear in (x, y) (the sign of h is the same over the screen).
  const glm::dmat4 inverse = glm::inverse(view.view_projection);
  const auto towards_far = [&](double x, double y) {
    const glm::dvec4 h = inverse * glm::dvec4(x, y, 1.0, 1.0);
    return glm::dvec3(h) - view.eye * h.w;
  };
  const double sign = (inverse * glm::dvec4(0.0, 0.0, 1.0, 1.0)).w < 0 ? -1.0 : 1.0;
  const glm::dvec3 base = sign * towards_far(0.0, 0.0);
  const glm::dvec3 per_x = sign * towards_far(1.0, 0.0) - base, per_y = sign * towards_far(0.0, 1.0) - base;
  const auto ray_direction = [&](int i, int j) {
    const double x = (2.0 * i + 1.0) / width - 1.0, y = (2.0 * j + 1.0) / height - 1.0;
    return glm::normalize(base + x * per_x + y * per_y);
  };

  // Each sphere's pixels first (in parallel chunks), then bands of rows on the caster's worker pool: a band
  // tests, in sphere order, the spheres whose pixels reach it, and writes only its own pixels.
  const int workers = detail::resolve_threads(0);
  std::vector<PixelRect>& rects = layer.rects;
  rects.resize(spheres.size());
  const int chunks = int((spheres.size() + kSpheresPerChunk - 1) / kSpheresPerChunk);
  detail::parallel_items(chunks, workers, [&](int, int chunk) {
    const std::size_t end = std::min(spheres.size(), std::size_t(chunk + 1) * kSpheresPerChunk);
    for (std::size_t s = std::size_t(chunk) * kSpheresPerChunk; s < end; ++s)
      rects[s] = pixels_of(spheres[s], view);
  });
  const int bands = (height + kBandRows - 1) / kBandRows;
  detail::parallel_items(bands, workers, [&](int, int band) {
    const int band_first = band * kBandRows, band_last = std::min(height, band_first + kBandRows) - 1;
    for (std::size_t s = 0; s < spheres.size(); ++s) {
      const PixelRect& rect = rects[s];
      const int y0 = std::max(rect.y0, band_first), y1 = std::min(rect.y1, band_last);
      if (y0 > y1 || rect.x0 > rect.x1) continue;
      const Sphere& sphere = spheres[s];
      for (int j = y0; j <= y1; ++j)
        for (int i = rect.x0; i <= rect.x1; ++i) {
          const glm::dvec3 d = ray_direction(i, j);
          // The caster's own test (the stable form, as sphere.frag: no cancellation at a distance): the
          // nearest t ≥ 0, the far side from inside a sphere, kNoHit for a miss.
          const double t = nearest_hit_t(view.eye, d, sphere.centre, sphere.radius, IntersectFormula::stable);
          const std::size_t p = std::size_t(j) * width + std::size_t(i);
          if (!(t < nearest[p])) continue;  // strict: the first sphere drawn keeps a tie, as GL_LESS
          const glm::dvec4 clip = view.view_projection * glm::dvec4(view.eye + t * d, 1.0);
          const double z = clip.z / clip.w;
          if (!(z >= -1.0 && z <= 1.0)) continue;  // GL clips it at the near or far plane
          nearest[p] = t;
          layer.ids[p] = int(s);
          layer.depth[p] = float(0.5 * z + 0.5);
        }
    }
    for (int j = band_first; j <= band_last; ++j)  // shading, where a sphere is seen
      for (int i = 0; i < width; ++i) {
        const std::size_t p = std::size_t(j) * width + std::size_t(i);
        std::uint8_t* texel = &layer.rgba[p * 4];
        if (layer.ids[p] < 0) {
          texel[3] = 0;
          continue;
        }
        const Sphere& sphere = spheres[std::size_t(layer.ids[p])];
        const glm::dvec3 hit = view.eye + nearest[p] * ray_direction(i, j);
        const glm::dvec3 normal = (hit - sphere.centre) / sphere.radius;
        const double shade = 0.45 + 0.55 * std::max(glm::dot(normal, view.light_direction), 0.0);
        const Rgb8 c = sphere.colour;
        texel[0] = std::uint8_t(std::lround(std::min(255.0, c.r * shade)));
        texel[1] = std::uint8_t(std::lround(std::min(255.0, c.g * shade)));
        texel[2] = std::uint8_t(std::lround(std::min(255.0, c.b * shade)));
        texel[3] = 255;
      }
  });
}

}  // namespace raycam::gl
