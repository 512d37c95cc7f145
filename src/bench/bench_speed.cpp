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
#include <regex>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "bench/bench_commands.h"
#include "flags/flag_values.h"
#include "raycam/process_memory.h"
#include "check/progress_line.h"
#include "raycam/parallel.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/speed_families.h"
#include "raycam/standard_scenes.h"
#include "raycam/view_setup.h"
#include "session/view.h"
#include "flags/view_options.h"
#ifdef RAYCAM_HAVE_EMBREE
#include "bench/embree_caster.h"
#endif

namespace raycam::bench {

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
  std::vector<std::string> families = testkit::speed_family_names();  // the families' table, at the most threads
  std::vector<int> family_counts{1000, 10000, 100000};
  std::string write_family, write_path;  // --write-family NAME --to FILE: its scene file instead of a run
  int repeats = 7;
  double min_seconds = 0.1;  // per repetition: Google Benchmark runs as many iterations as fit
  bool extras = true;        // scaling with the pixel count, 2D bars
  std::string csv_path, scene_path;
  std::optional<std::vector<int>> scene_size;  // --size, else the scene file's
  std::vector<std::string> benchmark_flags;  // --benchmark_* passed through to Google Benchmark
  bool quiet = false;                        // no progress on stderr
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
  const std::vector<std::string> family_names = testkit::speed_family_names();
  // --quick first: CLI11 runs the callbacks in this order, so `--quick --repeats 1` keeps the 1.
  app.add_flag_callback("--quick", [&o] {
    o.counts = {1, 100, 10000};
    o.sides = {256};
    o.repeats = 3;
    o.min_seconds = 0.01;
    o.extras = false;
    o.family_counts = {1000};
  }, "K = 1,100,10000 at 256 px (families: K = 1000), 3 short repetitions, no extras (a smoke test)");
  const auto list = [&app](const char* name, const char* help, int lo, int hi, std::vector<int>& store) {
    flags::add_checked_list<int>(app, name, "LIST", help, flags::integer_in(lo, hi),
                                 [&store](std::vector<int> values) { store = std::move(values); });
  };
  list("--counts", "sphere counts K (default 1,10,100,1000,10000,100000)", 0, 2000000, o.counts);
  list("--sizes", "image sides (default 256,1024)", 1, 8192, o.sides);
  list("--threads", "thread counts (default 1,2)", 1, 256, o.threads);
  list("--family-counts", "sphere counts K of the families' table (default 1000,10000,100000)", 0, 2000000,
       o.family_counts);
  flags::add_checked_list<int>(app, "--families", "LIST", "scene families of the families' table (default all)",
                               flags::one_of(family_names), [&o, family_names](std::vector<int> picked) {
                                 o.families.clear();
                                 for (int i : picked) o.families.push_back(family_names[std::size_t(i)]);
                               });
  flags::add_checked_option<int>(app, "--write-family", "NAME",
                                 "write that family's scene (K: the first of --family-counts) with its camera "
                                 "to --to FILE, and stop (to time it in the window: shot --soak)",
                                 flags::one_of(family_names),
                                 [&o, family_names](int i) { o.write_family = family_names[std::size_t(i)]; });
  flags::add_checked_option<std::string>(app, "--to", "FILE", "with --write-family: the scene file to write",
                                         flags::file_name(), [&o](std::string path) { o.write_path = std::move(path); });
  flags::add_checked_option<int>(app, "--repeats", "R", "repetitions per variant, the median is reported (default 7)",
                                 flags::integer_in(1, 1000), [&o](int r) { o.repeats = r; });
  flags::add_checked_option<std::string>(app, "--csv", "FILE", "also write every median as CSV", flags::file_name(),
                                         [&o](std::string path) { o.csv_path = std::move(path); });
  flags::add_checked_option<std::string>(app, "--scene", "FILE",
                                         "time a scene file's camera preset instead, at --size",
                                         flags::file_name(), [&o](std::string path) { o.scene_path = std::move(path); });
  app.add_flag("--quiet", o.quiet, "no progress on stderr (by default each benchmark is announced as it starts, "
               "with the time left)");
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
  if (o.write_family.empty() != o.write_path.empty()) {
    std::fprintf(stderr, "raycam-cli bench speed: error: --write-family and --to go together\n");
    return 2;
  }
  return std::nullopt;
}

// ---- fixtures
// ----------------------------------------------------------------------------------------------
// The cube family's camera: the grid's scene and the scaling extras.
Camera3D bench_camera(int columns, int rows) {
  Camera3D camera(columns, rows);
  camera.set_orbit(testkit::speed_family("cube", 0).orbit);  // the whole cube in view
  return camera;
}

// The grid's fixtures, built once on first use and kept for the run (outside every timing): a scene and its
// Embree BVH per (family, K); a camera, the reference ids and Embree's ray table per (family, K, side).
struct SceneFixture {
  testkit::SpeedFamily family;
  PackedScene3D packed;  // raycam's compact copy, made once as Embree's BVH is (its cost: the "packing" variant)
#ifdef RAYCAM_HAVE_EMBREE
  std::unique_ptr<bench::EmbreeCaster> embree;
#endif
};
// The reference ids: the plain loop's map when affordable; else the object-order caster's (every box test
// run, nothing skipped, itself checked against the plain loop pixel for pixel by the test suite), with the
// plain loop on sampled pixels besides.
struct ImageFixture {
  Camera3D camera{1, 1};
  bool plain_affordable = false;
  ColourMap reference;
  std::vector<Ray3D> ray_table;
};

class SceneGrid {
 public:
  SceneFixture& scene(const std::string& family, int count) {
    const auto key = std::make_pair(family, count);
    auto found = scenes_.find(key);
    if (found != scenes_.end()) return *found->second;
    auto fixture = std::make_unique<SceneFixture>();
    fixture->family = testkit::speed_family(family, count);
    fixture->packed.pack(fixture->family.scene);
#ifdef RAYCAM_HAVE_EMBREE
    fixture->embree = std::make_unique<bench::EmbreeCaster>(fixture->family.scene);
#endif
    return *scenes_.emplace(key, std::move(fixture)).first->second;
  }
  ImageFixture& image(const std::string& family, int count, int side) {
    const auto key = std::make_tuple(family, count, side);
    auto found = images_.find(key);
    if (found != images_.end()) return *found->second;
    auto fixture = std::make_unique<ImageFixture>();
    SceneFixture& scene_fixture = scene(family, count);
    fixture->camera = Camera3D(side, side);
    fixture->camera.set_orbit(scene_fixture.family.orbit);
    fixture->plain_affordable = double(side) * side * std::max(count, 1) <= kMaxPlainTests;
    CastOptions options;
    options.method = fixture->plain_affordable ? CastMethod::plain : CastMethod::automatic;
    options.near_to_far = false;
    cast_primary_rays(fixture->camera, scene_fixture.packed, fixture->reference, options);
    return *images_.emplace(key, std::move(fixture)).first->second;
  }
  std::vector<Ray3D>& ray_table(const std::string& family, int count, int side) {
    ImageFixture& f = image(family, count, side);
    if (f.ray_table.empty()) {
      f.ray_table.resize(std::size_t(side) * side);
      for (int row = 0; row < side; ++row)
        f.camera.primary_rays(row, 0, side - 1, &f.ray_table[std::size_t(row) * side]);
    }
    return f.ray_table;
  }

 private:
  std::map<std::pair<std::string, int>, std::unique_ptr<SceneFixture>> scenes_;
  std::map<std::tuple<std::string, int, int>, std::unique_ptr<ImageFixture>> images_;
};

// Ids checked against the reference map, every pixel; when that is not the plain loop's, also sampled
// pixels recomputed with nearest_hit over every sphere (the plain loop, pixel by pixel), once.
struct IdCheck {
  long long differing = 0, checked = 0;
};
IdCheck check_ids(const ImageFixture& image, const Scene3D& scene, const ColourMap& map, bool sample_plain) {
  IdCheck check;
  for (std::size_t i = 0; i < map.ids.size(); ++i) check.differing += map.ids[i] != image.reference.ids[i];
  check.checked = static_cast<long long>(map.ids.size());
  if (image.plain_affordable || !sample_plain) return check;
  std::mt19937 engine(7);
  const Camera3D& camera = image.camera;
  // About 10⁸ tests: 4096 pixels up to K = 24000, fewer beyond (1000 at K = 10⁵).
  const int samples = int(std::clamp(1e8 / std::max(1.0, double(scene.spheres.size())), 256.0, double(kSampledPixels)));
  for (int s = 0; s < samples; ++s) {
    const int row = int(engine() % unsigned(camera.rows())), column = int(engine() % unsigned(camera.columns()));
    const Hit hit = nearest_hit(scene.spheres, camera.primary_ray(row, column), IntersectFormula::stable);
    check.differing += hit.id != map.id_at(row, column);
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

// The automatic caster as it was before the near-to-far order: the before/after in one run.
const char* const kObjectOrder = "object order";
// The automatic caster without the float culling pass (CastOptions::float_culling): what that pass saves.
const char* const kDoubleCulling = "double culling";

std::vector<Variant> variants() {
  std::vector<Variant> v = {
      {"fill only", Kind::floor}, {"rays only", Kind::floor}, {"projection", Kind::floor}, {"packing", Kind::floor}};
  for (CastMethod method : {CastMethod::plain, CastMethod::culled, CastMethod::footprint, CastMethod::binned,
                            CastMethod::automatic})
    v.push_back({cast_method_name(method), Kind::raycam});
  v.push_back({kObjectOrder, Kind::raycam});
  v.push_back({kDoubleCulling, Kind::raycam});
#ifdef RAYCAM_HAVE_EMBREE
  for (const char* name : {"embree packet1", "embree packet16", "embree p16 ray table"})
    v.push_back({name, Kind::embree});
#endif
  return v;
}

// ---- registration
// ------------------------------------------------------------------------------------------
struct Case {
  std::string family;
  int count = 0, side = 0, threads = 0;
  Variant variant;
  IdCheck ids;
};

// What the reporter keeps of each benchmark: the median and the spread of its repetitions.
struct Result {
  double median_ms = 0, stddev_ms = 0, mrays = 0, tests_per_pixel = 0, box_tests_per_pixel = 0;
};

benchmark::internal::Benchmark* configure(benchmark::internal::Benchmark* b, const SpeedOptions& o) {
  return b->Repetitions(o.repeats)
      ->ReportAggregatesOnly(true)
      ->UseRealTime()            // the work runs on our own threads: wall time is what the user waits
      ->MeasureProcessCPUTime()  // and the CPU time of every thread, steadier on a shared machine
      ->Unit(benchmark::kMillisecond)
      ->MinTime(o.min_seconds);
}

// The benchmarks in the order they run, each announced on stderr as it starts (check::ProgressLine: in
// place on a terminal, a line each in a log, nothing with --quiet), with the time left at the pace so far.
class Steps {
 public:
  // Registers `body` as benchmark `name`, configured as every variant; `work` is its share of the estimate.
  benchmark::internal::Benchmark* add(const std::string& name, std::function<void(benchmark::State&)> body,
                                      const SpeedOptions& o, std::size_t work = kWorkPerBenchmark) {
    steps_.push_back({name, work});
    return configure(benchmark::RegisterBenchmark(name.c_str(),
                                                  [this, name, body, work](benchmark::State& state) {
                                                    // Called for each trial and repetition: a new name is a new step.
                                                    if (line_ && name != current_) line_->start(current_ = name, work);
                                                    body(state);
                                                  }),
                     o);
  }
  // A grid case's work: a benchmark takes its minimum time whatever K, and its fixtures (the reference ids,
  // the sampled plain loop) grow with K. One run of 103 benchmarks (K = 1, 10⁴, 10⁵ at 256² and 1024², two
  // threads, 3 repetitions): 0.45 s a benchmark at K = 1, 0.62–0.72 s at 10⁴, 0.81–0.88 s at 10⁵; counted
  // alike, the first estimate said 44 s of a 67 s run.
  static std::size_t work_at(int count) {
    return kWorkPerBenchmark + std::size_t(std::lround(2.0 * std::log10(std::max(count, 1))));
  }
  // Before the run: the line, its totals those of the benchmarks --benchmark_filter keeps.
  void begin(const SpeedOptions& o) {
    std::size_t steps = 0, work = 0;
    for (const Step& step : steps_)
      if (kept_by_filter(step.name, o.benchmark_flags)) {
        ++steps;
        work += step.work;
      }
    line_ = std::make_unique<check::ProgressLine>("bench speed", unknown_filter_ ? 0 : steps, o.quiet, stderr, work);
  }
  check::ProgressLine* line() const { return line_.get(); }

 private:
  static constexpr std::size_t kWorkPerBenchmark = 10;
  struct Step {
    std::string name;
    std::size_t work;
  };
  // Google Benchmark's own rule: the last filter, "" or "all" for every benchmark, a leading '-' negates. A
  // pattern std::regex does not read as Google Benchmark does leaves the total unknown.
  bool kept_by_filter(const std::string& name, const std::vector<std::string>& benchmark_flags) {
    const std::string flag = "--benchmark_filter=";
    std::string filter;
    for (const std::string& f : benchmark_flags)
      if (f.rfind(flag, 0) == 0) filter = f.substr(flag.size());
    if (filter.empty() || filter == "all") return true;
    const bool negated = filter[0] == '-';
    try {
      return std::regex_search(name, std::regex(negated ? filter.substr(1) : filter, std::regex::extended)) != negated;
    } catch (const std::regex_error&) {
      unknown_filter_ = true;
      return false;
    }
  }
  std::vector<Step> steps_;
  bool unknown_filter_ = false;
  std::unique_ptr<check::ProgressLine> line_;
  std::string current_;
};

struct Run {
  SpeedOptions options;
  SceneGrid grid;
  std::vector<std::unique_ptr<Case>> cases;  // stable addresses: the benchmarks point at them
  std::map<std::string, Result> results;     // by benchmark name
  Steps steps;
};

std::string case_name(const Case& c) {
  return "speed/" + c.family + "/K:" + std::to_string(c.count) + "/side:" + std::to_string(c.side) +
         "/threads:" + std::to_string(c.threads) + "/" + c.variant.name;
}

void run_case(benchmark::State& state, Run& run, Case& c) {
  SceneFixture& fixture = run.grid.scene(c.family, c.count);
  ImageFixture& image = run.grid.image(c.family, c.count, c.side);
  const Camera3D& camera = image.camera;
  const Scene3D& scene = fixture.family.scene;
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
    const std::vector<Ray3D>* table = &run.grid.ray_table(c.family, c.count, c.side);
    cast = [&, table] { fixture.embree->cast(camera, 16, c.threads, map, table); };
  }
#endif
  else {
    const bool automatic = name == kObjectOrder || name == kDoubleCulling;
    options.method = automatic ? CastMethod::automatic : cast_method_named(name).value();
    options.near_to_far = name != kObjectOrder;
    options.float_culling = name != kDoubleCulling;
    cast = [&] { cast_primary_rays(camera, fixture.packed, map, options, &stats); };
  }
  cast();  // warm-up: first touch of the map and of the caster's reused memory
  for (auto _ : state) cast();
  state.counters["Mrays/s"] =
      benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tests/px"] = double(stats.intersection_tests) / pixels;
  state.counters["boxes/px"] = double(stats.box_tests) / pixels;
  // Every repetition is checked against the reference map; the sampled plain loop (about a second at
  // K = 10⁵) once.
  if (c.variant.kind != Kind::floor) {
    const IdCheck check = check_ids(image, scene, map, c.ids.checked == 0);
    if (c.variant.kind == Kind::raycam) c.ids.differing = std::max(c.ids.differing, check.differing);
    c.ids.checked = check.checked;
  }
}

void register_case(Run& run, const Case& c) {
  const std::string name = case_name(c);
  for (const auto& existing : run.cases)
    if (case_name(*existing) == name) return;  // the cube's rows of the families' table are the grid's
  run.cases.push_back(std::make_unique<Case>(c));
  Case* kept = run.cases.back().get();
  run.steps.add(name, [&run, kept](benchmark::State& state) { run_case(state, run, *kept); }, run.options,
                Steps::work_at(c.count));
}

void register_grid(Run& run) {
  const SpeedOptions& o = run.options;
  for (int count : o.counts)
    for (int side : o.sides)
      for (int threads : o.threads)
        for (const Variant& variant : variants()) {
          const bool quadratic = variant.name == "plain" || variant.name == "culled";
          if (quadratic && double(side) * side * std::max(count, 1) > kMaxPlainTests) continue;
          register_case(run, Case{"cube", count, side, threads, variant, {}});
        }
  // The families' table: the automatic caster before and after, Embree and the floor, at the most threads.
  const std::vector<Variant> all = variants();
  for (const std::string& family : o.families)
    for (int count : o.family_counts)
      for (int side : o.sides)
        for (const Variant& variant : all)
          if (variant.kind == Kind::embree ? variant.name != "embree p16 ray table"
                                           : variant.name == "automatic" || variant.name == kObjectOrder ||
                                                 variant.name == "fill only" || variant.name == "projection")
            register_case(run, Case{family, count, side, o.threads.back(), variant, {}});
}

// How cost grows with the pixel count (K = 1000, automatic, the most threads), and 2D bars (demo scene).
void register_extras(Run& run) {
  const SpeedOptions& o = run.options;
  const int threads = o.threads.back();
  for (int side : {128, 256, 512, 1024, 2048})
    run.steps.add("scaling/side:" + std::to_string(side),
                  [&run, side, threads](benchmark::State& state) {
                    const PackedScene3D& scene = run.grid.scene("cube", 1000).packed;
                    const Camera3D camera = bench_camera(side, side);
                    ColourMap map;
                    CastOptions options;
                    options.threads = threads;
                    for (auto _ : state) cast_primary_rays(camera, scene, map, options);
                  },
                  o);
  for (int n = 16; n <= 4096; n *= 4)
    for (const char* method : {"plain", "automatic"})
      run.steps
          .add("bar2d/n:" + std::to_string(n) + "/" + method,
               [n, method](benchmark::State& state) {
                 static const Scene2D scene = demo_scene_2d();
                 const Camera2D camera(n);
                 ColourMap map;
                 CastOptions options;
                 options.method = cast_method_named(method).value();
                 CastStats stats;
                 for (auto _ : state) cast_primary_rays(camera, scene, map, options, &stats);
                 state.counters["tests"] = double(stats.intersection_tests);
               },
               o)
          ->Unit(benchmark::kMicrosecond);
}

// ---- reporting
// --------------------------------------------------------------------------------------------- Google
// Benchmark's console table as usual, and the medians kept for raycam's own tables.
class KeepingReporter : public benchmark::ConsoleReporter {
 public:
  KeepingReporter(std::map<std::string, Result>& results, const Steps& steps)
      : ConsoleReporter(OO_Tabular), results_(results), steps_(steps) {}  // counters as columns, no colour codes
  void ReportRuns(const std::vector<benchmark::BenchmarkReporter::Run>& runs) override {
    // The table's row on a line of its own when stdout and stderr share a terminal.
    if (check::ProgressLine* line = steps_.line()) line->clear();
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
        result.box_tests_per_pixel = counter("boxes/px");
      } else if (r.aggregate_name == "stddev") {
        result.stddev_ms = ms;
      }
    }
    ConsoleReporter::ReportRuns(runs);
    GetOutputStream().flush();
  }

 private:
  std::map<std::string, Result>& results_;
  const Steps& steps_;
};

const Result* find(const Run& run, const std::string& family, int count, int side, int threads, const std::string& variant) {
  const auto found = run.results.find(case_name(Case{family, count, side, threads, {variant, Kind::raycam}, {}}));
  return found == run.results.end() ? nullptr : &found->second;
}

// The best of Embree's variants for one case, 0 when Embree is not in this build.
double embree_best_ms(const Run& run, const std::string& family, int count, int side, int threads) {
  double best = 0.0;
  for (const char* e : {"embree packet1", "embree packet16", "embree p16 ray table"})
    if (const Result* r = find(run, family, count, side, threads, e))
      best = best == 0.0 ? r->median_ms : std::min(best, r->median_ms);
  return best;
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
        const Result* raycam = find(run, "cube", count, side, threads, "automatic");
        if (!raycam) continue;
        const double embree = embree_best_ms(run, "cube", count, side, threads);
        double spread = raycam->stddev_ms / raycam->median_ms;
        for (const char* e : {"embree packet1", "embree packet16", "embree p16 ray table"})
          if (const Result* r = find(run, "cube", count, side, threads, e))
            spread = std::max(spread, r->stddev_ms / r->median_ms);
        const Result* fill = find(run, "cube", count, side, threads, "fill only");
        const Result* rays = find(run, "cube", count, side, threads, "rays only");
        const Result* projection = find(run, "cube", count, side, threads, "projection");
        const Result* packing = find(run, "cube", count, side, threads, "packing");
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

// One row per family, K and side; then the worst family's speed-up against Embree per K and side, the
// goal's measure (≥ 10× at 1024², ≥ 5× at 256²).
void print_families(const Run& run) {
  const SpeedOptions& o = run.options;
  if (o.families.empty()) return;
  const int threads = o.threads.back();
  std::printf(
      "\nScene families, %d threads: raycam (automatic, near to far) against itself in object order (the caster "
      "before), Embree's best and the floor; tests/px are the intersection tests run per pixel, boxes/px the "
      "tests without skipping (the depth complexity of what overlaps):\n\n"
      "| family | K | side | raycam ms | object order ms | after/before | Embree best ms | speed-up | tests/px "
      "| boxes/px | fill only ms | projection ms |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      threads);
  std::map<std::pair<int, int>, std::pair<double, std::string>> worst;  // (K, side) -> speed-up, family
  for (const std::string& family : o.families) {
    for (int count : o.family_counts)
      for (int side : o.sides) {
        const Result* after = find(run, family, count, side, threads, "automatic");
        const Result* before = find(run, family, count, side, threads, kObjectOrder);
        if (!after || !before) continue;
        const double embree = embree_best_ms(run, family, count, side, threads);
        const Result* fill = find(run, family, count, side, threads, "fill only");
        const Result* projection = find(run, family, count, side, threads, "projection");
        std::printf("| %s | %d | %d | %.3f | %.3f | %.2f | ", family.c_str(), count, side, after->median_ms,
                    before->median_ms, after->median_ms / before->median_ms);
        if (embree > 0) {
          const double speed_up = embree / after->median_ms;
          std::printf("%.3f | %.1fx | ", embree, speed_up);
          auto& w = worst[{count, side}];
          if (w.second.empty() || speed_up < w.first) w = {speed_up, family};
        } else {
          std::printf("- | - | ");
        }
        std::printf("%.2f | %.2f | %.3f | %.3f |\n", after->tests_per_pixel, after->box_tests_per_pixel,
                    fill ? fill->median_ms : 0.0, projection ? projection->median_ms : 0.0);
      }
  }
  if (worst.empty()) return;
  std::printf("\nWorst family against Embree (goal: at least 10x at 1024 px, 5x at 256 px):\n\n"
              "| K | side | worst family | speed-up | goal |\n|---|---|---|---|---|\n");
  for (const auto& [key, value] : worst) {
    const double goal = key.second >= 1024 ? 10.0 : 5.0;
    std::printf("| %d | %d | %s | %.1fx | %s |\n", key.first, key.second, value.second.c_str(), value.first,
                value.first >= goal ? "met" : "NOT met");
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
  csv << "family,K,side,threads,variant,median_ms,stddev_ms,mrays_per_s,tests_per_pixel,ids_differing,ids_checked\n";
  for (const auto& c : run.cases) {
    const auto found = run.results.find(case_name(*c));
    if (found == run.results.end()) continue;
    const Result& r = found->second;
    csv << '"' << c->family << "\"," << c->count << ',' << c->side << ',' << c->threads << ",\"" << c->variant.name << "\"," << r.median_ms
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
  const session::View view = session::views_from_setup(setup).on_screen;  // the app's view of the scene
  session::validate(view);
  const double pixels = std::visit([](const auto& v) { return session::ray_count(v.camera); }, view);
  const std::size_t objects = std::visit([](const auto& v) { return objects_of(v.scene).size(); }, view);
  const bool plain_affordable = pixels * double(objects) <= kMaxPlainTests;
  // Packed once, as the app packs its scene once per scene (packing is not a frame's cost).
  PackedScene3D packed;
  session::pack_scene(view, packed);
  std::map<std::string, Result> results;
  CastStats stats;
  Steps steps;
  for (const char* method : {"automatic", kDoubleCulling, "plain"}) {
    if (std::string(method) == "plain" && !plain_affordable) continue;
    steps.add(std::string("scene/") + method,
              [&, method](benchmark::State& state) {
                ColourMap map;
                CastOptions options;
                options.method = cast_method_named(method).value_or(CastMethod::automatic);
                options.float_culling = method != std::string(kDoubleCulling);
                options.threads = threads;
                for (auto _ : state) session::cast_view(view, packed, map, options, &stats);
                state.counters["Mrays/s"] =
                    benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
              },
              o);
  }
  initialise_benchmark(o);
  steps.begin(o);
  KeepingReporter reporter(results, steps);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  steps.line()->finish();
  const Result& fast = results["scene/automatic"];
  std::printf("%s: %dD, %.0f pixels, %d threads: automatic %.3f ms median (%.1f Mrays/s)",
              o.scene_path.c_str(), session::dimension_of(view), pixels, threads, fast.median_ms, fast.mrays);
  const Result& double_only = results[std::string("scene/") + kDoubleCulling];
  std::printf("; without the float culling pass %.3f ms (%.2fx)", double_only.median_ms,
              double_only.median_ms / fast.median_ms);
  if (results.count("scene/plain"))
    std::printf("; plain loop %.3f ms (%.1fx)", results["scene/plain"].median_ms,
                results["scene/plain"].median_ms / fast.median_ms);
  std::printf("\n");
  return 0;
}

// A family as a scene file, its camera as the file's preset (angles in degrees, as files take them).
int write_family_scene(const SpeedOptions& o) {
  const int count = o.family_counts.front();
  const testkit::SpeedFamily family = testkit::speed_family(o.write_family, count);
  SceneFile file;
  file.dimension = 3;
  file.scene3d = family.scene;
  const Orbit3D& orbit = family.orbit;
  file.camera.target = std::vector<double>{orbit.target.x, orbit.target.y, orbit.target.z};
  file.camera.d = orbit.d;
  file.camera.theta_deg = glm::degrees(orbit.theta);
  file.camera.phi_deg = glm::degrees(orbit.phi);
  file.camera.df = orbit.df;
  save_scene_file(file, o.write_path);
  std::printf("%s: the \"%s\" family, K = %d (%s)\n", o.write_path.c_str(), family.name.c_str(), count,
              family.description.c_str());
  return 0;
}
}  // namespace

// ---- entry point
// -------------------------------------------------------------------------------------------
int run_bench_speed(const Args& args) {
  Run run;
  if (const std::optional<int> exit_now = parse_options(args, run.options)) return *exit_now;
  if (!run.options.scene_path.empty()) return run_scene(run.options);
  if (!run.options.write_family.empty()) return write_family_scene(run.options);
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
  run.steps.begin(run.options);
  KeepingReporter reporter(run.results, run.steps);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  run.steps.line()->finish();
  print_summary(run);
  print_families(run);
  if (run.options.extras) print_extras(run);
  std::printf("\nPeak resident memory of this run: %.1f MB\n", double(testkit::resident_kb("VmHWM:")) / 1024.0);
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

}  // namespace raycam::bench
