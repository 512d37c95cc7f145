#include "raycam/transform.h"

#include <cmath>

namespace raycam {

// GLM matrices are built column by column: dmat3(col0, col1, col2).

glm::dmat3 scaling_2d(double sx, double sy) { return glm::dmat3({sx, 0, 0}, {0, sy, 0}, {0, 0, 1}); }

glm::dmat3 rotation_2d(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dmat3({c, s, 0}, {-s, c, 0}, {0, 0, 1});
}

glm::dmat3 translation_2d(glm::dvec2 offset) {
  return glm::dmat3({1, 0, 0}, {0, 1, 0}, {offset.x, offset.y, 1});
}

glm::dvec2 transform_point(const glm::dmat3& m, glm::dvec2 p) { return glm::dvec2(m * glm::dvec3(p, 1.0)); }
glm::dvec2 transform_vector(const glm::dmat3& m, glm::dvec2 v) { return glm::dvec2(m * glm::dvec3(v, 0.0)); }

glm::dmat4 scaling_3d(double sx, double sy, double sz) {
  return glm::dmat4({sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, sz, 0}, {0, 0, 0, 1});
}

glm::dmat4 rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dmat4({c, s, 0, 0}, {-s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
}

glm::dmat4 rotation_y(double angle) {
  // Right-handed about +y: +z turns towards +x, +x towards -z.
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dmat4({c, 0, -s, 0}, {0, 1, 0, 0}, {s, 0, c, 0}, {0, 0, 0, 1});
}

glm::dmat4 translation_3d(glm::dvec3 offset) {
  return glm::dmat4({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {offset.x, offset.y, offset.z, 1});
}

glm::dvec3 transform_point(const glm::dmat4& m, glm::dvec3 p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }
glm::dvec3 transform_vector(const glm::dmat4& m, glm::dvec3 v) { return glm::dvec3(m * glm::dvec4(v, 0.0)); }

}  // namespace raycam
