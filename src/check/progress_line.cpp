#include "check/progress_line.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

#include "check/check_texts.h"

namespace raycam::check {

std::string progress_text(const std::string& command, const Progress& progress, const std::string& what,
                          double elapsed_seconds) {
  const bool known = progress.steps > 0 && progress.work > 0;
  std::string text = command + ": " + std::to_string(progress.step + 1);
  if (known) text += "/" + std::to_string(progress.steps);
  if (!what.empty()) text += " (" + what + ")";
  if (!known) return text;
  // Work past the total (a count that was off) never reads as more than 100 %.
  const std::size_t done = std::min(progress.done, progress.work);
  text += ", " + std::to_string(done * 100 / progress.work) + " %";
  const std::string left = time_left(Language::en, done, progress.work, elapsed_seconds);
  return left.empty() ? text : text + ", " + left;
}

ProgressLine::ProgressLine(std::string command, std::size_t steps, bool quiet, std::FILE* out, std::size_t work)
    : command_(std::move(command)),
      progress_{0, steps, 0, work > 0 ? work : steps},
      quiet_(quiet),
      terminal_(isatty(fileno(out)) != 0),
      out_(out),
      began_(std::chrono::steady_clock::now()) {}

// Columns of the terminal `out` is, 0 when it is none or does not say.
std::size_t terminal_width(std::FILE* out) {
  winsize size{};
  return isatty(fileno(out)) && ioctl(fileno(out), TIOCGWINSZ, &size) == 0 ? size.ws_col : 0;
}

void ProgressLine::show(const std::string& line) {
  if (terminal_) {
    // Padded: a shorter line must cover the longer one it replaces.
    const std::size_t pad = shown_width_ > line.size() ? shown_width_ - line.size() : 0;
    std::fprintf(out_, "\r%s%s", line.c_str(), std::string(pad, ' ').c_str());
    shown_width_ = line.size();
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
}

void ProgressLine::start(const std::string& what, std::size_t work) {
  if (quiet_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  // A step past the total (a count that was off) is still shown, without a total.
  Progress now = progress_;
  if (now.step >= now.steps) now.steps = 0;
  std::string text = progress_text(command_, now, what, elapsed);
  // On a terminal, within its width (a line that wraps cannot be rewritten from its start): `what` loses
  // its beginning first, so the count and the time left stay.
  const std::size_t width = terminal_ ? terminal_width(out_) : 0;
  if (width > 1 && text.size() > width - 1) {
    const std::size_t over = text.size() - (width - 1) + 3;
    text = progress_text(command_, now, over < what.size() ? "..." + what.substr(over) : "", elapsed);
    text.resize(std::min(text.size(), width - 1));
  }
  show(text);
  ++progress_.step;
  progress_.done += work;
}

void ProgressLine::clear() {
  if (quiet_ || !terminal_ || shown_width_ == 0) return;
  std::fprintf(out_, "\r%s\r", std::string(shown_width_, ' ').c_str());
  std::fflush(out_);
  shown_width_ = 0;
}

void ProgressLine::finish() {
  if (quiet_ || progress_.step == 0) return;  // nothing ran (--benchmark_list_tests): nothing to close
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  char line[160];
  std::snprintf(line, sizeof line, "%s: %zu steps in %.0f s", command_.c_str(), progress_.step, elapsed);
  show(line);
  if (terminal_) std::fprintf(out_, "\n");
  shown_width_ = 0;
}

}  // namespace raycam::check
