// Section index: the worker · CameraCheck (debounce) · what the panel reads.
#include "session/camera_check.h"

#include <sys/stat.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "check/check_texts.h"
#include "raycam/view_setup.h"
#include "check/student_process.h"
#include "session/text.h"

namespace raycam::session {

// ---- the worker ----------------------------------------------------------------------------------------
struct CheckJob {
  std::string key;
  check::CheckCase checked;
  check::CaseSource source;
};

struct CheckShared {
  std::mutex mutex;
  std::condition_variable wake;
  std::optional<CheckJob> pending;
  bool running = false, stop = false, worker_started = false;
  // Set when a newer job arrives while one runs: the running program is stopped (within 50 ms) and its
  // verdict dropped, so the newer camera's verdict does not wait up to a whole timeout behind a stale run.
  std::atomic<bool> cancel_running{false};
  std::shared_ptr<const KeyedVerdict> latest;
  double started_at = 0;
};

namespace {
// A case that could not be run (a command that does not split, a camera the core refuses): shown as a
// crash with its reason, never thrown at the frame.
std::shared_ptr<const KeyedVerdict> crashed(const std::string& key, const std::string& why) {
  auto verdict = std::make_shared<KeyedVerdict>();
  verdict->key = key;
  verdict->verdict.result.status = check::CaseStatus::crash;
  verdict->verdict.result.detail = why;
  return verdict;
}

// The job's verdict; a camera the core refuses is a crash with its reason.
std::shared_ptr<const KeyedVerdict> graded(const CheckJob& job) {
  try {
    return std::make_shared<const KeyedVerdict>(KeyedVerdict{job.key, check::grade_case(job.checked, job.source)});
  } catch (const std::exception& error) {
    return crashed(job.key, error.what());
  }
}

// The worker thread's loop (a host that grades in the background; a page grades at once in update()).
void work(std::shared_ptr<CheckShared> shared) {
  for (;;) {
    CheckJob job;
    {
      std::unique_lock<std::mutex> lock(shared->mutex);
      shared->wake.wait(lock, [&] { return shared->stop || shared->pending; });
      if (shared->stop) return;
      job = std::move(*shared->pending);
      shared->pending.reset();
      shared->running = true;
      shared->cancel_running = false;
    }
    job.source.cancel = &shared->cancel_running;
    std::shared_ptr<const KeyedVerdict> verdict = graded(job);
    std::lock_guard<std::mutex> lock(shared->mutex);
    if (!shared->cancel_running) shared->latest = std::move(verdict);  // else a newer job waits: its turn
    shared->running = false;
  }
}

}  // namespace

SceneFile camera_case(const Lesson& state) {
  return scene_file_of(state.view, active_preset(state));
}

// ---- CameraCheck (debounce) -------------------------------------------------------------------------------
CameraCheck::CameraCheck() : shared_(std::make_shared<CheckShared>()) {}

CameraCheck::~CameraCheck() {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  shared_->stop = true;
  shared_->cancel_running = true;  // a program still running is stopped, not left to its timeout
  shared_->wake.notify_all();
}

void CameraCheck::set_command(const std::string& command, bool is_file) {
  request_.command = command;
  request_.is_file = is_file;
}

SceneFile CameraCheck::case_for_download(const Lesson& state) {
  downloaded_ = DownloadedCase{camera_key(state), camera_case(state)};
  return downloaded_->file;
}

void CameraCheck::give_answer(const std::string& path) {
  set_command(path, true);
  request_.check_now = true;
}

void CameraCheck::clear() {
  if (request_.is_file) request_.command.clear();
  request_.check_now = false;
  std::lock_guard<std::mutex> lock(shared_->mutex);
  shared_->latest.reset();
}

std::string CameraCheck::camera_key(const Lesson& state) const {
  // Cheap to build every frame: what the case depends on (the scene by version, the camera by value).
  const CameraPreset p = active_preset(state);
  std::ostringstream key;
  key << std::hexfloat << dimension(state) << '|' << state.opened_version << '|' << scene_path(state) << '|'
      << p.d.value_or(0) << '|' << p.theta_deg.value_or(0) << '|' << p.phi_deg.value_or(0) << '|'
      << p.df.value_or(0) << '|' << p.res.value_or(0) << '|' << p.res_rows.value_or(0) << '|';
  for (double t : p.target.value_or(std::vector<double>{})) key << t << ',';
  for (int s : p.size.value_or(std::vector<int>{})) key << s << ',';
  return key.str();
}

std::string CameraCheck::command_key() const {
  std::ostringstream key;
  key << '|' << request_.is_file << '|' << request_.command;
  if (request_.is_file) {  // an answer file edited by hand counts as a change
    struct stat info;
    if (stat(request_.command.c_str(), &info) == 0)
      key << '|' << info.st_mtim.tv_sec << '.' << info.st_mtim.tv_nsec;
  }
  return key.str();
}

void CameraCheck::update(const Lesson& state, const HostLink& link, double now) {
  if (request_.command.empty()) return;
  const std::string command = command_key();
  const std::string key = camera_key(state) + command;
  if (key != last_key_) {
    last_key_ = key;
    changed_at_ = now;
  }
  // A host that runs no program re-grades nothing by itself: an answer file is for the case it was made for.
  const bool automatic = request_.automatic && link.host.runs_programs;
  const bool due =
      request_.check_now || (automatic && key != submitted_key_ && now - changed_at_ >= kQuietSeconds);
  if (!due) return;
  request_.check_now = false;
  CheckJob job;
  // An answer file after a case download answers that case, whatever the camera did since.
  const bool for_download = request_.is_file && downloaded_;
  job.key = for_download ? downloaded_->camera_key + command : key;
  job.checked = {"the current camera", for_download ? downloaded_->file : camera_case(state)};
  job.source.timeout_seconds = kCheckTimeout;
  job.source.diagnosis_budget = kDiagnosisBudget;
  try {
    if (request_.is_file)
      job.source.answer_path = request_.command;
    else
      job.source.argv = check::absolutise_paths(check::split_command(request_.command, "command"));
  } catch (const std::invalid_argument& error) {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    shared_->latest = crashed(key, error.what());
    submitted_key_ = key;
    return;
  }
  submitted_key_ = key;
  if (!link.host.grades_in_background) {
    // A page has no thread to spare and runs no program: its answer file is graded at once (milliseconds).
    std::shared_ptr<const KeyedVerdict> verdict = graded(job);
    std::lock_guard<std::mutex> lock(shared_->mutex);
    shared_->latest = std::move(verdict);
    return;
  }
  std::lock_guard<std::mutex> lock(shared_->mutex);
  shared_->pending = std::move(job);  // a newer case replaces one still waiting
  if (shared_->running) shared_->cancel_running = true;  // and stops one still running
  shared_->started_at = now;
  if (!shared_->worker_started) {
    shared_->worker_started = true;
    std::thread(work, shared_).detach();  // it holds the shared state; it ends when stop is set
  }
  shared_->wake.notify_all();
}

// ---- what the panel reads
// ----------------------------------------------------------------------------------
std::shared_ptr<const KeyedVerdict> CameraCheck::latest() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->latest;
}

CheckProgress CameraCheck::progress() const {
  CheckProgress progress;
  std::lock_guard<std::mutex> lock(shared_->mutex);
  progress.running = shared_->running || shared_->pending.has_value();
  progress.started_at = shared_->started_at;
  progress.latest = shared_->latest;
  progress.current = progress.latest && progress.latest->key == last_key_;
  return progress;
}

VerdictState CameraCheck::verdict_state() const {
  const auto verdict = latest();
  if (!verdict) return VerdictState::no_answer;
  return verdict->key == last_key_ ? VerdictState::for_camera_shown : VerdictState::for_earlier_camera;
}

const char* verdict_state_name(VerdictState state) {
  switch (state) {
    case VerdictState::no_answer: return "no-answer";
    case VerdictState::for_camera_shown: return "camera-shown";
    case VerdictState::for_earlier_camera: return "earlier-camera";
  }
  return "";
}

std::string CameraCheck::status() const {
  const auto verdict = latest();
  return verdict ? check::status_name(verdict->verdict.result.status) : "";
}

std::string CameraCheck::top_diagnosis() const {
  const auto verdict = latest();
  return verdict && !verdict->verdict.diagnosis.empty() ? verdict->verdict.diagnosis[0].id() : "";
}

long long CameraCheck::wrong_pixels() const {
  const auto verdict = latest();
  return verdict ? verdict->verdict.result.wrong_pixels : 0;
}

bool CameraCheck::up_to_date() const {
  const auto verdict = latest();
  return verdict && verdict->key == last_key_;
}

bool CameraCheck::waiting() const {
  return busy() || (!request_.command.empty() && request_.automatic && last_key_ != submitted_key_) ||
         request_.check_now;
}

bool CameraCheck::busy() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->running || shared_->pending.has_value();
}

std::vector<WrongPixel> first_wrong_pixels(const check::CaseVerdict& verdict, int count) {
  std::vector<WrongPixel> found;
  if (verdict.columns <= 0) return found;
  for (std::size_t i = 0; i < verdict.wrong.size() && int(found.size()) < count; ++i)
    if (verdict.wrong[i] != 0) found.push_back({int(i / std::size_t(verdict.columns)), int(i % std::size_t(verdict.columns))});
  return found;
}

std::string wrong_pixels_named(const check::CaseVerdict& verdict) {
  std::string named;
  for (const WrongPixel& p : first_wrong_pixels(verdict, kNamedWrongPixels))
    named += (named.empty() ? "(" : ", (") + std::to_string(p.row) + ", " + std::to_string(p.column) + ")";
  if (verdict.result.wrong_pixels > kNamedWrongPixels) named += ", …";
  return named;
}

CheckHeader check_header(Language language, const CheckProgress& progress, const std::string& mistakes,
                         bool downloaded_case) {
  if (progress.running || !progress.latest || !progress.current) return {};
  const check::CaseResult& r = progress.latest->verdict.result;
  if (!mistakes.empty() && (r.status == check::CaseStatus::pass || r.status == check::CaseStatus::fail)) {
    const char* m = mistakes.c_str();
    if (r.status == check::CaseStatus::pass)
      return {{trf(language, downloaded_case ? "CHECK: passed for the downloaded case — the image shown shows the mistake « %s »"
                                             : "CHECK: passed for your camera — the image shown shows the mistake « %s »", m),
               trf(language, "✓ case passed — the image shows « %s »", m), tr(language, "✓ case passed")},
              true, true};
    return {{trf(language, downloaded_case ? "CHECK: %lld {{pixel|pixels}} wrong for the downloaded case — the image shown shows the mistake « %s »"
                                           : "CHECK: %lld {{pixel|pixels}} wrong for your camera — the image shown shows the mistake « %s »",
                 r.wrong_pixels, m),
             trf(language, "✗ case: %lld wrong — the image shows « %s »", r.wrong_pixels, m),
             trf(language, "✗ case: %lld wrong", r.wrong_pixels)},
            false, true};
  }
  if (r.status == check::CaseStatus::pass) return {{tr(language, "CHECK: passed"), tr(language, "✓ passed")}, true};
  if (r.status == check::CaseStatus::fail)
    return {{trf(language, "CHECK: %lld {{pixel|pixels}} wrong", r.wrong_pixels), trf(language, "✗ %lld {{pixel|pixels}} wrong", r.wrong_pixels),
             trf(language, "✗ %lld wrong", r.wrong_pixels)}};
  const char* status = check::text(language, check::status_name(r.status));
  return {{trf(language, "CHECK: %s", status), std::string("✗ ") + status}};
}

}  // namespace raycam::session
