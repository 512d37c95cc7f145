// Views that hold still and follow, without a window: the demo ground never swallows the camera on the
// default orbit, Reset returns to the scene file's preset, the observer frames and follows the camera, and a
// drag moves the camera the way the mouse goes as the observer sees it.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "../scratch_dir.h"
#include "app_state_for.h"
#include "observer_view.h"

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
