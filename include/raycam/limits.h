// Documented limits, checked before anything is allocated (docs/cli.md, "Limits and guarantees").
#pragma once

#include <cstddef>

namespace raycam {

inline constexpr int kMaxPixels2D = 1 << 20;                   // N for a Camera2D
inline constexpr int kMaxSide3D = 16384;                       // columns or rows of a Camera3D
inline constexpr long long kMaxPixels3D = 1LL << 26;           // columns × rows (64 Mpixels, ~320 MB of map)
inline constexpr std::size_t kMaxObjects = 2'000'000;          // circles or spheres in one scene
inline constexpr std::size_t kMaxSceneFileBytes = 256u << 20;  // 256 MiB
// |coordinate| and radius beyond this lose all precision in double when squared; refused as input.
inline constexpr double kMaxCoordinate = 1e12;
// Focal distance d_f: below 1e-9 the ray directions (x, -d_f) lose their y component to underflow when
// squared; above 1e9 the field of view is under 1e-9 rad and nothing is seen.
inline constexpr double kMinFocalDistance = 1e-9;
inline constexpr double kMaxFocalDistance = 1e9;

}  // namespace raycam
