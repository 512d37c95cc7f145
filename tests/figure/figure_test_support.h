// What the figure tests share: two small scenes, cameras that exercise every quadrant, reading a file and a
// command's output.
#pragma once

#include <cstdio>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/scene.h"

namespace raycam::figure_tests {

inline const Scene2D& scene_2d() {
  static const Scene2D scene = [] {
    Scene2D s;
    s.circles = {{{-1.0, -0.5}, 0.8, {230, 60, 50}, "red"}, {{1.5, 0.8}, 0.5, {60, 190, 80}, "green"}};
    return s;
  }();
  return scene;
}

inline const Scene3D& scene_3d() {
  static const Scene3D scene = [] {
    Scene3D s;
    s.spheres = {{{0.0, 0.0, 0.0}, 1.0, {230, 60, 50}, "red"}, {{2.0, 1.0, 0.5}, 0.5, {60, 90, 230}, "blue"}};
    return s;
  }();
  return scene;
}

// Cameras that exercise every quadrant of θ, a target away from the origin and d_f ≠ 1.
inline std::vector<Camera2D> cameras_2d() {
  std::vector<Camera2D> cameras;
  for (double theta_deg : {90.0, 0.0, 200.0, -35.0}) {
    Orbit2D orbit;
    orbit.target = {2.0, -1.0};
    orbit.d = 5.0;
    orbit.theta = glm::radians(theta_deg);
    orbit.df = 1.7;
    cameras.emplace_back(16, orbit);
  }
  return cameras;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string run_output(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    pclose(pipe);
  }
  return out;
}

}  // namespace raycam::figure_tests
