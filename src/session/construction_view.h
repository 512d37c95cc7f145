// The construction of M_d drawn step by step (the handout's frames): the intermediate camera after the first
// `step` factors, as 3D segments that the overhead view projects from above and the observer view draws in
// 3D. Its screen (top edge marked: the image's up side), the eye's field-of-view edges, and its axes from the
// screen centre: image right (red), image up (green), view direction (blue). Each step moves something
// visible: H pushes the eye back and narrows the edges, the roll turns the axes, R_y tilts, R_z(θ) turns
// about z, T carries the camera to P.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "session/app_state.h"
#include "raycam/camera2d.h"
#include "raycam/camera3d.h"

namespace raycam::session {

// The construction panel's caption of `step` (0: the canonical camera) in `dimension`: an English key of
// the text table, shown through tr(). It names the points and rotations the figure's frame names, in the
// notation of docs/conventions.md (Ω, C, P, E0, E, α = φv + ψ0); tests/session/test_notation.cpp compares.
const char* construction_caption(int dimension, int step);

// The construction's pose after `step` factors with the last one applied only `fraction` of the way
// (fraction 1: construction_step(placement, step), exactly). Rotations turn by fraction·angle (the shorter
// way), H scales by 1 + fraction·(d_f − 1), T moves by fraction·OP.
glm::dmat3 construction_pose(const Placement2D& placement, int step, double fraction);
glm::dmat4 construction_pose(const Placement3D& placement, int step, double fraction);
// True when the views draw a construction pose besides the placed camera: a step before the last, or the
// last one part way (a recording sliding the camera to P).
bool shows_construction(const Lesson& state);

enum class ConstructionPart { screen, top_edge, field_edge, right_axis, up_axis, view_axis };

struct ConstructionSegment {
  glm::dvec3 from{0.0}, to{0.0};
  ConstructionPart part = ConstructionPart::screen;
};

// axis_length: world length of the axes and of the field-of-view edges beyond the eye (both in 3D, so that
// H's narrower field shows even from above).
std::vector<ConstructionSegment> construction_camera(const glm::dmat4& world_from_camera, double axis_length);

// Colour of each part, RGBA in [0, 1].
glm::vec4 construction_colour(ConstructionPart part);

}  // namespace raycam::session
