// "Check my camera" (src/session/camera_check.h) without a window: the verdict on the current camera comes
// from a thread of its own after the quiet time, a mistaken program is diagnosed, and a hanging one never
// blocks.
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <thread>

#include "../scratch_dir.h"
#include "session/app_options.h"
#include "check/answer.h"
#include "session/camera_check.h"
#include "check/case_image.h"

using namespace raycam;
using namespace raycam::session;

namespace {
AppState classic_2d() {
  AppOptions options;
  options.view.scene_path = std::string(SCENES_DIR) + "/classic2d.json";
  return make_app_state(options);
}

// Drives update() as frames would, `seconds` apart, until the check is idle (or 60 s pass).
void settle(CameraCheck& check, const AppState& state, double& now) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  do {
    now += 0.1;
    check.update(state, state, now);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (!check.up_to_date() && std::chrono::steady_clock::now() < deadline);
}
}  // namespace

TEST_CASE("Check my camera grades the current camera in the background and names the mistake",
          "[ui][check]") {
  AppState state = classic_2d();
  double now = 0;
  CameraCheck check;
  check.update(state, state, now);  // no command: nothing runs
  CHECK_FALSE(check.busy());

  check.set_command(EXAMPLE_STUDENT_CPP, false);
  check.update(state, state, now);
  CHECK_FALSE(check.busy());  // waits for the quiet time first
  settle(check, state, now);
  CHECK(check.status() == "pass");

  check.set_command(std::string(MISTAKEN_STUDENT) + " --mistake mirrored", false);
  settle(check, state, now);
  CHECK(check.status() == "fail");
  CHECK(check.wrong_pixels() > 0);
  CHECK(check.top_diagnosis() == "mirrored");

  // A new camera is checked again: the right program passes there too.
  check.set_command(EXAMPLE_STUDENT_CPP, false);
  view2d(state).orbit.theta += 0.5;
  place_cameras(state);
  settle(check, state, now);
  CHECK(check.status() == "pass");
}

TEST_CASE("a hanging program never blocks a frame", "[ui][check]") {
  AppState state = classic_2d();
  CameraCheck check;
  check.set_command(std::string("python3 ") + MISBEHAVING_PY + " hang", false);
  const auto start = std::chrono::steady_clock::now();
  for (double now = 0; now < 1.0; now += 0.05) check.update(state, state, now);  // 20 frames past the quiet time
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (double now = 1.0; now < 2.0; now += 0.05) check.update(state, state, now);
  const double frames_took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(check.busy());       // still running (its timeout is 10 s)
  CHECK(frames_took < 2.0);  // 40 frames, none waited for it
  CHECK(check.status().empty());
  CHECK_FALSE(check.up_to_date());
}  // the destructor does not wait either: the worker finishes on its own

// QA: with a hanging program running, a new program (or camera) waited behind it for the whole timeout (a
// verdict 21 s after the change). The run that nobody wants any more is stopped: the new verdict comes in
// seconds, and the stale one is never shown.
TEST_CASE("a newer check stops a run still going instead of waiting for its timeout", "[ui][check]") {
  AppState state = classic_2d();
  CameraCheck check;
  check.set_command(std::string("python3 ") + MISBEHAVING_PY + " hang", false);
  double now = 0;
  while (!check.busy() && now < 5.0) {  // past the quiet time: the hanging run starts
    now += 0.1;
    check.update(state, state, now);
  }
  REQUIRE(check.busy());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // it is running now
  const auto changed = std::chrono::steady_clock::now();
  check.set_command(EXAMPLE_STUDENT_CPP, false);
  settle(check, state, now);
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - changed).count();
  CHECK(check.status() == "pass");  // the new program's verdict, not the stale run's timeout
  CHECK(waited < 6.0);              // the hang's timeout is 10 s (kCheckTimeout)
}

TEST_CASE("a host without a thread to spare (the page) has the verdict in the frame that asks for it",
          "[ui][check][host]") {
  const test::ScratchDir scratch("page-check");
  const std::string answer = scratch.path("answer.json");
  {
    std::ofstream file(answer);
    file << "{\"ids\": []}";  // the wrong size: a verdict at once, whatever it says
  }
  for (const bool in_background : {false, true}) {
    AppState state = classic_2d();
    state.host = in_background ? kDesktopHost : kPageHost;
    CameraCheck check;
    check.set_command(answer, true);
    check.request().check_now = true;  // the page grades an answer when given, never by itself
    check.update(state, state, 0.0);
    check.update(state, state, 10.0);
    if (in_background) {
      double now = 10.0;
      settle(check, state, now);  // a worker's verdict arrives later
    } else {
      CHECK_FALSE(check.busy());  // graded in update() itself: no worker, nothing queued
      CHECK(check.up_to_date());
    }
    CHECK_FALSE(check.status().empty());
  }
}

TEST_CASE("the check's verdict names itself in the image's header, a re-run clears it", "[ui][check]") {
  session::CheckProgress progress;
  CHECK(session::check_header(Language::en, progress).forms.empty());  // no verdict yet
  auto verdict = std::make_shared<session::KeyedVerdict>();
  verdict->verdict.result.status = check::CaseStatus::fail;
  verdict->verdict.result.wrong_pixels = 27932;
  progress.latest = verdict;
  progress.current = true;
  // Longest first, each shorter than the one before, every one naming the count.
  const std::vector<std::string> failing = session::check_header(Language::en, progress).forms;
  REQUIRE(failing.size() == 3);
  CHECK(failing[0] == "CHECK: 27932 pixels wrong");
  for (std::size_t i = 0; i < failing.size(); ++i) {
    CHECK(failing[i].find("27932") != std::string::npos);
    if (i > 0) CHECK(failing[i].size() < failing[i - 1].size());
  }
  CHECK_FALSE(session::check_header(Language::en, progress).passed);
  progress.running = true;  // checking again: the old verdict is not this image's any more
  CHECK(session::check_header(Language::en, progress).forms.empty());
  progress.running = false;
  progress.current = false;  // made for the camera before the last change
  CHECK(session::check_header(Language::en, progress).forms.empty());
  progress.current = true;
  verdict->verdict.result.status = check::CaseStatus::crash;
  CHECK(session::check_header(Language::en, progress).forms.front() == "CHECK: crash");
  verdict->verdict.result.status = check::CaseStatus::pass;  // a pass is said too: where the eye is
  CHECK(session::check_header(Language::en, progress).passed);
  CHECK(session::check_header(Language::en, progress).forms.front() == "CHECK: passed");
}

namespace {
// The right answer file for a case, from the checker's own reference rendering (what a correct program prints).
void write_right_answer(const SceneFile& made_for, const std::string& path) {
  const check::CaseImage reference = check::render_case(made_for);
  check::Answer answer;
  answer.rows = reference.rows;
  answer.columns = reference.columns;
  answer.ids = reference.ids;
  std::ofstream(path) << check::answer_to_json(answer, reference.dimension);
}
}  // namespace

TEST_CASE("the page grades an answer for the case downloaded, greyed as an earlier camera's once it moved",
          "[ui][check][host]") {
  const test::ScratchDir scratch("page-verdict-states");
  const std::string answer = scratch.path("answer.json");
  AppState state = classic_2d();
  state.host = kPageHost;
  CameraCheck check;
  CHECK(check.verdict_state() == VerdictState::no_answer);
  write_right_answer(check.case_for_download(state), answer);
  const double theta = view2d(state).orbit.theta;
  view2d(state).orbit.theta += 0.3;  // the student moved before giving the answer
  place_cameras(state);
  check.give_answer(answer);
  check.update(state, state, 1.0);
  // Graded for the case it answers (a pass), shown as an earlier camera's: no header over this image.
  CHECK(check.status() == "pass");
  CHECK(check.verdict_state() == VerdictState::for_earlier_camera);
  CHECK(check_header(Language::en, check.progress()).forms.empty());
  view2d(state).orbit.theta = theta;  // back to the case's camera: the verdict is this image's again
  place_cameras(state);
  check.update(state, state, 2.0);
  CHECK(check.verdict_state() == VerdictState::for_camera_shown);
  check.clear();  // the clear button
  CHECK(check.verdict_state() == VerdictState::no_answer);
  CHECK(check.status().empty());
  CHECK(check.request().command.empty());
}

TEST_CASE("the page never re-grades an answer against a camera it was not made for", "[ui][check][host]") {
  const test::ScratchDir scratch("page-no-regrade");
  const std::string answer = scratch.path("answer.json");
  for (const bool page : {true, false}) {
    AppState state = classic_2d();
    state.host = page ? kPageHost : kDesktopHost;
    CameraCheck check;
    write_right_answer(camera_case(state), answer);
    check.give_answer(answer);
    double now = 0.0;
    settle(check, state, now);
    CHECK(check.status() == "pass");
    CHECK(check.verdict_state() == VerdictState::for_camera_shown);
    view2d(state).orbit.theta += 0.3;  // one arrow key
    place_cameras(state);
    for (int frame = 0; frame < 20; ++frame) check.update(state, state, now += 0.1);  // well past the quiet time
    if (page) {  // the page keeps the verdict, greyed: a red fail would blame the program for the move
      CHECK(check.status() == "pass");
      CHECK(check.verdict_state() == VerdictState::for_earlier_camera);
    } else {  // the desktop checks the file again for the new camera, as it always did
      settle(check, state, now);
      CHECK(check.status() == "fail");
      CHECK(check.verdict_state() == VerdictState::for_camera_shown);
    }
  }
}

// Issue 45: back at the case's camera by any route, the verdict is this image's again (QA: after Tab there
// and back it stayed "earlier camera", the arrow keys brought it back).
TEST_CASE("the page's verdict comes back with the case's camera by Tab, keys, typed values or Reset",
          "[ui][check][host]") {
  const test::ScratchDir scratch("page-verdict-routes");
  const std::string answer = scratch.path("answer.json");
  AppState state = classic_2d();
  state.host = kPageHost;
  CameraCheck check;
  write_right_answer(check.case_for_download(state), answer);
  check.give_answer(answer);
  double now = 1.0;
  check.update(state, state, now);
  REQUIRE(check.status() == "pass");
  REQUIRE(check.verdict_state() == VerdictState::for_camera_shown);
  const double theta = view2d(state).orbit.theta;
  const auto away_and_back = [&](const char* route, auto&& away, auto&& back) {
    INFO(route);
    away(), place_cameras(state), check.update(state, state, now += 0.1);
    CHECK(check.verdict_state() == VerdictState::for_earlier_camera);
    back(), place_cameras(state), check.update(state, state, now += 0.1);
    CHECK(check.verdict_state() == VerdictState::for_camera_shown);
    CHECK(check.status() == "pass");
  };
  away_and_back("Tab there and back", [&] { switch_dimension(state, 3); }, [&] { switch_dimension(state, 2); });
  away_and_back("an arrow key and back", [&] { view2d(state).orbit.theta += 0.05; }, [&] { view2d(state).orbit.theta = theta; });
  const double typed_degrees = glm::degrees(theta);
  away_and_back("θ typed", [&] { view2d(state).orbit.theta = glm::radians(typed_degrees + 10.0); },
                [&] { view2d(state).orbit.theta = glm::radians(typed_degrees); });
  away_and_back("Reset camera", [&] { view2d(state).orbit.theta += 0.3; }, [&] { reset_camera(state, state); });
}
