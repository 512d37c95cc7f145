// `raycam-cli bench accuracy --stress` and `--angles`: the stress table and the arccos-vs-atan2 table.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <map>
#include <stdexcept>
#include <vector>

#include "bench/accuracy_sweep.h"
#include "raycam/camera3d.h"
#include "raycam/stress_cases.h"

namespace raycam::bench {

namespace {

struct Config {
  Scalar scalar;
  IntersectFormula formula;
  bool relative;
};

std::vector<Config> stress_configs() {
  std::vector<Config> configs;
  for (bool relative : {false, true})
    for (Scalar scalar : {Scalar::float32, Scalar::float64})
      for (IntersectFormula formula : {IntersectFormula::naive, IntersectFormula::stable})
        configs.push_back(Config{scalar, formula, relative});
  return configs;
}

std::string config_name(const Config& c) {
  return std::string(scalar_name(c.scalar)) + " " + formula_name(c.formula) +
         (c.relative ? " rel" : " world");
}

std::ofstream open_csv(const std::string& path) {
  std::ofstream csv(path);
  if (!csv) throw std::runtime_error("cannot write " + path);
  return csv;
}
}  // namespace

int run_stress_table(bool long_sweep, const std::string& csv_path) {
  const std::vector<Config> configs = stress_configs();
  std::ofstream csv = open_csv(csv_path);
  csv << "dimension,group,case,precision,intersect,frame,id_error,finite\n";
  // worst[group label][config index]
  std::map<std::string, std::vector<double>> worst;
  std::vector<std::string> order;
  int non_finite = 0;
  auto record = [&](const std::string& group, const std::string& name, int dimension, std::size_t index,
                    const StressResult& result) {
    const Config& c = configs[index];
    csv << dimension << "D," << group << ",\"" << name << "\"," << scalar_name(c.scalar) << ','
        << formula_name(c.formula) << ',' << (c.relative ? "camera-relative" : "world") << ','
        << result.id_error << ',' << (result.all_finite ? 1 : 0) << '\n';
    const std::string key = std::to_string(dimension) + "D " + group;
    if (!worst.count(key)) {
      worst[key].assign(configs.size(), 0.0);
      order.push_back(key);
    }
    worst[key][index] = std::max(worst[key][index], result.id_error);
    if (!result.all_finite) {
      ++non_finite;
      std::fprintf(stderr, "NON-FINITE: %s %s %s\n", key.c_str(), name.c_str(), config_name(c).c_str());
    }
  };
  auto sweep = [&](const auto& cases, int dimension) {  // the 2D and the 3D cases alike
    for (const auto& stress_case : cases) {
      const CoverageImage reference = stress_reference(stress_case);
      for (std::size_t i = 0; i < configs.size(); ++i)
        record(stress_case.group, stress_case.name, dimension, i,
               measure(stress_case, reference,
                       ReferenceOptions{configs[i].scalar, configs[i].formula, 1, configs[i].relative}));
    }
  };
  sweep(stress_cases_2d(long_sweep), 2);
  sweep(stress_cases_3d(long_sweep), 3);
  std::printf("Worst fraction of pixel ids differing from the exact reference (%s sweep):\n\n| setting |",
              long_sweep ? "long" : "short");
  for (const Config& c : configs) std::printf(" %s |", config_name(c).c_str());
  std::printf("\n|---|");
  for (std::size_t i = 0; i < configs.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const std::string& key : order) {
    std::printf("| %s |", key.c_str());
    for (double value : worst[key]) std::printf(value == 0.0 ? " 0 |" : " %.3g |", value);
    std::printf("\n");
  }
  std::printf("\nnon-finite configurations: %d (csv: %s)\n", non_finite, csv_path.c_str());
  return non_finite;
}

// ---- arccos against atan2 ------------------------------------------------------------------------------
void run_angle_table(const std::string& csv_path) {
  std::ofstream csv = open_csv(csv_path);
  csv << "where,offset,route,abs_error_rad\n";
  struct Row {
    std::string where;
    double worst_arccos = 0, worst_stable = 0, at_arccos = 0;
  };
  std::vector<Row> rows;
  // Offsets δ from the ill-conditioned spot, log-spaced 1e-12 … 1e-2, plus δ = 0.
  std::vector<double> offsets = {0.0};
  for (double e = -12; e <= -2.0001; e += 0.25) offsets.push_back(std::pow(10.0, e));

  auto sweep = [&](const std::string& where, auto&& true_and_measured) {
    Row row{where};
    for (double delta : offsets) {
      double truth, arccos_value, stable_value;
      true_and_measured(delta, truth, arccos_value, stable_value);
      const double e_arccos = std::abs(arccos_value - truth), e_stable = std::abs(stable_value - truth);
      csv << '"' << where << "\"," << delta << ",arccos," << e_arccos << '\n';
      csv << '"' << where << "\"," << delta << ",atan2," << e_stable << '\n';
      if (e_arccos > row.worst_arccos) {
        row.worst_arccos = e_arccos;
        row.at_arccos = delta;
      }
      row.worst_stable = std::max(row.worst_stable, e_stable);
    }
    rows.push_back(row);
  };
  // 2D: the angle of a unit vector near +x (x_v ≈ 1) and near -x (x_v ≈ -1).
  for (double base : {0.0, glm::pi<double>()}) {
    sweep(std::string("2D angle near ") + (base == 0.0 ? "0 (x=+1)" : "pi (x=-1)"),
          [&](double delta, double& truth, double& a, double& s) {
            truth = base == 0.0 ? delta : glm::pi<double>() - delta;
            const glm::dvec2 v(std::cos(truth), std::sin(truth));
            a = polar_angle(v, AngleRoute::handout_arccos);
            s = polar_angle(v, AngleRoute::stable);
          });
  }
  // 3D: φ near the poles (z ≈ ±1), then θ near 0 and π at φ = 1 (x/sin φ ≈ ±1).
  for (double base : {0.0, glm::pi<double>()}) {
    sweep(std::string("3D phi near ") + (base == 0.0 ? "0 (pole +z)" : "pi (pole -z)"),
          [&](double delta, double& truth, double& a, double& s) {
            truth = base == 0.0 ? delta : glm::pi<double>() - delta;
            const glm::dvec3 v(std::cos(0.7) * std::sin(truth), std::sin(0.7) * std::sin(truth),
                               std::cos(truth));
            a = spherical_angles(v, AngleRoute::handout_arccos).phi;
            s = spherical_angles(v, AngleRoute::stable).phi;
          });
  }
  for (double base : {0.0, glm::pi<double>()}) {
    sweep(std::string("3D theta near ") + (base == 0.0 ? "0" : "pi") + " at phi=1",
          [&](double delta, double& truth, double& a, double& s) {
            truth = base == 0.0 ? delta : glm::pi<double>() - delta;
            const glm::dvec3 v(std::cos(truth) * std::sin(1.0), std::sin(truth) * std::sin(1.0),
                               std::cos(1.0));
            a = spherical_angles(v, AngleRoute::handout_arccos).theta;
            s = spherical_angles(v, AngleRoute::stable).theta;
          });
  }
  std::printf(
      "Angle recovered from a unit vector, worst absolute error over offsets 0 and 1e-12…1e-2 rad from "
      "the ill-conditioned spot:\n\n| where | arccos (handout) | at offset | atan2 (stable) |\n"
      "|---|---|---|---|\n");
  for (const Row& row : rows)
    std::printf("| %s | %.2g rad | %.2g | %.2g rad |\n", row.where.c_str(), row.worst_arccos, row.at_arccos,
                row.worst_stable);
  std::printf("\n(csv: %s)\n", csv_path.c_str());
}

}  // namespace raycam::bench
