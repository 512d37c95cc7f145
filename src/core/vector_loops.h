// Loops written to vectorise. The build targets plain x86-64 (SSE2: two doubles a vector); on GCC, a
// function marked RAYCAM_VECTOR_LOOP is also built for AVX2 (four doubles) and for x86-64-v4 (AVX-512:
// eight), and the best copy the CPU runs is picked when the program loads (measured on this Zen 5 machine:
// projecting 10⁵ spheres took 1.11 ms with AVX2, 0.72 ms with AVX-512, one thread). flatten inlines what the
// loop calls, so that it vectorises at -O2. The copies run the same operations in the same order, with no
// FMA (-ffp-contract=off, though x86-64-v4 has it): they give the same bits. The tests run the copy this
// CPU picks, and the others under qemu (tests/core/CMakeLists.txt). The files holding such loops are
// compiled with the flags that let GCC vectorise them (src/core/CMakeLists.txt).
#pragma once

// Built with -DRAYCAM_VECTOR_CLONES=OFF, one copy for x86-64-v2 (SSE4.2: two doubles a vector, and the
// rounding instructions, as WebAssembly's SIMD has): native timed at the page's width.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(RAYCAM_NO_VECTOR_CLONES)
#define RAYCAM_VECTOR_LOOP __attribute__((flatten, target("arch=x86-64-v2")))
#elif defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RAYCAM_VECTOR_LOOP __attribute__((flatten, target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define RAYCAM_VECTOR_LOOP
#endif

namespace raycam::detail {
// Selects on values, for the loops above (branch-free: a vector unit's min and max, with a's side on a tie or
// a NaN in b), in double (the boxes) and in float (the float culling pass).
template <class T>
inline T lower(T a, T b) {
  return b < a ? b : a;
}
template <class T>
inline T higher(T a, T b) {
  return a < b ? b : a;
}
}  // namespace raycam::detail
