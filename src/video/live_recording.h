// A recording of what a window shows while someone uses it (the window's Record control, F9): frames arrive
// when the window draws, at no fixed rate, and the video runs at a fixed rate on the wall clock. Video frame
// k is the first picture the window drew at or after time k/fps (the window draws one when a frame's time
// comes and it had nothing else to draw), so a pause in the window is a still in the video, as long as it
// lasted. Encoding runs on a thread of its own: the window keeps drawing while the encoder works.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "video/video_writer.h"

namespace raycam::video {

// How many video frames the picture drawn at `elapsed_seconds` fills, `written` being already there: every
// frame k ≥ written whose time k/fps has come (k ≤ elapsed · fps). 0: it came before the next frame's time.
int frames_due(double elapsed_seconds, int fps, int written);

// The seconds from `elapsed_seconds` to the next video frame's time (k/fps for the smallest k past it).
double seconds_to_next_frame(double elapsed_seconds, int fps);

// `rgba` (width × height) fitted into a target_width × target_height frame, its aspect ratio kept: scaled by
// the largest factor that fits (nearest pixel: the window's text stays sharp at factor 1, the usual case),
// centred, the rest black. A window resized or made full screen during a recording keeps the video's size.
std::vector<std::uint8_t> fit_frame(const std::uint8_t* rgba, int width, int height, int target_width,
                                    int target_height);

class LiveRecording {
 public:
  // The video's size: the window's, each side rounded down to even (H.264 and VP9 in yuv420p).
  static int even(int side) { return side - side % 2; }

  // Opens the temporary output (throws as VideoWriter does) and starts the encoding thread.
  LiveRecording(const std::string& path, VideoFormat format, int width, int height, int fps);
  ~LiveRecording();  // without finish(): the encoder stops, the temporary output is removed
  LiveRecording(const LiveRecording&) = delete;
  LiveRecording& operator=(const LiveRecording&) = delete;

  // The frame the window just drew (width × height RGBA, top row first), `elapsed_seconds` after the
  // recording started. Waits only when the encoder is more than a few frames behind.
  void add(const std::uint8_t* rgba, int width, int height, double elapsed_seconds);
  // Whether a frame is due at `elapsed_seconds` that the window has not drawn (it must draw one).
  bool frame_due(double elapsed_seconds) const { return frames_due(elapsed_seconds, fps_, queued_frames_) > 0; }
  double seconds_to_next_frame(double elapsed_seconds) const { return video::seconds_to_next_frame(elapsed_seconds, fps_); }
  // The encoder's error (a full disk): the recording cannot go on; finish() throws it.
  std::string error() const;
  // Encodes what is queued, closes the file and renames it to its name. Returns the number of frames.
  int finish();

  const std::string& path() const { return path_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int fps() const { return fps_; }

 private:
  struct Job {
    std::vector<std::uint8_t> rgba;
    int copies;
  };
  void encode_jobs();

  std::string path_;
  int width_, height_, fps_;
  int queued_frames_ = 0;  // video frames handed to the encoder so far (the window's thread only)
  VideoWriter writer_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  bool closing_ = false;
  std::string error_;
  std::thread encoder_;
};

}  // namespace raycam::video
