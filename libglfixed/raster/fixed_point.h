// Sub-pixel snapping: window coordinates to fixed point with 8 fractional bits,
// the way llvmpipe does it (lp_setup_tri.c, calc_fixed_position).
#pragma once

#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace glfixed::raster {

// GL_SUBPIXEL_BITS: 8 (REFERENCE.md, "Coverage").
constexpr int kSubpixelBits = 8;
constexpr int32_t kFixedOne = 1 << kSubpixelBits;

// Float to int32 as x86's cvtss2si/cvtps2dq do it (llvmpipe's iround): round
// to nearest, ties to even; NaN and values out of range give INT32_MIN (the
// "integer indefinite").
inline int32_t roundToInt32(float v) {
#if defined(__SSE2__)
  return _mm_cvtss_si32(_mm_set_ss(v));
#else
  if (!(v >= -2147483648.0f && v < 2147483648.0f)) return INT32_MIN;
  return static_cast<int32_t>(std::nearbyint(v));
#endif
}

// A window coordinate to fixed point. llvmpipe moves the pixel centre to the
// integer grid first: a single-precision subtraction of 0.5, then the scale by
// 256 (exact), then round to nearest even. Pixel (i, j) then sits at the fixed
// point (256 i, 256 j).
inline int32_t snapToFixed(float windowCoord) {
  float centred = windowCoord - 0.5f;
  return roundToInt32(centred * static_cast<float>(kFixedOne));
}

}  // namespace glfixed::raster
