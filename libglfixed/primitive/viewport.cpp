// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include "primitive/viewport.h"

#include <algorithm>
#include <cmath>

namespace glfixed::primitive {

ViewportTransform ViewportTransform::make(int x, int y, int width, int height, double depthNear,
                                          double depthFar, int framebufferHeight, bool flipY) {
  ViewportTransform v;
  const float fx = static_cast<float>(x), fy = static_cast<float>(y);
  const float halfWidth = 0.5f * static_cast<float>(width);
  const float halfHeight = 0.5f * static_cast<float>(height);
  // Mesa keeps the depth range as floats and computes in double from them.
  const double n = static_cast<float>(std::clamp(depthNear, 0.0, 1.0));
  const double f = static_cast<float>(std::clamp(depthFar, 0.0, 1.0));
  v.scale[0] = halfWidth;
  v.translate[0] = halfWidth + fx;
  // y flipped: gallium's y = 0 is the top row of the OSMesa buffer.
  v.scale[1] = flipY ? -halfHeight : halfHeight;
  v.translate[1] = flipY ? static_cast<float>(framebufferHeight) - (halfHeight + fy) : halfHeight + fy;
  v.scale[2] = static_cast<float>(0.5 * (f - n));
  v.translate[2] = static_cast<float>(0.5 * (n + f));
  return v;
}

void ViewportTransform::windowFromClip(const glm::vec4& clip, float out[4]) const {
  const float oow = 1.0f / clip.w;
  for (int i = 0; i < 3; ++i) out[i] = std::fma(clip[i] * oow, scale[i], translate[i]);
  out[3] = oow;
}

void ViewportTransform::windowFromClipUnfused(const glm::vec4& clip, float out[4]) const {
  const float oow = 1.0f / clip.w;
  for (int i = 0; i < 3; ++i) {
    float projected = clip[i] * oow;
    float scaled = projected * scale[i];
    out[i] = scaled + translate[i];
  }
  out[3] = oow;
}

}  // namespace glfixed::primitive
