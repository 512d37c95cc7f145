// `raycam-cli record`: the app's whole window, rendered headless as `shot` renders it, along a camera path
// (slider sweeps, key cameras, or the construction of M_d), written as MP4, WebM, GIF or PNG files.
// Frame k shows the camera of time k/fps, exactly the frame `shot` gives for that camera.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "cli/commands.h"
#include "flags/flag_values.h"
#include "headless/headless_renderer.h"
#include "ui/overhead_view.h"
#include "flags/app/path_flags.h"
#include "video/video_writer.h"

namespace raycam::cli {

namespace {
// --only: one view of the window instead of the whole window.
enum class ShownPart { window, image, overhead, observer };

struct RecordOptions {
  session::AppOptions app;
  flags::PathFlags path;
  std::string out_path;
  ShownPart only = ShownPart::window;
  double seconds = 4.0;
  bool seconds_given = false;
  int fps = 30;
};

// The times of the frames: 0, 1/fps, … up to the path's end, which is the last frame (so that the video
// stops on the path's last camera).
int frame_count(double seconds, int fps) { return int(std::lround(seconds * fps)) + 1; }

// One overhead rectangle for the whole recording: the union of the fits at every frame's camera, so that the
// view holds still (as in the window while a slider moves) and the camera never leaves it.
void hold_overhead_view(session::AppState& state, const session::CameraPath& path, int frames, int fps) {
  glm::dvec2 low(0.0), high(0.0);
  for (int k = 0; k < frames; ++k) {
    session::apply_pose(state, path.at(double(k) / fps));
    session::place_cameras(state);
    ui::fit_overhead(state, state);
    low = k == 0 ? state.overhead_low : glm::min(low, state.overhead_low);
    high = k == 0 ? state.overhead_high : glm::max(high, state.overhead_high);
  }
  state.overhead_low = low;
  state.overhead_high = high;
  state.overhead_fit_pending = false;
}

// Encoding beside rendering: the writer takes frame k on its own thread while the next frame is drawn
// (llvmpipe and the encoder each keep a core busy). At most two frames wait, so memory stays small.
class EncodingThread {
 public:
  explicit EncodingThread(video::VideoWriter& writer) : writer_(writer), thread_([this] { loop(); }) {}
  ~EncodingThread() { stop(); }
  EncodingThread(const EncodingThread&) = delete;
  EncodingThread& operator=(const EncodingThread&) = delete;

  // Throws the writer's error (a full disk) as soon as it is known.
  void push(gl::RgbaImage image) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return queue_.size() < 2 || error_; });
    if (error_) std::rethrow_exception(error_);
    queue_.push_back(std::move(image));
    changed_.notify_all();
  }
  // Waits for every frame to be written; throws the writer's error.
  void finish() {
    stop();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
  }
  void loop() {
    for (;;) {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || done_; });
      if (queue_.empty()) return;
      gl::RgbaImage image = std::move(queue_.front());
      lock.unlock();
      try {
        writer_.add_frame(image.pixels.data());
      } catch (...) {
        lock.lock();
        error_ = std::current_exception();
        queue_.clear();
        changed_.notify_all();
        return;
      }
      lock.lock();
      queue_.pop_front();
      changed_.notify_all();
    }
  }
  video::VideoWriter& writer_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<gl::RgbaImage> queue_;
  bool done_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts once the rest is ready
};

// The pixels of the window a --only view takes: its rectangle in the first frame's layout (the layout holds
// still along a path: the window's size does not change), each side rounded down to even (H.264 and VP9).
struct Crop {
  int x = 0, y = 0, width = 0, height = 0;
};

Crop crop_of(const RecordOptions& options, const ui::FrameLayout& layout) {
  if (options.only == ShownPart::window) return {0, 0, options.app.width, options.app.height};
  if (options.only == ShownPart::observer && layout.observer.w <= 0)  // a 2D window has none
    throw std::invalid_argument(flags::bad_value_message("--only", "image or overhead for a 2D camera (the observer is 3D's)", "observer"));
  const ui::Rect& r = options.only == ShownPart::image      ? layout.image
                      : options.only == ShownPart::overhead ? layout.overhead
                                                            : layout.observer;
  Crop crop{int(std::ceil(r.x)), int(std::ceil(r.y)), int(std::floor(r.x + r.w)), int(std::floor(r.y + r.h))};
  crop.x = std::clamp(crop.x, 0, options.app.width);
  crop.y = std::clamp(crop.y, 0, options.app.height);
  crop.width = std::clamp(crop.width, crop.x, options.app.width) - crop.x;
  crop.height = std::clamp(crop.height, crop.y, options.app.height) - crop.y;
  crop.width -= crop.width % 2;
  crop.height -= crop.height % 2;
  if (crop.width < 16 || crop.height < 16)
    throw std::invalid_argument(flags::bad_value_message(
        "--only", "a view the window shows at 16 × 16 pixels or more (a larger --width/--height, or a smaller --font-scale)",
        std::to_string(crop.width) + "x" + std::to_string(crop.height) + " pixels"));
  return crop;
}

gl::RgbaImage cropped(gl::RgbaImage image, const Crop& crop) {
  if (crop.x == 0 && crop.y == 0 && crop.width == image.width && crop.height == image.height) return image;
  gl::RgbaImage part;
  part.width = crop.width;
  part.height = crop.height;
  part.pixels.resize(std::size_t(crop.width) * crop.height * 4);
  for (int y = 0; y < crop.height; ++y)
    std::copy_n(image.at(crop.x, crop.y + y), std::size_t(crop.width) * 4, part.pixels.begin() + std::ptrdiff_t(4) * y * crop.width);
  return part;
}

void check_output(const RecordOptions& options, video::VideoFormat format) {
  // The window's sides go to the video as they are; a --only view's are rounded down to even (crop_of).
  for (const auto& [flag, side] : {std::pair{"--width", options.app.width}, std::pair{"--height", options.app.height}})
    if (const std::string rule = video::side_rule(format, side); options.only == ShownPart::window && !rule.empty())
      throw std::invalid_argument(flags::bad_value_message(flag, rule + " for " + video::format_name(format),
                                                           std::to_string(side)));
  namespace fs = std::filesystem;
  std::error_code error;
  if (format == video::VideoFormat::png_folder && fs::exists(options.out_path, error) &&
      !fs::is_empty(options.out_path, error))
    throw std::invalid_argument(flags::bad_value_message("--out", "a new or empty folder for the PNG frames", options.out_path));
}

int run_record(const RecordOptions& options) {
  const std::optional<video::VideoFormat> format = video::format_of(options.out_path);
  if (!format) throw std::invalid_argument(flags::bad_value_message("--out", video::accepted_outputs(), options.out_path));
  check_output(options, *format);
  if (options.path.key_file && options.seconds_given)
    throw std::invalid_argument(flags::bad_value_message("--seconds", "none with --path (the key cameras give the durations)",
                                                         flags::short_number(options.seconds)));
  session::AppState state = session::make_app_state(options.app);
  const session::CameraPath path = flags::make_camera_path(options.path, state, options.seconds);
  const int frames = frame_count(path.seconds(), options.fps);
  if (frames > 100000)
    throw std::invalid_argument(flags::bad_value_message("--seconds", "at most 100000 frames in all", std::to_string(frames) + " frames"));
  if (!options.app.overhead_view) hold_overhead_view(state, path, frames, options.fps);
  session::apply_pose(state, path.at(0.0));

  headless::HeadlessRenderer renderer(options.app.width, options.app.height);
  renderer.panels() = ui::panel_state_for(options.app, state);
  // The first frame settles ImGui's layout as `shot` does (and gives a --only view's rectangle).
  renderer.render_settled(state, 2);
  const Crop crop = crop_of(options, renderer.layout());
  // Opened before the frames are rendered, so that an unwritable place fails at once.
  video::VideoWriter writer(options.out_path, *format, {crop.width, crop.height, options.fps});
  const auto start = std::chrono::steady_clock::now();
  double render_s = 0.0;
  EncodingThread encoding(writer);
  for (int k = 0; k < frames; ++k) {
    session::apply_pose(state, path.at(double(k) / options.fps));
    const auto render_start = std::chrono::steady_clock::now();
    renderer.run_frame(state);  // one frame each, as the window draws
    gl::RgbaImage image = cropped(renderer.read_back(), crop);
    render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
    encoding.push(std::move(image));
  }
  encoding.finish();
  writer.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s (%s, %d frames of %dx%d at %d fps, %.2f s of video) in %.1f s: %.1f frames/s\n",
              options.out_path.c_str(), video::format_name(*format), frames, crop.width, crop.height,
              options.fps, double(frames) / options.fps, seconds, frames / seconds);
  std::printf("per frame: %.1f ms rendering (the encoder works meanwhile, on its own thread)\n", 1e3 * render_s / frames);
  std::printf("overhead view held at --overhead-view %s,%s,%s,%s\n", flags::short_number(state.overhead_low.x).c_str(),
              flags::short_number(state.overhead_low.y).c_str(), flags::short_number(state.overhead_high.x).c_str(),
              flags::short_number(state.overhead_high.y).c_str());
  return 0;
}

constexpr const char* kRecordSummary =
    "record the app's window headless along a camera path to MP4, WebM, GIF, MKV or PNG files";
constexpr const char* kRecordDescription =
    "Renders the app's whole window as `shot` does (OSMesa, no display), once per frame, while the camera\n"
    "follows a path: sweeps of the Camera panel's sliders (--sweep theta=0:360 --sweep phi=60:30), key cameras\n"
    "(--path keys.json) or the construction of M_d (--construction). The format is the output's: FILE.mp4\n"
    "(H.264), FILE.webm (VP9), FILE.gif, FILE.mkv (lossless FFV1), a FOLDER/ of PNGs or a PATTERN%03d.png.\n"
    "Frame k is the camera of time k/fps, the last frame the path's end. The video is written under a\n"
    "temporary name and renamed when complete. Examples: docs/record.md.\n";
}  // namespace

void add_record_command(CLI::App& cli, int& exit_code) {
  CLI::App* record = add_described_subcommand(cli, "record", kRecordSummary, kRecordDescription);
  auto options = std::make_shared<RecordOptions>();
  flags::add_app_options(*record, options->app);
  flags::add_path_options(*record, options->path);
  CLI::Option_group* video = record->add_option_group("Video", "The output, its length and its rate");
  flags::add_checked_option<std::string>(*video, "--out", "FILE",
                                         std::string("the video: ") + video::accepted_outputs() +
                                             " (its name picks the format)",
                                         flags::file_name(), [options](std::string p) { options->out_path = p; })
      ->required();
  flags::add_checked_option<double>(*video, "--seconds", "S",
                                    "how long the sweeps or the construction take (default 4; a --path file gives "
                                    "its own)",
                                    flags::number_in({0.0, 600.0, true, false}), [options](double s) {
                                      options->seconds = s;
                                      options->seconds_given = true;
                                    });
  flags::add_checked_option<int>(*video, "--fps", "N", "frames per second (default 30)", flags::integer_in(1, 120),
                                 [options](int n) { options->fps = n; });
  flags::add_checked_option<int>(*video, "--only", "VIEW",
                                 "one view instead of the whole window, at its size in the window (each side "
                                 "rounded down to even): image (the colour bar or picture), overhead, observer (3D)",
                                 flags::one_of({"image", "overhead", "observer"}),
                                 [options](int part) { options->only = ShownPart(part + 1); });
  record->callback([options, &exit_code] { exit_code = run_record(*options); });
}

}  // namespace raycam::cli
