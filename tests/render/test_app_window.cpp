// The real GLFW app under Xvfb: it starts, runs a few frames, its screenshot is not blank, shows the scene's
// colours, and equals the headless twin's picture for the same arguments (up to the status line's timings).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "image_compare.h"
#include "raycam/scene.h"

using namespace raycam;

namespace {
int run(const std::string& command) { return std::system((command + " > /dev/null 2>&1").c_str()); }

long count_colour(const gl::RgbaImage& image, Rgb8 colour) {
  long count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      count += p[0] == colour.r && p[1] == colour.g && p[2] == colour.b;
    }
  return count;
}
}  // namespace

TEST_CASE("the GLFW window's screenshot equals the headless shot", "[app][xvfb]") {
  for (const std::string view : {"2d", "3d"}) {
    const std::string args = " --view " + view + " --width 1024 --height 640 --inspect " + (view == "2d" ? "40,0 " : "40,30 ");
    REQUIRE(run(std::string(XVFB_RUN) + " -a -s '-screen 0 1024x640x24' " + RAYCAM_APP + args + "--frames 4 --screenshot app_" + view + ".png") == 0);
    REQUIRE(run(std::string(RAYCAM_CLI) + " shot" + args + "--frames 4 --out shot_" + view + ".png") == 0);
    const gl::RgbaImage app = test::load_png("app_" + view + ".png"), shot = test::load_png("shot_" + view + ".png");
    REQUIRE(app.width == 1024);
    REQUIRE(app.height == 640);
    // The scene's colours are on screen (the demo scenes' red and blue objects), so it is not blank.
    const Scene2D scene2d = demo_scene_2d();
    const Scene3D scene3d = demo_scene_3d();
    const Rgb8 red = view == "2d" ? scene2d.circles[0].colour : scene3d.spheres[0].colour;
    const Rgb8 blue = view == "2d" ? scene2d.circles[2].colour : scene3d.spheres[2].colour;
    CHECK(count_colour(app, red) > 500);
    CHECK(count_colour(app, blue) > 500);
    const test::Difference d = test::compare(app, shot, 24, app.height - 40, app.height);
    INFO(view << ": " << d.differing << " of " << d.compared << " pixels differ");
    if (d.differing > d.compared / 1000) test::write_diff(app, shot, 24, "app_vs_shot_" + view + ".diff.png");
    CHECK(d.differing <= d.compared / 1000);
  }
}
