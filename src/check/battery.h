// The check battery: cases designed to reveal every classic mistake, jittered by a seed so that a class
// shares one battery (the default seed) and an instructor can pick a secret one.
//
// Each designed case has a purpose (quadrant of θ, pole, res < 1, objects between the eye and the screen,
// behind the camera, overlapping, off-centre target, small and large d_f) and the list of mistakes it must
// reveal. The jitter is drawn again (from the same seed) until every one of them changes a pixel that is
// not ambiguous, so any seed gives a battery that reveals every mistake. Cases past the designed ones are
// random scenes. The random numbers come from std::mt19937_64 (its output is fixed by the standard) turned
// into doubles here, so a seed gives the same cases on every platform.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raycam/scene_file.h"

namespace raycam::check {

enum class BatteryMode { two_d, three_d, both };

inline constexpr std::uint64_t kDefaultSeed = 2026;

// The version of the protocol the battery follows, stated in every case it writes, its JSON report and its
// batch record (docs/check.md, "Protocol versions"). Version 2: every case of the default battery has one
// number `res`, the one resolution variable the handout requires; --two-res asks the 3D case whose `res` is
// [res_c, res_l] (the second variable the handout allows) in place of its one-number version.
inline constexpr int kProtocolVersion = 2;

struct CheckCase {
  std::string purpose;  // one line, English: what the case is designed to exercise
  SceneFile file;       // the scene with its complete camera block (the protocol's input)
};

// The number of designed cases in a mode (the default --cases).
int designed_case_count(BatteryMode mode);
// `count` cases (designed first, 2D and 3D interleaved in `both`), from `seed`. count in [1, 1000].
// two_res: the designed 3D case with one res per side keeps both (check --two-res); otherwise it has one
// number res, and every other case is the same either way.
std::vector<CheckCase> make_battery(BatteryMode mode, int count, std::uint64_t seed, bool two_res = false);

// The case's res is a pair [res_c, res_l] (asked only by --two-res).
bool asks_two_res(const CheckCase& c);

// "2d", "3d", "both"; throws std::invalid_argument naming `flag`.
BatteryMode parse_battery_mode(const std::string& text, const std::string& flag);

}  // namespace raycam::check
