#include "raycam/scene.h"

#include <stdexcept>
#include <string>

#include "demo_scenes.inc"  // generated: raycam::generated::demo_scene_2d/3d
#include "raycam/limits.h"
#include "validation.h"

namespace raycam {

namespace {
void require_object_count(std::size_t count) {
  if (count > kMaxObjects)
    throw std::invalid_argument("objects: " + std::to_string(count) + " objects is over the limit of " +
                                std::to_string(kMaxObjects));
}

std::string object_field(std::size_t index, const char* field) {
  return "objects[" + std::to_string(index) + "]." + field;
}
}  // namespace

void validate(const Scene2D& scene) {
  require_object_count(scene.circles.size());
  for (std::size_t i = 0; i < scene.circles.size(); ++i) {
    const Circle& circle = scene.circles[i];
    detail::require_coordinate(circle.centre.x, object_field(i, "center[0]"));
    detail::require_coordinate(circle.centre.y, object_field(i, "center[1]"));
    detail::require_positive(circle.radius, object_field(i, "radius"));
  }
}

void validate(const Scene3D& scene) {
  require_object_count(scene.spheres.size());
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& sphere = scene.spheres[i];
    detail::require_coordinate(sphere.centre.x, object_field(i, "center[0]"));
    detail::require_coordinate(sphere.centre.y, object_field(i, "center[1]"));
    detail::require_coordinate(sphere.centre.z, object_field(i, "center[2]"));
    detail::require_positive(sphere.radius, object_field(i, "radius"));
  }
}

// The demo scenes are scenes/classic2d.json and classic3d.json, compiled in at build time
// (embed_demo_scenes.cmake): one definition, and the file a student opens is the built-in scene. In 3D, a
// red sphere on the target, three around it, and a grey "ground" below them so that world up is visible in
// the image. The ground is a sphere small enough to stay inside the default orbit: every point at distance 8
// (the default d) from the target is at least 8 - 4.4 = 3.6 > 3.2 from its centre, so the camera never
// enters it, whatever θ and φ (a ground of radius 100 just below the objects swallowed the camera for φ
// above ~99°). From above it is a disc under the objects.
Scene2D demo_scene_2d() { return generated::demo_scene_2d(); }
Scene3D demo_scene_3d() { return generated::demo_scene_3d(); }

}  // namespace raycam
