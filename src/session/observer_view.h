// The observer's viewpoint in the 3D observer view (world: z up). It frames the camera (eye and screen), its
// target and the objects around the target, and follows the camera as it orbits: the framed box moves with
// the eye. The student turns it (yaw, pitch: right drag) and zooms (ctrl+wheel) through AppState::observer.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "app_state.h"

namespace raycam::session {

inline constexpr double kObserverFovY = 0.7853981633974483;  // 45°, in radians

struct ObserverCamera {
  glm::dvec3 eye{0.0}, look_at{0.0};
  glm::dvec3 right{1.0, 0.0, 0.0};  // the view's right, in the world
  double distance = 1.0;            // from eye to look_at
  glm::mat4 view{1.0f}, projection{1.0f};
};

// aspect = width / height of the view.
ObserverCamera observer_camera(const Lesson& state, const Display& display, double aspect);

// A left drag by (dx, dy) pixels in the observer view moves the camera the way the mouse went: up is up
// (φ decreases, so the camera rises), and right is right on the screen whichever side the observer looks
// from (θ's sign from the camera's motion seen by the observer).
void drag_camera_in_observer(Lesson& state, const ObserverCamera& observer, double dx, double dy);

}  // namespace raycam::session
