// Ray / circle and ray / sphere intersection: the nearest t ≥ 0 along a ray with a UNIT direction.
// Templated on the scalar (float, double, long double) and the dimension (2 for circles, 3 for spheres).
//
// naive:  the textbook quadratic t² + 2bt + c = 0 with Δ = b² - c; cancels catastrophically when the
//         ray starts far away (b² ≈ c) and when the two roots differ greatly in size.
// stable: Δ from the perpendicular distance (r² - |f - b·u|²), and the smaller root from q = -(b + sign(b)√Δ)
//         then c/q (Haines, Günther, Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection",
//         Ray Tracing Gems, 2019).
// A ray starting inside the ball hits its far side (the smallest non-negative root).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace raycam {

enum class IntersectFormula { stable, naive };

template <class T>
inline constexpr T kNoHit = std::numeric_limits<T>::infinity();

// std::copysign(magnitude, sign), the same bits. In WebAssembly a double's is masks on its bits: LLVM 14 has
// no vector copysign there, and took each lane of a vector out to a scalar copysign and back (the page's cast
// of radii ×20 at K = 10³: 0.79 -> 0.76 ms, in Node).
template <class T>
inline T copysign_bits(T magnitude, T sign) {
#ifdef __wasm__
  if constexpr (std::is_same_v<T, double>) {
    constexpr std::uint64_t kSign = std::uint64_t(1) << 63;
    std::uint64_t m, s;
    std::memcpy(&m, &magnitude, sizeof m);
    std::memcpy(&s, &sign, sizeof s);
    const std::uint64_t bits = (m & ~kSign) | (s & kSign);
    double result;
    std::memcpy(&result, &bits, sizeof result);
    return result;
  }
#endif
  return std::copysign(magnitude, sign);
}

// Written without branches (every value computed, then selected): the accelerated caster's loop over a row of
// pixels vectorises, and a ray that misses half the time costs no mispredicted branch. The values are those
// of the early-return form, bit for bit: only which one is returned is chosen by selects.
template <int D, class T>
T nearest_hit_t(const glm::vec<D, T>& origin, const glm::vec<D, T>& unit_direction,
                const glm::vec<D, T>& centre, T radius, IntersectFormula formula) {
  const glm::vec<D, T> f = origin - centre;
  const T b = glm::dot(f, unit_direction);
  const T c = glm::dot(f, f) - radius * radius;  // > 0: origin outside the ball
  const bool moving_away = c > T(0) && b > T(0);  // outside and moving away: both roots negative
  T disc, t_near, t_far;
  bool tangent_at_origin = false;
  if (formula == IntersectFormula::naive) {
    disc = b * b - c;
    const T root = std::sqrt(disc < T(0) ? T(0) : disc);
    t_near = -b - root;
    t_far = -b + root;
  } else {
    const glm::vec<D, T> perpendicular = f - b * unit_direction;
    disc = radius * radius - glm::dot(perpendicular, perpendicular);
    const T q = -b - copysign_bits(std::sqrt(disc < T(0) ? T(0) : disc), b);
    tangent_at_origin = q == T(0);
    const T t_other = c / q;  // product of the roots is c
    t_near = q < t_other ? q : t_other;
    t_far = q < t_other ? t_other : q;
  }
  T t = t_near >= T(0) ? t_near : (t_far >= T(0) ? t_far : kNoHit<T>);
  t = tangent_at_origin ? T(0) : t;
  return moving_away || disc < T(0) ? kNoHit<T> : t;
}

// The classic mistake no_t_min (ClassicMistakes): the smaller root of the same quadratic whatever its sign,
// so a hit behind the ray's origin counts (and beats any in front); kNoHit only when the line misses.
template <int D, class T>
T smaller_root_t(const glm::vec<D, T>& origin, const glm::vec<D, T>& unit_direction,
                 const glm::vec<D, T>& centre, T radius, IntersectFormula formula) {
  const glm::vec<D, T> f = origin - centre;
  const T b = glm::dot(f, unit_direction);
  const T c = glm::dot(f, f) - radius * radius;
  if (formula == IntersectFormula::naive) {
    const T disc = b * b - c;
    return disc < T(0) ? kNoHit<T> : -b - std::sqrt(disc);
  }
  const glm::vec<D, T> perpendicular = f - b * unit_direction;
  const T disc = radius * radius - glm::dot(perpendicular, perpendicular);
  if (disc < T(0)) return kNoHit<T>;
  const T q = -b - std::copysign(std::sqrt(disc), b);
  if (q == T(0)) return std::min(T(0), -T(2) * b);  // c = 0: the roots are 0 and -2b
  const T t_other = c / q;
  return q < t_other ? q : t_other;
}

}  // namespace raycam
