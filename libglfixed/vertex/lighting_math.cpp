// gallivm's exp2, log2 and pow (Mesa src/gallium/auxiliary/gallivm/lp_bld_arit.c,
// Mesa 22.3), written from their definition: the same polynomial coefficients
// (rounded to float, as gallivm's constant vectors are), the same even/odd
// evaluation order, and fused multiply-adds where gallivm emits llvm.fmuladd.
// The code (lighting_pow.inc) is compiled twice: with FMA instructions where
// the CPU has them, and with the exact software fmaf elsewhere; both give the
// same results.
#include "vertex/lighting_math.h"

#include <cstdint>
#include <cstring>
#include <limits>

namespace glfixed::vertex::lp {

namespace {

inline uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}
inline float fromBits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

namespace software {
#define LP_FMA(a, b, c) std::fma((a), (b), (c))
#include "vertex/lighting_pow.inc"
#undef LP_FMA
}  // namespace software

#if defined(__x86_64__) && defined(__GNUC__)
#define GLFIXED_HAVE_FMA_TARGET 1
#pragma GCC push_options
#pragma GCC target("fma")
namespace hardware {
#define LP_FMA(a, b, c) __builtin_fmaf((a), (b), (c))
#include "vertex/lighting_pow.inc"
#undef LP_FMA
}  // namespace hardware
float powHardware(float x, float y) { return hardware::powImpl(x, y); }
#pragma GCC pop_options
#endif

float powSoftware(float x, float y) { return software::powImpl(x, y); }

using PowFn = float (*)(float, float);

PowFn powFunction() {
  static const PowFn fn = [] {
#ifdef GLFIXED_HAVE_FMA_TARGET
    if (__builtin_cpu_supports("fma")) return &powHardware;
#endif
    return &powSoftware;
  }();
  return fn;
}

}  // namespace

float exp2(float x) { return software::exp2Impl(x); }
float log2(float x) { return software::log2Impl(x); }
float pow(float x, float y) { return powFunction()(x, y); }
bool hardwareFma() { return powFunction() != &powSoftware; }

}  // namespace glfixed::vertex::lp
