// A video file read back with FFmpeg's libavformat and libavcodec, for the tests: its frames as RGBA (rows
// top-down) and what the container says of its rate.
#pragma once

#include <cstdint>
#include <string>

#include "gl/framebuffer_image.h"
#include <vector>

namespace raycam::test {

struct DecodedVideo {
  std::string codec;             // libavcodec's name: "h264", "vp9", "gif"
  double frame_rate = 0.0;       // the stream's average rate
  std::vector<double> times;     // each frame's presentation time, seconds
  std::vector<gl::RgbaImage> frames;
  // YUV videos: each frame's luma plane as decoded (width × height, no padding), before any conversion.
  std::vector<std::vector<std::uint8_t>> luma;
};

// Throws std::runtime_error when the file cannot be opened or decoded.
DecodedVideo decode_video(const std::string& path);

// `image` as a perfect 4:2:0 codec would give it back: to BT.709 limited-range yuv420p and back to RGBA
// with swscale (one colour sample per 2×2 pixels). What is left between this and a decoded frame is the
// codec's own loss; what is between this and `image` is the format's (browsers play only 4:2:0).
gl::RgbaImage through_yuv420(const gl::RgbaImage& image);

}  // namespace raycam::test
