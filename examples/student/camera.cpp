// A reference answer to the camera exercises, in C++17 with the standard library only.
//
// Reads ONE case on standard input (a raycam scene file: JSON, angles in degrees) and prints ONE answer on
// standard output: {"ids": [...], "md": [[...], ...]} (see README.md beside this file).
//
//   g++ -O2 -std=c++17 camera.cpp -o camera
//   ./camera < case_01.json
//   raycam-cli check --student ./camera
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "mini_json.h"

namespace {
constexpr double kPi = 3.141592653589793;

// Homogeneous matrices up to 4x4 (a 2D camera uses the top-left 3x3), rows first.
struct Matrix {
  int size = 4;
  std::array<std::array<double, 4>, 4> m{};
  static Matrix identity(int size) {
    Matrix r;
    r.size = size;
    for (int i = 0; i < size; ++i) r.m[i][i] = 1;
    return r;
  }
  Matrix operator*(const Matrix& b) const {
    Matrix r;
    r.size = size;
    for (int i = 0; i < size; ++i)
      for (int j = 0; j < size; ++j)
        for (int k = 0; k < size; ++k) r.m[i][j] += m[i][k] * b.m[k][j];
    return r;
  }
  // m times (p, w): w = 1 for a point (translated), w = 0 for a vector (not translated).
  std::vector<double> apply(const std::vector<double>& p, double w) const {
    std::vector<double> out(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (std::size_t k = 0; k < p.size(); ++k) out[i] += m[i][k] * p[k];
      out[i] += m[i][p.size()] * w;
    }
    return out;
  }
};

Matrix translation(const std::vector<double>& p) {
  Matrix t = Matrix::identity(int(p.size()) + 1);
  for (std::size_t i = 0; i < p.size(); ++i) t.m[i][p.size()] = p[i];
  return t;
}

// Rotation by `angle` in the plane of axes (a, b), counter-clockwise from a towards b.
Matrix rotation(int size, int a, int b, double angle) {
  Matrix r = Matrix::identity(size);
  r.m[a][a] = std::cos(angle);
  r.m[a][b] = -std::sin(angle);
  r.m[b][a] = std::sin(angle);
  r.m[b][b] = std::cos(angle);
  return r;
}

double radians(double degrees) { return degrees * kPi / 180.0; }

// Exercise 1 step 3: n = res*N rounded to the nearest integer, between 1 and N.
int useful_size(double res, int size) {
  const int n = int(std::floor(res * size + 0.5));
  return n < 1 ? 1 : n > size ? size : n;
}

// Exercise 1: M_d = T(OP) . R(theta - pi/2) . H(1, d_f). R turns u0 = (0,-1) towards the target.
Matrix placement_2d(const mini_json::Value& camera) {
  const double theta = radians(camera["theta"].number), d = camera["d"].number;
  const std::vector<double> p = {camera["target"][0].number + d * std::cos(theta),
                                 camera["target"][1].number + d * std::sin(theta)};
  Matrix h = Matrix::identity(3);
  h.m[1][1] = camera["df"].number;
  return translation(p) * rotation(3, 0, 1, theta - kPi / 2) * h;
}

// Exercise 3: M_d = T(OP) . Rz(theta) . Ry(phi) . Rz(pi/2) . H(1, 1, d_f), (theta, phi) the angles of CP.
// The roll +pi/2 keeps world up (+z) at the top of the image.
Matrix placement_3d(const mini_json::Value& camera) {
  const double theta = radians(camera["theta"].number), phi = radians(camera["phi"].number), d = camera["d"].number;
  const mini_json::Value& c = camera["target"];
  const std::vector<double> p = {c[0].number + d * std::cos(theta) * std::sin(phi),
                                 c[1].number + d * std::sin(theta) * std::sin(phi), c[2].number + d * std::cos(phi)};
  Matrix h = Matrix::identity(4);
  h.m[2][2] = camera["df"].number;
  // Rotation about y by phi: z turns towards x, so the plane is (z, x).
  return translation(p) * rotation(4, 0, 1, theta) * rotation(4, 2, 0, phi) * rotation(4, 0, 1, kPi / 2) * h;
}

// Exercise 2: the object hit first with t >= 0 (ties: the lower index), -1 if none. `u` is a unit vector.
int nearest_hit(const mini_json::Value& objects, const std::vector<double>& origin, const std::vector<double>& u) {
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    double b = 0, c = 0;
    for (std::size_t k = 0; k < origin.size(); ++k) {
      const double f = origin[k] - objects[i]["center"][k].number;
      b += f * u[k];
      c += f * f;
    }
    const double r = objects[i]["radius"].number;
    const double disc = b * b - (c - r * r);
    if (disc < 0) continue;
    const double near = -b - std::sqrt(disc), far = -b + std::sqrt(disc);
    const double t = near >= 0 ? near : far;  // from inside a ball, its far side
    if (t >= 0 && t < best_t) best = int(i), best_t = t;
  }
  return best;
}

int ray_id(const Matrix& md, const std::vector<double>& pixel, const std::vector<double>& eye,
           const mini_json::Value& objects) {
  const std::vector<double> origin = md.apply(pixel, 1);  // P_k = M_d . P_k^0: a point
  std::vector<double> towards(pixel.size());
  for (std::size_t k = 0; k < pixel.size(); ++k) towards[k] = pixel[k] - eye[k];
  std::vector<double> u = md.apply(towards, 0);  // a vector: no translation
  double length = 0;
  for (double x : u) length += x * x;
  for (double& x : u) x /= std::sqrt(length);  // renormalise: M_d contains the scaling H
  return nearest_hit(objects, origin, u);
}

void print_matrix(const Matrix& md) {
  std::printf(", \"md\": [");
  for (int i = 0; i < md.size; ++i) {
    std::printf("%s[", i ? ", " : "");
    for (int j = 0; j < md.size; ++j) std::printf("%s%.17g", j ? ", " : "", md.m[i][j]);
    std::printf("]");
  }
  std::printf("]}\n");
}
}  // namespace

int main() {
  try {
    const std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    const mini_json::Value scene = mini_json::parse(text);
    const mini_json::Value& camera = scene["camera"];
    const mini_json::Value& objects = scene["objects"];
    std::printf("{\"ids\": [");
    if (scene["dimension"].number == 2) {
      const Matrix md = placement_2d(camera);
      const int n = useful_size(camera["res"].number, int(camera["size"].number));
      for (int k = 0; k < n; ++k)
        std::printf("%s%d", k ? ", " : "", ray_id(md, {-1.0 + (2.0 * k + 1.0) / n, 0.0}, {0.0, 1.0}, objects));
      std::printf("]");
      print_matrix(md);
    } else {
      const Matrix md = placement_3d(camera);
      // The handout's one or two resolution variables: res, or [columns' res, rows' res].
      const mini_json::Value& res = camera["res"];
      const int columns = useful_size(res.is_array() ? res[0].number : res.number, int(camera["size"][0].number));
      const int rows = useful_size(res.is_array() ? res[1].number : res.number, int(camera["size"][1].number));
      for (int r = 0; r < rows; ++r) {  // row 0 at the top: canonical y near +1
        std::printf("%s[", r ? ", " : "");
        for (int c = 0; c < columns; ++c) {
          const std::vector<double> pixel = {-1.0 + (2.0 * c + 1.0) / columns, 1.0 - (2.0 * r + 1.0) / rows, 0.0};
          std::printf("%s%d", c ? ", " : "", ray_id(md, pixel, {0.0, 0.0, 1.0}, objects));
        }
        std::printf("]");
      }
      std::printf("]");
      print_matrix(md);
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "camera: %s\n", error.what());
    return 1;
  }
}
