// Documented limits, checked before anything is allocated (README, "Limits and guarantees").
#pragma once

#include <cstddef>

namespace raycam {

inline constexpr int kMaxPixels2D = 1 << 20;          // N for a Camera2D
inline constexpr int kMaxSide3D = 16384;              // columns or rows of a Camera3D
inline constexpr long long kMaxPixels3D = 1LL << 26;  // columns × rows (64 Mpixels, ~320 MB of map)
inline constexpr std::size_t kMaxObjects = 2'000'000; // circles or spheres in one scene
inline constexpr std::size_t kMaxSceneFileBytes = 256u << 20;  // 256 MiB
// |coordinate| and radius beyond this lose all precision in double when squared; refused as input.
inline constexpr double kMaxCoordinate = 1e12;

}  // namespace raycam
