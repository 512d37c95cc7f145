// `raycam-cli shot`: the app's whole window rendered headless (OSMesa) to PNG, with the app's own frame code.
// `--soak N` instead renders N frames with random parameter changes and reports frame times and memory.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "cli/commands.h"
#include "flags/flag_values.h"
#include "headless/headless_renderer.h"
#include "raycam/process_memory.h"

namespace raycam::cli {

namespace {
// CPU time of the whole process (every thread: the caster's and llvmpipe's), in ms. On a shared machine the
// wall-clock frame time includes waiting for a core; the CPU time is what the frame costs.
double process_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

// Every id is -1 or a real object, every colour is the background or that object's: a NaN anywhere in the
// camera would break this (NaN compares false and leaves garbage ids or all-background maps with hits).
bool colour_map_is_consistent(const session::AppState& state) {
  return std::visit(
      [&](const auto& view) {
        const auto& objects = objects_of(view.scene);
        for (std::size_t i = 0; i < state.map.ids.size(); ++i) {
          const int id = state.map.ids[i];
          if (id < -1 || id >= int(objects.size())) return false;
          const Rgb8 expected = id < 0 ? view.scene.background : objects[std::size_t(id)].colour;
          if (state.map.colours[i] != expected) return false;
        }
        return true;
      },
      state.view);
}

int soak(session::AppState& state, headless::HeadlessRenderer& renderer, int frames) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> times, cpu_times;
  renderer.render_settled(state);
  const long rss_start = testkit::resident_kb("VmRSS:");
  int bad_frames = 0;
  for (int frame = 0; frame < frames; ++frame) {
    // A student dragging sliders: small random steps, sometimes a jump, sometimes a mode or res change.
    const double jump = unit(random) < 0.05 ? 10.0 : 1.0;
    Orbit2D& o2 = view2d(state).orbit;
    Orbit3D& o3 = view3d(state).orbit;
    o2.theta += jump * (unit(random) - 0.5) * 0.2;
    o3.theta += jump * (unit(random) - 0.5) * 0.2;
    o3.phi = std::clamp(o3.phi + jump * (unit(random) - 0.5) * 0.2, 0.0, glm::pi<double>());
    o2.d = o3.d = std::clamp(o3.d * std::exp((unit(random) - 0.5) * 0.1 * jump), 0.1, 200.0);
    o2.df = o3.df = std::clamp(o3.df * std::exp((unit(random) - 0.5) * 0.1 * jump), 0.05, 20.0);
    if (unit(random) < 0.02) state.res = std::clamp(unit(random), 0.01, 1.0);
    state.cameras_dirty = true;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_ms();
    renderer.run_frame(state);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    cpu_times.push_back(process_cpu_ms() - cpu_start);
    if (!colour_map_is_consistent(state)) ++bad_frames;
  }
  const long rss_end = testkit::resident_kb("VmRSS:"), peak = testkit::resident_kb("VmHWM:");
  std::sort(times.begin(), times.end());
  std::sort(cpu_times.begin(), cpu_times.end());
  const auto at = [&](double q) { return times[std::min(times.size() - 1, std::size_t(q * double(times.size())))]; };
  std::printf(
      "soak: %d frames %dx%d (%dD), frame ms: median %.2f, p95 %.2f, max %.2f; CPU ms (all threads): median "
      "%.2f\n",
      frames, renderer.width(), renderer.height(), dimension(state), at(0.5), at(0.95), times.back(),
      cpu_times[cpu_times.size() / 2]);
  std::printf("soak: RSS %ld KB after the first frames, %ld KB at the end (%+ld KB), peak %ld KB\n", rss_start, rss_end,
              rss_end - rss_start, peak);
  std::printf("soak: %d frames with an inconsistent colour map\n", bad_frames);
  return bad_frames == 0 ? 0 : 1;
}
struct ShotOptions {
  session::AppOptions app;
  std::string out_path = "raycam-shot.png";
  int frames = 3, soak_frames = 0;
};

int run_shot(const ShotOptions& options) {
  session::AppState state = session::make_app_state(options.app);
  headless::HeadlessRenderer renderer(options.app.width, options.app.height);
  renderer.panels() = ui::panel_state_for(options.app, state);  // --check CMD, the Open box's file
  if (options.soak_frames > 0) return soak(state, renderer, options.soak_frames);
  const auto start = std::chrono::steady_clock::now();
  const gl::RgbaImage image = renderer.render_settled(state, options.frames);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  gl::write_png(image, options.out_path);
  std::printf("wrote %s (%dx%d, %dD, %d frames in %.0f ms, last frame %.1f ms)\n", options.out_path.c_str(),
              image.width, image.height, dimension(state), options.frames, ms, state.frame_ms);
  return 0;
}

constexpr const char* kShotSummary = "render the app's whole window headless (OSMesa) to PNG; --soak N for a long run";
constexpr const char* kShotDescription =
    "Renders the app's whole window (panels, colour bar or image, overhead and observer views) with no display,\n"
    "through OSMesa, with the same frame code as the `raycam` app, and writes a PNG.\n";
}  // namespace

void add_shot_command(CLI::App& cli, int& exit_code) {
  CLI::App* shot = add_described_subcommand(cli, "shot", kShotSummary, kShotDescription);
  auto options = std::make_shared<ShotOptions>();
  flags::add_app_options(*shot, options->app);
  flags::add_checked_option<std::string>(*shot, "--out", "FILE", "output PNG (default raycam-shot.png)",
                                         flags::file_name(),
                                         [options](std::string p) { options->out_path = p; });
  flags::add_checked_option<int>(*shot, "--frames", "N", "frames to run before the capture (default 3)",
                                 flags::integer_in(2, 1000), [options](int n) { options->frames = n; });
  flags::add_checked_option<int>(
      *shot, "--soak", "N",
      "render N frames with random camera changes; report frame times, peak memory, and "
      "check every frame's colour map",
      flags::integer_in(1, 1000000), [options](int n) { options->soak_frames = n; });
  shot->callback([options, &exit_code] { exit_code = run_shot(*options); });
}

}  // namespace raycam::cli
