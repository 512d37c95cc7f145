#include "construction_view.h"

#include <glm/geometric.hpp>

#include "raycam/camera3d.h"
#include "raycam/transform.h"

namespace raycam::session {

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
