// Every float operation here must round exactly as Mesa's draw module does:
// forbid contracting a * b + c into a fused multiply-add.
#pragma GCC optimize("fp-contract=off")

#include "primitive/clip_line.h"

#include <cmath>

#include "primitive/viewport.h"

namespace glfixed::primitive {

bool clipLine(const ClipVertex& v0, const ClipVertex& v1, uint32_t m0, uint32_t m1, uint32_t planes,
              int attribCount, const ViewportTransform& viewport, bool flat, const ClipVertex& provoking,
              ClipVertex made[2], const ClipVertex** out0, const ClipVertex** out1,
              const UserClipPlanes& user) {
  float t0 = 0.0f, t1 = 0.0f;
  while (planes != 0) {
    const int plane = __builtin_ctz(planes);
    planes &= planes - 1;
    const float dp0 = distanceToPlane(plane, v0.clip, user);  // user clip planes: 6..
    const float dp1 = distanceToPlane(plane, v1.clip, user);
    if (!std::isfinite(dp0) || !std::isfinite(dp1)) return false;
    if (dp1 < 0.0f) {
      const float t = dp1 / (dp1 - dp0);
      t1 = t1 > t ? t1 : t;  // MAX2
    }
    if (dp0 < 0.0f) {
      const float t = dp0 / (dp0 - dp1);
      t0 = t0 > t ? t0 : t;
    }
    if (t0 + t1 >= 1.0f) return false;
  }
  *out0 = &v0;
  *out1 = &v1;
  auto moveEnd = [&](const ClipVertex& end, const ClipVertex& other, float t, ClipVertex& dst) {
    interpolateClipVertex(end, other, t, attribCount, viewport, dst);
    if (flat)
      for (int k = 0; k < attribCount && k < kClipColorAttribs; ++k) dst.attr[k] = provoking.attr[k];
  };
  if (m0 != 0) {
    moveEnd(v0, v1, t0, made[0]);
    *out0 = &made[0];
  }
  if (m1 != 0) {
    moveEnd(v1, v0, t1, made[1]);
    *out1 = &made[1];
  }
  return true;
}

}  // namespace glfixed::primitive
