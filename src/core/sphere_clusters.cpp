// SphereClusters (raycam/scene.h): spheres in clusters of neighbours, with bounding spheres.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raycam/scene.h"

namespace raycam {

namespace {
// A sphere's centre and index, side by side: the splits below read and move them together (read through an
// index into the columns, packing 10⁵ spheres took 17 ms).
struct Centre {
  double at[3];
  int index;
};

// Splits spheres [begin, end) in two along the longest side of their centres' bounds, the first part a whole
// number of clusters, about half; and each part again, down to one cluster: clusters as compact as the
// spheres allow (runs of 64 along a Morton curve, tried first, were a third wider: fewer were culled).
// Returns the part's place in the tree: a split's index, or -1 - k for cluster k. Parts start at whole
// clusters, so cluster k is spheres k·kSize onwards.
int split(std::vector<Centre>& centres, int begin, int end, std::vector<SphereClusters::Split>& splits) {
  constexpr int kSize = SphereClusters::kSize;
  if (end - begin <= kSize) return -1 - begin / kSize;
  double low[3], high[3];
  for (int a = 0; a < 3; ++a) low[a] = high[a] = centres[std::size_t(begin)].at[a];
  for (int j = begin; j < end; ++j)
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], centres[std::size_t(j)].at[a]);
      high[a] = std::max(high[a], centres[std::size_t(j)].at[a]);
    }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (high[a] - low[a] > high[axis] - low[axis]) axis = a;
  const int clusters = (end - begin + kSize - 1) / kSize;
  const int middle = begin + clusters / 2 * kSize;
  // Ties by index: the same parts on every machine.
  std::nth_element(centres.begin() + begin, centres.begin() + middle, centres.begin() + end,
                   [axis](const Centre& a, const Centre& b) {
                     return a.at[axis] < b.at[axis] || (a.at[axis] == b.at[axis] && a.index < b.index);
                   });
  const int node = int(splits.size());
  splits.push_back({axis, centres[std::size_t(middle)].at[axis], 0, 0});
  const int first = split(centres, begin, middle, splits);
  const int second = split(centres, middle, end, splits);
  splits[std::size_t(node)].first = first;
  splits[std::size_t(node)].second = second;
  return node;
}
}  // namespace

void SphereClusters::build(const std::vector<double>& sx, const std::vector<double>& sy,
                           const std::vector<double>& sz, const std::vector<double>& sr) {
  const std::size_t count = sr.size();
  std::vector<Centre> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = {{sx[i], sy[i], sz[i]}, int(i)};
  splits.clear();
  if (count > 0) split(order, 0, int(count), splits);

  x.resize(count);
  y.resize(count);
  z.resize(count);
  radius.resize(count);
  object.resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t i = std::size_t(order[j].index);
    x[j] = sx[i];
    y[j] = sy[i];
    z[j] = sz[i];
    radius[j] = sr[i];
    object[j] = int(i);
  }
  float_x.assign(x.begin(), x.end());
  float_y.assign(y.begin(), y.end());
  float_z.assign(z.begin(), z.end());
  float_radius.assign(radius.begin(), radius.end());
  const std::size_t clusters = (count + kSize - 1) / kSize;
  for (std::vector<double>* column : {&bound_x, &bound_y, &bound_z, &bound_radius}) column->resize(clusters);
  for (std::size_t k = 0; k < clusters; ++k) {
    const std::size_t begin = k * kSize, end = std::min(count, begin + kSize);
    // The centre of the members' bounding box, then the farthest member's far side from it.
    glm::dvec3 lo(x[begin], y[begin], z[begin]), hi = lo;
    for (std::size_t j = begin; j < end; ++j) {
      const glm::dvec3 c(x[j], y[j], z[j]);
      lo = glm::min(lo, c - radius[j]);
      hi = glm::max(hi, c + radius[j]);
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    double reach = 0.0;
    for (std::size_t j = begin; j < end; ++j) {
      const glm::dvec3 d = glm::dvec3(x[j], y[j], z[j]) - centre;
      reach = std::max(reach, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) + radius[j]);
    }
    bound_x[k] = centre.x;
    bound_y[k] = centre.y;
    bound_z[k] = centre.z;
    // Rounded up past the few ulps the sums above may have lost: every member stays inside.
    bound_radius[k] = reach * (1.0 + 1e-12);
  }
}


void SphereClusters::near_to_far(const glm::dvec3& eye, std::vector<int>& out) const {
  out.clear();
  if (cluster_count() == 0) return;
  if (splits.empty()) {
    out.push_back(0);
    return;
  }
  // Depth first, the eye's side of each split first. The splits halve, so the tree is at most
  // log2(kMaxObjects / kSize) + 1 deep and the stack holds at most one more entry than that: no allocation.
  int pending[64];
  int top = 0;
  pending[top++] = 0;
  while (top > 0) {
    const int at = pending[--top];
    if (at < 0) {
      out.push_back(-1 - at);
      continue;
    }
    const Split& s = splits[std::size_t(at)];
    const bool first_nearer = eye[s.axis] < s.at;
    assert(top + 2 <= 64);
    pending[top++] = first_nearer ? s.second : s.first;
    pending[top++] = first_nearer ? s.first : s.second;
  }
}

}  // namespace raycam
