// Homogeneous transforms used to place the canonical cameras (handout, exercise 1 step 2 and exercise 3).
//
// Conventions: column vectors, matrices multiply on the left (M·p); GLM matrices are column-major, so
// m[c][r] is column c, row r. Angles are in radians, counter-clockwise (right-handed about the axis).
// 2D uses 3×3 matrices on (x, y, 1); 3D uses 4×4 matrices on (x, y, z, 1). A point carries w = 1 and is
// translated; a vector carries w = 0 and is not (handout, exercise 2: "u_k = M_d × u_k^0").
#pragma once

#include <cstddef>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raycam {

// ---- 2D -------------------------------------------------------------------------------------------
glm::dmat3 scaling_2d(double sx, double sy);
glm::dmat3 rotation_2d(double angle);  // angle in radians, counter-clockwise
glm::dmat3 translation_2d(glm::dvec2 offset);
glm::dvec2 transform_point(const glm::dmat3& m, glm::dvec2 p);
glm::dvec2 transform_vector(const glm::dmat3& m, glm::dvec2 v);

// The product of the first `count` factors in the order they apply: factors[count-1]·…·factors[0] (each new
// factor multiplies on the left). The cameras' construction steps (handout: frames a → d, steps 1–4).
template <class Matrix, std::size_t N>
Matrix compose_first(const Matrix (&factors)[N], int count) {
  Matrix product(1.0);
  for (int i = 0; i < count && i < int(N); ++i) product = factors[i] * product;
  return product;
}

// ---- 3D -------------------------------------------------------------------------------------------
glm::dmat4 scaling_3d(double sx, double sy, double sz);
glm::dmat4 rotation_z(double angle);  // angle in radians; turns +x towards +y
glm::dmat4 rotation_y(double angle);  // angle in radians; turns +z towards +x
glm::dmat4 translation_3d(glm::dvec3 offset);
glm::dvec3 transform_point(const glm::dmat4& m, glm::dvec3 p);
glm::dvec3 transform_vector(const glm::dmat4& m, glm::dvec3 v);

}  // namespace raycam
