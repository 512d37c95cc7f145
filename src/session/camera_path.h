// A camera moving over time, for `raycam-cli record`: sweeps of the Camera panel's sliders one after the
// other, key cameras from a JSON file, or the construction of M_d factor by factor. A path gives the pose
// at any time; apply_pose puts it into the session's state, as dragging the sliders would.
#pragma once

#include <string>
#include <vector>

#include "session/app_state.h"

namespace raycam::session {

// The sliders a path can move, with the ranges a sweep may take (angles in degrees). θ goes two turns each
// way (the panel's slider shows −180…180, but an orbit is one or more turns); the others are the panel's.
enum class Slider { df, d, theta, phi, res };
struct SliderInfo {
  Slider slider;
  const char* name;  // as --sweep and a path file name it
  double low, high;
  bool low_open;     // res: ]0, 1]
  bool only_3d;      // φ
};
const std::vector<SliderInfo>& path_sliders();
const SliderInfo& slider_info(Slider slider);

// What a frame shows: every slider's value (degrees for the angles) and the construction step with the
// fraction of its factor applied (step -1: the placed camera).
struct Pose {
  double df = 1.0, d = 1.0, theta = 0.0, phi = 0.0, res = 1.0;
  int step = -1;
  double fraction = 1.0;
};
double& value_of(Pose& pose, Slider slider);
Pose current_pose(const Lesson& state);
// Sets the orbit, res and construction step; the cameras are re-placed at the next frame.
void apply_pose(Lesson& state, const Pose& pose);

enum class Easing { linear, ease_in_out };
// Time in [0, 1] to progress in [0, 1]: linear, or the smoothstep 3t² − 2t³ (starts and stops at rest).
double eased(Easing easing, double t);

struct PathSegment {
  Pose from, to;  // a construction segment keeps its step and moves the fraction 0 → 1
  double seconds = 0.0;
  Easing easing = Easing::linear;
};
struct CameraPath {
  Pose start;
  std::vector<PathSegment> segments;
  double seconds() const;
  Pose at(double time) const;  // before 0: start; after the end: the last pose
};

struct Sweep {
  Slider slider;
  double from, to;
};
// One sweep after the other, each taking an equal share of `seconds`; a slider no sweep moves keeps its
// value from `start`. Throws std::invalid_argument naming --sweep (a φ sweep in 2D).
CameraPath sweep_path(const Pose& start, int dimension, const std::vector<Sweep>& sweeps, double seconds,
                      Easing easing);
// The construction: frame a (step 0), then each factor in turn, ending on the placed camera (its last
// step). Each step's share of `seconds` is its factor moving, then kConstructionHold of it held still.
inline constexpr double kConstructionHold = 0.3;
CameraPath construction_path(const Pose& start, int steps, double seconds, Easing easing);
// A key-camera file: {"keys": [{"theta": 0, "phi": 60}, {"theta": 90, "seconds": 2, "ease": true}, …]}.
// Each key sets any sliders (the others keep the previous key's values; the first key's start from
// `start`); "seconds" (> 0, required after the first key) is the time from the previous key. Throws
// std::invalid_argument naming the file and the field, as scene files do.
CameraPath key_camera_path(const Pose& start, int dimension, const std::string& path, Easing easing);

}  // namespace raycam::session
