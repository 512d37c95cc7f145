#include "observer_view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "camera_ranges.h"
#include "construction_view.h"

namespace raycam::session {

namespace {
constexpr double kRadiansPerPixel = 0.01;  // drag speed
}

ObserverCamera observer_camera(const Lesson& state, const Display& display, double aspect) {
  const Camera3D& camera = view3d(state).camera;
  const glm::dvec3 target = view3d(state).orbit.target;
  // What must be in view: the camera (eye and screen corners), its target, and the objects within d of the
  // target (farther ones, and a ground larger than the orbit, would shrink the camera to a few pixels).
  glm::dvec3 low = camera.eye(), high = low;
  auto include = [&](glm::dvec3 p) { low = glm::min(low, p), high = glm::max(high, p); };
  if (state.construction_step >= 0 && state.construction_step < kConstructionSteps3D) {
    // A construction step before T(OP): the intermediate camera sits at the origin; frame it closely, so that
    // each factor's change (eye pushed back, axes rolled, tilted, turned) is large on screen.
    const glm::dmat4 m = construction_pose(camera.placement(), state.construction_step, state.construction_fraction);
    low = high = eye_of(m);
    for (const glm::dvec3& corner : screen_corners_of(m)) include(corner), include(corner * 1.5);
  } else {
    for (const glm::dvec3& corner : camera.screen_corners()) include(corner);
    include(target);
    if (shows_construction(state))  // T(OP) part way: the camera sliding from the origin to P stays in view
      for (const glm::dvec3& corner :
           screen_corners_of(construction_pose(camera.placement(), state.construction_step, state.construction_fraction)))
        include(corner);
    const double near_target = view3d(state).orbit.d;
    for (const Sphere& s : view3d(state).scene.spheres)
      if (glm::length(s.centre - target) + s.radius <= near_target + 1e-9)
        include(s.centre - s.radius), include(s.centre + s.radius);
  }
  ObserverCamera observer;
  observer.look_at = 0.5 * (low + high);
  const double radius = std::max(0.5 * glm::length(high - low), 1e-6);
  // The bounding sphere fits the narrower of the two fields of view.
  const double half_fov =
      0.5 * std::min(kObserverFovY, 2.0 * std::atan(std::tan(0.5 * kObserverFovY) * aspect));
  observer.distance = radius / std::sin(half_fov) * double(display.observer.zoom);
  const double yaw = glm::radians(double(display.observer.yaw_deg)),
               pitch = glm::radians(double(display.observer.pitch_deg));
  const glm::dvec3 towards_eye{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                               std::sin(pitch)};
  observer.eye = observer.look_at + observer.distance * towards_eye;
  observer.right = glm::normalize(glm::cross(-towards_eye, glm::dvec3(0, 0, 1)));
  observer.view = glm::lookAt(glm::vec3(observer.eye), glm::vec3(observer.look_at), glm::vec3(0, 0, 1));
  observer.projection = glm::perspective(float(kObserverFovY), float(aspect), float(observer.distance * 0.01),
                                         float(observer.distance * 50));
  return observer;
}

void drag_camera_in_observer(Lesson& state, const ObserverCamera& observer, double dx, double dy) {
  Orbit3D& orbit = view3d(state).orbit;
  // dP/dθ = d·sin φ·(−sin θ, cos θ, 0): its component along the observer's right says which way θ moves
  // the camera on screen. (Side-on, where it vanishes, either way is fine.)
  const glm::dvec3 along_theta{-std::sin(orbit.theta), std::cos(orbit.theta), 0.0};
  const double theta_sign = glm::dot(along_theta, observer.right) >= 0.0 ? 1.0 : -1.0;
  orbit.theta += theta_sign * dx * kRadiansPerPixel;
  // Screen y grows downwards; z = d·cos φ grows as φ decreases: dragging up (dy < 0) lowers φ.
  orbit.phi = kPolarRange.clamp(orbit.phi + dy * kRadiansPerPixel);
  state.cameras_dirty = true;
}

}  // namespace raycam::session
