// Frames (RGBA, row 0 at the top) to a video file through Debian's FFmpeg libraries — MP4 (H.264 by
// libx264), WebM (VP9 by libvpx), animated GIF, lossless Matroska (FFV1 in RGB) — or to a PNG sequence. Nothing is left under the asked name
// until finish() succeeds: the video is written to a temporary name in the same folder and renamed at the
// end; a writer destroyed before finish() (an error, a full disk) removes what it wrote.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace raycam::video {

enum class VideoFormat { mp4, webm, gif, mkv, png_folder, png_pattern };

// The format an output name asks for: NAME.mp4, NAME.webm, NAME.gif, NAME.mkv, a folder (an existing one, or a name
// ending in '/'), or a printf pattern of PNG files (frames/f%03d.png). nullopt: none of these.
std::optional<VideoFormat> format_of(const std::string& path);
// "FILE.mp4, FILE.webm, FILE.gif, FILE.mkv, a FOLDER/ or a PATTERN%03d.png": what format_of accepts.
const char* accepted_outputs();
const char* format_name(VideoFormat format);  // "H.264 MP4", …

// When a size cannot be encoded in `format`: what is expected of a side ("an even number of pixels
// (H.264 in yuv420p halves each side for colour)"), else empty.
std::string side_rule(VideoFormat format, int side);

struct VideoSettings {
  int width = 0, height = 0;
  int fps = 30;
};

class VideoWriter {
 public:
  // Opens the temporary output (so that an unwritable folder fails before any frame is rendered).
  // Throws std::invalid_argument for a size the format refuses, std::runtime_error naming the path when it
  // cannot be written or the encoder cannot be opened.
  VideoWriter(const std::string& path, VideoFormat format, const VideoSettings& settings);
  ~VideoWriter();  // without finish(): removes the temporary output
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame, width × height RGBA, rows top-down. Throws std::runtime_error (e.g. no space left).
  void add_frame(const std::uint8_t* rgba);
  // Flushes the encoder, closes the file and renames it to the asked name. Throws std::runtime_error.
  void finish();
  int frames_written() const;
  const std::string& temporary_path() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace raycam::video
