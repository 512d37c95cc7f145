// "Check my camera": the student's own program (or an answer file) run on the CURRENT camera and scene,
// through the same protocol and grading as `raycam-cli check` (src/check). It runs on a thread of its own,
// debounced (kQuietSeconds after the last change), so the frame never waits for it: a slow or broken
// program only shows "running" or its error. The image window marks the wrong pixels in red.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "app_state.h"

struct ImDrawList;

namespace raycam::ui {

inline constexpr double kQuietSeconds = 0.3;   // after the last camera or scene change
inline constexpr double kCheckTimeout = 10.0;  // per run, as `raycam-cli check`'s default
// Above this many ray-object tests the single case is still graded but not diagnosed (91 renders of it).
inline constexpr double kDiagnosisBudget = 2e7;

struct CheckView;  // the latest verdict, shared with the worker thread

class CameraCheck {
 public:
  CameraCheck();
  ~CameraCheck();  // never waits for a running program: the worker finishes on its own (its timeout)

  // Every frame, after the cast: notices a changed case or command and, after kQuietSeconds of quiet, hands
  // it to the worker. `now` is seconds on any steady clock.
  void update(const AppState& state, double now);
  // The panel section: the command, the verdict, the diagnosis, the program's stderr.
  void section(AppState& state, double now);
  // Translucent red over the wrong pixels of the image drawn in [x0, x1] × [y0, y1] (only while the verdict
  // is for the image on screen).
  void overlay(const AppState& state, ImDrawList* list, float x0, float y0, float x1, float y1) const;

  // For tests and the host: the command (a program, or an answer file's path when `is_file`).
  void set_command(const std::string& command, bool is_file);
  // The latest verdict's status ("pass", "fail", "crash", "timeout", "bad-output"), empty while none; its
  // first diagnosis ("" if none); whether a run is queued or running.
  std::string status() const;
  std::string top_diagnosis() const;
  long long wrong_pixels() const;
  bool busy() const;
  // The latest verdict is for the camera, scene and command seen at the last update().
  bool up_to_date() const;
  // A verdict is on its way (quiet time, queued or running): the window keeps drawing to show it.
  bool waiting() const;

 private:
  std::string case_key(const AppState& state) const;

  std::shared_ptr<CheckView> view_;
  char command_[512] = {};
  bool is_file_ = false;
  bool automatic_ = true;
  std::string last_key_;       // the case (and command) last seen
  std::string submitted_key_;  // the case last handed to the worker
  double changed_at_ = 0;
  bool check_now_ = false;
};

}  // namespace raycam::ui
