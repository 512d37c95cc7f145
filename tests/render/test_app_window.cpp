// The real GLFW app under Xvfb: it starts, runs a few frames, its screenshot is not blank, shows the scene's
// colours, and equals the headless twin's picture for the same arguments (up to the status line's timings).
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "../scratch_dir.h"
#include "image_compare.h"
#include "raycam/scene.h"

using namespace raycam;

namespace {
int run(const std::string& command) { return std::system((command + " > /dev/null 2>&1").c_str()); }

// Where this process's files go: the system's temporary folder.
std::string scratch(const std::string& file) {
  static const test::ScratchDir dir("app-window");
  return dir.path(file);
}

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
    REQUIRE(run(std::string(XVFB_RUN) + " -a -s '-screen 0 1024x640x24' " + RAYCAM_APP + args + "--frames 4 --screenshot " + scratch("app_" + view + ".png")) == 0);
    REQUIRE(run(std::string(RAYCAM_CLI) + " shot" + args + "--frames 4 --out " + scratch("shot_" + view + ".png")) == 0);
    const gl::RgbaImage app = test::load_png(scratch("app_" + view + ".png")),
                      shot = test::load_png(scratch("shot_" + view + ".png"));
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

TEST_CASE("the window fits a screen smaller than the size asked for", "[app][xvfb]") {
  // A 1024×768 projector: the default 1280×720 window would be cut at the right-hand edge.
  const std::string shot = scratch("app_small_screen.png");
  REQUIRE(run(std::string(XVFB_RUN) + " -a -s '-screen 0 1024x768x24' " + RAYCAM_APP + " --frames 3 --screenshot " +
              shot) == 0);
  const gl::RgbaImage app = test::load_png(shot);
  CHECK(app.width == 1024);
  CHECK(app.height == 720);
  // Asked for more than the screen on both sides: the screen's size.
  REQUIRE(run(std::string(XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + RAYCAM_APP +
              " --width 1600 --height 1200 --frames 3 --screenshot " + shot) == 0);
  const gl::RgbaImage small = test::load_png(shot);
  CHECK(small.width == 800);
  CHECK(small.height == 600);
}

namespace {
struct WindowRun {
  int exit_code = -1;
  long long frames = -1, casts = -1;
  double cpu_ms = -1;  // the whole run's, start-up included
};

// Runs the interactive app (no --frames) under Xvfb for `seconds`, with `input` (xdotool commands, or
// nothing) sent after it settled, then asks it to quit with SIGTERM and reads its exit line.
WindowRun run_window(const std::string& name, double seconds, const std::string& input) {
  const std::string out = scratch("window_" + name + ".txt");
  const std::string script = std::string(RAYCAM_APP) + " --width 1024 --height 640 > " + out +
                             " 2>&1 & pid=$!; sleep 2; " + input + "; sleep " + std::to_string(seconds) +
                             "; kill -TERM $pid; wait $pid";
  WindowRun result;
  const int status =
      std::system((std::string(XVFB_RUN) + " -a -s '-screen 0 1024x640x24' sh -c '" + script + "'").c_str());
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(out);
  std::string line;
  while (std::getline(in, line))
    if (std::sscanf(line.c_str(), "raycam: %lld frames drawn, %lld casts, %lf ms of CPU", &result.frames,
                    &result.casts, &result.cpu_ms) == 3)
      break;
  return result;
}
}  // namespace

TEST_CASE("an idle window waits for events instead of drawing, and draws at once on input",
          "[app][xvfb][idle]") {
  // Idle: the start-up frames (GlfwHost::kSettleFrames after the first events) and nothing while nobody
  // touches it. Redrawing continuously, it drew hundreds of frames a second.
  const WindowRun idle = run_window("idle", 3.0, "true");
  REQUIRE(idle.exit_code == 0);  // SIGTERM leaves the loop cleanly
  INFO("frames drawn in ~5 s with no input: " << idle.frames << ", CPU " << idle.cpu_ms << " ms");
  CHECK(idle.frames >= 1);
  CHECK(idle.frames <= 12);
  // And no work between frames: start-up and a few frames take well under a second of CPU; a loop that
  // polls instead of waiting burns ~40 % of a core, 2 s in these 5.
  CHECK(idle.cpu_ms >= 0);
  CHECK(idle.cpu_ms < 1000);
  // Input: a drag in the overhead view moves the camera, so the window redraws and casts again.
  const WindowRun dragged = run_window("drag", 1.0,
                                       "xdotool mousemove 850 150 sleep 0.3 mousedown 1 sleep 0.3 mousemove "
                                       "880 170 sleep 0.3 mousemove 920 200 sleep 0.3 mouseup 1");
  REQUIRE(dragged.exit_code == 0);
  INFO("frames " << dragged.frames << ", casts " << dragged.casts);
  CHECK(dragged.casts >= 2);
  CHECK(dragged.frames > idle.frames);
}
