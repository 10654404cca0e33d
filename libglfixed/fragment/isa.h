// The lane types of the fragment stage. The block shader (block_shader.inc)
// is written once on them and compiled twice: for any x86-64 CPU, and with
// AVX2 and FMA, where llvmpipe itself runs eight lanes with these
// instructions. Both give the same bits: every operation is an IEEE
// single-precision operation, fused multiply-adds only where written (fma),
// float-to-int conversions round to nearest even.
#pragma once

#include <immintrin.h>

#include <cmath>
#include <cstdint>

#include "fragment/lanes.h"

namespace glfixed::fragment {

// GCC vector extensions: arithmetic, comparisons (lanes of -1 or 0) and
// `mask ? a : b` work lane by lane; one AVX register, or two SSE ones.
typedef float F8 __attribute__((vector_size(32)));
typedef int32_t I8 __attribute__((vector_size(32)));
typedef int32_t I4 __attribute__((vector_size(16)));
typedef uint16_t U16x4 __attribute__((vector_size(8)));

// Always inlined, even unoptimized: a function taking or returning a vector
// type has another calling convention in the AVX2 build than in the generic
// one, so none may be called across them.
#define GLFIXED_INLINE __attribute__((always_inline)) inline

GLFIXED_INLINE F8 load(const Lanes& l) {
  F8 v;
  __builtin_memcpy(&v, l.v, sizeof v);
  return v;
}
GLFIXED_INLINE void store(Lanes& l, F8 v) { __builtin_memcpy(l.v, &v, sizeof v); }

bool haveAvx2Fma();

}  // namespace glfixed::fragment
