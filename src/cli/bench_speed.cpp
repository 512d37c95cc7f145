// `raycam-cli bench speed`: raycam's casters against Embree 3 on the same scenes in the same run (README,
// "Speed"). Scenes: K random spheres in [-10, 10]³, radius 2·K^(-1/3) so the scene stays sparse as K
// grows, seen whole by one orbit camera. Every variant writes ids and colours into a reused map; every
// variant's ids are checked against the plain loop (the whole image, or sampled pixels when the plain
// loop would take minutes).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <glm/trigonometric.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "commands.h"
#include "raycam/parallel.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"
#ifdef RAYCAM_HAVE_EMBREE
#include "embree_caster.h"
#endif

namespace raycam::cli {

namespace {
// Plain and culled test every pixel against every visible object: beyond this many tests (~1 s) they are
// skipped, and ids are checked on sampled pixels instead.
constexpr double kMaxPlainTests = 2e8;
constexpr int kSampledPixels = 4096;

struct SpeedOptions {
  std::vector<int> counts{1, 10, 100, 1000, 10000, 100000};
  std::vector<int> sides{256, 1024};
  std::vector<int> threads{1, 2};
  int repeats = 7;
  std::string csv_path, scene_path;
  int scene_columns = 512, scene_rows = 512;
};

void print_help() {
  std::printf(
      "usage: raycam-cli bench speed [--quick] [--counts LIST] [--sizes LIST] [--threads LIST] [--repeats R]\n"
      "                              [--csv FILE]\n"
      "       raycam-cli bench speed --scene FILE [--size WxH] [--threads T] [--repeats R]\n\n"
      "Median time and Mrays/s of one primary ray per pixel, for raycam's casters (plain, culled, footprint,\n"
      "binned, automatic) and Embree 3 (rtcIntersect1 and rtcIntersect16, when built with libembree-dev), on\n"
      "K random spheres in [-10,10]^3 with radius 2*K^(-1/3), at side x side pixels. Then: cost against K and\n"
      "against the pixel count, 2D bars for n = 16...4096, and peak memory.\n\n"
      "  --counts LIST   sphere counts K (default 1,10,100,1000,10000,100000)\n"
      "  --sizes LIST    image sides (default 256,1024)\n"
      "  --threads LIST  thread counts (default 1,2)\n"
      "  --repeats R     timed runs per variant, the median is reported (default 7, in [1, 1000])\n"
      "  --quick         K = 1,100,10000 at 256 px, 3 repeats (a smoke test: seconds)\n"
      "  --csv FILE      also write every row as CSV\n"
      "  --scene FILE    time a scene file's camera preset instead, at --size WxH (3D) or N (2D)\n");
}

std::vector<int> integer_list(const std::string& text, const std::string& flag, int lo, int hi) {
  std::vector<int> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    values.push_back(parse_integer_flag(text.substr(start, comma - start), flag, lo, hi));
    start = comma + 1;
  }
  return values;
}

SpeedOptions parse_options(const Args& args, bool& help) {
  SpeedOptions o;
  for (std::size_t i = 0; i < args.size();) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      help = true;
      return o;
    }
    if (flag == "--quick") {
      o.counts = {1, 100, 10000};
      o.sides = {256};
      o.repeats = 3;
      ++i;
      continue;
    }
    if (i + 1 >= args.size()) throw std::invalid_argument(flag + ": missing value (see bench speed --help)");
    const std::string& value = args[i + 1];
    if (flag == "--counts") o.counts = integer_list(value, flag, 0, 2000000);
    else if (flag == "--sizes") o.sides = integer_list(value, flag, 1, 8192);
    else if (flag == "--threads") o.threads = integer_list(value, flag, 1, 256);
    else if (flag == "--repeats") o.repeats = parse_integer_flag(value, flag, 1, 1000);
    else if (flag == "--csv") o.csv_path = value;
    else if (flag == "--scene") o.scene_path = value;
    else if (flag == "--size") {
      const std::size_t x = value.find('x');
      o.scene_columns = parse_integer_flag(value.substr(0, x), flag, 1, 16384);
      o.scene_rows = x == std::string::npos ? 1 : parse_integer_flag(value.substr(x + 1), flag, 1, 16384);
    } else throw std::invalid_argument("unknown option '" + flag + "' (see raycam-cli bench speed --help)");
    i += 2;
  }
  return o;
}

double median_ms(int repeats, const std::function<void()>& run) {
  run();  // warm-up: first-touch of the map, caches
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

long peak_rss_kb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

Scene3D random_scene(int count) {
  std::mt19937_64 engine(20261122u + unsigned(count));
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  const double radius = 2.0 * std::pow(double(std::max(count, 1)), -1.0 / 3.0);
  Scene3D scene;
  for (int i = 0; i < count; ++i) {
    const double x = coordinate(engine), y = coordinate(engine), z = coordinate(engine);
    scene.spheres.push_back({{x, y, z}, radius, {std::uint8_t(40 + i % 200), std::uint8_t(i * 7), 200}, ""});
  }
  return scene;
}

Camera3D bench_camera(int columns, int rows) {
  Camera3D camera(columns, rows);
  camera.set_orbit({{0, 0, 0}, 35.0, glm::radians(30.0), glm::radians(60.0), 2.0});  // the whole cube in view
  return camera;
}

// Ids checked against the plain loop: every pixel when `plain` is given, else sampled pixels recomputed
// with nearest_hit over every sphere (the plain loop, pixel by pixel). Returns the differing count.
struct IdCheck {
  long long differing = 0, checked = 0;
};
IdCheck check_ids(const Camera3D& camera, const Scene3D& scene, const ColourMap& map, const ColourMap* plain) {
  IdCheck check;
  if (plain) {
    for (std::size_t i = 0; i < map.ids.size(); ++i) check.differing += map.ids[i] != plain->ids[i];
    check.checked = static_cast<long long>(map.ids.size());
    return check;
  }
  std::mt19937 engine(7);
  for (int s = 0; s < kSampledPixels; ++s) {
    const int row = int(engine() % unsigned(camera.rows())), column = int(engine() % unsigned(camera.columns()));
    const Hit hit = nearest_hit(scene.spheres, camera.primary_ray(row, column), IntersectFormula::stable);
    check.differing += hit.id != map.id_at(row, column);
    ++check.checked;
  }
  return check;
}

struct Row {
  int count = 0, side = 0, threads = 0;
  std::string variant;
  double ms = 0.0, mrays = 0.0;
  IdCheck ids;
  std::string note;
};

void print_row(const Row& r) {
  std::printf("| %6d | %4d | %d | %-20s | %9.3f | %8.1f | ", r.count, r.side, r.threads, r.variant.c_str(), r.ms,
              r.mrays);
  if (r.ids.checked == 0) std::printf("- | %s |\n", r.note.c_str());
  else
    std::printf("%lld of %lld%s | %s |\n", r.ids.differing, r.ids.checked,
                r.ids.checked < static_cast<long long>(r.side) * r.side ? " sampled" : "", r.note.c_str());
  std::fflush(stdout);
}

// The floor: the same rays generated and the map written, with no object tested.
void rays_only(const Camera3D& camera, Rgb8 background, int threads, ColourMap& map) {
  map.resize(camera.columns(), camera.rows());
  std::vector<std::vector<Ray3D>> rays(static_cast<std::size_t>(threads));
  for (std::vector<Ray3D>& r : rays) r.resize(static_cast<std::size_t>(camera.columns()));
  // One row per item, on the casters' own persistent pool.
  detail::parallel_items(camera.rows(), threads, [&](int worker, int row) {
    Ray3D* row_rays = rays[std::size_t(worker)].data();
    camera.primary_rays(row, 0, camera.columns() - 1, row_rays);
    for (int column = 0; column < camera.columns(); ++column) {
      const std::size_t p = map.index(row, column);
      map.ids[p] = row_rays[column].direction.x > 2.0 ? 0 : -1;  // never: keeps the rays alive
      map.colours[p] = background;
    }
  });
}

std::vector<Row> run_grid(const SpeedOptions& o) {
  std::vector<Row> rows;
  std::printf("| K | side | threads | variant | median ms | Mrays/s | ids differing from plain | note |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (int count : o.counts) {
    const Scene3D scene = random_scene(count);
#ifdef RAYCAM_HAVE_EMBREE
    const bench::EmbreeCaster embree(scene);
    const std::string build_note = "BVH build " + std::to_string(embree.build_ms()).substr(0, 5) + " ms";
#endif
    for (int side : o.sides) {
      const Camera3D camera = bench_camera(side, side);
      const double pixels = double(side) * side;
      const bool plain_affordable = pixels * std::max(count, 1) <= kMaxPlainTests;
      ColourMap plain;
      if (plain_affordable) {
        CastOptions options;
        options.method = CastMethod::plain;
        cast_primary_rays(camera, scene, plain, options);
      }
#ifdef RAYCAM_HAVE_EMBREE
      std::vector<Ray3D> ray_table(static_cast<std::size_t>(side) * side);
      for (int row = 0; row < side; ++row) camera.primary_rays(row, 0, side - 1, &ray_table[std::size_t(row) * side]);
#endif
      for (int threads : o.threads) {
        ColourMap map;
        auto time = [&](const std::string& variant, const std::function<void()>& run, std::string note = "") {
          Row r;
          r.count = count;
          r.side = side;
          r.threads = threads;
          r.variant = variant;
          r.ms = median_ms(o.repeats, run);
          r.mrays = pixels / (r.ms * 1e3);
          const bool floor = variant.rfind("rays only", 0) == 0;  // no objects: nothing to check
          if (!floor) r.ids = check_ids(camera, scene, map, plain_affordable ? &plain : nullptr);
          r.note = std::move(note);
          print_row(r);
          rows.push_back(r);
        };
        time("rays only (floor)", [&] { rays_only(camera, scene.background, threads, map); });
        for (CastMethod method : {CastMethod::plain, CastMethod::culled, CastMethod::footprint, CastMethod::binned,
                                  CastMethod::automatic}) {
          if ((method == CastMethod::plain || method == CastMethod::culled) && !plain_affordable) continue;
          CastOptions options;
          options.method = method;
          options.threads = threads;
          CastStats stats;
          time(cast_method_name(method), [&] { cast_primary_rays(camera, scene, map, options, &stats); });
          rows.back().note = std::to_string(stats.intersection_tests) + " tests, " +
                             std::to_string(stats.pixels_skipped) + " px skipped, " +
                             std::to_string(stats.objects_culled) + " culled";
        }
#ifdef RAYCAM_HAVE_EMBREE
        time("embree packet1", [&] { embree.cast(camera, 1, threads, map); }, build_note);
        time("embree packet16", [&] { embree.cast(camera, 16, threads, map); }, build_note);
        time("embree p16 ray table", [&] { embree.cast(camera, 16, threads, map, &ray_table); },
             "rays made beforehand, untimed");
#endif
      }
    }
  }
  return rows;
}

// Best raycam (automatic) against the best Embree variant, per K, side and thread count.
void print_ratios(const std::vector<Row>& rows) {
#ifdef RAYCAM_HAVE_EMBREE
  std::printf("\nraycam automatic against Embree's best variant (same K, size, threads):\n\n"
              "| K | side | threads | raycam ms | Embree best ms | speed-up |\n|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    if (r.variant != "automatic") continue;
    double best = 1e300;
    for (const Row& e : rows)
      if (e.count == r.count && e.side == r.side && e.threads == r.threads && e.variant.rfind("embree", 0) == 0)
        best = std::min(best, e.ms);
    std::printf("| %d | %d | %d | %.3f | %.3f | %.1fx |\n", r.count, r.side, r.threads, r.ms, best, best / r.ms);
  }
#else
  (void)rows;
  std::printf("\nEmbree: not in this build (install libembree-dev and reconfigure to compare against it).\n");
#endif
}

// How cost grows with the pixel count (K = 1000) and with K (already in the grid), automatic, all threads.
void print_scaling(int repeats, int threads) {
  std::printf("\nCost against the pixel count (K = 1000, automatic, %d threads):\n\n"
              "| side | pixels | median ms | ns per pixel |\n|---|---|---|---|\n", threads);
  const Scene3D scene = random_scene(1000);
  for (int side : {128, 256, 512, 1024, 2048}) {
    const Camera3D camera = bench_camera(side, side);
    ColourMap map;
    CastOptions options;
    options.threads = threads;
    const double ms = median_ms(repeats, [&] { cast_primary_rays(camera, scene, map, options); });
    std::printf("| %d | %d | %.3f | %.2f |\n", side, side * side, ms, ms * 1e6 / (double(side) * side));
  }
}

// 2D bars: the demo scene (three circles), plain loop against automatic, in microseconds.
void print_bars(int repeats) {
  std::printf("\n2D bars, demo scene (3 circles), one thread:\n\n"
              "| n | plain us | automatic us | tests plain | tests automatic |\n|---|---|---|---|---|\n");
  const Scene2D scene = demo_scene_2d();
  for (int n = 16; n <= 4096; n *= 4) {
    Camera2D camera(n);
    ColourMap map;
    CastOptions plain, automatic;
    plain.method = CastMethod::plain;
    CastStats plain_stats, automatic_stats;
    const double plain_ms = median_ms(repeats * 3, [&] { cast_primary_rays(camera, scene, map, plain, &plain_stats); });
    const double fast_ms =
        median_ms(repeats * 3, [&] { cast_primary_rays(camera, scene, map, automatic, &automatic_stats); });
    std::printf("| %d | %.1f | %.1f | %lld | %lld |\n", n, plain_ms * 1e3, fast_ms * 1e3,
                plain_stats.intersection_tests, automatic_stats.intersection_tests);
  }
}

void write_csv(const std::vector<Row>& rows, const std::string& path) {
  if (path.empty()) return;
  std::ofstream csv(path);
  if (!csv) throw std::runtime_error(path + ": cannot write the CSV");
  csv << "K,side,threads,variant,median_ms,mrays_per_s,ids_differing,ids_checked\n";
  for (const Row& r : rows)
    csv << r.count << ',' << r.side << ',' << r.threads << ",\"" << r.variant << "\"," << r.ms << ',' << r.mrays
        << ',' << r.ids.differing << ',' << r.ids.checked << '\n';
}

int run_scene(const SpeedOptions& o) {
  ViewFlags flags;
  flags.scene_path = o.scene_path;
  ViewSetup setup = make_view_setup(flags);
  const int threads = o.threads.back();
  CastOptions automatic, plain;
  automatic.threads = threads;
  plain.method = CastMethod::plain;
  ColourMap map;
  CastStats stats;
  double ms = 0.0, plain_ms = -1.0, pixels = 0.0;
  if (setup.dimension == 2) {
    Camera2D camera(o.scene_columns);
    camera.set_orbit(setup.camera2d.orbit());
    validate(setup.file.scene2d);
    pixels = camera.pixel_count();
    ms = median_ms(o.repeats, [&] { cast_primary_rays(camera, setup.file.scene2d, map, automatic, &stats); });
    plain_ms = median_ms(o.repeats, [&] { cast_primary_rays(camera, setup.file.scene2d, map, plain); });
  } else {
    Camera3D camera(o.scene_columns, o.scene_rows);
    camera.set_orbit(setup.camera3d.orbit());
    validate(setup.file.scene3d);
    pixels = double(camera.columns()) * camera.rows();
    ms = median_ms(o.repeats, [&] { cast_primary_rays(camera, setup.file.scene3d, map, automatic, &stats); });
    if (pixels * double(setup.file.scene3d.spheres.size()) <= kMaxPlainTests)
      plain_ms = median_ms(o.repeats, [&] { cast_primary_rays(camera, setup.file.scene3d, map, plain); });
  }
  std::printf("%s: %dD, %.0f pixels, %d threads: automatic %.3f ms median (%.1f Mrays/s; %lld tests, %lld px "
              "skipped, %lld culled)",
              o.scene_path.c_str(), setup.dimension, pixels, threads, ms, pixels / (ms * 1e3),
              stats.intersection_tests, stats.pixels_skipped, stats.objects_culled);
  if (plain_ms >= 0) std::printf("; plain loop %.3f ms (%.1fx)", plain_ms, plain_ms / ms);
  std::printf("\n");
  return 0;
}
}  // namespace

int run_bench_speed(const Args& args) {
  bool help = false;
  const SpeedOptions o = parse_options(args, help);
  if (help) {
    print_help();
    return 0;
  }
  if (!o.scene_path.empty()) return run_scene(o);
  const int hardware = int(std::thread::hardware_concurrency());
  std::printf("raycam bench speed: %d hardware threads, median of %d runs", hardware, o.repeats);
#ifdef RAYCAM_HAVE_EMBREE
  std::printf(", %s\n\n", bench::EmbreeCaster(Scene3D{}).isa_note().c_str());
#else
  std::printf(", Embree not in this build\n\n");
#endif
  const std::vector<Row> rows = run_grid(o);
  print_ratios(rows);
  print_scaling(o.repeats, o.threads.back());
  print_bars(o.repeats);
  std::printf("\nPeak resident memory of this run: %.1f MB\n", double(peak_rss_kb()) / 1024.0);
  write_csv(rows, o.csv_path);
  long long differing = 0;
  for (const Row& r : rows)
    if (r.variant.rfind("embree", 0) != 0) differing += r.ids.differing;
  if (differing > 0) {
    std::printf("FAILED: raycam's casters disagree with the plain loop on %lld pixels\n", differing);
    return 1;
  }
  return 0;
}

}  // namespace raycam::cli
