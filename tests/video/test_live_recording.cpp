// The window's live recording (video/live_recording.h): its clock, its fitting of a resized window, and the
// encoder thread against a writer, without a window.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "decoded_video.h"
#include "video/live_recording.h"
#include "scratch_dir.h"

using namespace raycam;

TEST_CASE("live recording: frame k is the first picture drawn at or after k/fps", "[live]") {
  // At 30 fps: a frame drawn at t = 0 is frame 0; at 0.1 s, frames 1, 2, 3 (the window was still meanwhile).
  CHECK(video::frames_due(0.0, 30, 0) == 1);
  CHECK(video::frames_due(0.01, 30, 1) == 0);  // before frame 1's time: nothing new
  CHECK(video::frames_due(0.1, 30, 1) == 3);
  CHECK(video::frames_due(2.0 / 30.0, 30, 2) == 1);  // exactly at k/fps, though 2/30 is 0.0666…6 in binary
  CHECK(video::frames_due(10.0, 30, 301) == 0);
  CHECK(video::frames_due(-1.0, 30, 0) == 1);  // a clock gone back: the first frame, never a negative count
  CHECK(video::frames_due(std::nan(""), 30, 5) == 0);
  // Over a random draw schedule, the frames added equal the frames whose time has come, one for one.
  int written = 0;
  double t = 0.0;
  for (int i = 0; i < 1000; ++i) {
    t += 0.001 + 0.07 * ((i * 7919) % 13) / 13.0;
    written += video::frames_due(t, 25, written);
    REQUIRE(written == int(std::floor(t * 25 + 1e-9)) + 1);
  }
  CHECK(video::seconds_to_next_frame(0.0, 30) == Approx(1.0 / 30));
  CHECK(video::seconds_to_next_frame(0.05, 20) == Approx(0.05));
  CHECK(video::seconds_to_next_frame(0.02, 20) == Approx(0.03));
}

TEST_CASE("live recording: a resized window is fitted in, its aspect kept, centred on black", "[live]") {
  // A 4 × 2 picture into 8 × 8: scaled by 2 to 8 × 4, rows 2..5, the rest opaque black.
  std::vector<std::uint8_t> picture(4 * 2 * 4);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      std::uint8_t* p = &picture[std::size_t(4 * (y * 4 + x))];
      p[0] = std::uint8_t(10 * x), p[1] = std::uint8_t(100 + y), p[2] = 7, p[3] = 255;
    }
  const std::vector<std::uint8_t> fitted = video::fit_frame(picture.data(), 4, 2, 8, 8);
  REQUIRE(fitted.size() == 8 * 8 * 4);
  const auto at = [&](int x, int y) { return &fitted[std::size_t(4 * (y * 8 + x))]; };
  for (int x = 0; x < 8; ++x) {
    CHECK(at(x, 0)[0] + at(x, 0)[1] + at(x, 0)[2] == 0);
    CHECK(at(x, 7)[3] == 255);
    CHECK(at(x, 2)[0] == 10 * (x / 2));  // each source pixel twice
    CHECK(at(x, 3)[1] == 100);
    CHECK(at(x, 4)[1] == 101);
    CHECK(at(x, 5)[1] == 101);
  }
  // Larger than the video: shrunk by the smaller factor (10 × 4 into 5 × 4: factor 1/2, 5 × 2, rows 1..2).
  std::vector<std::uint8_t> wide(10 * 4 * 4, 200);
  const std::vector<std::uint8_t> shrunk = video::fit_frame(wide.data(), 10, 4, 5, 4);
  CHECK(shrunk[4 * (0 * 5 + 2)] == 0);
  CHECK(shrunk[4 * (1 * 5 + 0)] == 200);
  CHECK(shrunk[4 * (2 * 5 + 4)] == 200);
  CHECK(shrunk[4 * (3 * 5 + 2)] == 0);
}

TEST_CASE("live recording: a still window is a still video, as long as it lasted", "[live]") {
  const test::ScratchDir dir("live-recording");
  const std::string path = dir.path("live.mkv");  // lossless: the frames come back as they were given
  const int w = 16, h = 8;
  std::vector<std::uint8_t> red(w * h * 4), blue(w * h * 4);
  for (int i = 0; i < w * h; ++i) {
    red[std::size_t(4 * i)] = 255, red[std::size_t(4 * i + 3)] = 255;
    blue[std::size_t(4 * i + 2)] = 255, blue[std::size_t(4 * i + 3)] = 255;
  }
  {
    // Drawn at 0 s (red), 0.012 s (before frame 1's time: dropped), 0.21 s (blue: the first picture drawn
    // after the times of frames 1..4, 0.05 .. 0.2 s), 0.3 s (frames 5, 6).
    video::LiveRecording recording(path, video::VideoFormat::mkv, w, h, 20);
    recording.add(red.data(), w, h, 0.0);
    recording.add(blue.data(), w, h, 0.012);
    recording.add(blue.data(), w, h, 0.21);
    recording.add(blue.data(), w, h, 0.3);
    CHECK(recording.finish() == 7);
  }
  const test::DecodedVideo decoded = test::decode_video(path);
  REQUIRE(decoded.frames.size() == 7);
  CHECK(decoded.frame_rate == Approx(20.0));
  // Frame 0 red; frames 1..6 blue, 1..4 from the picture drawn at 0.21 s.
  CHECK(decoded.frames[0].at(3, 3)[0] == 255);
  for (int k = 1; k < 7; ++k) {
    INFO("frame " << k);
    CHECK(decoded.frames[std::size_t(k)].at(3, 3)[2] == 255);
  }
  // Nothing but the video: the temporary name was renamed.
  CHECK(std::distance(std::filesystem::directory_iterator(dir.dir), {}) == 1);
}
