// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include "primitive/cull.h"

namespace glfixed::primitive {

bool drawModuleCulls(const FaceRule& rule, const float* w0, const float* w1, const float* w2) {
  if (!rule.cullFace) return false;
  const float ex = w0[0] - w2[0];
  const float ey = w0[1] - w2[1];
  const float fx = w1[0] - w2[0];
  const float fy = w1[1] - w2[1];
  const float a = ex * fy;
  const float b = ey * fx;
  const float det = a - b;
  if (det == 0.0f) return rule.culls(false);
  // det < 0 is counter-clockwise in GL window space (y is down here).
  return rule.culls(rule.isFront(det < 0.0f ? 1 : -1));
}

}  // namespace glfixed::primitive
