// `raycam-cli bench accuracy`: run time against error (docs/accuracy.md, "Time against error").
// Sections: options; standard scenes and their references; the sweep; Pareto fronts; CSV (plotted by
// scripts/accuracy_plot.sh, not from here).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <glm/gtc/constants.hpp>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bench/accuracy_sweep.h"
#include "bench/bench_commands.h"
#include "flags/flag_values.h"
#include "check/progress_line.h"
#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"
#include "raycam/reference_caster.h"
#include "raycam/standard_scenes.h"

namespace raycam::bench {

namespace {

// ---- Options --------------------------------------------------------------------------------------------
enum class Placement { orbit, arccos, stable };

struct BenchOptions {
  std::vector<Scalar> scalars{Scalar::float32, Scalar::float64, Scalar::extended};
  std::vector<IntersectFormula> formulas{IntersectFormula::naive, IntersectFormula::stable};
  std::vector<int> spps{1, 4, 16, 64};
  std::vector<bool> frames{false, true};  // camera_relative
  std::vector<Placement> placements{Placement::orbit};
  int repeats = 5;
  bool quick = false;
  std::string csv_path = "accuracy.csv";
  bool stress = false, long_sweep = false, angles = false;
  bool quiet = false;  // no progress on stderr
};

const char* placement_name(Placement p) {
  return p == Placement::orbit ? "orbit" : p == Placement::arccos ? "arccos" : "stable";
}

std::vector<std::string> names_of_scalars() {
  std::vector<std::string> names;
  for (Scalar scalar : kScalars) names.push_back(scalar_name(scalar));
  return names;
}
std::vector<std::string> names_of_formulas() {
  std::vector<std::string> names;
  for (IntersectFormula formula : kIntersectFormulas) names.push_back(formula_name(formula));
  return names;
}

void add_options(CLI::App& bench, BenchOptions& o) {
  bench.footer(
      "Sweeps the caster's knobs on standard scenes and measures median run time against error:\n"
      "  id error     fraction of pixel-centre ids differing from the exact reference\n"
      "  colour error mean |colour - exact coverage colour| per channel, 8-bit units\n"
      "References: 2D, the exact bar (analytic footprints); 3D, long double, stable, camera-relative,\n"
      "1024 stratified samples per pixel (256 with --quick). LISTs are comma-separated.\n"
      "--stress: the numerical stress table; --angles: the arccos-vs-atan2 angle error table.\n");
  CLI::Option_group* sweep = bench.add_option_group("Sweep", "The knobs swept (comma-separated lists)");
  using flags::add_checked_list;
  add_checked_list<int>(*sweep, "--precision", "LIST", "scalar of the per-ray arithmetic (default: all)",
                        flags::one_of(names_of_scalars()), [&o](std::vector<int> items) {
                          o.scalars.clear();
                          for (int i : items) o.scalars.push_back(kScalars[i]);
                        });
  add_checked_list<int>(*sweep, "--intersect", "LIST",
                        "ray/object formula, textbook b^2-c or Ray Tracing Gems (default: both)",
                        flags::one_of(names_of_formulas()), [&o](std::vector<int> items) {
                          o.formulas.clear();
                          for (int i : items) o.formulas.push_back(kIntersectFormulas[i]);
                        });
  add_checked_list<int>(*sweep, "--spp", "LIST",
                        "stratified samples per pixel; 3D takes the perfect squares (default 1,4,16,64)",
                        flags::integer_in(1, kMaxSamplesPerPixel),
                        [&o](std::vector<int> items) { o.spps = items; });
  add_checked_list<int>(*sweep, "--frame", "LIST", "world coordinates or relative to the eye (default: both)",
                        flags::one_of({"world", "relative"}), [&o](std::vector<int> items) {
                          o.frames.clear();
                          for (int i : items) o.frames.push_back(i == 1);
                        });
  add_checked_list<int>(*sweep, "--placement", "LIST",
                        "camera from (d, theta, phi), or from P and C by the handout's arccos route or atan2 "
                        "(default: orbit)",
                        flags::one_of({"orbit", "arccos", "stable"}), [&o](std::vector<int> items) {
                          o.placements.clear();
                          for (int i : items) o.placements.push_back(Placement(i));
                        });
  flags::add_checked_option<int>(bench, "--repeats", "R", "timing repeats, the median is kept (default 5)",
                                 flags::integer_in(1, 1000), [&o](int r) { o.repeats = r; });
  bench.add_flag("--quick", o.quick, "smaller images and reference (for CI)");
  flags::add_checked_option<std::string>(bench, "--csv", "FILE",
                                         "default accuracy.csv (stress: stress.csv, angles: angles.csv)",
                                         flags::file_name(), [&o](std::string p) { o.csv_path = p; });
  bench.add_flag("--stress", o.stress,
                 "the numerical stress table (worst id error per setting); exit 1 if anything is non-finite");
  bench.add_flag("--long", o.long_sweep, "the long stress list (more values, larger images)");
  bench.add_flag("--angles", o.angles, "the arccos-vs-atan2 angle error table");
  bench.add_flag("--quiet", o.quiet,
                 "no progress on stderr (by default each reference and setting is announced as it starts, with "
                 "the time left)");
}

// ---- Standard scenes ------------------------------------------------------------------------------------
struct StandardScene {
  std::string name;
  int dimension = 2;
  Scene2D scene2d;
  Scene3D scene3d;
  Orbit2D orbit2d;
  Orbit3D orbit3d;
  int size = 0;
  // For the progress line's estimate: pixels cast, and the reference's samples a pixel (2D: the exact bar).
  std::size_t pixels = 0, reference_samples = 1;
  CoverageImage reference;
};

Scene2D cluster_2d(glm::dvec2 t) { return testkit::demo_cluster_2d(t); }
Scene3D cluster_3d(glm::dvec3 t) { return testkit::demo_cluster_3d(t); }

// The scene's camera placed by its orbit, or freely from P and C by the chosen route.
template <class Camera, class Orbit>
Camera placed(Camera camera, const Orbit& o, Placement placement) {
  if (placement == Placement::orbit)
    camera.set_orbit(o);
  else
    camera.set_free(orbit_screen_centre(o), o.target, o.df,
                    placement == Placement::arccos ? AngleRoute::handout_arccos : AngleRoute::stable);
  return camera;
}
Camera2D make_camera(const StandardScene& s, Placement placement) {
  return placed(Camera2D(s.size), s.orbit2d, placement);
}
Camera3D make_camera_3d(const StandardScene& s, Placement placement) {
  return placed(Camera3D(s.size, s.size), s.orbit3d, placement);
}
// Calls function(camera, scene) with the scene's camera placed by `placement` and its objects, 2D or 3D: the
// sweep is written once over the core's overloads (cast_primary_rays, reference_cast).
template <class Function>
void with_camera(const StandardScene& s, Placement placement, Function&& function) {
  if (s.dimension == 2)
    function(make_camera(s, placement), s.scene2d);
  else
    function(make_camera_3d(s, placement), s.scene3d);
}

// The exact reference: 2D, the exact bar (analytic footprints); 3D, long double, stable, camera-relative.
CoverageImage reference_image(const Camera2D& camera, const Scene2D& scene, std::size_t) {
  return exact_bar_image(exact_bar(camera, scene), scene);
}
CoverageImage reference_image(const Camera3D& camera, const Scene3D& scene, std::size_t samples) {
  return reference_cast(camera, scene, ReferenceOptions{Scalar::extended, IntersectFormula::stable, int(samples), true});
}

std::vector<StandardScene> standard_scenes(bool quick) {
  std::vector<StandardScene> scenes;
  const int size2d = quick ? 256 : 1024, size3d = quick ? 48 : 96;
  // Ordinary view; the same scene 10 000 away, zoomed in (d_f ∝ d); the same moved 1e6 from the origin.
  StandardScene s;
  s.dimension = 2;
  s.size = size2d;
  s.pixels = std::size_t(size2d);
  s.name = "2d-classic";
  s.scene2d = cluster_2d({0, 0});
  s.orbit2d = Orbit2D{{0, 0}, 6.0, glm::half_pi<double>(), 1.5};
  scenes.push_back(s);
  s.name = "2d-far";
  s.orbit2d = Orbit2D{{0, 0}, 1e4, glm::half_pi<double>() + 0.3, 2500.0};
  scenes.push_back(s);
  s.name = "2d-translated";
  s.scene2d = cluster_2d({1e6, -7e5});
  s.orbit2d = Orbit2D{{1e6, -7e5}, 6.0, glm::half_pi<double>(), 1.5};
  scenes.push_back(s);
  StandardScene t;
  t.dimension = 3;
  t.size = size3d;
  t.pixels = std::size_t(size3d) * std::size_t(size3d);
  t.reference_samples = quick ? 256 : 1024;
  t.name = "3d-classic";
  t.scene3d = cluster_3d({0, 0, 0});
  t.orbit3d = Orbit3D{{0, 0, 0}, 8.0, 0.5, 1.0, 2.0};
  scenes.push_back(t);
  t.name = "3d-far";
  t.orbit3d = Orbit3D{{0, 0, 0}, 1e4, 0.5, 1.0, 2500.0};
  scenes.push_back(t);
  t.name = "3d-translated";
  t.scene3d = cluster_3d({1e6, 1e6, -1e6});
  t.orbit3d = Orbit3D{{1e6, 1e6, -1e6}, 8.0, 0.5, 1.0, 2.0};
  scenes.push_back(t);
  return scenes;
}

void compute_reference(StandardScene& scene) {
  with_camera(scene, Placement::orbit, [&](const auto& camera, const auto& objects) {
    scene.reference = reference_image(camera, objects, scene.reference_samples);
  });
}

// ---- The sweep ------------------------------------------------------------------------------------------
struct Point {
  std::string scene, label, precision, intersect, frame, placement;
  int spp = 1;
  double median_ms = 0, id_error = 0, colour_error = 0;
  bool pareto_colour = false, pareto_id = false;
};

// Google Benchmark keeps only the median of the repetitions (one cast per repetition, as the sweep has
// hundreds of settings); the reporter hands it back instead of printing.
class MedianReporter : public benchmark::BenchmarkReporter {
 public:
  double median_ms = 0.0;
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs)  // one repetition has no aggregates: its own time is the median
      if (run.run_type == Run::RT_Iteration || run.aggregate_name == "median")
        median_ms = run.GetAdjustedRealTime();
  }
};

double median_ms(int repeats, const std::function<void()>& cast) {
  benchmark::ClearRegisteredBenchmarks();
  benchmark::RegisterBenchmark("cast",
                               [&cast](benchmark::State& state) {
                                 for (auto _ : state) cast();
                               })
      ->Repetitions(repeats)
      ->Iterations(1)
      ->ReportAggregatesOnly(repeats > 1)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  return reporter.median_ms;
}

CoverageImage from_colour_map(const ColourMap& map) {
  CoverageImage image{map.width, map.height, map.ids, {}};
  for (Rgb8 c : map.colours) image.colours.push_back(to_dvec3(c));
  return image;
}

// A point is on the front when no other point of its scene is at least as fast and at least as accurate,
// and strictly better in one of the two.
// Ids come from the pixel-centre ray whatever the spp, so the id front considers 1-spp settings only.
void mark_pareto(std::vector<Point>& points, double Point::*error, bool Point::*flag,
                 bool single_sample_only) {
  for (Point& p : points) {
    p.*flag = !single_sample_only || p.spp == 1;
    if (!(p.*flag)) continue;
    for (const Point& q : points) {
      if (&p == &q || q.scene != p.scene || (single_sample_only && q.spp != 1)) continue;
      if (q.median_ms <= p.median_ms && q.*error <= p.*error &&
          (q.median_ms < p.median_ms || q.*error < p.*error)) {
        p.*flag = false;
        break;
      }
    }
  }
}

std::string short_label(Scalar scalar, IntersectFormula formula, bool relative, int spp,
                        Placement placement) {
  std::string label = std::string(1, scalar_name(scalar)[0]) +
                      (formula == IntersectFormula::naive ? "n" : "s") + (relative ? "r" : "w") +
                      std::to_string(spp);
  if (placement != Placement::orbit) label += placement == Placement::arccos ? "-acos" : "-atan2";
  return label;
}

// One point of the sweep: the core caster as it is, the exact bar (2D), or the reference caster with its knobs.
enum class Timed { core, exact, knobs };
struct Setting {
  Timed timed = Timed::knobs;
  Placement placement = Placement::orbit;
  Scalar scalar = Scalar::float64;
  IntersectFormula formula = IntersectFormula::stable;
  bool relative = false;
  int spp = 1;
};

// The settings swept on one scene, in the order they are timed (listed first: the progress line's total).
std::vector<Setting> settings_of(const BenchOptions& o, const StandardScene& s) {
  std::vector<Setting> settings{Setting{Timed::core}};
  if (s.dimension == 2) settings.push_back(Setting{Timed::exact});
  for (Placement placement : o.placements)
    for (Scalar scalar : o.scalars)
      for (IntersectFormula formula : o.formulas)
        for (bool relative : o.frames)
          for (int spp : o.spps) {
            if (s.dimension == 3 &&
                int(std::lround(std::sqrt(double(spp)))) * int(std::lround(std::sqrt(double(spp)))) != spp)
              continue;  // 3D takes square grids only
            settings.push_back(Setting{Timed::knobs, placement, scalar, formula, relative, spp});
          }
  return settings;
}

std::string label_of(const Setting& setting) {
  if (setting.timed == Timed::core) return "core";
  if (setting.timed == Timed::exact) return "exact";
  return short_label(setting.scalar, setting.formula, setting.relative, setting.spp, setting.placement);
}

Point measure(const BenchOptions& o, const StandardScene& s, const Setting& setting) {
  CoverageImage image;
  Point p;
  if (setting.timed == Timed::core) {
    // The plain core caster, for comparison: double, stable, world, 1 spp (conversion not timed).
    p = Point{s.name, "core", "double", "stable", "world", "orbit", 1};
    ColourMap map;
    with_camera(s, Placement::orbit, [&](const auto& camera, const auto& scene) {
      p.median_ms = median_ms(o.repeats, [&] { map = cast_primary_rays(camera, scene); });
    });
    image = from_colour_map(map);
  } else if (setting.timed == Timed::exact) {
    // The exact bar itself: the reference, so its errors are 0 by definition.
    p = Point{s.name, "exact", "long-double", "exact", "world", "orbit", 1};
    const Camera2D camera = make_camera(s, Placement::orbit);
    p.median_ms = median_ms(o.repeats, [&] { image = exact_bar_image(exact_bar(camera, s.scene2d), s.scene2d); });
  } else {
    const ReferenceOptions options{setting.scalar, setting.formula, setting.spp, setting.relative};
    p = Point{s.name,
              label_of(setting),
              scalar_name(setting.scalar),
              formula_name(setting.formula),
              setting.relative ? "relative" : "world",
              placement_name(setting.placement),
              setting.spp};
    with_camera(s, setting.placement, [&](const auto& camera, const auto& scene) {
      p.median_ms = median_ms(o.repeats, [&] { image = reference_cast(camera, scene, options); });
    });
  }
  p.id_error = id_disagreement(image, s.reference);
  p.colour_error = mean_colour_error(image, s.reference);
  return p;
}

// A step's work for the progress line's estimate, in samples cast, each cast repeated as timed; long double
// counts three (3d-classic at 96², 64 samples: 122 ms against 41 ms in double, 29 ms in float). The 3D
// references (1024 samples a pixel, once) are the first seconds of a run; counted alike, their pace
// promised minutes to a 20 s sweep.
std::size_t reference_work(const StandardScene& s) { return s.pixels * s.reference_samples * 3; }  // long double
std::size_t setting_work(const BenchOptions& o, const StandardScene& s, const Setting& setting) {
  const bool knobs = setting.timed == Timed::knobs;
  const bool extended = setting.timed == Timed::exact || (knobs && setting.scalar == Scalar::extended);
  return s.pixels * std::size_t(knobs ? setting.spp : 1) * (extended ? 3 : 1) * std::size_t(o.repeats);
}

// Every scene's reference, then every setting timed on every scene, each announced as it starts.
std::vector<Point> sweep(const BenchOptions& o, std::vector<StandardScene>& scenes) {
  std::vector<std::vector<Setting>> settings;
  std::size_t steps = scenes.size(), work = 0;
  for (const StandardScene& s : scenes) {
    settings.push_back(settings_of(o, s));
    steps += settings.back().size();
    work += reference_work(s);
    for (const Setting& setting : settings.back()) work += setting_work(o, s, setting);
  }
  check::ProgressLine progress("bench accuracy", steps, o.quiet, stderr, work);
  for (StandardScene& s : scenes) {
    progress.start(s.name + " reference", reference_work(s));
    compute_reference(s);
  }
  std::vector<Point> points;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::size_t first_of_scene = points.size();
    for (const Setting& setting : settings[i]) {
      progress.start(scenes[i].name + " " + label_of(setting), setting_work(o, scenes[i], setting));
      points.push_back(measure(o, scenes[i], setting));
    }
    std::sort(
        points.begin() + std::ptrdiff_t(first_of_scene), points.end(),
        [](const Point& a, const Point& b) { return a.median_ms < b.median_ms; });  // for the front's line
  }
  progress.finish();
  mark_pareto(points, &Point::colour_error, &Point::pareto_colour, false);
  mark_pareto(points, &Point::id_error, &Point::pareto_id, true);
  return points;
}

// ---- Output ---------------------------------------------------------------------------------------------
void write_csv(const std::vector<Point>& points, const std::string& path) {
  std::ofstream csv(path);
  if (!csv) throw std::runtime_error("cannot write " + path);
  csv << "scene,label,precision,intersect,frame,placement,spp,median_ms,id_error,colour_error,pareto_colour,"
         "pareto_id\n";
  for (const Point& p : points)
    csv << p.scene << ',' << p.label << ',' << p.precision << ',' << p.intersect << ',' << p.frame << ','
        << p.placement << ',' << p.spp << ',' << p.median_ms << ',' << p.id_error << ',' << p.colour_error
        << ',' << p.pareto_colour << ',' << p.pareto_id << '\n';
}


int run_bench_accuracy(BenchOptions o) {
  if (o.stress) {
    if (o.csv_path == "accuracy.csv") o.csv_path = "stress.csv";
    return run_stress_table(o.long_sweep, o.csv_path) == 0 ? 0 : 1;
  }
  if (o.angles) {
    if (o.csv_path == "accuracy.csv") o.csv_path = "angles.csv";
    run_angle_table(o.csv_path);
    return 0;
  }
  std::vector<StandardScene> scenes = standard_scenes(o.quick);
  const std::vector<Point> points = sweep(o, scenes);
  write_csv(points, o.csv_path);
  std::printf(
      "| scene | setting | median ms | id error | colour error | Pareto (colour / id) "
      "|\n|---|---|---|---|---|---|\n");
  for (const Point& p : points)
    std::printf("| %s | %s | %.3f | %.3g | %.3g | %s / %s |\n", p.scene.c_str(), p.label.c_str(), p.median_ms,
                p.id_error, p.colour_error, p.pareto_colour ? "yes" : "", p.pareto_id ? "yes" : "");
  std::printf("csv: %s (plots: scripts/accuracy_plot.sh)\n", o.csv_path.c_str());
  return 0;
}
}  // namespace

void add_bench_accuracy_command(CLI::App& bench, int& exit_code) {
  CLI::App* accuracy =
      bench.add_subcommand("accuracy", "time against error, --stress, --angles (docs/accuracy.md)");
  auto options = std::make_shared<BenchOptions>();
  add_options(*accuracy, *options);
  accuracy->callback([options, &exit_code] { exit_code = run_bench_accuracy(*options); });
}

}  // namespace raycam::bench
