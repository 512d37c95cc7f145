// "Check my camera": the student's own program (or an answer file) run on the CURRENT camera and scene,
// through the same protocol and grading as `raycam-cli check` (check::grade_case). It runs on a thread of
// its own, debounced (kQuietSeconds after the last change), so the frame never waits for it: a slow or broken
// program only shows "running" or its error. The panel that shows it is ui/check_panel.h.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "session/app_state.h"
#include "check/case_verdict.h"

namespace raycam::session {

inline constexpr double kQuietSeconds = 0.3;   // after the last camera or scene change
inline constexpr double kCheckTimeout = 10.0;  // per run, as `raycam-cli check`'s default
// Above this many ray-object tests the single case is still graded but not diagnosed (91 renders of it).
inline constexpr double kDiagnosisBudget = 2e7;

// What the panel edits: the command and when to run it.
struct CheckRequest {
  std::string command;  // a program, or an answer file's path when `is_file`
  bool is_file = false;
  bool automatic = true;   // check when the camera changes
  bool check_now = false;  // once, at the next update()
  // The page (no program runs there): the host writes the camera's case as a download, or asks the browser
  // for the answer file; each is reset by the host once done.
  bool download_case = false, pick_answer = false;
};

// A verdict and the case (and command) it was made for.
struct KeyedVerdict {
  std::string key;
  check::CaseVerdict verdict;
};

// What the latest verdict grades, as the panel says it: none yet; the camera and scene shown; or an earlier
// camera or scene (the student moved since, or gave an answer made for a case downloaded before a move):
// then the verdict is greyed, never a red fail for a camera the answer was not made for.
enum class VerdictState { no_answer, for_camera_shown, for_earlier_camera };
const char* verdict_state_name(VerdictState state);  // "no-answer", "camera-shown", "earlier-camera"

// What the panel shows, taken at once.
struct CheckProgress {
  bool running = false;  // queued or running
  double started_at = 0;
  std::shared_ptr<const KeyedVerdict> latest;  // null while none
  bool current = false;                        // `latest` is for the case seen at the last update()
};

// The case of the camera on screen, as the student's program reads it: the scene and the camera's parameters
// (the page offers it as a download: it runs no program, and grades the answer file given back).
SceneFile camera_case(const Lesson& state);

// What the image's header says about the check, as it names a mistake that is on, longest first (the header
// takes the longest that fits, and the last always fits: a verdict is never cut): "CHECK: 27932 pixels
// wrong", "✗ 27932 pixels wrong", "✗ 27932 wrong" (or the failing status), or "CHECK: passed", "✓ passed";
// empty while none, or while a run is going (the old verdict is no longer the image's).
// With a classic mistake on (`mistakes`, its names), the verdict is still the case's camera's (the camera the
// student set: the case never carries the mistake) while the image shows the mistake: the header says both
// plainly, "CHECK: passed for the downloaded case — the image shown shows the mistake « mirrored »" (the
// page's case; on the desktop "for your camera"), and names the mistake itself (`names_mistake`): no pass
// inside a red "MISTAKE ON" header.
struct CheckHeader {
  std::vector<std::string> forms;
  bool passed = false;
  bool names_mistake = false;
};
CheckHeader check_header(Language language, const CheckProgress& progress, const std::string& mistakes = "",
                         bool downloaded_case = false);

// The first `count` wrong pixels of a failing verdict in protocol order, as (row, column) of the answer's ids
// (a 2D answer's one row: (0, k)); the panel names them and the image marks them.
struct WrongPixel {
  int row = 0, column = 0;
};
std::vector<WrongPixel> first_wrong_pixels(const check::CaseVerdict& verdict, int count);
inline constexpr int kNamedWrongPixels = 5;
// "(12, 40), (12, 41)" and "…" after the last when there are more wrong pixels than named.
std::string wrong_pixels_named(const check::CaseVerdict& verdict);

struct CheckShared;  // the job and the latest verdict, shared with the worker thread

class CameraCheck {
 public:
  CameraCheck();
  ~CameraCheck();  // never waits for a running program: the worker finishes on its own (its timeout)

  // Every frame, after the cast: notices a changed case or command and, after kQuietSeconds of quiet, hands
  // it to the worker. `now` is seconds on any steady clock.
  void update(const Lesson& state, const HostLink& link, double now);

  CheckRequest& request() { return request_; }
  CheckProgress progress() const;

  // For tests and the host: the command (a program, or an answer file's path when `is_file`).
  void set_command(const std::string& command, bool is_file);
  // The page's route: the case of the camera on screen, remembered as the one the student's program will
  // answer; an answer file given later is graded against it (not the camera on screen, which may have moved).
  SceneFile case_for_download(const Lesson& state);
  // An answer file to grade at the next update().
  void give_answer(const std::string& path);
  // The clear button: no verdict, no answer file (a program's command stays).
  void clear();
  VerdictState verdict_state() const;
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
  std::string camera_key(const Lesson& state) const;  // the camera and scene
  std::string command_key() const;                       // the program or the answer file
  std::shared_ptr<const KeyedVerdict> latest() const;

  std::shared_ptr<CheckShared> shared_;
  CheckRequest request_;
  std::string last_key_;       // the case (and command) last seen
  std::string submitted_key_;  // the case last handed to the worker
  double changed_at_ = 0;
  struct DownloadedCase {
    std::string camera_key;
    SceneFile file;
  };
  std::optional<DownloadedCase> downloaded_;  // the page: the case offered last
};

}  // namespace raycam::session
