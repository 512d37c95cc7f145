// Views that hold still and follow, without a window: the demo ground never swallows the camera on the
// default orbit, Reset returns to the scene file's preset, the observer frames and follows the camera, and a
// drag moves the camera the way the mouse goes as the observer sees it.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <cstdlib>

#include "../scratch_dir.h"
#include "app_state_for.h"
#include "session/construction_view.h"
#include "session/observer_view.h"

using namespace raycam;
using raycam::test::state_for;

namespace {
// Normalised device coordinates of a world point seen by the observer (x right, y up, both in [-1, 1]).
glm::dvec2 ndc(const session::ObserverCamera& observer, glm::dvec3 p) {
  const glm::vec4 clip = observer.projection * observer.view * glm::vec4(glm::vec3(p), 1.0f);
  return {clip.x / clip.w, clip.y / clip.w};
}
constexpr double kObserverAspect = 890.0 / 345.0;  // the observer view's rectangle at 1280×800
}  // namespace

TEST_CASE("the demo scene's ground never swallows the camera on the default orbit", "[ui][views]") {
  const Scene3D scene = demo_scene_3d();
  const Orbit3D defaults;
  int placements = 0;
  for (double theta_deg = -180; theta_deg <= 180; theta_deg += 15)
    for (double phi_deg = 0; phi_deg <= 180; phi_deg += 2.5) {
      Orbit3D orbit = defaults;
      orbit.theta = glm::radians(theta_deg);
      orbit.phi = glm::radians(phi_deg);
      Camera3D camera(16, 16);
      camera.set_orbit(orbit);
      std::vector<glm::dvec3> points{camera.eye(), camera.screen_centre()};
      for (const glm::dvec3& corner : camera.screen_corners()) points.push_back(corner);
      for (const Sphere& sphere : scene.spheres)
        for (const glm::dvec3& p : points) {
          INFO(sphere.name << " at theta " << theta_deg << ", phi " << phi_deg);
          CHECK(glm::length(p - sphere.centre) > sphere.radius);
        }
      ++placements;
    }
  CHECK(placements == 25 * 73);
}

TEST_CASE("Reset camera returns to the scene file's preset, with the command line's overrides",
          "[ui][views]") {
  const test::ScratchDir scratch("views");
  const std::string preset_scene = scratch.path("preset_scene.json");
  {
    std::ofstream file(preset_scene);
    file << R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
                "camera": {"target": [1, 2, 3], "d": 5, "theta": 40, "phi": 70, "df": 1.25, "res": 0.5}})";
  }
  session::AppState state = state_for({"--scene", preset_scene});
  view3d(state).orbit.theta = 2.0, view3d(state).orbit.phi = 0.3, view3d(state).orbit.d = 30, view3d(state).orbit.df = 7,
  state.res = 1;
  view3d(state).orbit.target = glm::dvec3(0.0);
  session::reset_camera(state, state);
  CHECK(view3d(state).orbit.d == 5);
  CHECK(view3d(state).orbit.theta == Approx(glm::radians(40.0)));
  CHECK(view3d(state).orbit.phi == Approx(glm::radians(70.0)));
  CHECK(view3d(state).orbit.df == 1.25);
  CHECK(view3d(state).orbit.target == glm::dvec3(1, 2, 3));
  CHECK(state.res == 0.5);
  CHECK(state.overhead_fit_pending);
  session::AppState overridden = state_for({"--scene", preset_scene, "--d", "9"});
  view3d(overridden).orbit.d = 2;
  session::reset_camera(overridden, overridden);
  CHECK(view3d(overridden).orbit.d == 9);
  // A scene opened later brings its own preset.
  session::AppState opened = state_for({});
  REQUIRE(session::open_scene(opened, preset_scene));
  view3d(opened).orbit.phi = 0.1;
  session::reset_camera(opened, opened);
  CHECK(view3d(opened).orbit.phi == Approx(glm::radians(70.0)));
}

TEST_CASE("the observer frames the camera and follows it round the orbit", "[ui][views]") {
  session::AppState state = state_for({});
  session::place_cameras(state);
  {  // Default settings: the camera's screen is at least a tenth of the view's height.
    const session::ObserverCamera observer = session::observer_camera(state, state, kObserverAspect);
    double low = 1, high = -1;
    for (const glm::dvec3& corner : view3d(state).camera.screen_corners()) {
      low = std::min(low, ndc(observer, corner).y);
      high = std::max(high, ndc(observer, corner).y);
    }
    CHECK((high - low) / 2.0 >= 0.1);
  }
  for (double theta_deg : {-150.0, -60.0, 0.0, 30.0, 120.0})
    for (double phi_deg : {0.0, 30.0, 90.0, 150.0, 180.0}) {
      view3d(state).orbit.theta = glm::radians(theta_deg);
      view3d(state).orbit.phi = glm::radians(phi_deg);
      session::place_cameras(state);
      const session::ObserverCamera observer = session::observer_camera(state, state, kObserverAspect);
      std::vector<glm::dvec3> points{view3d(state).camera.eye(), view3d(state).orbit.target};
      for (const glm::dvec3& corner : view3d(state).camera.screen_corners()) points.push_back(corner);
      for (const glm::dvec3& p : points) {
        const glm::dvec2 at = ndc(observer, p);
        INFO("theta " << theta_deg << ", phi " << phi_deg << ": (" << at.x << ", " << at.y << ")");
        CHECK(std::abs(at.x) < 1.0);
        CHECK(std::abs(at.y) < 1.0);
      }
    }
}

TEST_CASE("dragging in the observer view moves the camera the way the mouse goes", "[ui][views]") {
  for (float yaw : {-60.0f, 30.0f, 150.0f})
    for (float pitch : {10.0f, 45.0f})
      for (double theta_deg : {-120.0, 0.0, 75.0})
        for (double phi_deg : {40.0, 90.0, 130.0}) {
          session::AppState state = state_for({});
          state.observer.yaw_deg = yaw;
          state.observer.pitch_deg = pitch;
          view3d(state).orbit.theta = glm::radians(theta_deg);
          view3d(state).orbit.phi = glm::radians(phi_deg);
          session::place_cameras(state);
          const session::ObserverCamera observer = session::observer_camera(state, state, kObserverAspect);
          const glm::dvec2 before = ndc(observer, view3d(state).camera.screen_centre());
          INFO("yaw " << yaw << ", pitch " << pitch << ", theta " << theta_deg << ", phi " << phi_deg);
          session::AppState up = state;  // screen y grows downwards: up is dy < 0
          session::drag_camera_in_observer(up, observer, 0.0, -10.0);
          session::place_cameras(up);
          // Up on the screen too, unless the camera moves (almost) along the line of sight: seen from close (the
          // observer frames its content tightly), a camera coming towards it below the view's middle goes down
          // the screen even as it rises.
          const glm::dvec3 up_vector = glm::cross(observer.right, observer.look_at - observer.eye);
          const glm::dvec3 rising = view3d(up).camera.screen_centre() - view3d(state).camera.screen_centre();
          if (std::abs(glm::dot(glm::normalize(rising), glm::normalize(up_vector))) >= 0.2)
            CHECK(ndc(observer, view3d(up).camera.screen_centre()).y > before.y);
          CHECK(view3d(up).camera.screen_centre().z > view3d(state).camera.screen_centre().z);
          // Right: unless the camera moves (almost) along the line of sight, where left and right vanish.
          const glm::dvec3 along_theta{-std::sin(view3d(state).orbit.theta), std::cos(view3d(state).orbit.theta), 0.0};
          if (std::abs(glm::dot(along_theta, observer.right)) < 0.2) continue;
          session::AppState right = state;
          session::drag_camera_in_observer(right, observer, 10.0, 0.0);
          session::place_cameras(right);
          CHECK(ndc(observer, view3d(right).camera.screen_centre()).x > before.x);
        }
}

namespace {
// The extent, in normalised device coordinates, of what the observer shows of a ball: points spread over its
// surface (a point: itself). Whether every one is in front of the observer's near plane goes in `in_front`.
void extend_ndc(const session::ObserverCamera& observer, glm::dvec3 centre, double radius, glm::dvec2& low,
                glm::dvec2& high, bool& in_front) {
  const int rings = radius > 0 ? 24 : 0;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < (rings ? 48 : 1); ++j) {
      const double polar = rings ? glm::pi<double>() * i / rings : 0.0, azimuth = 2 * glm::pi<double>() * j / 48;
      const glm::dvec3 p = centre + radius * glm::dvec3(std::sin(polar) * std::cos(azimuth),
                                                        std::sin(polar) * std::sin(azimuth), std::cos(polar));
      const glm::dvec4 clip = glm::dmat4(observer.projection) * glm::dmat4(observer.view) * glm::dvec4(p, 1.0);
      in_front = in_front && clip.w > 0 && clip.z > -clip.w && clip.z < clip.w;
      const glm::dvec2 at{clip.x / clip.w, clip.y / clip.w};
      low = glm::min(low, at), high = glm::max(high, at);
    }
}
}  // namespace

// At 3× the observer was a strip where the scene, the camera and the rays took about 110×80 px of it: the
// observer now frames the camera (eye, screen, its field as far as the target), the target and the objects
// within d of the target so that together they span at least 80% of the view's width or of its height, and
// nothing of them is cut, over random cameras, observer directions, view shapes (a strip to a column) and the
// construction's steps (before T(OP): the intermediate camera at the origin).
TEST_CASE("the observer frames the camera, the target and the objects near it tightly, none cut", "[ui][views]") {
  std::srand(49);
  auto uniform = [](double low, double high) { return low + (high - low) * double(std::rand()) / RAND_MAX; };
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    session::AppState state = state_for({});
    Orbit3D& orbit = view3d(state).orbit;
    orbit.theta = uniform(-glm::pi<double>(), glm::pi<double>());
    orbit.phi = uniform(0.0, glm::pi<double>());
    orbit.d = uniform(2.0, 30.0);
    orbit.df = uniform(0.5, 5.0);
    if (trial % 3 == 0) orbit.target = view3d(state).scene.spheres[std::size_t(trial) % view3d(state).scene.spheres.size()].centre;
    state.observer.yaw_deg = float(uniform(-180.0, 180.0));
    state.observer.pitch_deg = float(uniform(-85.0, 85.0));
    state.construction_step = trial % 4 == 0 ? int(uniform(0.0, 5.99)) : -1;
    session::place_cameras(state);
    const double aspect = uniform(0.4, 8.0);
    const session::ObserverCamera observer = session::observer_camera(state, state, aspect);

    glm::dvec2 low{1e9}, high{-1e9};
    bool in_front = true;
    const Camera3D& camera = view3d(state).camera;
    if (state.construction_step >= 0 && state.construction_step < 5) {  // the intermediate camera, at the origin
      const glm::dmat4 m = session::construction_pose(camera.placement(), state.construction_step, 1.0);
      extend_ndc(observer, eye_of(m), 0.0, low, high, in_front);
      for (const glm::dvec3& corner : screen_corners_of(m))  // its axes drawn to 1.5 times them (construction_camera)
        extend_ndc(observer, corner, 0.0, low, high, in_front), extend_ndc(observer, 1.5 * corner, 0.0, low, high, in_front);
    } else {
      extend_ndc(observer, camera.eye(), 0.0, low, high, in_front);
      extend_ndc(observer, orbit.target, 0.0, low, high, in_front);
      for (const glm::dvec3& corner : camera.screen_corners()) {
        extend_ndc(observer, corner, 0.0, low, high, in_front);
        extend_ndc(observer, camera.eye() + glm::normalize(corner - camera.eye()) * orbit.d, 0.0, low, high, in_front);
      }
      for (const Sphere& s : view3d(state).scene.spheres)
        if (glm::length(s.centre - orbit.target) + s.radius <= orbit.d)
          extend_ndc(observer, s.centre, s.radius, low, high, in_front);
    }
    INFO("trial " << trial << ": theta " << orbit.theta << " phi " << orbit.phi << " d " << orbit.d << " df "
                  << orbit.df << ", observer " << state.observer.yaw_deg << "/" << state.observer.pitch_deg
                  << ", aspect " << aspect << ", step " << state.construction_step << ": content x " << low.x
                  << " … " << high.x << ", y " << low.y << " … " << high.y);
    CHECK(in_front);
    CHECK((low.x >= -1.0 && low.y >= -1.0 && high.x <= 1.0 && high.y <= 1.0));  // nothing cut
    CHECK(std::max(high.x - low.x, high.y - low.y) >= 2 * 0.8);                  // the view's room is used
    ++checked;
  }
  CHECK(checked == 400);
}
