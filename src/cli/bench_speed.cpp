// `raycam-cli bench speed`: raycam's casters against Embree 3 and against the floor, on the same scenes in
// the same run, timed by Google Benchmark (README, "Speed"). Section index: options · fixtures · variants ·
// registration · reporting · entry point.
//
// Scenes: K random spheres in [-10, 10]³, radius 2·K^(-1/3) so the scene stays sparse as K grows, seen whole
// by one orbit camera. Every variant writes ids and colours into a reused map; every raycam variant's ids are
// checked against the plain loop after its timing (the whole image, or sampled pixels when the plain loop
// would take minutes), and any difference makes the command fail.
// The floor: "fill only" is the automatic caster on the same camera with no object (the map written, nothing
// else); "rays only" also makes every pixel's ray; "projection" is the caster's first stage alone (every
// sphere culled or projected to its pixel box). raycam casts from a PackedScene3D made once per scene, as
// Embree from a BVH built once; "packing" times that copy (paid when the scene changes, not per frame).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <glm/trigonometric.hpp>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "commands.h"
#include "flag_values.h"
#include "process_memory.h"
#include "raycam/parallel.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/standard_scenes.h"
#include "raycam/view_setup.h"
#include "view_options.h"
#ifdef RAYCAM_HAVE_EMBREE
#include "embree_caster.h"
#endif

namespace raycam::cli {

namespace {
// ---- options
// -----------------------------------------------------------------------------------------------
// Plain and culled test every pixel against every visible object: beyond this many tests (~1 s) they are
// skipped, and ids are checked on sampled pixels instead.
constexpr double kMaxPlainTests = 2e8;
constexpr int kSampledPixels = 4096;

struct SpeedOptions {
  std::vector<int> counts{1, 10, 100, 1000, 10000, 100000};
  std::vector<int> sides{256, 1024};
  std::vector<int> threads{1, 2};
  int repeats = 7;
  double min_seconds = 0.1;  // per repetition: Google Benchmark runs as many iterations as fit
  bool extras = true;        // scaling with the pixel count, 2D bars
  std::string csv_path, scene_path;
  std::optional<std::vector<int>> scene_size;  // --size, else the scene file's
  std::vector<std::string> benchmark_flags;  // --benchmark_* passed through to Google Benchmark
};

// The command line on CLI11 with the shared flag rules (one message format); the `--benchmark_*` flags are
// left over as extras and passed through to Google Benchmark. Returns the exit code when the command must
// stop now (--help: 0, bad usage: 2).
std::optional<int> parse_options(const Args& args, SpeedOptions& o) {
  CLI::App app(
      "Median time (Google Benchmark, R repetitions) and Mrays/s of one primary ray per pixel, for raycam's "
      "casters (plain, culled, footprint, binned, automatic), the floor (fill only, rays only, projection) "
      "and Embree 3 (rtcIntersect1 and rtcIntersect16, when built with libembree-dev), on K random spheres "
      "in [-10,10]^3 with radius 2*K^(-1/3), at side x side pixels. Then: cost against the pixel count and "
      "2D bars. Fails (exit 1) if any raycam caster's ids differ from the plain loop's. Any --benchmark_* "
      "flag goes to Google Benchmark.",
      "raycam-cli bench speed");
  app.allow_extras();
  // --quick first: CLI11 runs the callbacks in this order, so `--quick --repeats 1` keeps the 1.
  app.add_flag_callback("--quick", [&o] {
    o.counts = {1, 100, 10000};
    o.sides = {256};
    o.repeats = 3;
    o.min_seconds = 0.01;
    o.extras = false;
  }, "K = 1,100,10000 at 256 px, 3 short repetitions, no extras (a smoke test: seconds)");
  const auto list = [&app](const char* name, const char* help, int lo, int hi, std::vector<int>& store) {
    flags::add_checked_list<int>(app, name, "LIST", help, flags::integer_in(lo, hi),
                                 [&store](std::vector<int> values) { store = std::move(values); });
  };
  list("--counts", "sphere counts K (default 1,10,100,1000,10000,100000)", 0, 2000000, o.counts);
  list("--sizes", "image sides (default 256,1024)", 1, 8192, o.sides);
  list("--threads", "thread counts (default 1,2)", 1, 256, o.threads);
  flags::add_checked_option<int>(app, "--repeats", "R", "repetitions per variant, the median is reported (default 7)",
                                 flags::integer_in(1, 1000), [&o](int r) { o.repeats = r; });
  flags::add_checked_option<std::string>(app, "--csv", "FILE", "also write every median as CSV", flags::file_name(),
                                         [&o](std::string path) { o.csv_path = std::move(path); });
  flags::add_checked_option<std::string>(app, "--scene", "FILE",
                                         "time a scene file's camera preset instead, at --size",
                                         flags::file_name(), [&o](std::string path) { o.scene_path = std::move(path); });
  flags::add_checked_option<std::vector<int>>(
      app, "--size", "N|WxH", "with --scene: the image size, as render takes it (default: the file's, else 256)",
      flags::size_rule(), [&o](std::vector<int> size) { o.scene_size = std::move(size); });
  if (const std::optional<int> exit_now = flags::parse_command_line(app, args)) return exit_now;
  for (const std::string& extra : app.remaining()) {
    if (extra.rfind("--benchmark_", 0) == 0) {
      o.benchmark_flags.push_back(extra);
      continue;
    }
    std::fprintf(stderr, "raycam-cli bench speed: error: unknown option '%s' (see raycam-cli bench speed --help)\n",
                 extra.c_str());
    return 2;
  }
  return std::nullopt;
}

// ---- fixtures
// ----------------------------------------------------------------------------------------------
Camera3D bench_camera(int columns, int rows) {
  Camera3D camera(columns, rows);
  camera.set_orbit({{0, 0, 0}, 35.0, glm::radians(30.0), glm::radians(60.0), 2.0});  // the whole cube in view
  return camera;
}

// The grid's fixtures, built once on first use and kept for the run (outside every timing): a scene and its
// Embree BVH per K; a camera, the plain loop's map (when affordable) and Embree's ray table per (K, side).
struct SceneFixture {
  Scene3D scene;
  PackedScene3D packed;  // raycam's compact copy, made once as Embree's BVH is (its cost: the "packing" variant)
#ifdef RAYCAM_HAVE_EMBREE
  std::unique_ptr<bench::EmbreeCaster> embree;
#endif
};
struct ImageFixture {
  Camera3D camera{1, 1};
  bool plain_affordable = false;
  ColourMap plain;
  std::vector<Ray3D> ray_table;
};

class SceneGrid {
 public:
  SceneFixture& scene(int count) {
    auto found = scenes_.find(count);
    if (found != scenes_.end()) return *found->second;
    auto fixture = std::make_unique<SceneFixture>();
    fixture->scene = testkit::random_spheres(count);
    fixture->packed.pack(fixture->scene);
#ifdef RAYCAM_HAVE_EMBREE
    fixture->embree = std::make_unique<bench::EmbreeCaster>(fixture->scene);
#endif
    return *scenes_.emplace(count, std::move(fixture)).first->second;
  }
  ImageFixture& image(int count, int side) {
    const auto key = std::make_pair(count, side);
    auto found = images_.find(key);
    if (found != images_.end()) return *found->second;
    auto fixture = std::make_unique<ImageFixture>();
    fixture->camera = bench_camera(side, side);
    fixture->plain_affordable = double(side) * side * std::max(count, 1) <= kMaxPlainTests;
    if (fixture->plain_affordable) {
      CastOptions options;
      options.method = CastMethod::plain;
      cast_primary_rays(fixture->camera, scene(count).scene, fixture->plain, options);
    }
    return *images_.emplace(key, std::move(fixture)).first->second;
  }
  std::vector<Ray3D>& ray_table(int count, int side) {
    ImageFixture& f = image(count, side);
    if (f.ray_table.empty()) {
      f.ray_table.resize(std::size_t(side) * side);
      for (int row = 0; row < side; ++row)
        f.camera.primary_rays(row, 0, side - 1, &f.ray_table[std::size_t(row) * side]);
    }
    return f.ray_table;
  }

 private:
  std::map<int, std::unique_ptr<SceneFixture>> scenes_;
  std::map<std::pair<int, int>, std::unique_ptr<ImageFixture>> images_;
};

// Ids checked against the plain loop: every pixel when its map is at hand, else sampled pixels recomputed
// with nearest_hit over every sphere (the plain loop, pixel by pixel).
struct IdCheck {
  long long differing = 0, checked = 0;
};
IdCheck check_ids(const ImageFixture& image, const Scene3D& scene, const ColourMap& map) {
  IdCheck check;
  if (image.plain_affordable) {
    for (std::size_t i = 0; i < map.ids.size(); ++i) check.differing += map.ids[i] != image.plain.ids[i];
    check.checked = static_cast<long long>(map.ids.size());
    return check;
  }
  std::mt19937 engine(7);
  const Camera3D& camera = image.camera;
  for (int s = 0; s < kSampledPixels; ++s) {
    const int row = int(engine() % unsigned(camera.rows())), column = int(engine() % unsigned(camera.columns()));
    const Hit hit = nearest_hit(scene.spheres, camera.primary_ray(row, column), IntersectFormula::stable);
    check.differing += hit.id != map.id_at(row, column);
    ++check.checked;
  }
  return check;
}

// ---- variants
// ---------------------------------------------------------------------------------------------- "rays only":
// the same rays generated and the map written, with no object tested.
void rays_only(const Camera3D& camera, Rgb8 background, int threads, ColourMap& map) {
  map.resize(camera.columns(), camera.rows());
  thread_local std::vector<std::vector<Ray3D>> calling_thread_rays;  // reused, as the casters' scratch
  std::vector<std::vector<Ray3D>>& rays = calling_thread_rays;       // the pool's workers see this thread's
  rays.resize(static_cast<std::size_t>(threads));
  for (std::vector<Ray3D>& r : rays) r.resize(static_cast<std::size_t>(camera.columns()));
  detail::parallel_items(camera.rows(), threads, [&](int worker, int row) {  // one row per item
    Ray3D* row_rays = rays[std::size_t(worker)].data();
    camera.primary_rays(row, 0, camera.columns() - 1, row_rays);
    for (int column = 0; column < camera.columns(); ++column) {
      const std::size_t p = map.index(row, column);
      map.ids[p] = row_rays[column].direction.x > 2.0 ? 0 : -1;  // never: keeps the rays alive
      map.colours[p] = background;
    }
  });
}

enum class Kind { floor, raycam, embree };
struct Variant {
  std::string name;
  Kind kind;
};

std::vector<Variant> variants() {
  std::vector<Variant> v = {
      {"fill only", Kind::floor}, {"rays only", Kind::floor}, {"projection", Kind::floor}, {"packing", Kind::floor}};
  for (CastMethod method : {CastMethod::plain, CastMethod::culled, CastMethod::footprint, CastMethod::binned,
                            CastMethod::automatic})
    v.push_back({cast_method_name(method), Kind::raycam});
#ifdef RAYCAM_HAVE_EMBREE
  for (const char* name : {"embree packet1", "embree packet16", "embree p16 ray table"})
    v.push_back({name, Kind::embree});
#endif
  return v;
}

// ---- registration
// ------------------------------------------------------------------------------------------
struct Case {
  int count = 0, side = 0, threads = 0;
  Variant variant;
  IdCheck ids;
};

// What the reporter keeps of each benchmark: the median and the spread of its repetitions.
struct Result {
  double median_ms = 0, stddev_ms = 0, mrays = 0, tests_per_pixel = 0;
};

struct Run {
  SpeedOptions options;
  SceneGrid grid;
  std::vector<std::unique_ptr<Case>> cases;  // stable addresses: the benchmarks point at them
  std::map<std::string, Result> results;     // by benchmark name
};

std::string case_name(const Case& c) {
  return "speed/K:" + std::to_string(c.count) + "/side:" + std::to_string(c.side) +
         "/threads:" + std::to_string(c.threads) + "/" + c.variant.name;
}

benchmark::internal::Benchmark* configure(benchmark::internal::Benchmark* b, const SpeedOptions& o) {
  return b->Repetitions(o.repeats)
      ->ReportAggregatesOnly(true)
      ->UseRealTime()            // the work runs on our own threads: wall time is what the user waits
      ->MeasureProcessCPUTime()  // and the CPU time of every thread, steadier on a shared machine
      ->Unit(benchmark::kMillisecond)
      ->MinTime(o.min_seconds);
}

void run_case(benchmark::State& state, Run& run, Case& c) {
  SceneFixture& fixture = run.grid.scene(c.count);
  ImageFixture& image = run.grid.image(c.count, c.side);
  const Camera3D& camera = image.camera;
  const Scene3D& scene = fixture.scene;
  const double pixels = double(c.side) * c.side;
  ColourMap map;
  CastStats stats;
  CastOptions options;
  options.threads = c.threads;
  std::function<void()> cast;
  const std::string& name = c.variant.name;
  static const PackedScene3D no_objects;
  PackedScene3D packed_copy;
  if (name == "fill only")
    cast = [&] { cast_primary_rays(camera, no_objects, map, options, &stats); };
  else if (name == "rays only")
    cast = [&] { rays_only(camera, scene.background, c.threads, map); };
  else if (name == "projection")
    cast = [&] { benchmark::DoNotOptimize(project_spheres_only(camera, fixture.packed, options)); };
  else if (name == "packing")  // once per scene change, not per frame
    cast = [&] { packed_copy.pack(scene); };
#ifdef RAYCAM_HAVE_EMBREE
  else if (name == "embree packet1")
    cast = [&] { fixture.embree->cast(camera, 1, c.threads, map); };
  else if (name == "embree packet16")
    cast = [&] { fixture.embree->cast(camera, 16, c.threads, map); };
  else if (name == "embree p16 ray table") {
    const std::vector<Ray3D>* table = &run.grid.ray_table(c.count, c.side);
    cast = [&, table] { fixture.embree->cast(camera, 16, c.threads, map, table); };
  }
#endif
  else {
    options.method = cast_method_named(name).value();
    cast = [&] { cast_primary_rays(camera, fixture.packed, map, options, &stats); };
  }
  cast();  // warm-up: first touch of the map and of the caster's reused memory
  for (auto _ : state) cast();
  state.counters["Mrays/s"] =
      benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tests/px"] = double(stats.intersection_tests) / pixels;
  // Every repetition is checked when the plain map is at hand; sampled checks (about a second at K = 10⁵)
  // once.
  if (c.variant.kind != Kind::floor && (image.plain_affordable || c.ids.checked == 0)) {
    const IdCheck check = check_ids(image, scene, map);
    if (c.variant.kind == Kind::raycam) c.ids.differing = std::max(c.ids.differing, check.differing);
    c.ids.checked = check.checked;
  }
}

void register_grid(Run& run) {
  const SpeedOptions& o = run.options;
  for (int count : o.counts)
    for (int side : o.sides)
      for (int threads : o.threads)
        for (const Variant& variant : variants()) {
          const bool quadratic = variant.name == "plain" || variant.name == "culled";
          if (quadratic && double(side) * side * std::max(count, 1) > kMaxPlainTests) continue;
          run.cases.push_back(std::make_unique<Case>(Case{count, side, threads, variant, {}}));
          Case* c = run.cases.back().get();
          configure(
              benchmark::RegisterBenchmark(case_name(*c).c_str(),
                                           [&run, c](benchmark::State& state) { run_case(state, run, *c); }),
              o);
        }
}

// How cost grows with the pixel count (K = 1000, automatic, the most threads), and 2D bars (demo scene).
void register_extras(Run& run) {
  const SpeedOptions& o = run.options;
  const int threads = o.threads.back();
  for (int side : {128, 256, 512, 1024, 2048})
    configure(benchmark::RegisterBenchmark(("scaling/side:" + std::to_string(side)).c_str(),
                                           [&run, side, threads](benchmark::State& state) {
                                             const PackedScene3D& scene = run.grid.scene(1000).packed;
                                             const Camera3D camera = bench_camera(side, side);
                                             ColourMap map;
                                             CastOptions options;
                                             options.threads = threads;
                                             for (auto _ : state)
                                               cast_primary_rays(camera, scene, map, options);
                                           }),
              o);
  for (int n = 16; n <= 4096; n *= 4)
    for (const char* method : {"plain", "automatic"})
      configure(benchmark::RegisterBenchmark(("bar2d/n:" + std::to_string(n) + "/" + method).c_str(),
                                             [n, method](benchmark::State& state) {
                                               static const Scene2D scene = demo_scene_2d();
                                               const Camera2D camera(n);
                                               ColourMap map;
                                               CastOptions options;
                                               options.method = cast_method_named(method).value();
                                               CastStats stats;
                                               for (auto _ : state)
                                                 cast_primary_rays(camera, scene, map, options, &stats);
                                               state.counters["tests"] = double(stats.intersection_tests);
                                             }),
                o)
          ->Unit(benchmark::kMicrosecond);
}

// ---- reporting
// --------------------------------------------------------------------------------------------- Google
// Benchmark's console table as usual, and the medians kept for raycam's own tables.
class KeepingReporter : public benchmark::ConsoleReporter {
 public:
  explicit KeepingReporter(std::map<std::string, Result>& results)
      : ConsoleReporter(OO_Tabular), results_(results) {}  // counters as columns, no colour codes
  void ReportRuns(const std::vector<benchmark::BenchmarkReporter::Run>& runs) override {
    for (const auto& r : runs) {
      // One repetition gives no aggregates: its run is the median (--repeats 1 used to report 0 ms).
      const bool single = r.run_type == benchmark::BenchmarkReporter::Run::RT_Iteration && r.repetitions <= 1;
      if (r.run_type != benchmark::BenchmarkReporter::Run::RT_Aggregate && !single) continue;
      Result& result = results_[r.run_name.function_name];
      const double ms = r.GetAdjustedRealTime() * (r.time_unit == benchmark::kMicrosecond ? 1e-3 : 1.0);
      if (single || r.aggregate_name == "median") {
        result.median_ms = ms;
        const auto counter = [&](const char* name) {
          const auto found = r.counters.find(name);
          return found == r.counters.end() ? 0.0 : double(found->second);
        };
        result.mrays = counter("Mrays/s");
        result.tests_per_pixel = counter("tests/px");
      } else if (r.aggregate_name == "stddev") {
        result.stddev_ms = ms;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

 private:
  std::map<std::string, Result>& results_;
};

const Result* find(const Run& run, int count, int side, int threads, const std::string& variant) {
  const auto found = run.results.find(case_name(Case{count, side, threads, {variant, Kind::raycam}, {}}));
  return found == run.results.end() ? nullptr : &found->second;
}

void print_summary(const Run& run) {
  const SpeedOptions& o = run.options;
  std::printf(
      "\nraycam (automatic) against Embree's best variant and the floor, medians of %d repetitions in this "
      "run (spread: the largest stddev/median of the row's variants):\n\n"
      "| K | side | threads | raycam ms | Mrays/s | Embree best ms | speed-up | fill only ms | rays only ms "
      "| projection ms | packing ms | raycam / fill | spread |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      o.repeats);
  for (int count : o.counts)
    for (int side : o.sides)
      for (int threads : o.threads) {
        const Result* raycam = find(run, count, side, threads, "automatic");
        if (!raycam) continue;
        double embree = 0.0, spread = raycam->stddev_ms / raycam->median_ms;
        for (const char* e : {"embree packet1", "embree packet16", "embree p16 ray table"})
          if (const Result* r = find(run, count, side, threads, e)) {
            embree = embree == 0.0 ? r->median_ms : std::min(embree, r->median_ms);
            spread = std::max(spread, r->stddev_ms / r->median_ms);
          }
        const Result* fill = find(run, count, side, threads, "fill only");
        const Result* rays = find(run, count, side, threads, "rays only");
        const Result* projection = find(run, count, side, threads, "projection");
        const Result* packing = find(run, count, side, threads, "packing");
        std::printf("| %d | %d | %d | %.3f | %.0f | ", count, side, threads, raycam->median_ms,
                    raycam->mrays);
        if (embree > 0)
          std::printf("%.3f | %.1fx | ", embree, embree / raycam->median_ms);
        else
          std::printf("- | - | ");
        std::printf("%.3f | %.3f | %.3f | %.3f | %.1fx | %.0f%% |\n", fill ? fill->median_ms : 0.0,
                    rays ? rays->median_ms : 0.0, projection ? projection->median_ms : 0.0,
                    packing ? packing->median_ms : 0.0, fill ? raycam->median_ms / fill->median_ms : 0.0,
                    100.0 * spread);
      }
}

void print_extras(const Run& run) {
  std::printf(
      "\nCost against the pixel count (K = 1000, automatic, %d threads):\n\n"
      "| side | pixels | median ms | ns per pixel |\n|---|---|---|---|\n",
      run.options.threads.back());
  for (int side : {128, 256, 512, 1024, 2048}) {
    const auto found = run.results.find("scaling/side:" + std::to_string(side));
    if (found == run.results.end()) continue;
    std::printf("| %d | %d | %.3f | %.2f |\n", side, side * side, found->second.median_ms,
                found->second.median_ms * 1e6 / (double(side) * side));
  }
  std::printf(
      "\n2D bars, demo scene (3 circles), one thread:\n\n| n | plain us | automatic us |\n|---|---|---|\n");
  for (int n = 16; n <= 4096; n *= 4) {
    const auto plain = run.results.find("bar2d/n:" + std::to_string(n) + "/plain");
    const auto fast = run.results.find("bar2d/n:" + std::to_string(n) + "/automatic");
    if (plain == run.results.end() || fast == run.results.end()) continue;
    std::printf("| %d | %.1f | %.1f |\n", n, plain->second.median_ms * 1e3, fast->second.median_ms * 1e3);
  }
}

void write_csv(const Run& run) {
  if (run.options.csv_path.empty()) return;
  std::ofstream csv(run.options.csv_path);
  if (!csv) throw std::runtime_error(run.options.csv_path + ": cannot write the CSV");
  csv << "K,side,threads,variant,median_ms,stddev_ms,mrays_per_s,tests_per_pixel,ids_differing,ids_checked\n";
  for (const auto& c : run.cases) {
    const auto found = run.results.find(case_name(*c));
    if (found == run.results.end()) continue;
    const Result& r = found->second;
    csv << c->count << ',' << c->side << ',' << c->threads << ",\"" << c->variant.name << "\"," << r.median_ms
        << ',' << r.stddev_ms << ',' << r.mrays << ',' << r.tests_per_pixel << ',' << c->ids.differing << ','
        << c->ids.checked << '\n';
  }
}

void initialise_benchmark(const SpeedOptions& o) {
  static std::vector<std::string> storage;
  storage = {"raycam-cli bench speed"};
  storage.insert(storage.end(), o.benchmark_flags.begin(), o.benchmark_flags.end());
  static std::vector<char*> argv;
  argv.clear();
  for (std::string& s : storage) argv.push_back(s.data());
  int argc = int(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data()))
    throw std::invalid_argument("unknown Google Benchmark flag (see raycam-cli bench speed --help)");
}

// ---- a scene file
// ------------------------------------------------------------------------------------------
int run_scene(const SpeedOptions& o) {
  ViewFlags flags;
  flags.scene_path = o.scene_path;
  flags.camera.size = o.scene_size;
  const ViewSetup setup = make_view_setup(flags);  // the file's camera preset, at --size
  const int threads = o.threads.back();
  const Camera2D& camera2d = setup.camera2d;
  const Camera3D& camera3d = setup.camera3d;
  if (setup.dimension == 2) validate(setup.file.scene2d);
  else validate(setup.file.scene3d);
  const double pixels =
      setup.dimension == 2 ? double(camera2d.pixel_count()) : double(camera3d.columns()) * camera3d.rows();
  const std::size_t objects =
      setup.dimension == 2 ? setup.file.scene2d.circles.size() : setup.file.scene3d.spheres.size();
  const bool plain_affordable = pixels * double(objects) <= kMaxPlainTests;
  std::map<std::string, Result> results;
  CastStats stats;
  for (const char* method : {"automatic", "plain"}) {
    if (std::string(method) == "plain" && !plain_affordable) continue;
    configure(benchmark::RegisterBenchmark(
                  (std::string("scene/") + method).c_str(),
                  [&, method](benchmark::State& state) {
                    ColourMap map;
                    CastOptions options;
                    options.method = cast_method_named(method).value();
                    options.threads = threads;
                    for (auto _ : state) {
                      if (setup.dimension == 2)
                        cast_primary_rays(camera2d, setup.file.scene2d, map, options, &stats);
                      else
                        cast_primary_rays(camera3d, setup.file.scene3d, map, options, &stats);
                    }
                    state.counters["Mrays/s"] =
                        benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
                  }),
              o);
  }
  initialise_benchmark(o);
  KeepingReporter reporter(results);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  const Result& fast = results["scene/automatic"];
  std::printf("%s: %dD, %.0f pixels, %d threads: automatic %.3f ms median (%.1f Mrays/s)",
              o.scene_path.c_str(), setup.dimension, pixels, threads, fast.median_ms, fast.mrays);
  if (results.count("scene/plain"))
    std::printf("; plain loop %.3f ms (%.1fx)", results["scene/plain"].median_ms,
                results["scene/plain"].median_ms / fast.median_ms);
  std::printf("\n");
  return 0;
}
}  // namespace

// ---- entry point
// -------------------------------------------------------------------------------------------
int run_bench_speed(const Args& args) {
  Run run;
  if (const std::optional<int> exit_now = parse_options(args, run.options)) return *exit_now;
  if (!run.options.scene_path.empty()) return run_scene(run.options);
  const int hardware = int(std::thread::hardware_concurrency());
  std::printf("raycam bench speed: %d hardware threads, Google Benchmark, %d repetitions a variant", hardware,
              run.options.repeats);
#ifdef RAYCAM_HAVE_EMBREE
  std::printf(", %s\n\n", bench::EmbreeCaster(Scene3D{}).isa_note().c_str());
#else
  std::printf(", Embree not in this build (install libembree-dev and reconfigure to compare against it)\n\n");
#endif
  register_grid(run);
  if (run.options.extras) register_extras(run);
  initialise_benchmark(run.options);
  KeepingReporter reporter(run.results);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  print_summary(run);
  if (run.options.extras) print_extras(run);
  std::printf("\nPeak resident memory of this run: %.1f MB\n", double(resident_kb("VmHWM:")) / 1024.0);
  write_csv(run);
  long long differing = 0, checked = 0;
  for (const auto& c : run.cases) {
    if (c->variant.kind != Kind::raycam) continue;
    differing += c->ids.differing;
    checked += c->ids.checked;
  }
  std::printf("ids: %lld of %lld checked pixels differ from the plain loop\n", differing, checked);
  if (differing > 0) {
    std::printf("FAILED: raycam's casters disagree with the plain loop on %lld pixels\n", differing);
    return 1;
  }
  return 0;
}

}  // namespace raycam::cli
