// The single-precision arithmetic of llvmpipe's fixed-function vertex shader,
// reproduced operation by operation so that lit colours round the way the
// reference does (REFERENCE.md, "Lighting").
//
// Mesa turns the fixed-function state into a vertex program (ffvertex_prog.c);
// llvmpipe compiles it with gallivm. The facts this file matches:
//   - dot products are plain multiplies and adds summed from z down:
//     (z*z' + y*y') + x*x' (NIR's lowering of fdot3; llvmpipe lowers ffma to
//     fmul + fadd, so nothing is fused outside pow) -- read from the NIR that
//     ST_DEBUG=nir prints;
//   - RSQ is 1 / sqrt(x), RCP is 1 / x, both correctly rounded (gallivm uses
//     sqrtps and divps, not the 12-bit rsqrtps/rcpps estimates);
//   - POW (the LIT instruction's specular power and the spot factor) is
//     exp2(log2(x) * y) with gallivm's polynomial approximations of exp2 and log2,
//     whose multiply-adds are fused (llvm.fmuladd on an FMA machine), and
//     pow(0, y) = 0 for every y, including y = 0 (the shininess-0 quirk).
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace glfixed::vertex::lp {

// gallivm's exp2 (lp_build_exp2): clamp to [-126.99999, 128], split into
// integer and fraction, 2^fraction by a degree-5 minimax polynomial.
float exp2(float x);

// gallivm's log2 with edge cases (lp_build_log2_safe): exponent plus a degree-4
// polynomial in ((m-1)/(m+1))^2 of the mantissa m; log2(0) = -inf.
float log2(float x);

// gallivm's pow (lp_build_pow): exp2(log2(x) * y), and 0 where x == 0.
float pow(float x, float y);

// Whether pow runs on fused multiply-add instructions (true) or on the exact
// software fmaf (same results, slower).
bool hardwareFma();

inline float rsq(float x) { return 1.0f / std::sqrt(x); }
inline float rcp(float x) { return 1.0f / x; }

// The vertex colour clamp of llvmpipe: [0, 1], and NaN goes to 1 (measured:
// a NaN colour, lit or not, is drawn as 255).
inline float clampColor(float v) {
  if (!(v <= 1.0f)) return 1.0f;
  return v < 0.0f ? 0.0f : v;
}
inline glm::vec4 clampColor(const glm::vec4& c) {
  return glm::vec4(clampColor(c.r), clampColor(c.g), clampColor(c.b), clampColor(c.a));
}

// The shader's DP3.
inline float dot3(const glm::vec3& a, const glm::vec3& b) { return (a.z * b.z + a.y * b.y) + a.x * b.x; }

// NORMALIZE_3FV of Mesa's macros.h, as the CPU evaluates it when the state
// changes: v * (1 / sqrt(|v|^2)), left unchanged when |v|^2 is 0.
inline glm::vec3 normalizeLikeMesa(const glm::vec3& v) {
  float len = (v.x * v.x + v.y * v.y) + v.z * v.z;
  if (len == 0.0f) return v;
  len = 1.0f / std::sqrt(len);
  return glm::vec3(v.x * len, v.y * len, v.z * len);
}

// The shader's normalize (DP3, RSQ, MUL): v * rsq(dot(v, v)).
inline glm::vec3 normalizeLikeShader(const glm::vec3& v) {
  const float s = rsq(dot3(v, v));
  return glm::vec3(v.x * s, v.y * s, v.z * s);
}

}  // namespace glfixed::vertex::lp
