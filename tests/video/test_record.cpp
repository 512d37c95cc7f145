// `raycam-cli record` against what can be known without it: frame k is `raycam-cli shot` at the camera of
// time k/fps (that camera computed here from the sweep's ends), the videos decoded back by libavcodec are
// those frames within a PSNR bound, and libavformat reads the asked frame count, size and rate.
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/matrix_access.hpp>
#include <map>
#include <string>
#include <vector>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "session/camera_path.h"
#include "session/construction_view.h"
#include "decoded_video.h"
#include "headless/headless_renderer.h"
#include "image_compare.h"
#include "raycam/transform.h"
#include "scratch_dir.h"

using namespace raycam;
using session::construction_pose;

namespace {
const std::string kCli = RAYCAM_CLI;
// Small frames and a fixed overhead rectangle: `shot` then frames the overhead view as the recording does.
const std::vector<std::string> kWindow{"--width", "320", "--height", "240", "--overhead-view", "-10,-10,10,10"};

int run(const std::vector<std::string>& args) {
  std::string command = kCli;
  for (const std::string& arg : args) command += " '" + arg + "'";
  const int status = std::system((command + " > /dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// The first row of the status line (it shows the frame's and the cast's times, which no two runs share).
int status_row(const std::vector<std::string>& args) {
  session::AppOptions options = flags::parse_app_options(args);
  session::AppState state = session::make_app_state(options);
  headless::HeadlessRenderer renderer(options.width, options.height);
  renderer.render_settled(state);
  return int(renderer.layout().status.y);
}

gl::RgbaImage shot(const test::ScratchDir& dir, const std::vector<std::string>& camera) {
  const std::string out = dir.path("shot.png");
  REQUIRE(run(joined(joined({"shot", "--out", out}, kWindow), camera)) == 0);
  return test::load_png(out);
}

gl::RgbaImage frame_png(const std::string& folder, int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", k);
  return test::load_png(folder + "/" + name);
}

double psnr_of(double squares, long count) {
  return squares == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / (squares / double(count)));
}

// Luma PSNR: the decoded Y plane against the frame's own luma, BT.709 in limited range (what the stream
// declares: Y = 16 + 219·(0.2126 R + 0.7152 G + 0.0722 B)/255), over the rows above `rows`. This is the
// codec's loss; the colour's (4:2:0 keeps one chroma sample per 2×2 pixels) is measured in RGB below.
double luma_psnr(const std::vector<std::uint8_t>& y, const gl::RgbaImage& b, int rows) {
  double sum = 0.0;
  long count = 0;
  for (int row = 0; row < rows; ++row)
    for (int x = 0; x < b.width; ++x) {
      const std::uint8_t* p = b.at(x, row);
      const double expected = 16.0 + 219.0 * (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
      const double d = double(y[std::size_t(row) * b.width + x]) - expected;
      sum += d * d, ++count;
    }
  return psnr_of(sum, count);
}

// PSNR of `a` against `b` over the rows above `rows` (RGB; +inf when equal).
double psnr(const gl::RgbaImage& a, const gl::RgbaImage& b, int rows) {
  double sum = 0.0;
  long count = 0;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.at(x, y)[c]) - double(b.at(x, y)[c]);
        sum += d * d, ++count;
      }
  return psnr_of(sum, count);
}
}  // namespace

TEST_CASE("record: frame k of a PNG sequence is shot's frame at the sweeps' camera of time k/fps", "[record]") {
  const test::ScratchDir dir("record-sweeps");
  const std::string folder = dir.path("frames") + "/";
  // Two sweeps one after the other, half a second each; 10 fps: 11 frames, the last the path's end.
  REQUIRE(run(joined({"record", "--sweep", "theta=-40:50", "--sweep", "phi=60:30", "--seconds", "1", "--fps", "10",
                      "--out", folder},
                     kWindow)) == 0);
  REQUIRE(std::filesystem::exists(frame_png(folder, 10).width ? folder : ""));
  CHECK_FALSE(std::filesystem::exists(folder + "frame_00011.png"));
  const int rows = status_row(kWindow);
  for (int k : {0, 3, 5, 8, 10}) {
    const double t = k / 10.0;
    const double theta = t < 0.5 ? -40.0 + 90.0 * t / 0.5 : 50.0;
    const double phi = t < 0.5 ? 60.0 : 60.0 - 30.0 * (t - 0.5) / 0.5;
    const gl::RgbaImage expected = shot(dir, {"--theta", number(theta), "--phi", number(phi)});
    const gl::RgbaImage frame = frame_png(folder, k);
    INFO("frame " << k << ": theta " << theta << ", phi " << phi);
    REQUIRE(frame.width == expected.width);
    REQUIRE(frame.height == expected.height);
    CHECK(test::compare(frame, expected, 0, rows, frame.height).differing == 0);
  }
}

TEST_CASE("record: --construction holds each step on shot --step K's frame, and moves in between", "[record]") {
  const test::ScratchDir dir("record-construction");
  const std::string folder = dir.path("frames") + "/";
  // 3D, 5 factors: with 2.65 s each step's share is 0.5 s (frame a held 0.15 s, then each factor moves for
  // 0.35 s and is held 0.15 s): at 10 fps, frame 5K+1 (t = 0.5K + 0.1) is step K held.
  REQUIRE(run(joined({"record", "--construction", "--seconds", "2.65", "--fps", "10", "--out", folder}, kWindow)) == 0);
  const int rows = status_row(kWindow);
  for (int step = 0; step <= 5; ++step) {
    const int k = step == 0 ? 0 : 5 * step + 1;
    INFO("step " << step << ", frame " << k);
    CHECK(test::compare(frame_png(folder, k), shot(dir, {"--step", std::to_string(step)}), 0, rows, 240).differing == 0);
  }
  // Half-way through R_y(φ) (frame 14, t = 1.4: fraction 0.5 of step 3), the frame is neither step's.
  const gl::RgbaImage middle = frame_png(folder, 14);
  CHECK(test::compare(middle, frame_png(folder, 11), 0, rows, 240).differing > 20);
  CHECK(test::compare(middle, frame_png(folder, 16), 0, rows, 240).differing > 20);
}

TEST_CASE("record: MP4, WebM and GIF decode back to the PNG frames, with the asked count, size and rate", "[record]") {
  const test::ScratchDir dir("record-videos");
  const std::vector<std::string> path{"record", "--sweep", "theta=0:90", "--seconds", "0.75", "--fps", "20"};
  REQUIRE(run(joined(joined(path, kWindow), {"--out", dir.path("png") + "/"})) == 0);
  const int rows = status_row(kWindow);
  // H.264 and VP9: the codec's loss, luma PSNR ≥ 40 dB (the issue's bound); in RGB, ≥ 30 dB: 4:2:0, the
  // format every browser plays, halves the colour's resolution both ways, and the window's coloured 1-pixel
  // lines and small text lose most of it (about 33 dB at 320×240, the colour conversion alone). GIF: 256
  // colours from the first frame; 30 dB is an error of about 8 levels, what a 5-bit-per-channel palette's
  // rounding (up to 4) and the anti-aliased text's edges give.
  struct Case {
    const char* file;
    const char* codec;
    double min_psnr;  // RGB
  };
  for (const Case& c : {Case{"v.mp4", "h264", 30.0}, Case{"v.webm", "vp9", 30.0}, Case{"v.gif", "gif", 30.0}}) {
    INFO(c.file);
    REQUIRE(run(joined(joined(path, kWindow), {"--out", dir.path(c.file)})) == 0);
    const test::DecodedVideo video = test::decode_video(dir.path(c.file));
    CHECK(video.codec == c.codec);
    REQUIRE(video.frames.size() == 16);  // 0.75 s · 20 fps, and the last camera
    CHECK(video.frames[0].width == 320);
    CHECK(video.frames[0].height == 240);
    for (std::size_t k = 1; k < video.times.size(); ++k) CHECK(video.times[k] - video.times[k - 1] == Approx(0.05));
    if (std::string(c.codec) != "gif") CHECK(video.frame_rate == Approx(20.0));
    double worst = INFINITY;
    for (int k = 0; k < 16; ++k) worst = std::min(worst, psnr(video.frames[std::size_t(k)], frame_png(dir.path("png"), k), rows));
    INFO("worst RGB PSNR " << worst << " dB");
    CHECK(worst >= c.min_psnr);
    if (std::string(c.codec) == "gif") continue;
    REQUIRE(video.luma.size() == 16);
    double worst_luma = INFINITY;
    for (int k = 0; k < 16; ++k)
      worst_luma = std::min(worst_luma, luma_psnr(video.luma[std::size_t(k)], frame_png(dir.path("png"), k), rows));
    INFO("worst luma PSNR " << worst_luma << " dB");
    CHECK(worst_luma >= 40.0);
    // The codec's own loss in RGB: against each frame as a perfect 4:2:0 codec returns it, ≥ 40 dB.
    double worst_codec = INFINITY;
    for (int k = 0; k < 16; ++k)
      worst_codec = std::min(worst_codec, psnr(video.frames[std::size_t(k)], test::through_yuv420(frame_png(dir.path("png"), k)), rows));
    INFO("worst RGB PSNR against the frames through 4:2:0 " << worst_codec << " dB");
    CHECK(worst_codec >= 40.0);
    WARN(c.file << ": worst PSNR luma " << worst_luma << " dB, RGB " << worst << " dB, RGB after 4:2:0 " << worst_codec << " dB");
  }
  // Nothing but the asked files: every temporary name was renamed.
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.dir)) entries += 1 + 0 * int(entry.is_regular_file());
  CHECK(entries == 4);
}

TEST_CASE("record: a lossless MKV (FFV1) decodes back to the PNG frames pixel for pixel", "[record]") {
  const test::ScratchDir dir("record-lossless");
  const std::vector<std::string> path{"record", "--sweep", "theta=10:100", "--sweep", "d=8:12", "--seconds", "0.5", "--fps", "20"};
  REQUIRE(run(joined(joined(path, kWindow), {"--out", dir.path("png") + "/"})) == 0);
  REQUIRE(run(joined(joined(path, kWindow), {"--out", dir.path("v.mkv")})) == 0);
  const test::DecodedVideo video = test::decode_video(dir.path("v.mkv"));
  CHECK(video.codec == "ffv1");
  REQUIRE(video.frames.size() == 11);  // 0.5 s · 20 fps, and the last camera
  CHECK(video.frame_rate == Approx(20.0));
  const int rows = status_row(kWindow);  // the status line shows each run's own frame times
  for (int k = 0; k < 11; ++k) {
    INFO("frame " << k);
    const test::Difference diff = test::compare(video.frames[std::size_t(k)], frame_png(dir.path("png"), k), 0, rows, 240);
    CHECK(diff.differing == 0);
  }
  // And the frames move: a video of one frame repeated would pass the comparison above only if the PNGs did too.
  CHECK(test::compare(video.frames[0], video.frames[10], 0, rows, 240).differing > 100);
}

TEST_CASE("record: --only gives one view, the very pixels it has in the whole window's frame", "[record]") {
  const test::ScratchDir dir("record-only");
  const std::vector<std::string> path{"record", "--sweep", "theta=0:60", "--seconds", "0.2", "--fps", "10"};
  REQUIRE(run(joined(joined(path, kWindow), {"--out", dir.path("whole") + "/"})) == 0);
  std::map<std::string, std::pair<int, int>> places;  // where each view was found in frame 0
  for (const char* view : {"image", "overhead", "observer"}) {
    INFO(view);
    REQUIRE(run(joined(joined(path, kWindow), {"--only", view, "--out", dir.path(view) + "/"})) == 0);
    for (int k : {0, 2}) {
      const gl::RgbaImage whole = frame_png(dir.path("whole"), k), part = frame_png(dir.path(view), k);
      REQUIRE(part.width >= 16);
      CHECK(part.width % 2 == 0);
      CHECK(part.height % 2 == 0);
      CHECK(part.width < whole.width);
      // Found in the whole frame at some place, pixel for pixel (searched, not computed from the layout).
      bool found = false;
      for (int y0 = 0; y0 + part.height <= whole.height && !found; ++y0)
        for (int x0 = 0; x0 + part.width <= whole.width && !found; ++x0) {
          bool same = true;
          for (int y = 0; y < part.height && same; ++y)
            same = std::equal(part.at(0, y), part.at(0, y) + 4 * part.width, whole.at(x0, y0 + y));
          if (same && k == 0) places[view] = {x0, y0};
          found = same;
        }
      CHECK(found);
      // The image is the 3D camera's square picture, exactly (its rectangle, sides rounded down to even).
      if (std::string(view) == "image") CHECK(std::abs(part.width - part.height) <= 2);
    }
  }
  // Three views, three places: the image beside the overhead view, the observer below them.
  CHECK(places["image"].first < places["overhead"].first);
  CHECK(places["observer"].second > places["overhead"].second + 20);
}

TEST_CASE("record: a pattern's folder is made, as a FOLDER/ output's is", "[record]") {
  const test::ScratchDir dir("record-pattern");
  REQUIRE(run(joined({"record", "--sweep", "theta=0:10", "--seconds", "0.1", "--fps", "10", "--out",
                      dir.path("made") + "/f%03d.png"},
                     kWindow)) == 0);
  CHECK(std::filesystem::exists(dir.path("made") + "/f000.png"));
  CHECK(std::filesystem::exists(dir.path("made") + "/f001.png"));
  CHECK_FALSE(std::filesystem::exists(dir.path("made") + "/f002.png"));
}

TEST_CASE("record: a construction factor part way turns, scales and moves by that part", "[record]") {
  const Placement3D p = placement_matrix(Orbit3D{{1, 2, 3}, 8.0, glm::radians(30.0), glm::radians(60.0), 2.0});
  for (int step = 1; step <= kConstructionSteps3D; ++step) {
    INFO("step " << step);
    const glm::dmat4 before = construction_step(p, step - 1), after = construction_step(p, step);
    CHECK(construction_pose(p, step, 0.0) == before);
    CHECK(construction_pose(p, step, 1.0) == after);
    // Half a factor twice is the whole factor: half an angle, half a scale step is not (1 + (d_f−1)/2)² …
    const glm::dmat4 half_factor = construction_pose(p, step, 0.5) * glm::inverse(before);
    if (step == 1) CHECK(half_factor[2][2] == Approx(1.5));                       // H: z scaled by 1 + (2 − 1)/2
    else if (step == 5) CHECK(glm::dvec3(half_factor[3]) == glm::dvec3(0.5 * glm::dvec3(p.translation[3])));  // T: half OP
    else {
      const glm::dmat4 twice = half_factor * half_factor, whole = after * glm::inverse(before);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(twice[i][j] == Approx(whole[i][j]).margin(1e-12));
    }
  }
  const Placement2D q = placement_matrix(Orbit2D{{0, 0}, 6.0, glm::radians(70.0), 1.5});
  const glm::dmat3 half = construction_pose(q, 2, 0.5) * glm::inverse(construction_step(q, 1));
  CHECK(std::atan2(half[0][1], half[0][0]) == Approx(0.5 * q.alpha));  // R(α/2)
}

TEST_CASE("record: a key-camera file's errors name the file and the field", "[record]") {
  const test::ScratchDir dir("record-keys");
  const auto write = [&](const std::string& text) {
    std::FILE* f = std::fopen(dir.path("keys.json").c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return dir.path("keys.json");
  };
  const session::Pose start;
  CHECK_THROWS_WITH(session::key_camera_path(start, 3, write(R"({"keys": [{"theta": 0}, {"theta": 900, "seconds": 1}]})"),
                                             session::Easing::linear),
                    Catch::Contains("keys[1].theta: expected a number in [-720, 720], got 900"));
  CHECK_THROWS_WITH(session::key_camera_path(start, 3, write(R"({"keys": [{"theta": 0}, {"zoom": 2, "seconds": 1}]})"),
                                             session::Easing::linear),
                    Catch::Contains("keys[1].zoom"));
  CHECK_THROWS_WITH(session::key_camera_path(start, 3, write(R"({"keys": [{"theta": 0}, {"theta": 5}]})"),
                                             session::Easing::linear),
                    Catch::Contains("keys[1]: expected \"seconds\""));
  const session::CameraPath path = session::key_camera_path(
      start, 3, write(R"({"keys": [{"theta": 0, "phi": 60}, {"theta": 90, "seconds": 2}, {"phi": 30, "seconds": 1}]})"),
      session::Easing::linear);
  CHECK(path.seconds() == 3.0);
  CHECK(path.at(1.0).theta == 45.0);
  CHECK(path.at(2.5).phi == 45.0);
  CHECK(path.at(2.5).theta == 90.0);
}
