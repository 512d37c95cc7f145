// Standard and random scenes shared by the tests, the fuzzers and the benchmarks (raycam_testkit: never
// linked by the app or the core).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raycam/scene.h"

namespace raycam::testkit {

// The demo scene's objects (scenes/classic2d.json, the built-in demo_scene_2d) moved to `target` and turned
// by `rotation` radians about it: the cluster the stress cases and the accuracy benchmark look at.
Scene2D demo_cluster_2d(glm::dvec2 target, double rotation = 0.0);
// The 3D demo's objects without its ground (scenes/classic3d.json), moved to `target` and turned by
// `rotation_z` radians about the z axis through it.
Scene3D demo_cluster_3d(glm::dvec3 target, double rotation_z = 0.0);

// K random spheres with centres uniform in [-10, 10]³ and radius 2·K^(-1/3) (so that the scene's density
// stays about the same), from a fixed seed per K: the speed benchmark's scene grid.
Scene3D random_spheres(int count);

}  // namespace raycam::testkit
