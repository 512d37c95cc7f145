// The ranges the app's sliders, keys, mouse wheel and drags keep the camera in. A slider needs finite ends,
// and past them the lecture's view is no longer useful; the command line and scene files accept the core's
// wider ranges (raycam/limits.h), and the app keeps such a camera until the student moves it.
#pragma once

#include <algorithm>
#include <glm/gtc/constants.hpp>

namespace raycam::session {

struct CameraRange {
  double low, high;
  double clamp(double value) const { return std::clamp(value, low, high); }
};

inline constexpr CameraRange kDistanceRange{0.1, 200.0};           // d, the distance to the target C
inline constexpr CameraRange kFocalRange{0.05, 20.0};              // d_f, the focal distance
inline constexpr CameraRange kPolarRange{0.0, glm::pi<double>()};  // φ in radians (3D)
inline constexpr int kMaxPixels2DInApp = 4096;                     // N, the 2D camera's max pixels
inline constexpr int kMaxSideInApp = 2048;                         // W and H, the 3D camera's max size

}  // namespace raycam::session
