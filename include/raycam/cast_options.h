// What a cast is asked (CastMethod, CastOptions) and what it gives back (each ray's Hit, the work done:
// CastStats): the words the dispatcher (raycam/ray_caster.h) and the accelerated casters it calls
// (src/core/footprint_caster.h) share, in a header of their own so that neither includes the other.
#pragma once

#include <optional>
#include <string_view>

#include "raycam/intersect.h"

namespace raycam {

struct Hit {
  int id = -1;  // object index, -1 for background
  double t = kNoHit<double>;
};

enum class CastMethod {
  automatic,  // footprint or binned, by the crossover measured with `raycam-cli bench speed`
  plain,      // every object for every pixel (the handout's loop; the reference)
  culled,     // objects behind the screen or outside the field of view dropped once, then every pixel
  footprint,  // each object tested only on the pixels of its projection's bounding box
  binned,     // footprint, with objects sorted into bands of rows first (for many objects)
};
inline constexpr CastMethod kCastMethods[] = {CastMethod::automatic, CastMethod::plain, CastMethod::culled,
                                             CastMethod::footprint, CastMethod::binned};
// "automatic", "plain", ...: the names the command line and the app show.
const char* cast_method_name(CastMethod method);
// The method of that name, or nothing (a pure lookup: what to say about a bad name is the caller's business).
std::optional<CastMethod> cast_method_named(std::string_view name);

struct CastOptions {
  IntersectFormula formula = IntersectFormula::stable;
  CastMethod method = CastMethod::automatic;
  int threads = 0;  // 0: all hardware threads; 3D only (a 2D bar takes microseconds on one)
  // 3D footprint and binned casters: take each pixel's candidates near to far and skip those that cannot
  // be nearer than its hit so far (the stable formula only). false: object order and every test, the
  // caster as it was before (the speed bench's before/after). The ids are the same either way.
  bool near_to_far = true;
  // 3D footprint and binned casters: a first culling pass in single precision, proven never to drop a sphere
  // the double pass keeps (src/core/float_culling.cpp), where most spheres are culled; the same ids either
  // way. false: the double pass alone (the speed bench's before/after).
  bool float_culling = true;
};

// Work done by one cast, shown by the app's status line.
struct CastStats {
  long long rays = 0;                // pixels answered
  long long intersection_tests = 0;  // ray/object tests actually run
  long long objects_culled = 0;      // behind the screen or outside the field of view: never tested
  long long pixels_skipped = 0;      // pixels no object can cover: background without casting a ray
  int threads = 1;                   // threads that shared the pixels (one when the work is too small)
  long long box_tests = 0;           // 3D accelerated: the tests with no skipping (the boxes' total area,
                                     // so box_tests / rays is the depth complexity of what overlaps)
};

}  // namespace raycam
