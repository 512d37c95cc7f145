// The observer's viewpoint in the 3D observer view (world: z up). It frames the camera (eye and screen), its
// target and the objects around the target, and follows the camera as it orbits: the framed box moves with
// the eye. The student turns it (yaw, pitch: right drag) and zooms (ctrl+wheel) through AppState::observer.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "session/app_state.h"

namespace raycam::session {

inline constexpr double kObserverFovY = 0.7853981633974483;  // 45°, in radians
// The part of the view's width or height the framed content spans along its tighter direction: a margin of
// 4% on each side, room for the frustum's lines to show where they meet the edge.
inline constexpr double kObserverFill = 0.92;

// A ball the observer frames whole: a point of the camera (radius 0) or an object.
struct FramedBall {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

struct ObserverCamera {
  glm::dvec3 eye{0.0}, look_at{0.0};
  glm::dvec3 right{1.0, 0.0, 0.0};  // the view's right, in the world
  double distance = 1.0;            // from eye to look_at
  glm::mat4 view{1.0f}, projection{1.0f};
};

// What the observer frames: the camera (eye, screen corners, its field of view as far as the target), the
// target and the objects within d of it; during the construction's steps before T(OP), the intermediate
// camera at the origin, closely.
std::vector<FramedBall> observer_content(const Lesson& state);

// aspect = width / height of the view. Looking from the observer's direction (yaw, pitch), the eye is the
// nearest from which every framed ball lies inside the view's field narrowed to kObserverFill: the content
// spans that part of the view's width or of its height, and is centred in the other direction. The zoom
// moves the eye along its line of sight (1: fitted).
ObserverCamera observer_camera(const Lesson& state, const Display& display, double aspect);

// A left drag by (dx, dy) pixels in the observer view moves the camera the way the mouse went: up is up
// (φ decreases, so the camera rises), and right is right on the screen whichever side the observer looks
// from (θ's sign from the camera's motion seen by the observer).
void drag_camera_in_observer(Lesson& state, const ObserverCamera& observer, double dx, double dy);

}  // namespace raycam::session
