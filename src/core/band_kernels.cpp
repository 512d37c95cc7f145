#include "core/band_kernels.h"

#include <cassert>

#include "core/primary_ray.h"
#include "raycam/classic_mistakes.h"
#include "core/vector_loops.h"

namespace raycam::detail {

namespace {
// __restrict: the arrays are distinct; without it GCC would need more run-time overlap checks than it
// allows itself, and would not vectorise.
RAYCAM_VECTOR_LOOP void rays_of_line(const Camera3D::RayLine line, const double* __restrict column_x, int columns,
                                     double* __restrict ox, double* __restrict oy, double* __restrict oz,
                                     double* __restrict dx, double* __restrict dy, double* __restrict dz) {
  // Locals: the stores below could alias the line's fields, which would keep the loop from vectorising.
  const glm::dvec3 origin_base = line.origin_base, direction_base = line.direction_base, axis = line.axis;
  for (int i = 0; i < columns; ++i) {
    glm::dvec3 origin, direction;
    ray_on_line(origin_base, direction_base, axis, column_x[i], true, origin, direction);
    ox[i] = origin.x;
    oy[i] = origin.y;
    oz[i] = origin.z;
    dx[i] = direction.x;
    dy[i] = direction.y;
    dz[i] = direction.z;
  }
}


template <IntersectFormula kFormula>
RAYCAM_VECTOR_LOOP void test_row(glm::dvec3 centre, double radius, int object, int count,
                                 const double* __restrict ox, const double* __restrict oy,
                                 const double* __restrict oz, const double* __restrict dx,
                                 const double* __restrict dy, const double* __restrict dz,
                                 double* __restrict depth, int* __restrict id, unsigned char* __restrict covered) {
  for (int i = 0; i < count; ++i)
    test_pixel<kFormula>(centre, radius, object, std::size_t(i), ox, oy, oz, dx, dy, dz, depth, id, covered);
}
template <IntersectFormula kFormula>
RAYCAM_VECTOR_LOOP void pending_hits(PendingTests& q) {
  const int count = q.count;
  for (int i = 0; i < count; ++i)
    q.t[i] = nearest_hit_t(glm::dvec3(q.ox[i], q.oy[i], q.oz[i]), glm::dvec3(q.dx[i], q.dy[i], q.dz[i]),
                           glm::dvec3(q.cx[i], q.cy[i], q.cz[i]), q.radius[i], kFormula);
}
}  // namespace

void run_pending_tests(IntersectFormula formula, BandPixels& band) {
  PendingTests& q = band.pending;
  if (formula == IntersectFormula::naive) pending_hits<IntersectFormula::naive>(q);
  else pending_hits<IntersectFormula::stable>(q);
  // In order: two tests of one pixel must not race. Locals, and selects without a branch: whether a test
  // wins is a coin toss (a branch on it was mispredicted, the loop a sixth of a cast at K = 10⁵, 1024²).
  double* __restrict depth = band.depth.data();
  int* __restrict id = band.id.data();
  const int count = q.count;
  for (int i = 0; i < count; ++i) {
    const std::size_t p = std::size_t(q.pixel[i]);
    const double t = q.t[i], held = depth[p];
    const int object = q.object[i], held_id = id[p];
    const bool nearer = nearer_hit(t, object, held, held_id);
    depth[p] = nearer ? t : held;
    id[p] = nearer ? object : held_id;
  }
  q.count = 0;
}

void BandPixels::reset(std::size_t pixels) {
  pending.count = 0;
  for (std::vector<double>* column : {&ox, &oy, &oz, &dx, &dy, &dz}) column->resize(pixels);
  depth.assign(pixels, kNoHit<double>);
  id.assign(pixels, -1);
  covered.assign(pixels, 0);
}

void make_row_rays(const Camera3D& camera, int row, int first, int last, const std::vector<double>& column_x,
                   BandPixels& band, std::size_t row_at) {
  assert(mistakes_change_only_placement(camera.mistakes()) && int(column_x.size()) == camera.columns());
  assert(first >= 0 && last < camera.columns());
  const std::size_t at = row_at + std::size_t(first);
  rays_of_line(camera.ray_line(row), &column_x[std::size_t(first)], last - first + 1, &band.ox[at], &band.oy[at],
               &band.oz[at], &band.dx[at], &band.dy[at], &band.dz[at]);
}

void test_sphere_vectorised(const glm::dvec3& centre, double radius, int object, IntersectFormula formula,
                            const PixelRun& run, BandPixels& band) {
  const auto row_test = formula == IntersectFormula::naive ? test_row<IntersectFormula::naive>
                                                           : test_row<IntersectFormula::stable>;
  for (int row = 0; row < run.rows; ++row) {
    const std::size_t at = run.at + std::size_t(row) * std::size_t(run.stride);
    row_test(centre, radius, object, run.count, &band.ox[at], &band.oy[at], &band.oz[at], &band.dx[at],
             &band.dy[at], &band.dz[at], &band.depth[at], &band.id[at], &band.covered[at]);
  }
}

}  // namespace raycam::detail
