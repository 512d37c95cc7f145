// The speed bench's scene families (`raycam-cli bench speed`, docs/speed.md): K spheres and a camera each,
// chosen so that no one scene can be tuned for. They differ in what makes a caster slow: the field of view,
// the spread of radii, clumping, an eye inside the cloud, a grazing view of a layer (many spheres behind
// each other in every pixel).
#pragma once

#include <string>
#include <vector>

#include "raycam/camera3d.h"
#include "raycam/scene.h"

namespace raycam::testkit {

struct SpeedFamily {
  std::string name;         // short, for the bench's table: "cube", "narrow 20°", ...
  std::string description;  // one line: the scene and the camera
  Scene3D scene;
  Orbit3D orbit;
};

// The families' names, in the table's order.
std::vector<std::string> speed_family_names();
// The family of that name with `count` spheres (same seed per family and count); throws
// std::invalid_argument for an unknown name, listing the known ones.
SpeedFamily speed_family(const std::string& name, int count);

}  // namespace raycam::testkit
