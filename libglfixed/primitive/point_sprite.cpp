// Point sprite coordinates (primitive/point_sprite.h). Float operations as
// llvmpipe's C setup does them (no fused multiply-adds); a0 is 0.5 minus a
// float, subtracted in double (the constant is a double) and stored as float.
#pragma GCC optimize("fp-contract=off")

#include "primitive/point_sprite.h"

#include <cstdint>
#include <initializer_list>

namespace glfixed::primitive {

namespace {

constexpr float kFixedOne = 256.0f;
constexpr float kMaxPointWidth = 255.0f;  // LP_MAX_POINT_WIDTH
constexpr float kPixelOffset = 0.5f;      // GL's half-pixel centres

// subpixel_snap: util_iround(256 v), the C fallback (ties away from zero).
int32_t snap(float v) {
  const float scaled = v * kFixedOne;
  const float r = scaled >= 0.0f ? scaled + 0.5f : scaled - 0.5f;
  if (!(r > -2147483648.0f && r < 2147483648.0f)) return INT32_MIN;
  return static_cast<int32_t>(r);
}

}  // namespace

int spriteFixedWidth(float size) {
  if (size > kMaxPointWidth) size = kMaxPointWidth;
  const int32_t w = snap(size);
  return w > static_cast<int32_t>(kFixedOne) ? w : static_cast<int32_t>(kFixedOne);  // MAX2(FIXED_ONE, .)
}

SpriteCoordPlanes spriteCoordPlanes(float x, float y, float size, GLenum origin, float oneOverW,
                                    bool perspective) {
  const float step = kFixedOne / static_cast<float>(spriteFixedWidth(size));
  const float x0 = x - kPixelOffset, y0 = y - kPixelOffset;
  SpriteCoordPlanes p;
  // s: across (dady 0), t: down for GL_UPPER_LEFT, up for GL_LOWER_LEFT.
  p.s.dadx = step;
  p.s.dady = 0.0f;
  p.s.a0 = static_cast<float>(0.5 - static_cast<double>(step * x0 + 0.0f * y0));
  p.t.dadx = 0.0f;
  p.t.dady = origin == GL_LOWER_LEFT ? -step : step;
  p.t.a0 = static_cast<float>(0.5 - static_cast<double>(0.0f * x0 + p.t.dady * y0));
  p.q.a0 = perspective ? oneOverW : 1.0f;
  if (perspective) {
    for (SpritePlane* c : {&p.s, &p.t}) {
      c->dadx *= oneOverW;
      c->dady *= oneOverW;
      c->a0 *= oneOverW;
    }
  }
  return p;
}

}  // namespace glfixed::primitive
