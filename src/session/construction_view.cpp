#include "session/construction_view.h"

#include <cmath>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "raycam/camera3d.h"
#include "raycam/transform.h"
#include "session/text.h"

namespace raycam::session {

namespace {
// A factor `fraction` of the way from the identity. Scales and translations blend linearly with the
// identity (that is exactly the scale or the vector times the fraction); a rotation is slerped, so that
// it turns by that part of its angle.
glm::dmat4 partial_factor(const glm::dmat4& factor, double fraction, bool rotation) {
  if (!rotation) return glm::dmat4(1.0) + fraction * (factor - glm::dmat4(1.0));
  const glm::dquat turn = glm::quat_cast(glm::dmat3(factor));
  return glm::mat4_cast(glm::slerp(glm::dquat(1.0, 0.0, 0.0, 0.0), turn, fraction));
}
glm::dmat3 partial_factor(const glm::dmat3& factor, double fraction, bool rotation) {
  if (!rotation) return glm::dmat3(1.0) + fraction * (factor - glm::dmat3(1.0));
  const double angle = std::atan2(factor[0][1], factor[0][0]);  // column 0 is (cos α, sin α)
  return rotation_2d(fraction * angle);
}
template <class Matrix, std::size_t N>
Matrix pose_of(const Matrix (&factors)[N], const bool (&rotations)[N], int step, double fraction) {
  if (fraction >= 1.0 || step <= 0) return compose_first(factors, step);
  return partial_factor(factors[step - 1], fraction, rotations[step - 1]) * compose_first(factors, step - 1);
}
}  // namespace

glm::dmat3 construction_pose(const Placement2D& p, int step, double fraction) {
  if (fraction >= 1.0) return construction_step(p, step);  // the very matrices the panel shows
  const glm::dmat3 factors[] = {p.scale, p.rotation, p.translation};
  const bool rotations[] = {false, true, false};
  return pose_of(factors, rotations, step, fraction);
}

glm::dmat4 construction_pose(const Placement3D& p, int step, double fraction) {
  if (fraction >= 1.0) return construction_step(p, step);
  const glm::dmat4 factors[] = {p.scale, p.roll, p.polar, p.azimuth, p.translation};
  const bool rotations[] = {false, true, true, true, false};
  return pose_of(factors, rotations, step, fraction);
}

const char* construction_caption(int dimension, int step) {
  static const std::vector<const char*> k2D = {
      tr_later("a: the canonical camera (identity): screen centred at Ω, eye E₀"),
      tr_later("b: H(1, d_f) sets the focal distance: the eye moves back to E"),
      tr_later("c: R(α) = R(φᵥ)·R(ψ₀) turns u₀ onto v = PC/‖PC‖"),
      tr_later("d: T(ΩP) moves the screen from Ω to P = C + d(cos θ, sin θ)")};
  static const std::vector<const char*> k3D = {
      tr_later("the canonical camera (identity): screen centred at Ω, eye E₀"),
      tr_later("1: H(1, 1, d_f) sets the focal distance: the eye moves back to E"),
      tr_later("2: Rz(ψ₀), ψ₀ = +90°, rolls the image upright"),
      tr_later("3: Ry(φ) tilts u₀ into the plane y = 0"),
      tr_later("4: Rz(θ) turns u₀ onto v"),
      tr_later("5: T(ΩP) moves the screen from Ω to P: M_d = T·Rz(θ)·Ry(φ)·Rz(ψ₀)·H")};
  const std::vector<const char*>& captions = dimension == 2 ? k2D : k3D;
  const int last = int(captions.size()) - 1;
  return captions[std::size_t(step < 0 || step > last ? last : step)];
}

bool shows_construction(const Lesson& state) {
  const int steps = construction_steps(state);
  return state.construction_step >= 0 && (state.construction_step < steps || state.construction_fraction < 1.0);
}

std::vector<ConstructionSegment> construction_camera(const glm::dmat4& m, double axis_length) {
  std::vector<ConstructionSegment> segments;
  const std::array<glm::dvec3, 4> corners =
      screen_corners_of(m);  // top-left, top-right, bottom-right, bottom-left
  for (std::size_t i = 0; i < corners.size(); ++i)
    segments.push_back(
        {corners[i], corners[(i + 1) % 4], i == 0 ? ConstructionPart::top_edge : ConstructionPart::screen});
  const glm::dvec3 eye = eye_of(m);
  for (const glm::dvec3& corner : corners) {  // from the eye through each corner, a little past the screen
    const glm::dvec3 along = corner - eye;
    segments.push_back(
        {eye, corner + glm::normalize(along) * (2.0 * axis_length), ConstructionPart::field_edge});
  }
  const glm::dvec3 centre = transform_point(m, glm::dvec3(0.0));
  auto axis = [&](glm::dvec3 canonical, ConstructionPart part) {
    const glm::dvec3 direction = transform_vector(m, canonical);  // the axis as M_s carries it (H scales z)
    segments.push_back({centre, centre + glm::normalize(direction) * axis_length, part});
  };
  axis({1, 0, 0}, ConstructionPart::right_axis);
  axis({0, 1, 0}, ConstructionPart::up_axis);
  axis({0, 0, -1}, ConstructionPart::view_axis);
  return segments;
}

glm::vec4 construction_colour(ConstructionPart part) {
  switch (part) {
    case ConstructionPart::screen:
      return {1.0f, 0.59f, 0.16f, 1.0f};  // kConstructionColour
    case ConstructionPart::top_edge:
      return {0.35f, 1.0f, 0.35f, 1.0f};
    case ConstructionPart::field_edge:
      return {1.0f, 0.59f, 0.16f, 0.55f};
    case ConstructionPart::right_axis:
      return {1.0f, 0.3f, 0.3f, 1.0f};
    case ConstructionPart::up_axis:
      return {0.35f, 1.0f, 0.35f, 1.0f};
    case ConstructionPart::view_axis:
      return {0.35f, 0.55f, 1.0f, 1.0f};
  }
  return {1, 1, 1, 1};
}

}  // namespace raycam::session
