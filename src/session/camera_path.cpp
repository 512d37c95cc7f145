#include "session/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "session/camera_ranges.h"

namespace raycam::session {

const std::vector<SliderInfo>& path_sliders() {
  static const std::vector<SliderInfo> sliders{
      {Slider::df, "df", kFocalRange.low, kFocalRange.high, false, false},
      {Slider::d, "d", kDistanceRange.low, kDistanceRange.high, false, false},
      {Slider::theta, "theta", -720.0, 720.0, false, false},
      {Slider::phi, "phi", glm::degrees(kPolarRange.low), glm::degrees(kPolarRange.high), false, true},
      {Slider::res, "res", 0.0, 1.0, true, false},
  };
  return sliders;
}

const SliderInfo& slider_info(Slider slider) {
  for (const SliderInfo& info : path_sliders())
    if (info.slider == slider) return info;
  throw std::logic_error("slider_info: unknown slider");
}

double& value_of(Pose& pose, Slider slider) {
  switch (slider) {
    case Slider::df: return pose.df;
    case Slider::d: return pose.d;
    case Slider::theta: return pose.theta;
    case Slider::phi: return pose.phi;
    case Slider::res: return pose.res;
  }
  throw std::logic_error("value_of: unknown slider");
}

Pose current_pose(const Lesson& state) {
  Pose pose;
  const SharedOrbit<const double> orbit = active_orbit(state);
  pose.df = orbit.df;
  pose.d = orbit.d;
  pose.theta = glm::degrees(orbit.theta);
  pose.phi = glm::degrees(view3d(state).orbit.phi);
  pose.res = state.res;
  pose.step = state.construction_step;
  pose.fraction = state.construction_fraction;
  return pose;
}

void apply_pose(Lesson& state, const Pose& pose) {
  const SharedOrbit<double> orbit = active_orbit(state);
  orbit.df = pose.df;
  orbit.d = pose.d;
  orbit.theta = glm::radians(pose.theta);
  if (dimension(state) == 3) view3d(state).orbit.phi = glm::radians(pose.phi);
  state.res = pose.res;
  state.construction_step = pose.step;
  state.construction_fraction = pose.fraction;
  state.cameras_dirty = true;
}

double eased(Easing easing, double t) {
  t = std::clamp(t, 0.0, 1.0);
  return easing == Easing::linear ? t : t * t * (3.0 - 2.0 * t);
}

namespace {
Pose between(const Pose& a, const Pose& b, double s) {
  const auto mix = [s](double x, double y) { return s >= 1.0 ? y : x + s * (y - x); };  // ends exact
  Pose pose = b;
  pose.df = mix(a.df, b.df);
  pose.d = mix(a.d, b.d);
  pose.theta = mix(a.theta, b.theta);
  pose.phi = mix(a.phi, b.phi);
  pose.res = mix(a.res, b.res);
  if (a.step == b.step) pose.fraction = mix(a.fraction, b.fraction);
  return pose;
}

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", x);
  return text;
}
}  // namespace

double CameraPath::seconds() const {
  double total = 0.0;
  for (const PathSegment& segment : segments) total += segment.seconds;
  return total;
}

Pose CameraPath::at(double time) const {
  Pose pose = start;
  double segment_start = 0.0;
  for (const PathSegment& segment : segments) {
    if (time < segment_start + segment.seconds)
      return between(segment.from, segment.to, eased(segment.easing, (time - segment_start) / segment.seconds));
    segment_start += segment.seconds;
    pose = segment.to;
  }
  return pose;
}

CameraPath sweep_path(const Pose& start, int dimension, const std::vector<Sweep>& sweeps, double seconds,
                      Easing easing) {
  CameraPath path;
  Pose pose = start;
  for (const Sweep& sweep : sweeps) {
    if (slider_info(sweep.slider).only_3d && dimension != 3)
      throw std::invalid_argument("--sweep: expected a slider of the 2D camera (df, d, theta or res), got '" +
                                  std::string(slider_info(sweep.slider).name) + "'");
    PathSegment segment;
    segment.from = pose;
    value_of(segment.from, sweep.slider) = sweep.from;
    segment.to = segment.from;
    value_of(segment.to, sweep.slider) = sweep.to;
    segment.seconds = seconds / double(sweeps.size());
    segment.easing = easing;
    if (path.segments.empty()) path.start = segment.from;
    path.segments.push_back(segment);
    pose = segment.to;
  }
  if (path.segments.empty()) path.start = start;
  return path;
}

CameraPath construction_path(const Pose& start, int steps, double seconds, Easing easing) {
  // Frame a held, then each factor: 70% of its share moving, 30% held on the step (its caption and matrix
  // readable, and the very frame `shot --step K` gives).
  const double share = seconds / (steps + kConstructionHold);
  CameraPath path;
  path.start = start;
  path.start.step = 0;  // frame a: the canonical camera
  path.start.fraction = 1.0;
  path.segments.push_back({path.start, path.start, kConstructionHold * share, Easing::linear});
  for (int step = 1; step <= steps; ++step) {
    PathSegment segment;
    segment.from = segment.to = start;
    segment.from.step = segment.to.step = step;  // the step's caption while its factor applies
    segment.from.fraction = 0.0;
    segment.to.fraction = 1.0;
    segment.seconds = (1.0 - kConstructionHold) * share;
    segment.easing = easing;
    path.segments.push_back(segment);
    path.segments.push_back({segment.to, segment.to, kConstructionHold * share, Easing::linear});
  }
  return path;
}

CameraPath key_camera_path(const Pose& start, int dimension, const std::string& file, Easing easing) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument("--path: cannot open '" + file + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > (1u << 20)) throw std::invalid_argument("--path: " + file + ": larger than 1 MiB");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& error) {
    throw std::invalid_argument("--path: " + file + ": " + error.what());
  }
  const auto fail = [&file](const std::string& where, const std::string& expected, const nlohmann::json& got) {
    throw std::invalid_argument("--path: " + file + ": " + where + ": expected " + expected + ", got " + got.dump());
  };
  if (!json.is_object() || !json.contains("keys") || json.size() != 1)
    fail("(top)", "an object with one field, \"keys\"", json.is_object() ? nlohmann::json("other fields") : json);
  const nlohmann::json& keys = json["keys"];
  if (!keys.is_array() || keys.empty() || keys.size() > 10000)
    fail("keys", "an array of 1 to 10000 key cameras", keys);
  CameraPath path;
  Pose pose = start;
  pose.step = -1;
  pose.fraction = 1.0;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::string at = "keys[" + std::to_string(k) + "]";
    if (!keys[k].is_object()) fail(at, "an object", keys[k]);
    Pose next = pose;
    double seconds = 0.0;
    bool eases = easing == Easing::ease_in_out;
    for (const auto& [name, value] : keys[k].items()) {
      const std::string where = at + "." + name;
      if (name == "seconds") {
        if (!value.is_number() || !(value.get<double>() > 0.0) || value.get<double>() > 3600.0)
          fail(where, "a number in ]0, 3600]", value);
        seconds = value.get<double>();
        continue;
      }
      if (name == "ease") {
        if (!value.is_boolean()) fail(where, "true or false", value);
        eases = value.get<bool>();
        continue;
      }
      const std::string field = name;  // a structured binding cannot be captured in C++17 (clang refuses)
      const auto info = std::find_if(path_sliders().begin(), path_sliders().end(),
                                     [&](const SliderInfo& s) { return field == s.name; });
      if (info == path_sliders().end()) fail(where, "a field among df, d, theta, phi, res, seconds, ease", name);
      if (info->only_3d && dimension != 3) fail(where, "no phi for a 2D camera", value);
      const double x = value.is_number() ? value.get<double>() : NAN;
      if (!(x >= info->low && x <= info->high) || (info->low_open && x == info->low))
        fail(where,
             "a number in " + std::string(info->low_open ? "]" : "[") + number_text(info->low) + ", " +
                 number_text(info->high) + "]",
             value);
      value_of(next, info->slider) = x;
    }
    if (k == 0) {
      if (keys[k].contains("seconds")) fail(at + ".seconds", "none on the first key (where the path starts)", keys[k]["seconds"]);
      path.start = next;
    } else {
      if (!keys[k].contains("seconds")) fail(at, "\"seconds\": the time from the previous key", keys[k]);
      path.segments.push_back({pose, next, seconds, eases ? Easing::ease_in_out : Easing::linear});
    }
    pose = next;
  }
  return path;
}

}  // namespace raycam::session
