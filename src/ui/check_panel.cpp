// Section index: the worker · CameraCheck (debounce) · the panel section · the overlay.
#include "check_panel.h"

#include <imgui.h>
#include <sys/stat.h>

#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "check_run.h"
#include "panels.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"
#include "text.h"
#include "theme.h"

namespace raycam::ui {

// ---- the worker ----------------------------------------------------------------------------------------
struct CheckJob {
  std::string key;
  check::CheckCase checked;
  std::vector<std::string> argv;  // empty: read `answer_path`
  std::string answer_path;
};

struct CheckVerdict {
  std::string key;
  check::CaseResult result;
  std::vector<check::Explanation> diagnosis;
  bool diagnosed = false;
  int rows = 0, columns = 0, dimension = 2;
  std::vector<std::uint8_t> wrong;  // protocol order: 2D pixel k, 3D row-major
  bool sandboxed = false;
};

struct CheckView {
  std::mutex mutex;
  std::condition_variable wake;
  std::optional<CheckJob> pending;
  bool running = false, stop = false, worker_started = false;
  std::optional<CheckVerdict> latest;
  double started_at = 0;
};

namespace {
CheckVerdict verdict_of(const CheckJob& job) {
  const check::CaseImage reference = check::render_case(job.checked.file);
  check::RunResult run;
  std::string why;
  const std::optional<check::Sandbox> sandbox = job.argv.empty() ? std::nullopt : check::probe_sandbox(why);
  if (job.argv.empty()) {
    std::ifstream in(job.answer_path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    run.end = in ? check::RunResult::End::exited : check::RunResult::End::could_not_start;
    run.out = text.str();
    run.error = job.answer_path + ": cannot open the answer file";
  } else {
    check::RunLimits limits;
    limits.timeout_seconds = kCheckTimeout;
    run = check::run_student(job.argv, scene_to_json(job.checked.file), limits, sandbox);
  }
  CheckVerdict verdict;
  verdict.key = job.key;
  verdict.sandboxed = bool(sandbox);
  verdict.result = check::result_of_run(1, job.checked, reference, run);
  verdict.dimension = reference.dimension;
  verdict.rows = reference.rows;
  verdict.columns = reference.columns;
  const check::CaseResult& r = verdict.result;
  verdict.wrong.assign(reference.pixels(), 0);
  if (r.answer && r.answer->rows == reference.rows && r.answer->columns == reference.columns)
    for (std::size_t i = 0; i < reference.pixels(); ++i)
      verdict.wrong[i] = !reference.ambiguous[i] && reference.ids[i] != r.answer->ids[i];
  const double tests = double(reference.pixels()) * std::max(1, check::object_count(job.checked.file));
  if (r.answer && r.status != check::CaseStatus::pass && tests <= kDiagnosisBudget) {
    std::vector<check::CaseResult> results = {verdict.result};
    verdict.diagnosis = check::diagnose({job.checked}, results);
    verdict.diagnosed = true;
  }
  return verdict;
}

void work(std::shared_ptr<CheckView> view) {
  for (;;) {
    CheckJob job;
    {
      std::unique_lock<std::mutex> lock(view->mutex);
      view->wake.wait(lock, [&] { return view->stop || view->pending; });
      if (view->stop) return;
      job = std::move(*view->pending);
      view->pending.reset();
      view->running = true;
    }
    std::optional<CheckVerdict> verdict;
    try {
      verdict = verdict_of(job);
    } catch (const std::exception& error) {  // a camera the core refuses: shown, never thrown at the frame
      verdict = CheckVerdict{};
      verdict->key = job.key;
      verdict->result.status = check::CaseStatus::crash;
      verdict->result.detail = error.what();
    }
    std::lock_guard<std::mutex> lock(view->mutex);
    view->latest = std::move(verdict);
    view->running = false;
  }
}

// The case as the student's program receives it: the scene and the current camera's parameters.
SceneFile current_case(const AppState& state) {
  SceneFile file = state.file;
  file.dimension = state.dimension;
  file.camera = state.dimension == 2 ? preset_of(state.camera2d) : preset_of(state.camera3d);
  return file;
}
}  // namespace

// ---- CameraCheck (debounce) -------------------------------------------------------------------------------
CameraCheck::CameraCheck() : view_(std::make_shared<CheckView>()) {}

CameraCheck::~CameraCheck() {
  std::lock_guard<std::mutex> lock(view_->mutex);
  view_->stop = true;
  view_->wake.notify_all();
}

void CameraCheck::set_command(const std::string& command, bool is_file) {
  std::snprintf(command_, sizeof command_, "%s", command.c_str());
  is_file_ = is_file;
}

std::string CameraCheck::case_key(const AppState& state) const {
  // Cheap to build every frame: what the case depends on (the scene by version, the camera by value).
  const CameraPreset p = state.dimension == 2 ? preset_of(state.camera2d) : preset_of(state.camera3d);
  std::ostringstream key;
  key << std::hexfloat << state.dimension << '|' << state.scene_version << '|' << state.scene_path << '|'
      << p.d.value_or(0) << '|' << p.theta_deg.value_or(0) << '|' << p.phi_deg.value_or(0) << '|'
      << p.df.value_or(0) << '|' << p.res.value_or(0) << '|';
  for (double t : p.target.value_or(std::vector<double>{})) key << t << ',';
  for (int s : p.size.value_or(std::vector<int>{})) key << s << ',';
  key << '|' << is_file_ << '|' << command_;
  if (is_file_) {  // an answer file edited by hand counts as a change
    struct stat info;
    if (stat(command_, &info) == 0) key << '|' << info.st_mtim.tv_sec << '.' << info.st_mtim.tv_nsec;
  }
  return key.str();
}

void CameraCheck::update(const AppState& state, double now) {
  if (command_[0] == '\0') return;
  const std::string key = case_key(state);
  if (key != last_key_) {
    last_key_ = key;
    changed_at_ = now;
  }
  const bool due = check_now_ || (automatic_ && key != submitted_key_ && now - changed_at_ >= kQuietSeconds);
  if (!due) return;
  check_now_ = false;
  CheckJob job;
  job.key = key;
  job.checked = {"the current camera", current_case(state)};
  try {
    if (is_file_)
      job.answer_path = command_;
    else
      job.argv = check::absolutise_paths(check::split_command(command_, "command"));
  } catch (const std::invalid_argument& error) {
    std::lock_guard<std::mutex> lock(view_->mutex);
    view_->latest = CheckVerdict{};
    view_->latest->key = key;
    view_->latest->result.status = check::CaseStatus::crash;
    view_->latest->result.detail = error.what();
    submitted_key_ = key;
    return;
  }
  submitted_key_ = key;
  std::lock_guard<std::mutex> lock(view_->mutex);
  view_->pending = std::move(job);  // a newer case replaces one still waiting
  view_->started_at = now;
  if (!view_->worker_started) {
    view_->worker_started = true;
    std::thread(work, view_).detach();  // it holds the shared view; it ends when stop is set
  }
  view_->wake.notify_all();
}

std::string CameraCheck::status() const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  return view_->latest ? check::status_name(view_->latest->result.status) : "";
}

std::string CameraCheck::top_diagnosis() const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  return view_->latest && !view_->latest->diagnosis.empty() ? view_->latest->diagnosis[0].id() : "";
}

long long CameraCheck::wrong_pixels() const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  return view_->latest ? view_->latest->result.wrong_pixels : 0;
}

bool CameraCheck::up_to_date() const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  return view_->latest && view_->latest->key == last_key_;
}

bool CameraCheck::waiting() const {
  return busy() || (command_[0] != '\0' && automatic_ && last_key_ != submitted_key_) || check_now_;
}

bool CameraCheck::busy() const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  return view_->running || view_->pending.has_value();
}

// ---- the panel section -----------------------------------------------------------------------------------
void CameraCheck::section(AppState& state, double now) {
  if (!ui::section(tr("Check my camera###check"), tr("Check###check"))) return;
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
  ImGui::TextWrapped("%s",
                     tr("Your program reads this camera and scene as JSON on stdin and prints {\"ids\": …}; "
                        "it is checked whenever they change (README, \"Check your own camera\")."));
  ImGui::PopStyleColor();
  ImGui::InputText(tr("program###check_command"), command_, sizeof command_);
  checkbox(tr("an answer file, not a program###check_is_file"), &is_file_);
  checkbox(tr("check when the camera changes###check_auto"), &automatic_);
  ImGui::SameLine();
  if (ImGui::Button(tr("Check now###check_now"))) check_now_ = true;

  std::lock_guard<std::mutex> lock(view_->mutex);
  if (view_->running || view_->pending)
    ImGui::TextUnformatted(trf("running… (%.1f s)", now - view_->started_at).c_str());
  if (!view_->latest) return;
  const CheckVerdict& v = *view_->latest;
  const check::CaseResult& r = v.result;
  const bool current = v.key == last_key_;
  const ImVec4 colour =
      r.status == check::CaseStatus::pass ? current_theme().confirmation : current_theme().error;
  if (r.status == check::CaseStatus::pass)
    ImGui::TextColored(colour, "%s", tr("pass: every pixel agrees"));
  else if (r.status == check::CaseStatus::fail)
    ImGui::TextColored(
        colour, "%s",
        trf("fail: %lld of %lld pixels wrong (in red on the image)", r.wrong_pixels, r.pixels).c_str());
  else
    ImGui::TextColored(colour, "%s",
                       trf("%s: %s", tr(check::status_name(r.status)), r.detail.c_str()).c_str());
  if (!current) ImGui::TextUnformatted(tr("(for the camera before your last change)"));
  if (!v.sandboxed && !is_file_) ImGui::TextUnformatted(tr("no sandbox: bubblewrap is not available here"));
  if (v.diagnosed && v.diagnosis.empty())
    ImGui::TextWrapped("%s", tr("no classic mistake reproduces this image"));
  const char* lang = language_code(current_language());
  for (const check::Explanation& e : v.diagnosis) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s: %s", e.id().c_str(), e.text(lang).c_str());
  }
  if (!r.stderr_text.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
    ImGui::TextWrapped("%s", r.stderr_text.substr(0, 600).c_str());
    ImGui::PopStyleColor();
  }
  (void)state;
}

// ---- the overlay -----------------------------------------------------------------------------------------
void CameraCheck::overlay(const AppState& state, ImDrawList* list, float x0, float y0, float x1,
                          float y1) const {
  std::lock_guard<std::mutex> lock(view_->mutex);
  if (!view_->latest || view_->latest->key != last_key_) return;  // only over the image it was made for
  const CheckVerdict& v = *view_->latest;
  if (v.dimension != state.dimension || v.columns != state.map.width || v.rows != state.map.height) return;
  const float cw = (x1 - x0) / float(v.columns), ch = (y1 - y0) / float(v.rows);
  const ImU32 red = IM_COL32(255, 0, 0, 120);  // translucent: the student's mistake stays visible underneath
  // One rectangle per run of wrong pixels along a row: few rectangles even when most of the image is wrong.
  for (int row = 0; row < v.rows; ++row)
    for (int column = 0; column < v.columns;) {
      // The image's column `column`; a 2D bar shows pixel k = n-1-column there.
      auto wrong_at = [&](int c) {
        const int k = v.dimension == 2 ? v.columns - 1 - c : c;
        return v.wrong[std::size_t(row) * std::size_t(v.columns) + std::size_t(k)] != 0;
      };
      if (!wrong_at(column)) {
        ++column;
        continue;
      }
      int end = column;
      while (end < v.columns && wrong_at(end)) ++end;
      list->AddRectFilled({x0 + column * cw, y0 + row * ch}, {x0 + end * cw, y0 + (row + 1) * ch}, red);
      column = end;
    }
}

}  // namespace raycam::ui
