// Loops written to vectorise. The build targets plain x86-64 (SSE2: two doubles a vector); on GCC, a function
// marked RAYCAM_VECTOR_LOOP is also built for AVX2 (four doubles) and that copy is picked when the program
// loads on a CPU that has it. flatten inlines everything the loop calls, so that it vectorises at -O2. The
// copies run the same operations in the same order with no FMA (-ffp-contract=off): they give the same bits.
// The files holding such loops are compiled with the flags that let GCC vectorise them (CMakeLists.txt).
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RAYCAM_VECTOR_LOOP __attribute__((flatten, target_clones("avx2", "default")))
#else
#define RAYCAM_VECTOR_LOOP
#endif
