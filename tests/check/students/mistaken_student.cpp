// A test "student": the handout's camera written from the exercise sheet, with a switch per classic mistake,
// independently of raycam's core (own matrices, own rays, own intersection; only the example's JSON reader).
//
//   mistaken_student [--mistake ID[,ID...]] [--md] < case.json
//
// The mistakes are what a student writes, not what raycam's cameras do: the printed sign takes the angles of
// v = PC with atan2/acos, "mirrored" and "rows_flipped" store the ids in reverse, "no_t_min" keeps the
// smaller root whatever its sign, "skip_renormalise" feeds the scaled u_k to the textbook b² - c formula.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "mini_json.h"

namespace {
constexpr double kPi = 3.141592653589793;
std::set<std::string> mistakes;
bool has(const char* id) { return mistakes.count(id) > 0; }

using Vec = std::vector<double>;
using Mat = std::vector<Vec>;  // rows

Mat identity(int n) {
  Mat m(std::size_t(n), Vec(std::size_t(n), 0.0));
  for (int i = 0; i < n; ++i) m[std::size_t(i)][std::size_t(i)] = 1;
  return m;
}

Mat mul(const Mat& a, const Mat& b) {
  Mat r(a.size(), Vec(b[0].size(), 0.0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b[0].size(); ++j)
      for (std::size_t k = 0; k < b.size(); ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Vec times(const Mat& m, const Vec& v) {  // v already homogeneous
  Vec r(m.size(), 0.0);
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t k = 0; k < v.size(); ++k) r[i] += m[i][k] * v[k];
  return r;
}

Mat rot(int n, int a, int b, double angle) {  // a towards b
  Mat m = identity(n);
  m[std::size_t(a)][std::size_t(a)] = std::cos(angle);
  m[std::size_t(a)][std::size_t(b)] = -std::sin(angle);
  m[std::size_t(b)][std::size_t(a)] = std::sin(angle);
  m[std::size_t(b)][std::size_t(b)] = std::cos(angle);
  return m;
}

double angle_in(double degrees) { return has("degrees_as_radians") ? degrees : degrees * kPi / 180.0; }

int size_of(double res, int n_max) {
  const double n = has("res_truncated") ? std::floor(res * n_max) : std::floor(res * n_max + 0.5);
  return int(std::max(1.0, std::min(double(n_max), n)));
}

double pixel_x(int k, int n) { return has("pixel_edges") ? -1.0 + 2.0 * k / n : -1.0 + (2.0 * k + 1.0) / n; }

Mat camera_2d(const mini_json::Value& cam) {
  const double theta = angle_in(cam["theta"].number), d = cam["d"].number;
  const double cx = cam["target"][0].number, cy = cam["target"][1].number;
  const double px = cx + d * std::cos(theta), py = cy + d * std::sin(theta);
  double alpha = theta - kPi / 2;
  if (has("printed_rotation_sign")) {  // phi_v = angle of v = PC/|PC|, as printed
    const double vx = cx - px, vy = cy - py, len = std::hypot(vx, vy);
    const double phi_v = vy / len >= 0 ? std::acos(vx / len) : -std::acos(vx / len);
    alpha = phi_v - kPi / 2;
  }
  Mat t = identity(3);
  t[0][2] = px;
  t[1][2] = py;
  Mat h = identity(3);
  if (!has("no_focal_scale")) h[1][1] = cam["df"].number;
  return mul(mul(t, rot(3, 0, 1, alpha)), h);
}

Mat camera_3d(const mini_json::Value& cam) {
  double theta = angle_in(cam["theta"].number), phi = angle_in(cam["phi"].number);
  if (has("theta_phi_swapped")) std::swap(theta, phi);
  const double d = cam["d"].number;
  const Vec c = {cam["target"][0].number, cam["target"][1].number, cam["target"][2].number};
  const Vec p = {c[0] + d * std::cos(theta) * std::sin(phi), c[1] + d * std::sin(theta) * std::sin(phi),
                 c[2] + d * std::cos(phi)};
  if (has("printed_rotation_sign")) {  // the spherical angles of v = PC instead of CP
    const Vec v = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    phi = std::acos(v[2] / len);
    theta = std::atan2(v[1], v[0]);
  }
  Mat t = identity(4);
  for (int i = 0; i < 3; ++i) t[std::size_t(i)][3] = p[std::size_t(i)];
  Mat h = identity(4);
  if (!has("no_focal_scale")) h[2][2] = cam["df"].number;
  const double roll = has("upside_down") ? -kPi / 2 : kPi / 2;
  return mul(mul(mul(mul(t, rot(4, 0, 1, theta)), rot(4, 2, 0, phi)), rot(4, 0, 1, roll)), h);
}

int cast(const mini_json::Value& objects, const Mat& m, Vec pixel, Vec eye) {
  const std::size_t dim = pixel.size();
  Vec origin_h = pixel, dir_h = pixel;
  origin_h.push_back(1.0);
  for (std::size_t i = 0; i < dim; ++i) dir_h[i] = pixel[i] - eye[i];
  dir_h.push_back(has("direction_translated") ? 1.0 : 0.0);
  if (has("eye_origin")) {
    origin_h = eye;
    origin_h.push_back(1.0);
  }
  Vec o = times(m, origin_h), u = times(m, dir_h);
  o.resize(dim);
  u.resize(dim);
  if (!has("skip_renormalise")) {
    double len = 0;
    for (double x : u) len += x * x;
    for (double& x : u) x /= std::sqrt(len);
  }
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    double b = 0, ff = 0;
    for (std::size_t k = 0; k < dim; ++k) {
      const double f = o[k] - objects[i]["center"][k].number;
      b += f * u[k];
      ff += f * f;
    }
    const double r = objects[i]["radius"].number, disc = b * b - (ff - r * r);
    if (disc < 0) continue;
    double t = -b - std::sqrt(disc);
    if (!has("no_t_min") && t < 0) t = -b + std::sqrt(disc);
    if ((has("no_t_min") || t >= 0) && t < best_t) best = int(i), best_t = t;
  }
  return best;
}

std::string matrix_json(const Mat& m) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (std::size_t i = 0; i < m.size(); ++i) {
    out << (i ? ", [" : "[");
    for (std::size_t j = 0; j < m[i].size(); ++j) out << (j ? ", " : "") << m[i][j];
    out << "]";
  }
  return out.str() + "]";
}
}  // namespace

int main(int argc, char** argv) {
  bool with_md = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--md") with_md = true;
    if (arg == "--mistake" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string id; std::getline(list, id, ',');) mistakes.insert(id);
    }
  }
  const std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  const mini_json::Value scene = mini_json::parse(text);
  const mini_json::Value& cam = scene["camera"];
  const mini_json::Value& objects = scene["objects"];
  std::ostringstream ids;
  Mat m;
  if (scene["dimension"].number == 2) {
    m = camera_2d(cam);
    const int n = size_of(cam["res"].number, int(cam["size"].number));
    std::vector<int> row;
    for (int k = 0; k < n; ++k) row.push_back(cast(objects, m, {pixel_x(k, n), 0.0}, {0.0, 1.0}));
    if (has("mirrored")) std::reverse(row.begin(), row.end());
    ids << "[";
    for (std::size_t k = 0; k < row.size(); ++k) ids << (k ? "," : "") << row[k];
    ids << "]";
  } else {
    m = camera_3d(cam);
    const mini_json::Value& res = cam["res"];  // one number, or [columns' res, rows' res]
    const int columns = size_of(res.is_array() ? res[0].number : res.number, int(cam["size"][0].number));
    const int rows = size_of(res.is_array() ? res[1].number : res.number, int(cam["size"][1].number));
    std::vector<std::vector<int>> image;
    for (int r = 0; r < rows; ++r) {
      image.emplace_back();
      // pixel_edges: the printed -1 + 2k/n on both axes (y counts down from the top edge)
      const double y = has("pixel_edges") ? 1.0 - 2.0 * r / rows : 1.0 - (2.0 * r + 1.0) / rows;
      // square_pixels: the screen's half-width is the image's aspect, as a look-at camera makes it
      const double aspect = has("square_pixels") ? double(columns) / rows : 1.0;
      for (int c = 0; c < columns; ++c)
        image.back().push_back(cast(objects, m, {aspect * pixel_x(c, columns), y, 0.0}, {0.0, 0.0, 1.0}));
      if (has("mirrored")) std::reverse(image.back().begin(), image.back().end());
    }
    if (has("rows_flipped")) std::reverse(image.begin(), image.end());
    ids << "[";
    for (std::size_t r = 0; r < image.size(); ++r) {
      ids << (r ? ",[" : "[");
      for (std::size_t c = 0; c < image[r].size(); ++c) ids << (c ? "," : "") << image[r][c];
      ids << "]";
    }
    ids << "]";
  }
  std::printf("{\"ids\": %s%s}\n", ids.str().c_str(), with_md ? (", \"md\": " + matrix_json(m)).c_str() : "");
}
