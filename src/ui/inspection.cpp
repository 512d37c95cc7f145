#include "inspection.h"

namespace raycam::ui {

InspectedRay inspect_pixel(const AppState& state, PixelIndex pixel) {
  InspectedRay out;
  out.pixel = pixel;
  if (state.dimension == 2) {
    const Camera2D& camera = state.camera2d;
    out.k = camera.pixel_of_column(pixel.column);
    const glm::dvec2 p0 = camera.canonical_pixel(out.k);
    const Ray2D ray = camera.primary_ray(out.k);
    out.canonical_pixel = {p0, 0.0};
    out.canonical_direction = {p0 - kCanonicalEye2D, 0.0};  // u_k^0 = P_k^0 - E0
    out.origin = {ray.origin, 0.0};
    out.direction = {ray.direction, 0.0};
    out.hit = nearest_hit(state.file.scene2d.circles, ray, IntersectFormula::stable);
  } else {
    const Camera3D& camera = state.camera3d;
    const glm::dvec3 p0 = camera.canonical_pixel(pixel.row, pixel.column);
    const Ray3D ray = camera.primary_ray(pixel.row, pixel.column);
    out.canonical_pixel = p0;
    out.canonical_direction = p0 - kCanonicalEye3D;
    out.origin = ray.origin;
    out.direction = ray.direction;
    out.hit = nearest_hit(state.file.scene3d.spheres, ray, IntersectFormula::stable);
  }
  return out;
}

std::optional<PixelIndex> active_pixel(const AppState& state) {
  std::optional<PixelIndex> pixel = state.hovered_pixel ? state.hovered_pixel : state.pinned_pixel;
  if (pixel && (pixel->column >= state.map.width || pixel->row >= state.map.height)) return std::nullopt;
  return pixel;
}

}  // namespace raycam::ui
