#include "raycam/scene.h"

#include <stdexcept>
#include <string>

#include "demo_scenes.inc"  // generated: raycam::generated::demo_scene_2d/3d
#include "raycam/limits.h"
#include "core/validation.h"

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

// Circles and spheres alike: every coordinate of the centre finite and in range, the radius > 0. An object's
// field names are made only for an object that fails: made for every object, they took 1 s of the page's
// opening of 10⁵ spheres (docs/web.md).
template <class Objects>
void validate_objects(const Objects& objects) {
  require_object_count(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const auto& centre = objects[i].centre;
    bool fine = detail::is_positive(objects[i].radius);
    for (int axis = 0; axis < centre.length(); ++axis) fine = fine && detail::is_coordinate(centre[axis]);
    if (fine) continue;
    for (int axis = 0; axis < centre.length(); ++axis)
      detail::require_coordinate(centre[axis],
                                 object_field(i, ("center[" + std::to_string(axis) + "]").c_str()));
    detail::require_positive(objects[i].radius, object_field(i, "radius"));
  }
}
}  // namespace

void PackedScene3D::pack(const Scene3D& scene) {
  const std::size_t count = scene.spheres.size();
  x.resize(count);
  y.resize(count);
  z.resize(count);
  radius.resize(count);
  colour.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Sphere& sphere = scene.spheres[i];
    x[i] = sphere.centre.x;
    y[i] = sphere.centre.y;
    z[i] = sphere.centre.z;
    radius[i] = sphere.radius;
    colour[i] = sphere.colour;
  }
  background = scene.background;
  clusters.build(x, y, z, radius);
  shapes = scene.shapes;
}

void validate(const Scene2D& scene) { validate_objects(scene.circles); }
void validate(const Scene3D& scene) {
  require_object_count(scene.spheres.size() + scene.shapes.size());
  validate_objects(scene.spheres);
  for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
    const std::size_t id = scene.spheres.size() + k;
    std::visit(
        [id](const Plane& plane) {
          for (int axis = 0; axis < 3; ++axis) {
            detail::require_coordinate(plane.point[axis], object_field(id, ("point[" + std::to_string(axis) + "]").c_str()));
            detail::require_coordinate(plane.normal[axis], object_field(id, ("normal[" + std::to_string(axis) + "]").c_str()));
          }
          // A zero normal is no plane: every point or none would lie on it.
          if (plane.normal == glm::dvec3(0.0))
            throw std::invalid_argument(object_field(id, "normal") + ": must not be (0, 0, 0) (a plane's normal)");
        },
        scene.shapes[k]);
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
