// The overhead view's drawing order (overhead_view.h): lowest_first, a radix sort, against std::stable_sort
// by the same keys (the order the view used to get by sorting through the objects).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "ui/overhead_view.h"

using namespace raycam;

namespace {
std::vector<std::uint32_t> stable_order(const std::vector<double>& keys) {
  std::vector<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}
}  // namespace

TEST_CASE("the overhead discs' order: lowest top first, ties in the scene's order, as a stable sort gives",
          "[ui][overhead]") {
  std::mt19937_64 random(11);
  const double tiny = std::numeric_limits<double>::denorm_min(), huge = 1e300;
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = trial < 5 ? std::size_t(trial) : std::size_t(std::uniform_int_distribution<int>(5, 20000)(random));
    std::vector<double> keys(n);
    for (double& key : keys) {
      switch (std::uniform_int_distribution<int>(0, 6)(random)) {
        case 0: key = std::uniform_real_distribution<double>(-10, 10)(random); break;
        case 1: key = std::round(std::uniform_real_distribution<double>(-3, 3)(random)); break;  // many ties
        case 2: key = std::uniform_int_distribution<int>(0, 1)(random) ? 0.0 : -0.0; break;       // ±0 tie
        case 3: key = std::uniform_int_distribution<int>(0, 1)(random) ? tiny : -tiny; break;
        case 4: key = std::uniform_int_distribution<int>(0, 1)(random) ? huge : -huge; break;
        case 5: key = 1e6 + std::uniform_real_distribution<double>(0, 1e-9)(random); break;  // low digits only
        default: key = std::ldexp(1.0, std::uniform_int_distribution<int>(-1000, 1000)(random)); break;
      }
    }
    INFO("trial " << trial << ", " << n << " keys");
    CHECK(ui::lowest_first(keys) == stable_order(keys));
  }
  // All keys alike: every digit skipped, the scene's order kept.
  const std::vector<double> same(1000, 2.5);
  CHECK(ui::lowest_first(same) == stable_order(same));
}
