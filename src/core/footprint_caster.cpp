#include "core/footprint_caster.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>

#include "core/band_kernels.h"
#include "raycam/limits.h"
#include "raycam/parallel.h"
#include "core/screen_footprint.h"
#include "core/vector_loops.h"

namespace raycam::detail {

namespace {
constexpr int kBandRows = 8;              // a band's depth buffer stays in cache at any width
constexpr int kObjectsPerChunk = 4096;    // projection work handed out per item
constexpr int kRayBlock = 8;              // columns whose rays are made together: two AVX2 vectors
constexpr int kBatch = SphereClusters::kSize;  // a cluster's spheres
constexpr int kClustersPerChunk = kObjectsPerChunk / kBatch;
static_assert(kObjectsPerChunk % kBatch == 0, "a chunk holds whole clusters");
constexpr int kMaxRun = 256;  // spheres projected at once (their boxes: 4 KB, in L1)
// Starting a thread costs tens of microseconds: below this much work (intersection tests, plus a quarter of
// a test per pixel written and four per candidate) one thread finishes first. Measured with `bench speed`
// at 256² and K = 1…10⁵.
constexpr long long kThreadedWork = 100000;
// Buckets of the near-to-far order: finer than the spheres' depth spread needs (8 candidates a bucket).
constexpr int kMaxDepthBuckets = 8192;
// Where sorting near to far pays (measured with `bench speed`'s families): from an average box depth of 1,
// and boxes of 4 pixels on average (the narrow family at K = 10⁵, 2 pixels a box at 256²: 1.37× slower
// sorted; radii ×20, 7 pixels a box: 2.7× faster).
constexpr double kNearToFarDepth = 1.0;
constexpr double kNearToFarBoxPixels = 4.0;
// A band with at least one candidate per this many pixels gets every ray without marking where boxes need
// them: its boxes cover most of it, and marking costs a pass over its candidates (measured with `bench speed`'s
// families, one thread, K = 10⁵: 6–18 % faster at 256² and 1024², except radii ×20 at 1024², within the noise;
// at K = 10³ no band is that dense; 8 and 32 measured alike).
constexpr long long kCandidatesPerRayMarking = 32;

// An object that survived culling, with the pixels it can cover. A compact copy of what the pixel loop
// reads, in the order the loop takes them: with many objects, reading them from the scene (names and all)
// by index costs a cache miss per object.
// 48 bytes, not 64: the box in 16 bits (a side is at most kMaxSide3D) and the bound as a float rounded down.
// Candidates are copied twice a cast (projected, then binned) and read at least once: at 10⁵ spheres that
// is megabytes (measured, K = 10⁵, two threads: 1–3 % faster, the grazing layer at 256² and radii ×20 at 1024²).
struct Candidate {
  struct Span {
    std::int16_t first, last;
  };
  glm::dvec3 centre;
  double radius;
  struct {
    Span rows, columns;
  } box;
  float nearest_t;  // no ray of the camera can hit it at a smaller t (NearestTBound); -∞: no bound
  int object;
};
static_assert(kMaxSide3D <= 32767, "a Candidate's box holds pixel indices in 16 bits");

// Candidate lists per band of rows (compressed: band b owns entries[start[b] .. start[b+1])), each in the
// order the candidates were appended. Copies, not indices: a band then reads its candidates in a row, where
// indices into 10⁵ candidates cost a cache miss each (measured: 15 % of a cast). One per chunk of clusters,
// binned by the chunk's projection, on its thread and while its candidates are in cache (one binning of all
// candidates after the projection was a tenth of a cast of the grazing layer at 256², and on one thread); a
// band reads its list from each chunk in turn. Any order gives the plain loop's ids (nearer_hit's tie rule).
struct Bands {
  std::vector<int> start, fill;
  std::vector<Candidate> entries;
};

// The survivors of culling, in the clusters' memory order: packed at the front of each chunk of `projected`.
// Binning reads them there, cluster by cluster; otherwise they are copied into `visible` first, in the order
// the pixel loops take them.
struct Projection {
  std::vector<Candidate> projected;  // one slot per sphere
  std::vector<int> kept_in_chunk;
  int visible_count = 0;
  // Gathered while projecting (no pass of its own): the survivors' total box area, the tests a cast runs with
  // no skipping.
  long long box_area = 0;
  std::vector<long long> chunk_area;
  std::vector<Candidate> visible;  // filled by join() or, near to far, by a NearToFarSort
  std::vector<Bands> chunk_bands;  // when binned: each chunk's candidates per band
  // Clusters: where each one's survivors start in `projected`, and how many; the clusters near to far, and
  // grouped by chunk (chunk c's: near_clusters[chunk_clusters[c] …]); the chunks near to far.
  std::vector<int> cluster_start, cluster_kept, cluster_order, near_clusters, chunk_clusters, chunk_order;
  std::vector<int> chunk_fill;  // scratch for grouping the clusters by chunk

  template <class Use>
  void for_each_visible(Use&& use) const {
    for (std::size_t chunk = 0; chunk < kept_in_chunk.size(); ++chunk) {
      const Candidate* first = &projected[chunk * kObjectsPerChunk];
      for (const Candidate* c = first; c != first + kept_in_chunk[chunk]; ++c) use(*c);
    }
  }
  // Into `visible` as projected (the footprint and culled methods read them there).
  void join() {
    visible.resize(std::size_t(visible_count));
    std::size_t at = 0;
    for_each_visible([&](const Candidate& c) { visible[at++] = c; });
  }
};

// Candidates near to far by nearest_t. The order is only for speed: any order gives the same ids (nearer_hit's
// tie rule), so a counting sort into buckets of nearest_t over [lowest, highest] (their order within one)
// does: two passes, where a full sort would cost more than the cast it speeds up. The bands sort their own
// candidates, each on its thread: a few thousand, in cache (one sort of 10⁵ candidates scattered them across
// megabytes, on one thread: 13 % of a cast).
struct NearToFarSort {
  std::vector<int> bucket_of, bucket_start;

  // Returns false, with nothing done, when the candidates' nearest_t span no range to sort by.
  template <class ForEach>
  bool operator()(ForEach&& for_each, int count, std::vector<Candidate>& out) {
    double lowest = kNoHit<double>, highest = -kNoHit<double>;
    for_each([&](const Candidate& c) {
      lowest = std::min(lowest, double(c.nearest_t));
      highest = std::max(highest, double(c.nearest_t));
    });
    if (count < 2 || !(highest > lowest) || !std::isfinite(highest - lowest)) return false;
    const int buckets = std::clamp(count / 8, 2, kMaxDepthBuckets);
    const double per_unit = (buckets - 1) / (highest - lowest);
    bucket_of.resize(std::size_t(count));
    bucket_start.assign(std::size_t(buckets) + 1, 0);
    std::size_t at = 0;
    for_each([&](const Candidate& c) {
      const int bucket = int((c.nearest_t - lowest) * per_unit);
      bucket_of[at++] = bucket;
      ++bucket_start[std::size_t(bucket) + 1];
    });
    for (int b = 0; b < buckets; ++b) bucket_start[std::size_t(b) + 1] += bucket_start[std::size_t(b)];
    out.resize(std::size_t(count));
    at = 0;
    for_each([&](const Candidate& c) { out[std::size_t(bucket_start[std::size_t(bucket_of[at++])]++)] = c; });
    return true;
  }
};

// The lower bound behind the near-to-far order. A ray starts at its pixel o on the screen and points away
// from the eye e, so its point at t is at |o − e| + t from e; a hit on a sphere is at least |c − e| − r from
// e; so t ≥ |c − e| − r − max|o − e|, the maximum at a screen corner. Lowered by a slack (10⁻⁶ of the
// numbers' size) far above the stable formula's rounding (about 10⁻⁸ of it, a square root of ε near
// tangency). The naive formula's cancellation has no such bound: -∞, and every covering pixel is tested.
struct NearestTBound {
  glm::dvec3 eye{0.0};
  double corner_distance = 0.0, scale = 0.0;
  bool bounded = false;

  NearestTBound(const Camera3D& camera, IntersectFormula formula, bool wanted)
      : eye(camera.eye()), bounded(wanted && formula == IntersectFormula::stable) {
    for (const glm::dvec3& corner : camera.screen_corners())
      corner_distance = std::max(corner_distance, glm::length(corner - eye));
    scale = corner_distance + glm::length(eye);
  }
  // The bounds of `count` spheres given as columns, into `out`: one loop that vectorises (a scalar square root a
  // sphere, in the projection's loop, was 40 % of its time).
  void operator()(const SphereColumns& spheres, int count, double* out) const {
    if (bounded) bounds_of(eye, corner_distance, scale, spheres.x, spheres.y, spheres.z, spheres.radius, count, out);
    else std::fill(out, out + count, -kNoHit<double>);
  }

 private:
  RAYCAM_VECTOR_LOOP static void bounds_of(glm::dvec3 eye, double corner_distance, double scale,
                                           const double* __restrict x, const double* __restrict y,
                                           const double* __restrict z, const double* __restrict radius, int count,
                                           double* __restrict out) {
    for (int i = 0; i < count; ++i) {
      const double distance = glm::length(glm::dvec3(x[i], y[i], z[i]) - eye);
      out[i] = distance - radius[i] - corner_distance - 1e-6 * (distance + radius[i] + scale);
    }
  }
};

// The bands a candidate's rows meet: first / kBandRows … last / kBandRows.
template <class Use>
inline void for_each_band_of(const Candidate& c, Use&& use) {
  for (int b = c.box.rows.first / kBandRows; b <= c.box.rows.last / kBandRows; ++b) use(std::size_t(b));
}

// Counts a candidate in the bands its rows meet: count[b + 1] for band b.
inline void count_in_bands(const Candidate& c, int* count) {
  for_each_band_of(c, [count](std::size_t b) { ++count[b + 1]; });
}

// Candidate lists per band, each in the order `for_each` gives the candidates, from their counts per band
// (binned.start[b + 1] for band b, by count_in_bands: counted as they were projected, a pass saved).
template <class ForEach>
void bin_by_band(ForEach&& for_each, int bands, Bands& binned) {
  for (int b = 0; b < bands; ++b) binned.start[std::size_t(b) + 1] += binned.start[std::size_t(b)];
  binned.entries.resize(std::size_t(binned.start.back()));
  binned.fill.assign(binned.start.begin(), binned.start.end() - 1);
  for_each([&](const Candidate& c) {
    for_each_band_of(c, [&](std::size_t b) { binned.entries[std::size_t(binned.fill[b]++)] = c; });
  });
}

// The survivors among `size` spheres from `first` of the clusters' columns, appended at `out` (returned: past
// the last); their box area added to `area`. The culled spheres' places are compacted without a branch:
// every sphere's place is written at the next free slot, which only a survivor then keeps. Whether a sphere
// survives is a coin toss when many fall between pixel centres, and a branch on it was mispredicted about
// half the time (measured: a third of the projection's time). Then only the survivors are copied (a copy of
// every sphere, culled or not, was 27 % of a cast of the grazing layer at 256²). `cluster_start` gets, for
// each cluster of the run, where its survivors start. With float_first, the float pass drops what it can
// first (Footprint::spheres_maybe_seen) and only the rest are boxed in double.
Candidate* project_run(const Camera3D& camera, const Footprint& footprint, const NearestTBound& nearest_t,
                       const SphereClusters& spheres, int first, int size, Candidate* out, long long& area,
                       Candidate** cluster_start, int* band_count, bool float_first) {
  PixelBox boxes[kMaxRun];
  double nearest[kMaxRun];
  // The spheres projected in double: all of the run, or those the float pass kept (kept[j] is the run's
  // sphere j's place in the run), gathered into columns.
  int kept[kMaxRun];
  int projected = size;
  const std::size_t at = std::size_t(first);
  SphereColumns columns{&spheres.x[at], &spheres.y[at], &spheres.z[at], &spheres.radius[at]};
  double gathered[4][kMaxRun];
  if (float_first) {
    unsigned char scratch[kMaxRun];
    projected = footprint.spheres_maybe_seen({&spheres.float_x[at], &spheres.float_y[at], &spheres.float_z[at],
                                              &spheres.float_radius[at]},
                                             size, camera.rows(), camera.columns(), kept, scratch);
    for (int j = 0; j < projected; ++j) {
      const std::size_t i = at + std::size_t(kept[j]);
      gathered[0][j] = spheres.x[i];
      gathered[1][j] = spheres.y[i];
      gathered[2][j] = spheres.z[i];
      gathered[3][j] = spheres.radius[i];
    }
    columns = SphereColumns{gathered[0], gathered[1], gathered[2], gathered[3]};
  } else {
    for (int j = 0; j < size; ++j) kept[j] = j;
  }
  footprint.sphere_boxes(columns, projected, camera.rows(), camera.columns(), boxes);
  nearest_t(columns, projected, nearest);
  int survivor[kMaxRun];
  int survivors = 0;
  long long run_area = 0;
  int j = 0;  // the projected sphere next
  for (int cluster = 0; cluster * kBatch < size; ++cluster) {
    cluster_start[cluster] = out + survivors;
    for (const int end = std::min(size, (cluster + 1) * kBatch); j < projected && kept[j] < end; ++j) {
      // Sizes by max, not PixelBox::empty's test: a branch here was as unpredictable as the one above.
      const int box_rows = std::max(0, boxes[j].rows.last - boxes[j].rows.first + 1);
      const int box_columns = std::max(0, boxes[j].columns.last - boxes[j].columns.first + 1);
      survivor[survivors] = j;
      survivors += (box_rows > 0) & (box_columns > 0);
      run_area += static_cast<long long>(box_rows) * box_columns;  // 0 for a culled sphere
    }
  }
  area += run_area;
  // Field by field: a whole Candidate built first went through the stack (a stalled store forward).
  for (int s = 0; s < survivors; ++s) {
    const int k = survivor[s];
    const std::size_t i = at + std::size_t(kept[k]);
    Candidate& c = out[s];
    c.centre = glm::dvec3(spheres.x[i], spheres.y[i], spheres.z[i]);
    c.radius = spheres.radius[i];
    c.nearest_t = float_below(nearest[k]);
    c.box = {{std::int16_t(boxes[k].rows.first), std::int16_t(boxes[k].rows.last)},
             {std::int16_t(boxes[k].columns.first), std::int16_t(boxes[k].columns.last)}};
    c.object = spheres.object[i];
    if (band_count) count_in_bands(c, band_count);
  }
  return out + survivors;
}

// Culls and projects the spheres into w, a chunk of clusters at a time; with bands > 0, also bins each chunk's
// candidates by band. The clusters are projected in memory order, in runs of up to kMaxRun spheres (near to
// far, cluster by cluster, projecting took 17 % longer when none was culled), but binned near to far (the eye's
// side of each split first), and the bands read the chunks near to far too: the candidates then come near to
// far, roughly, in every cast, and the depth test skips much of what is hidden (the grazing layer's tests a
// pixel: 0.85 in the clusters' memory order, 0.53 in the scene's, 0.4 so).
void project_spheres(const Camera3D& camera, const PackedScene3D& scene, const CastOptions& options, int workers,
                     int bands, Projection& w) {
  const IntersectFormula formula = options.formula;
  const Footprint footprint(camera, formula);
  const NearestTBound nearest_t(camera, formula, options.near_to_far);
  const SphereClusters& spheres = scene.clusters;
  const int count = spheres.size(), cluster_count = spheres.cluster_count();
  const int chunks = (count + kObjectsPerChunk - 1) / kObjectsPerChunk;
  const bool cull_clusters = footprint.culls_clusters();
  const bool may_cull_in_float = cull_clusters && options.float_culling;
  w.projected.resize(std::size_t(count));
  w.kept_in_chunk.assign(std::size_t(chunks), 0);
  w.chunk_area.assign(std::size_t(chunks), 0);
  w.chunk_bands.resize(std::size_t(bands > 0 ? chunks : 0));
  w.cluster_start.resize(std::size_t(cluster_count));
  w.cluster_kept.resize(std::size_t(cluster_count));
  if (bands > 0) {  // each chunk's clusters near to far, and the chunks by their nearest cluster
    spheres.near_to_far(camera.eye(), w.cluster_order);
    w.chunk_clusters.assign(std::size_t(chunks) + 1, 0);
    for (int cluster : w.cluster_order) ++w.chunk_clusters[std::size_t(cluster / kClustersPerChunk) + 1];
    for (int chunk = 0; chunk < chunks; ++chunk) w.chunk_clusters[std::size_t(chunk) + 1] += w.chunk_clusters[std::size_t(chunk)];
    w.chunk_order.clear();
    w.near_clusters.resize(std::size_t(cluster_count));
    std::vector<int>& fill = w.chunk_fill;
    fill.assign(w.chunk_clusters.begin(), w.chunk_clusters.end() - 1);
    for (int cluster : w.cluster_order) {
      const int chunk = cluster / kClustersPerChunk;
      if (fill[std::size_t(chunk)] == w.chunk_clusters[std::size_t(chunk)]) w.chunk_order.push_back(chunk);
      w.near_clusters[std::size_t(fill[std::size_t(chunk)]++)] = cluster;
    }
  }
  parallel_items(chunks, count > 2 * kObjectsPerChunk ? workers : 1, [&](int, int chunk) {
    const int first_cluster = chunk * kClustersPerChunk;
    const int clusters = std::min(kClustersPerChunk, cluster_count - first_cluster);
    long long area = 0;
    // The chunk's clusters first: one out of view is skipped whole.
    unsigned char out_of_view[kClustersPerChunk] = {};
    if (cull_clusters) {
      const std::size_t at = std::size_t(first_cluster);
      footprint.clusters_out_of_view({&spheres.bound_x[at], &spheres.bound_y[at], &spheres.bound_z[at], &spheres.bound_radius[at]},
                                     clusters, out_of_view);
    }
    Candidate* const begin = &w.projected[std::size_t(first_cluster) * kBatch];
    Candidate* out = begin;
    int* band_count = nullptr;  // the chunk's candidates per band, counted as they are projected
    if (bands > 0) {
      std::vector<int>& start = w.chunk_bands[std::size_t(chunk)].start;
      start.assign(std::size_t(bands) + 1, 0);
      band_count = start.data();
    }
    // The float pass pays only where most spheres are culled (it costs about half the double pass a sphere,
    // and its survivors are gathered): used for a run when the run before it kept less than 40 % (runs are
    // neighbours in space: the clusters' order). Measured in the page: the clumps at K = 10⁵ (91 % culled)
    // 1.8 → 1.2 ms; used on every run, the cube at 10⁵ (most kept) took 9 % longer.
    bool float_first = false;
    for (int k = 0; k < clusters;) {
      const int cluster = first_cluster + k;
      if (out_of_view[k]) {  // no survivors, at the current place (a place from an earlier cast may be past the end)
        w.cluster_kept[std::size_t(cluster)] = 0;
        w.cluster_start[std::size_t(cluster)] = int(out - w.projected.data());
        ++k;
        continue;
      }
      int run = 1;  // clusters in this run: the kept ones that follow, up to kMaxRun spheres
      while (k + run < clusters && run * kBatch < kMaxRun && !out_of_view[k + run]) ++run;
      const int first = cluster * kBatch, size = std::min(run * kBatch, count - first);
      Candidate* starts[kMaxRun / kBatch];
      Candidate* const run_start = out;
      out = project_run(camera, footprint, nearest_t, spheres, first, size, out, area, starts, band_count, float_first);
      float_first = may_cull_in_float && (out - run_start) * 5 < size * 2;
      for (int r = 0; r < run; ++r)
        w.cluster_kept[std::size_t(cluster + r)] = int((r + 1 < run ? starts[r + 1] : out) - starts[r]);
      for (int r = 0; r < run; ++r) w.cluster_start[std::size_t(cluster + r)] = int(starts[r] - w.projected.data());
      k += run;
    }
    const int kept = int(out - begin);
    w.kept_in_chunk[std::size_t(chunk)] = kept;
    w.chunk_area[std::size_t(chunk)] = area;
    if (bands > 0) {
      const int* near = &w.near_clusters[std::size_t(w.chunk_clusters[std::size_t(chunk)])];
      const int* near_end = &w.near_clusters[0] + w.chunk_clusters[std::size_t(chunk) + 1];
      bin_by_band([&](auto&& use) {
        for (const int* cluster = near; cluster != near_end; ++cluster) {
          const Candidate* c = &w.projected[std::size_t(w.cluster_start[std::size_t(*cluster)])];
          std::for_each(c, c + w.cluster_kept[std::size_t(*cluster)], use);
        }
      }, bands, w.chunk_bands[std::size_t(chunk)]);
    }
  });
  w.visible_count = 0;
  w.box_area = 0;
  for (std::size_t chunk = 0; chunk < w.kept_in_chunk.size(); ++chunk) {
    w.visible_count += w.kept_in_chunk[chunk];
    w.box_area += w.chunk_area[chunk];
  }
}

// The 2D bar's depth buffer, with a line of rays made by the camera's primary_rays.
template <class Ray>
struct DepthBuffer {
  std::vector<double> depth;
  std::vector<int> id;       // the object seen (its index in the scene), -1 for none
  std::vector<Rgb8> colour;  // its colour
  std::vector<unsigned char> touched;
  std::vector<Ray> rays;
  long long tests = 0, touched_pixels = 0;
  void reset(std::size_t pixels, int line) {
    rays.resize(std::size_t(line));
    depth.assign(pixels, kNoHit<double>);
    id.assign(pixels, -1);
    colour.resize(pixels);  // read only where id ≥ 0
    touched.assign(pixels, 0);
  }
  // The plain loop's depth test: strict '<' in object order keeps the lower index on a tie.
  template <class Vector>
  void test(std::size_t p, const Ray& ray, const Vector& centre, double radius, int object,
            Rgb8 object_colour, IntersectFormula formula) {
    touched_pixels += touched[p] == 0;
    touched[p] = 1;
    const double t = nearest_hit_t(ray.origin, ray.direction, centre, radius, formula);
    ++tests;
    if (t < depth[p]) {
      depth[p] = t;
      id[p] = object;
      colour[p] = object_colour;  // kept now, while the object is in cache: no lookup per pixel afterwards
    }
  }
};

// One worker's band of pixels, and what it did. On a cache line of its own: its counters change at every
// row, and two workers' counters sharing a line would slow both.
struct alignas(64) BandScratch {
  BandPixels pixels;
  std::vector<unsigned char> ray_blocks;  // per row, which blocks of kRayBlock columns need rays
  NearToFarSort sort;
  std::vector<Candidate> sorted;          // the band's candidates near to far
  long long tests = 0, covered_pixels = 0;
};

// Memory a cast reuses from the last cast on the same calling thread. Fresh megabytes each frame would cost
// page faults that no second thread can share (measured: projecting 10⁵ spheres took as long on two
// threads as on one).
struct Workspace {
  Projection projection;
  std::vector<BandScratch> scratch;  // one per worker
  std::vector<double> column_x;
  NearToFarSort sort;                // the footprint method's, over all candidates
};

// The calling thread's: its helpers write into it, each their own part.
Workspace& calling_thread_workspace() {
  thread_local Workspace workspace;
  return workspace;
}

// Tests a candidate on its box (clipped to the band's rows), whose rays the band holds.
void splat(const Candidate& candidate, int columns, int row_begin, int row_end, IntersectFormula formula,
           BandScratch& scratch) {
  const auto& box = candidate.box;
  const int first = std::max(int(box.rows.first), row_begin), last = std::min(int(box.rows.last), row_end - 1);
  const PixelRun run{std::size_t(first - row_begin) * std::size_t(columns) + std::size_t(box.columns.first),
                     box.columns.last - box.columns.first + 1, last - first + 1, columns};
  if (run.rows <= 0) return;
  scratch.tests += test_sphere(candidate.centre, candidate.radius, candidate.nearest_t, candidate.object, formula, run,
                               scratch.pixels);
}

// Background and colours by value and pointer: read through the scene, they could alias the colours'
// byte stores, and were read again at every pixel. The ids in one copy; the colours eight pixels at a time:
// where none of them is hit (most of a sparse scene's image) the background in one copy of 24 bytes, a
// pixel's three byte stores and its select costing more (half of a cast of 50 spheres in the page).
void write_band(Rgb8 background, const Rgb8* colour, int row_begin, int row_end, BandScratch& scratch, ColourMap& out) {
  const std::size_t offset = out.index(row_begin, 0);
  const std::size_t pixels = std::size_t(row_end - row_begin) * out.width;
  const int* id = scratch.pixels.id.data();
  std::memcpy(&out.ids[offset], id, pixels * sizeof(int));
  Rgb8* colours = &out.colours[offset];
  constexpr std::size_t kGroup = 8;
  Rgb8 backgrounds[kGroup];
  std::fill(std::begin(backgrounds), std::end(backgrounds), background);
  const auto write_each = [&](std::size_t first, std::size_t end) {
    for (std::size_t p = first; p < end; ++p) colours[p] = id[p] < 0 ? background : colour[id[p]];
  };
  std::size_t p = 0;
  for (; p + kGroup <= pixels; p += kGroup) {
    // Two ids a 64-bit word: the group is all background when every id's sign bit is set. A loop over the eight
    // ids compiled to eight scalar steps in WebAssembly (the page's colours took twice as long).
    std::uint64_t words[kGroup / 2];
    std::memcpy(words, id + p, sizeof words);
    const std::uint64_t all = words[0] & words[1] & words[2] & words[3];
    constexpr std::uint64_t kSigns = 0x8000000080000000u;
    if ((all & kSigns) == kSigns) std::memcpy(colours + p, backgrounds, sizeof backgrounds);
    else write_each(p, p + kGroup);
  }
  write_each(p, pixels);
  // A byte a pixel, 0 or 1: eight at a time, their sum in a word's top byte after one multiplication (a loop over
  // the bytes took twice as long in WebAssembly; natively the same time).
  std::uint32_t covered = 0;
  const unsigned char* cov = scratch.pixels.covered.data();
  std::size_t q = 0;
  for (; q + 8 <= pixels; q += 8) {
    std::uint64_t w;
    std::memcpy(&w, cov + q, 8);
    covered += std::uint32_t((w * 0x0101010101010101u) >> 56);
  }
  for (; q < pixels; ++q) covered += cov[q];
  scratch.covered_pixels += covered;
}
}  // namespace

void cast_accelerated(const Camera3D& camera, const PackedScene3D& scene, ColourMap& out,
                      const CastOptions& options, CastStats& stats) {
  const int rows = camera.rows(), columns = camera.columns();
  const long long pixels = static_cast<long long>(rows) * columns;
  const int threads = resolve_threads(options.threads);
  Workspace& workspace = calling_thread_workspace();
  const int bands = (rows + kBandRows - 1) / kBandRows;
  // Binned while projecting whenever the method may be binned: for automatic, that is known only after.
  const bool may_bin = options.method == CastMethod::binned || options.method == CastMethod::automatic;
  project_spheres(camera, scene, options, threads, may_bin ? bands : 0, workspace.projection);
  Projection& projection = workspace.projection;
  const std::vector<Candidate>& visible = projection.visible;
  const long long visible_count = projection.visible_count;

  CastMethod method = options.method;
  if (method == CastMethod::automatic)
    method = visible_count <= kBinnedCrossover ? CastMethod::footprint : CastMethod::binned;
  // Each candidate costs a few tests' worth besides its tests (its rows of rays, its bands).
  long long work = pixels / 4 + 4 * visible_count;
  // The tests with no skipping. Sorting costs a pass over the candidates; it pays where they cover each pixel
  // at least kNearToFarDepth times on average (else few tests could be skipped) and each candidate's box holds
  // at least kNearToFarBoxPixels pixels (else the sort costs about what the tests it skips would).
  const long long box_area = method == CastMethod::culled ? pixels * visible_count : projection.box_area;
  const bool near_to_far = options.near_to_far && method != CastMethod::culled &&
                           double(box_area) >= kNearToFarDepth * double(pixels) &&
                           double(box_area) >= kNearToFarBoxPixels * double(visible_count);
  // Binned while projecting, each band sorting its own near to far; otherwise all visible at once.
  const auto for_each_visible = [&](auto&& use) { projection.for_each_visible(use); };
  if (method != CastMethod::binned &&
      !(near_to_far && workspace.sort(for_each_visible, int(visible_count), projection.visible)))
    projection.join();
  work += box_area;
  const int workers = work >= kThreadedWork ? threads : 1;
  std::vector<double>& column_x = workspace.column_x;  // every row's rays use the same canonical x
  column_x.resize(std::size_t(columns));
  for (int column = 0; column < columns; ++column) column_x[std::size_t(column)] = camera.canonical_x(column);
  std::vector<BandScratch>& scratch = workspace.scratch;
  scratch.resize(std::size_t(std::min(workers, bands)));
  for (BandScratch& s : scratch) s.tests = s.covered_pixels = 0;
  parallel_items(bands, workers, [&](int worker, int band) {
    BandScratch& s = scratch[std::size_t(worker)];
    const int row_begin = band * kBandRows, row_end = std::min(rows, row_begin + kBandRows);
    const int band_rows = row_end - row_begin;
    s.pixels.reset(std::size_t(band_rows) * columns);
    const auto row_at = [&](int row) { return std::size_t(row - row_begin) * std::size_t(columns); };
    if (method == CastMethod::culled) {  // every pixel, every object that survived culling
      for (int row = row_begin; row < row_end; ++row) make_row_rays(camera, row, 0, columns - 1, column_x, s.pixels, row_at(row));
      for (const Candidate& c : visible)
        s.tests += test_sphere(c.centre, c.radius, c.nearest_t, c.object, options.formula,
                               PixelRun{0, columns, band_rows, columns}, s.pixels);
    } else {
      // The band's candidates, near to far: its bin (sorted here), or every visible object whose rows meet the
      // band.
      int bin_size = 0;
      if (method == CastMethod::binned)
        for (const Bands& chunk : projection.chunk_bands)
          bin_size += chunk.start[std::size_t(band) + 1] - chunk.start[std::size_t(band)];
      const auto for_each_in_bin = [&](auto&& use) {
        for (int c : projection.chunk_order) {
          const Bands& chunk = projection.chunk_bands[std::size_t(c)];
          std::for_each(chunk.entries.data() + chunk.start[std::size_t(band)],
                        chunk.entries.data() + chunk.start[std::size_t(band) + 1], use);
        }
      };
      const bool sort_bin = method == CastMethod::binned && near_to_far && s.sort(for_each_in_bin, bin_size, s.sorted);
      const auto for_each_candidate = [&](auto&& use) {
        if (sort_bin) {
          for (const Candidate& c : s.sorted) use(c);
        } else if (method == CastMethod::binned) {
          for_each_in_bin(use);
        } else {
          for (const Candidate& c : visible)
            if (c.box.rows.last >= row_begin && c.box.rows.first < row_end) use(c);
        }
      };
      // Rays only where a box needs them (unless the band is dense: kCandidatesPerRayMarking): blocks of
      // kRayBlock columns are marked, then each run of marked blocks gets its rays in one vectorised call (a few
      // calls a row, not one per object and row).
      const int blocks = (columns + kRayBlock - 1) / kRayBlock;
      const long long band_candidates = method == CastMethod::binned ? bin_size : visible_count;
      const bool every_ray = band_candidates * kCandidatesPerRayMarking >= static_cast<long long>(band_rows) * columns;
      s.ray_blocks.assign(std::size_t(band_rows) * std::size_t(blocks), every_ray ? 1 : 0);
      if (!every_ray) for_each_candidate([&](const Candidate& c) {
        const int first = std::max(int(c.box.rows.first), row_begin), last = std::min(int(c.box.rows.last), row_end - 1);
        for (int row = first; row <= last; ++row)
          std::fill(&s.ray_blocks[std::size_t(row - row_begin) * blocks + std::size_t(c.box.columns.first / kRayBlock)],
                    &s.ray_blocks[std::size_t(row - row_begin) * blocks + std::size_t(c.box.columns.last / kRayBlock)] + 1, 1);
      });
      for (int row = row_begin; row < row_end; ++row) {
        const unsigned char* marked = &s.ray_blocks[std::size_t(row - row_begin) * blocks];
        const unsigned char* end = marked + blocks;
        for (const unsigned char* b = marked; (b = static_cast<const unsigned char*>(std::memchr(b, 1, std::size_t(end - b))));) {
          const unsigned char* e = static_cast<const unsigned char*>(std::memchr(b, 0, std::size_t(end - b)));
          if (!e) e = end;
          make_row_rays(camera, row, int(b - marked) * kRayBlock, std::min(columns, int(e - marked) * kRayBlock) - 1,
                        column_x, s.pixels, row_at(row));
          b = e;
        }
      }
      for_each_candidate([&](const Candidate& c) { splat(c, columns, row_begin, row_end, options.formula, s); });
    }
    run_pending_tests(options.formula, s.pixels);
    write_band(scene.background, scene.colour.data(), row_begin, row_end, s, out);
  });

  stats.rays = pixels;
  stats.objects_culled = static_cast<long long>(scene.size()) - visible_count;
  stats.intersection_tests = 0;
  long long covered = 0;
  for (const BandScratch& s : scratch) {
    stats.intersection_tests += s.tests;
    covered += s.covered_pixels;
  }
  stats.pixels_skipped = pixels - covered;
  stats.threads = int(scratch.size());
  stats.box_tests = box_area;
}

int project_visible(const Camera3D& camera, const PackedScene3D& scene, const CastOptions& options) {
  Workspace& workspace = calling_thread_workspace();
  project_spheres(camera, scene, options, resolve_threads(options.threads), 0, workspace.projection);
  return workspace.projection.visible_count;
}

void cast_accelerated(const Camera2D& camera, const Scene2D& scene, ColourMap& out, const CastOptions& options,
                      CastStats& stats) {
  // The 3D algorithm on one row, on one thread: a bar of a few thousand pixels takes microseconds.
  const Footprint footprint(camera, options.formula);
  const int n = camera.pixel_count();
  std::vector<int> visible;
  std::vector<PixelRange> range;
  for (int i = 0; i < int(scene.circles.size()); ++i) {
    const PixelRange r = footprint.circle_pixels(scene.circles[std::size_t(i)], n);
    if (r.empty()) continue;
    visible.push_back(i);
    range.push_back(options.method == CastMethod::culled ? PixelRange{0, n - 1} : r);
  }
  DepthBuffer<Ray2D> bar;  // ids are object indices
  bar.reset(std::size_t(n), n);
  for (std::size_t j = 0; j < visible.size(); ++j) {  // object order
    const Circle& circle = scene.circles[std::size_t(visible[j])];
    camera.primary_rays(range[j].first, range[j].last, bar.rays.data());
    for (int k = range[j].first; k <= range[j].last; ++k)
      bar.test(std::size_t(k), bar.rays[std::size_t(k - range[j].first)], circle.centre, circle.radius,
               visible[j], circle.colour, options.formula);
  }
  for (int k = 0; k < n; ++k) {
    const std::size_t column = std::size_t(camera.column_of_pixel(k));
    const int object = bar.id[std::size_t(k)];
    out.ids[column] = object;
    out.colours[column] = object < 0 ? scene.background : bar.colour[std::size_t(k)];
  }
  stats = CastStats{n, bar.tests, static_cast<long long>(scene.circles.size() - visible.size()),
                    n - bar.touched_pixels, 1};
}

}  // namespace raycam::detail
