// The window's Record control (F9), driven as a user would under Xvfb with xdotool: the videos it leaves,
// decoded back with FFmpeg's libraries.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "decoded_video.h"
#include "image_compare.h"
#include "scratch_dir.h"

using namespace raycam;

namespace {
// The frame count the app's "wrote FILE (m:ss, N frames)" line gives for `name`, -1 if none.
int frames_said(const std::string& log, const std::string& name) {
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t at = line.find(name + " (");
    int minutes = 0, seconds = 0, frames = -1;
    if (at != std::string::npos &&
        std::sscanf(line.c_str() + at + name.size(), " (%d:%d, %d frames)", &minutes, &seconds, &frames) == 3)
      return frames;
  }
  return -1;
}
}  // namespace

TEST_CASE("window: F9 records the window while a user drags, F9 stops, and quitting saves a recording under way",
          "[window][xvfb]") {
  const test::ScratchDir dir("window-recording");
  // In the scratch folder (recordings go to the working folder): F9, a drag in the overhead view, F9; then
  // F9 again and SIGTERM a second later.
  const std::string script =
      "cd " + dir.dir.string() + " && " + RAYCAM_APP + " --width 1024 --height 640 > log.txt 2>&1 & pid=$!; sleep 2; " +
      "xdotool key F9; sleep 0.5; xdotool mousemove 850 150 mousedown 1 sleep 0.2 mousemove 870 160 sleep 0.2 "
      "mousemove 900 180 sleep 0.2 mousemove 930 200 sleep 0.2 mouseup 1; sleep 1; xdotool key F9; sleep 0.5; "
      "xdotool key F9; sleep 1; kill -TERM $pid; wait $pid";
  const int status = std::system((std::string(XVFB_RUN) + " -a -s '-screen 0 1024x640x24' sh -c '" + script + "'").c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  const std::string first = "raycam-demo-3d-recording-001.mp4", second = "raycam-demo-3d-recording-002.mp4";
  REQUIRE(std::filesystem::exists(dir.path(first)));
  REQUIRE(std::filesystem::exists(dir.path(second)));

  const test::DecodedVideo video = test::decode_video(dir.path(first));
  CHECK(video.codec == "h264");
  CHECK(video.frame_rate == Approx(30.0));
  REQUIRE_FALSE(video.frames.empty());
  CHECK(video.frames[0].width == 1024);
  CHECK(video.frames[0].height == 640);
  // About 2.3 s between the two F9s (more on a loaded machine): at 30 fps, a frame for every 1/30 s.
  INFO("frames " << video.frames.size());
  CHECK(video.frames.size() >= 60);
  CHECK(video.frames.size() <= 30 * 8);
  CHECK(frames_said(dir.path("log.txt"), first) == int(video.frames.size()));
  // The drag turned the camera: the last frame's image and views differ from the first's (the status line,
  // the bottom 60 rows, shows the recording's clock and is left out).
  CHECK(test::compare(video.frames.front(), video.frames.back(), 24, 0, 580).differing > 2000);

  // Saved at SIGTERM, about 1 s long.
  const test::DecodedVideo cut = test::decode_video(dir.path(second));
  CHECK(cut.frames.size() >= 15);
  CHECK(frames_said(dir.path("log.txt"), second) == int(cut.frames.size()));
  // Nothing else but the log: no temporary file left.
  CHECK(std::distance(std::filesystem::directory_iterator(dir.dir), {}) == 3);
}
