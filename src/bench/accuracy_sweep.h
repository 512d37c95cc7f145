// Pieces of `raycam-cli bench accuracy` shared between its files: the stress table and the angle table
// (accuracy_tables.cpp) beside the time-against-error sweep (bench_accuracy.cpp).
#pragma once

#include <string>

namespace raycam::bench {

// The stress sweep: every stress case × {float, double} × {naive, stable} × {world, camera-relative}.
// Writes one CSV row per case and configuration, prints a markdown table (group → worst id error) to stdout.
// Returns the number of configurations that produced a non-finite value (0 is the only acceptable answer).
int run_stress_table(bool long_sweep, const std::string& csv_path);

// The handout's arccos route against atan2, near ±1 and near the poles: prints a markdown table.
void run_angle_table(const std::string& csv_path);

}  // namespace raycam::bench
