// Point set-up (GL 2.1 §3.4.1) as llvmpipe does it for a non-sprite point
// (lp_setup_point.c, the "legacy points" path): the size is rounded to a whole
// number of pixels with .5 going down, and the point is the square of that
// many pixels centred on the pixel that holds the vertex (odd sizes) or on the
// pixel corner nearest to it (even sizes). Attributes are constant over the
// point; a smooth colour is still stored as colour * (1/w) and divided back
// per fragment, as llvmpipe's perspective inputs are.
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cstdint>

#include "raster/fixed_point.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"

namespace glfixed::raster {

namespace {

// llvmpipe's largest point (LP_MAX_POINT_WIDTH).
constexpr float kMaxPointWidth = 255.0f;

}  // namespace

int pointWidthInPixels(float size) {
  if (size > kMaxPointWidth) size = kMaxPointWidth;
  // (snap(size) + 127) & ~255, at least one pixel; a NaN size snaps to
  // INT32_MIN and so gives one pixel.
  const int64_t fixed =
      (int64_t(roundToInt32(size * float(kFixedOne))) + kFixedOne / 2 - 1) & ~int64_t(kFixedOne - 1);
  return static_cast<int>(std::max<int64_t>(kFixedOne, fixed) >> kSubpixelBits);
}

bool setupPoint(const RasterState& state, const PointRegion& region, int framebufferHeight,
                const WindowVertex& v, float size, const float* flatVaryings, PrimitiveSetup& t) {
  // The vertex in fixed point without the half-pixel shift triangles use;
  // y one unit up for GL's bottom-left fill convention (llvmpipe's `adj`).
  const int64_t x0 = roundToInt32(v.x * float(kFixedOne));
  const int64_t y0 = int64_t(roundToInt32(v.y * float(kFixedOne))) - 1;
  const int width = pointWidthInPixels(size);
  int64_t bx, by;
  if (width == 1) {
    bx = x0 >> kSubpixelBits;
    by = y0 >> kSubpixelBits;
  } else if (width & 1) {
    bx = (x0 >> kSubpixelBits) - (width - 1) / 2;
    by = (y0 >> kSubpixelBits) - (width - 1) / 2;
  } else {
    bx = ((x0 + kFixedOne / 2) >> kSubpixelBits) - width / 2;
    by = ((y0 + kFixedOne / 2) >> kSubpixelBits) - width / 2;
  }
  // The region, GL window space (y up), in llvmpipe rows (y down).
  const int64_t rx0 = std::max(bx, int64_t(region.x0)),
                rx1 = std::min(bx + width - 1, int64_t(region.x1) - 1);
  const int64_t ry0 = std::max(by, int64_t(framebufferHeight) - region.y1);
  const int64_t ry1 = std::min(by + width - 1, int64_t(framebufferHeight) - 1 - region.y0);
  if (rx0 > rx1 || ry0 > ry1) return false;
  t.x0 = static_cast<int>(rx0);
  t.x1 = static_cast<int>(rx1);
  t.y0 = static_cast<int>(ry0);
  t.y1 = static_cast<int>(ry1);

  // Four edges on the pixel boundaries around the box, counter-clockwise in
  // GL window space: no pixel centre lies on one, so the fill rule never
  // decides.
  const int32_t left = t.x0 * kFixedOne - kFixedOne / 2, right = t.x1 * kFixedOne + kFixedOne / 2;
  const int32_t top = t.y0 * kFixedOne - kFixedOne / 2, bottom = t.y1 * kFixedOne + kFixedOne / 2;
  const int32_t ex[4] = {left, left, right, right}, ey[4] = {top, bottom, bottom, top};
  t.edgeCount = 4;
  for (int i = 0; i < 4; ++i) t.edge[i] = Edge::make(ex, ey, 4, i);

  // Constant planes: the window z, 1/w, and each colour.
  t.varyingCount = state.varyingCount == 8 ? 8 : 4;
  t.z = Plane{v.z, 0.0f, 0.0f};
  t.flatPrimary = flatVaryings && (state.flatGroups & RasterState::kPrimaryGroup);
  t.flatSecondary = flatVaryings && (state.flatGroups & RasterState::kSecondaryGroup);
  if (flatVaryings)
    for (int k = 0; k < t.varyingCount; ++k) t.flat[k] = flatVaryings[k];
  t.w = Plane{v.oneOverW, 0.0f, 0.0f};
  for (int k = 0; k < t.varyingCount; ++k) t.varying[k] = Plane{v.varying[k] * v.oneOverW, 0.0f, 0.0f};
  return true;
}

void drawPoint(const RasterState& state, Framebuffer& fb, const PointRegion& region, const WindowVertex& v,
               float size, const float* flatVaryings) {
  PrimitiveSetup t;
  if (!setupPoint(state, region, fb.height(), v, size, flatVaryings, t)) return;
  shadePrimitive(state, fb, t);
}

}  // namespace glfixed::raster
