#include "video/live_recording.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raycam::video {

namespace {
// Frames waiting for the encoder before the window waits for it: enough for a burst of drawing (a drag),
// few enough that memory stays small (at 1280×720, 3.7 MB a frame).
constexpr std::size_t kMaxQueuedImages = 8;
}  // namespace

int frames_due(double elapsed_seconds, int fps, int written) {
  if (!(elapsed_seconds >= 0.0)) elapsed_seconds = 0.0;  // a clock that went back, or NaN: the first frame
  // The small margin: 2/30 s computed as 0.0666…6 still reaches frame 2.
  const long long last = static_cast<long long>(std::floor(elapsed_seconds * fps + 1e-9));
  return int(std::max<long long>(0, last + 1 - written));
}

double seconds_to_next_frame(double elapsed_seconds, int fps) {
  if (!(elapsed_seconds >= 0.0)) return 0.0;
  const double next = std::floor(elapsed_seconds * fps + 1e-9) + 1.0;
  return std::max(0.0, next / fps - elapsed_seconds);
}

std::vector<std::uint8_t> fit_frame(const std::uint8_t* rgba, int width, int height, int target_width,
                                    int target_height) {
  std::vector<std::uint8_t> out(std::size_t(target_width) * target_height * 4, 0);
  for (std::size_t i = 3; i < out.size(); i += 4) out[i] = 255;  // opaque black around the picture
  if (width <= 0 || height <= 0) return out;
  const double scale = std::min(double(target_width) / width, double(target_height) / height);
  const int shown_w = std::max(1, int(std::floor(width * scale))), shown_h = std::max(1, int(std::floor(height * scale)));
  const int x0 = (target_width - shown_w) / 2, y0 = (target_height - shown_h) / 2;
  for (int y = 0; y < shown_h; ++y) {
    const int sy = std::min(height - 1, int((y + 0.5) / scale));
    for (int x = 0; x < shown_w; ++x) {
      const int sx = std::min(width - 1, int((x + 0.5) / scale));
      const std::uint8_t* from = rgba + 4 * (std::size_t(sy) * width + sx);
      std::copy(from, from + 4, out.begin() + 4 * (std::ptrdiff_t(y0 + y) * target_width + x0 + x));
    }
  }
  return out;
}

LiveRecording::LiveRecording(const std::string& path, VideoFormat format, int width, int height, int fps)
    : path_(path), width_(width), height_(height), fps_(fps), writer_(path, format, VideoSettings{width, height, fps}) {
  encoder_ = std::thread([this] { encode_jobs(); });
}

LiveRecording::~LiveRecording() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
    jobs_.clear();
  }
  changed_.notify_all();
  if (encoder_.joinable()) encoder_.join();
}  // writer_ unfinished: its temporary file goes

void LiveRecording::add(const std::uint8_t* rgba, int width, int height, double elapsed_seconds) {
  const int copies = frames_due(elapsed_seconds, fps_, queued_frames_);
  if (copies == 0) return;  // drawn between two video frames: the next one takes a later picture
  // The window as it was when the recording started (each side rounded down to even: its last odd row or
  // column is left out, no pixel moves); resized or full screen, fitted in.
  Job job{{}, copies};
  if (even(width) == width_ && even(height) == height_) {
    job.rgba.resize(std::size_t(width_) * height_ * 4);
    for (int y = 0; y < height_; ++y)
      std::copy(rgba + 4 * std::size_t(y) * width, rgba + 4 * (std::size_t(y) * width + width_),
                job.rgba.begin() + 4 * std::ptrdiff_t(y) * width_);
  } else {
    job.rgba = fit_frame(rgba, width, height, width_, height_);
  }
  queued_frames_ += copies;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.size() < kMaxQueuedImages || !error_.empty(); });
  if (!error_.empty()) return;
  jobs_.push_back(std::move(job));
  lock.unlock();
  changed_.notify_all();
}

std::string LiveRecording::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

void LiveRecording::encode_jobs() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return closing_ || !jobs_.empty(); });
      if (jobs_.empty()) return;  // closing, and everything is encoded
      job = std::move(jobs_.front());
    }
    std::string failure;
    try {
      for (int i = 0; i < job.copies; ++i) writer_.add_frame(job.rgba.data());
    } catch (const std::exception& e) {
      failure = e.what();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      jobs_.pop_front();
      if (!failure.empty()) {
        error_ = failure;
        jobs_.clear();
      }
    }
    changed_.notify_all();
    if (!failure.empty()) return;
  }
}

int LiveRecording::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  if (encoder_.joinable()) encoder_.join();
  if (!error_.empty()) throw std::runtime_error(error_);
  writer_.finish();
  return writer_.frames_written();
}

}  // namespace raycam::video
