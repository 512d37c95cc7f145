#include "band_kernels.h"

#include <cassert>

#include "primary_ray.h"
#include "raycam/classic_mistakes.h"
#include "vector_loops.h"

namespace raycam::detail {

namespace {
RAYCAM_VECTOR_LOOP void rays_of_line(const Camera3D::RayLine line, const double* column_x, int columns, double* ox,
                                     double* oy, double* oz, double* dx, double* dy, double* dz) {
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

// kFormula is fixed for the whole loop, so that only its own arithmetic is in it. Scalar: at 10⁵ spheres a
// box is a few pixels wide, too short for vectors (measured: a vectorised row was slower); but with
// nearest_hit_t written without branches, a ray that misses costs no mispredicted branch.
template <IntersectFormula kFormula>
void test_run(const glm::dvec3& centre, double radius, int object, const PixelRun& run, BandPixels& band) {
  for (int row = 0; row < run.rows; ++row) {
    const std::size_t begin = run.at + std::size_t(row) * std::size_t(run.stride), end = begin + std::size_t(run.count);
    for (std::size_t p = begin; p < end; ++p) {
      const double t = nearest_hit_t(glm::dvec3(band.ox[p], band.oy[p], band.oz[p]),
                                     glm::dvec3(band.dx[p], band.dy[p], band.dz[p]), centre, radius, kFormula);
      const bool nearer = t < band.depth[p];
      band.depth[p] = nearer ? t : band.depth[p];
      band.id[p] = nearer ? object : band.id[p];
      band.covered[p] = 1;
    }
  }
}
}  // namespace

void BandPixels::reset(std::size_t pixels) {
  for (std::vector<double>* column : {&ox, &oy, &oz, &dx, &dy, &dz}) column->resize(pixels);
  depth.assign(pixels, kNoHit<double>);
  id.assign(pixels, -1);
  covered.assign(pixels, 0);
}

void make_row_rays(const Camera3D& camera, int row, const std::vector<double>& column_x, BandPixels& band,
                   std::size_t at) {
  assert(mistakes_change_only_placement(camera.mistakes()) && int(column_x.size()) == camera.columns());
  rays_of_line(camera.ray_line(row), column_x.data(), camera.columns(), &band.ox[at], &band.oy[at], &band.oz[at],
               &band.dx[at], &band.dy[at], &band.dz[at]);
}

void test_sphere(const glm::dvec3& centre, double radius, int object, IntersectFormula formula, const PixelRun& run,
                 BandPixels& band) {
  if (formula == IntersectFormula::naive) test_run<IntersectFormula::naive>(centre, radius, object, run, band);
  else test_run<IntersectFormula::stable>(centre, radius, object, run, band);
}

}  // namespace raycam::detail
