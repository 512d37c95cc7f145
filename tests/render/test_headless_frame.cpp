// The app's frame rendered headless: what it shows is checked against what can be known independently —
// the core's colour map (recomputed here from the same parameters in radians), the overhead mapping's
// positions of the eye, target and screen, and the inspected ray's hit point — plus reviewed reference PNGs.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <set>
#include <string>
#include <vector>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "headless/headless_renderer.h"
#include "image_compare.h"
#include "session/inspection.h"
#include "raycam/ray_caster.h"
#include "raycam/transform.h"

using namespace raycam;

namespace {

struct Shot {
  session::AppState state;
  gl::RgbaImage image;
  ui::FrameLayout layout;
};

Shot shoot(const std::vector<std::string>& args, int width = 1280, int height = 720) {
  session::AppOptions options = flags::parse_app_options(args);
  options.width = width;
  options.height = height;
  Shot shot{session::make_app_state(options), {}, {}};
  headless::HeadlessRenderer renderer(width, height);
  shot.image = renderer.render_settled(shot.state);
  shot.layout = renderer.layout();
  return shot;
}

Rgb8 pixel(const gl::RgbaImage& image, double x, double y) {
  const std::uint8_t* p = image.at(int(std::floor(x)), int(std::floor(y)));
  return {p[0], p[1], p[2]};
}

// Is a pixel close to `colour` within a few pixels of (x, y)? (Markers are anti-aliased.)
bool colour_near(const gl::RgbaImage& image, ImVec2 at, ImU32 colour, int radius = 2, int tolerance = 40) {
  const int r = colour & 0xFF, g = (colour >> 8) & 0xFF, b = (colour >> 16) & 0xFF;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = int(at.x) + dx, y = int(at.y) + dy;
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const std::uint8_t* p = image.at(x, y);
      if (std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance && std::abs(p[2] - b) <= tolerance) return true;
    }
  return false;
}

void check_image_region_holds(const Shot& shot, const ColourMap& expected) {
  const ui::Rect& r = shot.layout.image;
  REQUIRE(r.w >= 2 * expected.width);  // at least 2 screen pixels per map pixel: centres are unambiguous
  REQUIRE(r.h >= 2 * expected.height);
  int wrong = 0;
  for (int row = 0; row < expected.height; ++row)
    for (int column = 0; column < expected.width; ++column) {
      const Rgb8 seen = pixel(shot.image, r.x + (column + 0.5) * r.w / expected.width, r.y + (row + 0.5) * r.h / expected.height);
      wrong += seen != expected.colour_at(row, column);
    }
  CHECK(wrong == 0);
}
}  // namespace

TEST_CASE("the 2D colour bar on screen is the core's colour map, pixel for pixel", "[render][2d]") {
  for (double theta : {90.0, 20.0, -135.0}) {
    const Shot shot = shoot({"--view", "2d", "--size", "200", "--theta", std::to_string(theta), "--df", "1.2", "--d", "7"});
    Camera2D camera(200);
    camera.set_orbit({{0, 0}, 7.0, glm::radians(theta), 1.2});
    check_image_region_holds(shot, cast_primary_rays(camera, demo_scene_2d()));
  }
}

TEST_CASE("the 3D image on screen is the core's colour map, pixel for pixel", "[render][3d]") {
  const Shot shot = shoot({"--size", "64x48", "--theta", "200", "--phi", "70", "--d", "6", "--df", "1.5"});
  Camera3D camera(64, 48);
  camera.set_orbit({{0, 0, 0}, 6.0, glm::radians(200.0), glm::radians(70.0), 1.5});
  check_image_region_holds(shot, cast_primary_rays(camera, demo_scene_3d()));
}

TEST_CASE("eye, target and screen are drawn where the overhead mapping puts them", "[render][overhead]") {
  const Shot two = shoot({"--view", "2d", "--theta", "60", "--target", "0.5,-0.5"});
  const ui::OverheadMapping& m2 = two.layout.overhead_mapping;
  const Camera2D& c2 = view2d(two.state).camera;
  CHECK(colour_near(two.image, m2.to_screen(c2.eye()), ui::kEyeColour));
  CHECK(colour_near(two.image, m2.to_screen({0.5, -0.5}), ui::kTargetColour));
  CHECK(colour_near(two.image, m2.to_screen(c2.screen_centre()), ui::kScreenColour));
  // The markers are not everywhere: far from the eye there is no eye colour.
  CHECK_FALSE(colour_near(two.image, {two.layout.overhead.x + 3, two.layout.overhead.y + two.layout.overhead.h - 3}, ui::kEyeColour));

  const Shot three = shoot({"--theta", "-40", "--phi", "50"});
  const ui::OverheadMapping& m3 = three.layout.overhead_mapping;
  const glm::dvec3 corner = transform_point(view3d(three.state).camera.world_from_camera(), glm::dvec3(1, 1, 0));
  CHECK(colour_near(three.image, m3.to_screen({corner.x, corner.y}), ui::kScreenColour));
  const glm::dvec3 eye = view3d(three.state).camera.eye();
  CHECK(colour_near(three.image, m3.to_screen({eye.x, eye.y}), ui::kEyeColour));
}

TEST_CASE("the inspected ray ends at its hit point", "[render][inspector]") {
  for (const char* view : {"2d", "3d"}) {
    const bool is_2d = std::string(view) == "2d";
    const Shot shot = shoot({"--view", view, "--inspect", is_2d ? "90,0" : "120,140"});
    glm::dvec2 origin, end;
    if (is_2d) {
      const Camera2D& camera = view2d(shot.state).camera;
      const Ray2D ray = camera.primary_ray(camera.pixel_of_column(90));
      const Hit hit = nearest_hit(view2d(shot.state).scene.circles, ray, IntersectFormula::stable);
      REQUIRE(hit.id >= 0);
      origin = ray.origin;
      end = ray.origin + hit.t * ray.direction;
    } else {
      const Ray3D ray = view3d(shot.state).camera.primary_ray(140, 120);
      const Hit hit = nearest_hit(view3d(shot.state).scene.spheres, ray, IntersectFormula::stable);
      REQUIRE(hit.id >= 0);
      origin = {ray.origin.x, ray.origin.y};
      end = glm::dvec2(ray.origin + hit.t * ray.direction);
    }
    const ui::OverheadMapping& m = shot.layout.overhead_mapping;
    const ImVec2 end_on_screen = m.to_screen(end), origin_on_screen = m.to_screen(origin);
    CHECK(colour_near(shot.image, {end_on_screen.x + 6, end_on_screen.y}, ui::kInspectedRayColour));  // the hit ring
    CHECK(colour_near(shot.image, {(end_on_screen.x + origin_on_screen.x) / 2, (end_on_screen.y + origin_on_screen.y) / 2},
                      ui::kInspectedRayColour));
  }
}

TEST_CASE("no region of the window is blank", "[render]") {
  const Shot shot = shoot({});
  for (const ui::Rect& r : {shot.layout.panel, shot.layout.image, shot.layout.overhead, shot.layout.observer}) {
    std::set<std::uint32_t> colours;
    for (int y = int(r.y); y < int(r.y + r.h); y += 3)
      for (int x = int(r.x); x < int(r.x + r.w); x += 3) {
        const std::uint8_t* p = shot.image.at(x, y);
        colours.insert(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
      }
    CHECK(colours.size() >= 4);
  }
}

TEST_CASE("the window matches the reviewed reference screenshots", "[render][reference]") {
  for (const char* name : {"ui2d", "ui3d"}) {
    const bool is_2d = std::string(name) == "ui2d";
    const Shot shot =
        shoot(is_2d ? std::vector<std::string>{"--lang", "en", "--view", "2d", "--inspect", "100,0"}
                    : std::vector<std::string>{"--lang", "en", "--inspect", "120,140", "--step", "3"});
    const std::string reference_path = std::string(RAYCAM_REFERENCE_DIR) + "/" + name + ".png";
    // Masked: the status line only, which holds the timings (they change every run) and, after them, the
    // caster's name that they shift. Its work counters live in a tooltip and are checked as text against the
    // state (tests/ui/test_panel_text.cpp). Every panel number is compared here: one changed digit fails.
    test::ScreenshotRules rules;
    const ui::Rect& status = shot.layout.status;
    rules.masked.push_back(
        {int(status.x), int(status.y), int(status.w) + 1, shot.image.height - int(status.y)});
    const test::ScreenshotDifference d = test::check_screenshot(shot.image, reference_path, rules, name);
    INFO(name << ": " << d.summary() << "; actual and diff written to the build directory (a missing or "
              << "outdated reference: review " << name << ".actual.png and copy it to " << reference_path
              << ")");
    CHECK(d.ok);
  }
}

TEST_CASE("a classic mistake that is on is named in the image's header, in red", "[render][mistakes]") {
  // Most of the header's pixels are red (the title's glyphs cover a small part of it, wherever the text
  // ends with the font in use); a normal header has none.
  auto header_is_red = [](const Shot& shot) {
    const ui::Rect& h = shot.layout.image_header;
    int red = 0, all = 0;
    for (int y = int(h.y) + 1; y < int(h.y + h.h) - 1; ++y)
      for (int x = int(h.x) + 1; x < int(h.x + h.w) - 1; ++x, ++all) {
        const Rgb8 c = pixel(shot.image, x, y);
        red += c.r > 120 && c.g < 60 && c.b < 60;
      }
    return all > 0 && red > all / 2;
  };
  CHECK_FALSE(header_is_red(shoot({})));
  CHECK_FALSE(header_is_red(shoot({"--view", "2d"})));
  CHECK(header_is_red(shoot({"--mistake", "pixel-edges"})));
  CHECK(header_is_red(shoot({"--view", "2d", "--mistake", "arccos"})));
}

TEST_CASE("the overhead view draws each ray to the hit the caster found, mistakes included",
          "[render][mistakes]") {
  // Naive formula without renormalising: the bar is full of swollen objects, and the view must show those
  // hits where the caster put them (it used to draw every ray as a miss).
  const Shot shot =
      shoot({"--view", "2d", "--size", "24", "--mistake", "no-renormalise", "--intersect", "naive"});
  const ui::OverheadMapping& m = shot.layout.overhead_mapping;
  int hits = 0;
  for (int column = 0; column < shot.state.map.width; ++column) {
    const session::InspectedRay ray = session::inspect_pixel(shot.state, shot.state, {0, column});
    if (ray.hit.id < 0) continue;
    ++hits;
    const Rgb8 c = view2d(shot.state).scene.circles[std::size_t(ray.hit.id)].colour;
    INFO("column " << column);
    CHECK(colour_near(shot.image, m.to_screen({ray.end(0).x, ray.end(0).y}), IM_COL32(c.r, c.g, c.b, 255), 1,
                      30));
  }
  CHECK(hits == shot.state.map.width);  // at d_f = 1.5 the swollen circles cover the whole bar
}

TEST_CASE("the screenshot comparison fails on one changed digit and ignores only the masked timings",
          "[render][reference]") {
  // The comparison itself, on a real frame: a digit of the ray inspector's t drawn differently must fail,
  // the same change inside a masked rectangle must not, and a few isolated stray pixels are tolerated.
  const Shot shot = shoot({"--inspect", "120,140"});
  gl::RgbaImage changed = shot.image;
  // Repaint a 6×10 glyph-sized block of the panel (where text is) with the text colour's complement.
  const ui::Rect& panel = shot.layout.panel;
  const int gx = int(panel.x) + 40, gy = int(panel.y + panel.h / 2);
  for (int y = gy; y < gy + 10; ++y)
    for (int x = gx; x < gx + 6; x += 2) {  // every other column: a glyph's strokes, not a filled box
      std::uint8_t* p = &changed.pixels[(std::size_t(y) * std::size_t(changed.width) + std::size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(255 - p[c]);
    }
  test::ScreenshotRules rules;
  CHECK(test::compare_screenshot(shot.image, shot.image, rules).ok);
  CHECK_FALSE(test::compare_screenshot(changed, shot.image, rules).ok);
  test::ScreenshotRules masked = rules;
  masked.masked.push_back({gx, gy, 6, 10});
  CHECK(test::compare_screenshot(changed, shot.image, masked).ok);
  // Isolated stray pixels (one per 64×64 block, 0.02 %) pass: rasteriser noise, not a change.
  gl::RgbaImage noisy = shot.image;
  for (int y = 0; y < noisy.height; y += 64)
    for (int x = 0; x < noisy.width; x += 64)
      noisy.pixels[(std::size_t(y) * std::size_t(noisy.width) + std::size_t(x)) * 4] ^= 0xFF;
  CHECK(test::compare_screenshot(noisy, shot.image, rules).ok);
}

TEST_CASE("the overhead view holds still while the camera moves inside it, and fits again when it would leave",
          "[render][views]") {
  session::AppOptions options;
  session::AppState state = session::make_app_state(options);
  headless::HeadlessRenderer renderer(1280, 800);
  renderer.render_settled(state);
  const ui::OverheadMapping before = renderer.layout().overhead_mapping;
  const ui::Rect& view = renderer.layout().overhead;
  auto inside = [&](ImVec2 p) {
    return p.x >= view.x && p.x <= view.x + view.w && p.y >= view.y && p.y <= view.y + view.h;
  };
  view3d(state).orbit.theta += 0.1;  // a small orbit: the camera stays in view, the objects neither slide nor scale
  state.cameras_dirty = true;
  renderer.render_settled(state);
  const ui::OverheadMapping during = renderer.layout().overhead_mapping;
  CHECK(during.scale == before.scale);
  CHECK(during.origin.x == before.origin.x);
  CHECK(during.origin.y == before.origin.y);
  view3d(state).orbit.theta = glm::radians(90.0);  // the demo's camera used to leave the top of the view here…
  view3d(state).orbit.d = 40.0;                    // …and a far camera its sides
  state.cameras_dirty = true;
  renderer.render_settled(state);
  const ui::OverheadMapping after = renderer.layout().overhead_mapping;
  const glm::dvec3 eye = view3d(state).camera.eye(), target = view3d(state).orbit.target;
  CHECK(after.scale < before.scale);  // fitted again, by itself
  CHECK(inside(after.to_screen({eye.x, eye.y})));
  CHECK(inside(after.to_screen({target.x, target.y})));
  ImGui::GetIO().AddInputCharacter('f');  // F still fits on demand
  renderer.run_frame(state);
  renderer.run_frame(state);
  CHECK(inside(renderer.layout().overhead_mapping.to_screen({eye.x, eye.y})));
}

TEST_CASE("each step of the 3D construction looks different from above and in the observer view",
          "[render][construction]") {
  // Each factor moves something the views can show: H the eye (label, narrower field), the roll the axes and
  // the screen's top edge, R_y the tilt, R_z(θ) the turn about z, T the position. Step 5 is the final camera.
  std::vector<Shot> shots;
  for (int step = 0; step <= 5; ++step) shots.push_back(shoot({"--step", std::to_string(step)}));
  auto differing = [](const Shot& a, const Shot& b, const ui::Rect& r) {
    int count = 0;
    for (int y = int(r.y); y < int(r.y + r.h); ++y)
      for (int x = int(r.x); x < int(r.x + r.w); ++x) count += pixel(a.image, x, y) != pixel(b.image, x, y);
    return count;
  };
  for (int step = 0; step < 5; ++step) {
    INFO("step " << step << " to " << step + 1);
    CHECK(differing(shots[step], shots[step + 1], shots[step].layout.overhead) > 300);
    CHECK(differing(shots[step], shots[step + 1], shots[step].layout.observer) > 300);
  }
}

TEST_CASE("the 2D screen segment marks pixel k = 0, and the eye's left at the other end",
          "[render][overhead]") {
  for (const char* theta : {"90", "20", "-135"}) {
    const Shot shot = shoot({"--view", "2d", "--theta", theta, "--res", "0.1"});
    const Camera2D& camera = view2d(shot.state).camera;
    const ui::OverheadMapping& m = shot.layout.overhead_mapping;
    INFO("theta " << theta);
    // Pixel k = 0 is at canonical x = -1 + 1/n: M_d carries it into the world; column 0 (the eye's left) is
    // the pixel k = n-1 at the other end, and has no such mark.
    const glm::dvec2 first = transform_point(camera.world_from_camera(), camera.canonical_pixel(0));
    const glm::dvec2 last =
        transform_point(camera.world_from_camera(), camera.canonical_pixel(camera.pixel_count() - 1));
    CHECK(colour_near(shot.image, m.to_screen(first), ui::kFirstPixelColour, 1, 20));
    CHECK_FALSE(colour_near(shot.image, m.to_screen(last), ui::kFirstPixelColour, 1, 20));
  }
}

TEST_CASE("the observer view shows the camera's screen at least a tenth of its height, at 1280x800",
          "[render][views]") {
  const Shot shot = shoot({}, 1280, 800);
  const session::ObserverCamera& observer = shot.layout.observer_camera;
  const ui::Rect& view = shot.layout.observer;
  double top = 1e9, bottom = -1e9;
  for (const glm::dvec3& corner : view3d(shot.state).camera.screen_corners()) {
    const glm::vec4 clip = observer.projection * observer.view * glm::vec4(glm::vec3(corner), 1.0f);
    const double y = view.y + (1.0 - clip.y / clip.w) * 0.5 * view.h;  // NDC y up, screen y down
    top = std::min(top, y), bottom = std::max(bottom, y);
  }
  CHECK(top >= view.y);
  CHECK(bottom <= view.y + view.h);
  CHECK(bottom - top >= 0.1 * view.h);
  // And it is drawn there: the screen's cyan outline crosses the projected box's middle row.
  bool cyan = false;
  for (int x = int(view.x); x < int(view.x + view.w) && !cyan; ++x)
    cyan = colour_near(shot.image, {float(x), float(0.5 * (top + bottom))}, ui::kScreenColour, 0, 60);
  CHECK(cyan);
}
