#include "raycam/standard_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace raycam::testkit {

Scene2D demo_cluster_2d(glm::dvec2 target, double rotation) {
  Scene2D scene = demo_scene_2d();  // centred on the origin, the demo camera's target
  const double c = std::cos(rotation), s = std::sin(rotation);
  for (Circle& circle : scene.circles) {
    const glm::dvec2 o = circle.centre;
    circle.centre = target + glm::dvec2(c * o.x - s * o.y, s * o.x + c * o.y);
  }
  return scene;
}

Scene3D demo_cluster_3d(glm::dvec3 target, double rotation_z) {
  Scene3D scene = demo_scene_3d();
  // The ground is there to show world up in the app; the cluster is the objects themselves.
  scene.spheres.erase(std::remove_if(scene.spheres.begin(), scene.spheres.end(),
                                     [](const Sphere& sphere) { return sphere.name == "ground"; }),
                      scene.spheres.end());
  const double c = std::cos(rotation_z), s = std::sin(rotation_z);
  for (Sphere& sphere : scene.spheres) {
    const glm::dvec3 o = sphere.centre;
    sphere.centre = target + glm::dvec3(c * o.x - s * o.y, s * o.x + c * o.y, o.z);
  }
  return scene;
}

Scene3D random_spheres(int count) {
  std::mt19937_64 engine(20261122u + unsigned(count));
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  const double radius = 2.0 * std::pow(double(std::max(count, 1)), -1.0 / 3.0);
  Scene3D scene;
  for (int i = 0; i < count; ++i) {
    const double x = coordinate(engine), y = coordinate(engine), z = coordinate(engine);
    scene.spheres.push_back({{x, y, z}, radius, {std::uint8_t(40 + i % 200), std::uint8_t(i * 7), 200}, ""});
  }
  return scene;
}

}  // namespace raycam::testkit
