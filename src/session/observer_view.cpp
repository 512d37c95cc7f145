#include "session/observer_view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "session/camera_ranges.h"
#include "session/construction_view.h"

namespace raycam::session {

namespace {
constexpr double kRadiansPerPixel = 0.01;  // drag speed
}

std::vector<FramedBall> observer_content(const Lesson& state) {
  const Camera3D& camera = view3d(state).camera;
  const glm::dvec3 target = view3d(state).orbit.target;
  std::vector<FramedBall> content;
  auto include = [&](glm::dvec3 p, double radius = 0.0) { content.push_back({p, radius}); };
  if (state.construction_step >= 0 && state.construction_step < kConstructionSteps3D) {
    // A construction step before T(OP): the intermediate camera sits at the origin; frame it closely, so that
    // each factor's change (eye pushed back, axes rolled, tilted, turned) is large on screen.
    const glm::dmat4 m = construction_pose(camera.placement(), state.construction_step, state.construction_fraction);
    include(eye_of(m));
    for (const glm::dvec3& corner : screen_corners_of(m)) include(corner), include(corner * 1.5);
    return content;
  }
  // The camera (eye, screen, and its field as far as the target), the target, and the objects within d of
  // the target (farther ones, and a ground larger than the orbit, would shrink the camera to a few pixels).
  const glm::dvec3 eye = camera.eye();
  const double d = view3d(state).orbit.d;
  include(eye);
  for (const glm::dvec3& corner : camera.screen_corners())
    include(corner), include(eye + glm::normalize(corner - eye) * d);
  include(target);
  if (shows_construction(state))  // T(OP) part way: the camera sliding from the origin to P stays in view
    for (const glm::dvec3& corner :
         screen_corners_of(construction_pose(camera.placement(), state.construction_step, state.construction_fraction)))
      include(corner);
  for (const Sphere& s : view3d(state).scene.spheres)
    if (glm::length(s.centre - target) + s.radius <= d + 1e-9) include(s.centre, s.radius);
  return content;
}

ObserverCamera observer_camera(const Lesson& state, const Display& display, double aspect) {
  const std::vector<FramedBall> content = observer_content(state);
  ObserverCamera observer;
  const double yaw = glm::radians(double(display.observer.yaw_deg)),
               pitch = glm::radians(double(display.observer.pitch_deg));
  const glm::dvec3 towards_eye{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                               std::sin(pitch)};
  observer.right = glm::normalize(glm::cross(-towards_eye, glm::dvec3(0, 0, 1)));
  const glm::dvec3 up = glm::cross(observer.right, -towards_eye);
  // The tightest eye for this direction: each ball inside the four planes of a field of view kObserverFill
  // of the view's (so a margin of (1 − kObserverFill)/2 on each side). Along the view's right (a, depth
  // coordinate w along towards_eye), a ball (a_c, w_c, r) lies inside both side planes of half-slope k
  // when the eye's w ≥ w_c ± (a_c − e_a)/k + r·√(1 + k²)/k: the largest of each sign, A − e_a/k and
  // B + e_a/k, meet at e_a = k(A − B)/2, w = (A + B)/2. The same vertically; the farther of the two
  // distances wins, and the other direction is centred with room to spare.
  const double tan_y = std::tan(0.5 * kObserverFovY) * kObserverFill, tan_x = tan_y * aspect;
  struct Fit { double offset, depth; };
  auto fit = [&](const glm::dvec3& across, double k) {
    double a = -1e300, b = -1e300;
    for (const FramedBall& ball : content) {
      const double c = glm::dot(ball.centre, across), w = glm::dot(ball.centre, towards_eye);
      const double room = ball.radius * std::sqrt(1.0 + k * k) / k;
      a = std::max(a, w + c / k + room), b = std::max(b, w - c / k + room);
    }
    return Fit{0.5 * k * (a - b), 0.5 * (a + b)};
  };
  const Fit across = fit(observer.right, tan_x), upwards = fit(up, tan_y);
  // w grows towards the eye: `back` is the content's farthest from it, `front` its nearest.
  double back = 1e300, front = -1e300, middle = 0.0;
  for (const FramedBall& ball : content) {
    const double w = glm::dot(ball.centre, towards_eye);
    back = std::min(back, w - ball.radius), front = std::max(front, w + ball.radius), middle += w;
  }
  middle /= double(content.size());
  const double extent = std::max(front - back, 1e-6);
  const double eye_depth = std::max({across.depth, upwards.depth, front + 1e-3 * extent});  // never inside
  const glm::dvec3 fitted = across.offset * observer.right + upwards.offset * up + eye_depth * towards_eye;
  // The observer turns about the content's middle, and the zoom moves the eye along its line of sight.
  const double distance = std::max(eye_depth - middle, 1e-6);
  observer.look_at = fitted - distance * towards_eye;
  observer.distance = distance * double(display.observer.zoom);
  observer.eye = observer.look_at + observer.distance * towards_eye;
  const double near = std::max(1e-4 * extent, 0.5 * (glm::dot(observer.eye, towards_eye) - front));
  observer.view = glm::lookAt(glm::vec3(observer.eye), glm::vec3(observer.look_at), glm::vec3(0, 0, 1));
  observer.projection = glm::perspective(float(kObserverFovY), float(aspect), float(std::max(near, 1e-6)),
                                         float(observer.distance + 50.0 * extent + 50.0 * distance));
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
