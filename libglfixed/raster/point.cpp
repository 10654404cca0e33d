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

#include "primitive/point_sprite.h"
#include "raster/fixed_point.h"
#include "raster/interpolate.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"

namespace glfixed::raster {

namespace {

// llvmpipe's largest point (LP_MAX_POINT_WIDTH).
constexpr float kMaxPointWidth = 255.0f;

// llvmpipe's subpixel_snap for points: util_iround(256 v), which on x86-64
// is the C fallback (int)(v + 0.5f), or (int)(v - 0.5f) below zero: ties go
// away from zero, not to even as a triangle's snap does (scene
// points_random). Out of range and NaN give INT32_MIN, as cvttss2si does.
int32_t snapPoint(float v) {
  const float scaled = v * float(kFixedOne);
  const float r = scaled >= 0.0f ? scaled + 0.5f : scaled - 0.5f;
  if (!(r > -2147483648.0f && r < 2147483648.0f)) return INT32_MIN;
  return static_cast<int32_t>(r);
}

}  // namespace

int pointWidthInPixels(float size) {
  if (size > kMaxPointWidth) size = kMaxPointWidth;
  // (snap(size) + 127) & ~255, at least one pixel; a NaN size snaps to
  // INT32_MIN and so gives one pixel.
  const int64_t fixed = (int64_t(snapPoint(size)) + kFixedOne / 2 - 1) & ~int64_t(kFixedOne - 1);
  return static_cast<int>(std::max<int64_t>(kFixedOne, fixed) >> kSubpixelBits);
}

bool setupPoint(const RasterState& state, const Framebuffer& fb, const WindowVertex& v, float size,
                const float* flatVaryings, PrimitiveSetup& t) {
  // The vertex in fixed point without the half-pixel shift triangles use;
  // y one unit up for GL's bottom-left fill convention in y-down rows
  // (llvmpipe's `adj`, 0 in a framebuffer object's rows).
  const int64_t adj = state.bottomEdgeRule ? 1 : 0;
  const int64_t x0 = snapPoint(v.x);
  const int64_t y0 = int64_t(snapPoint(v.y)) - adj;
  const int width = state.pointSprite ? 0 : pointWidthInPixels(size);
  int64_t bx, by, bx1, by1;
  if (state.pointSprite) {
    // A sprite is a quad of the snapped size (lp_setup_point.c, not the
    // legacy rules): [X0, X0 + w) across with the pixel centres at integer
    // 1/256 multiples, the left edge in; down, (Y0, Y0 + w], the bottom edge
    // in (GL's bottom-left rule in llvmpipe's y-down rows).
    const int64_t fw = primitive::spriteFixedWidth(size);
    const int64_t sx0 = int64_t(snapPoint(v.x - 0.5f)) - fw / 2,
                  sy0 = int64_t(snapPoint(v.y - 0.5f)) - fw / 2;
    bx = (sx0 + kFixedOne - 1) >> kSubpixelBits;
    bx1 = ((sx0 + fw + kFixedOne - 1) >> kSubpixelBits) - 1;
    // (Rows up, the top-left rule: [Y0, Y0 + w).)
    by = (sy0 + kFixedOne - 1 + adj) >> kSubpixelBits;
    by1 = ((sy0 + fw + kFixedOne - 1 + adj) >> kSubpixelBits) - 1;
  } else if (width == 1) {
    bx = x0 >> kSubpixelBits;
    by = y0 >> kSubpixelBits;
  } else if (width & 1) {
    bx = (x0 >> kSubpixelBits) - (width - 1) / 2;
    by = (y0 >> kSubpixelBits) - (width - 1) / 2;
  } else {
    bx = ((x0 + kFixedOne / 2) >> kSubpixelBits) - width / 2;
    by = ((y0 + kFixedOne / 2) >> kSubpixelBits) - width / 2;
  }
  if (!state.pointSprite) bx1 = bx + width - 1, by1 = by + width - 1;
  // The region cut to the buffer, GL window space (y up), in llvmpipe rows
  // (Framebuffer::rowsUp).
  const WindowRegion& region = state.pointLineRegion;
  const int64_t rx0 = std::max({bx, int64_t(region.x0), int64_t(0)}),
                rx1 = std::min({bx1, int64_t(region.x1) - 1, int64_t(fb.width()) - 1});
  const LlvmpipeRows rows = llvmpipeRows(fb, region.y0, region.y1);
  const int64_t ry0 = std::max(by, rows.first);
  const int64_t ry1 = std::min(by1, rows.last);
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
  for (int i = 0; i < 4; ++i) t.edge[i] = Edge::make(ex, ey, 4, i, state.bottomEdgeRule);

  // Constant planes: the window z, 1/w, and each colour.
  t.varyingCount = state.varyingCount == 8 ? 8 : 4;
  t.z = Plane{v.z, 0.0f, 0.0f};
  t.flatPrimary = flatVaryings && (state.flatGroups & RasterState::kPrimaryGroup);
  t.flatSecondary = flatVaryings && (state.flatGroups & RasterState::kSecondaryGroup);
  if (flatVaryings)
    for (int k = 0; k < t.varyingCount; ++k) t.flat[k] = flatVaryings[k];
  t.w = Plane{v.oneOverW, 0.0f, 0.0f};
  for (int k = 0; k < t.varyingCount; ++k) t.varying[k] = Plane{v.varying[k] * v.oneOverW, 0.0f, 0.0f};
  setTexCoordPlanes(
      state, t, [&] { return t.w; },
      [&](int k) {
        return Plane{v.varying[k] * v.oneOverW, 0.0f, 0.0f};
      });
  // Sprite coordinates replace the units with GL_COORD_REPLACE: texture
  // inputs are perspective in llvmpipe, so the planes are pre-multiplied by
  // the point's 1/w, which the fragment stage divides back out (`w`).
  if (state.pointSprite && state.spriteCoordReplace) {
    const primitive::SpriteCoordPlanes p =
        primitive::spriteCoordPlanes(v.x, v.y, size, state.spriteCoordOrigin, v.oneOverW, true);
    const primitive::SpritePlane* c[4] = {&p.s, &p.t, &p.r, &p.q};
    for (int u = 0; u < kMaxTexCoordUnits; ++u)
      if (state.spriteCoordReplace & (1u << u)) {
        for (int j = 0; j < 4; ++j)
          t.varying[kTexCoordVarying + 4 * u + j] = Plane{c[j]->a0, c[j]->dadx, c[j]->dady};
        t.texCoordUnits |= 1u << u;
      }
    t.w = Plane{v.oneOverW, 0.0f, 0.0f};
  }
  return true;
}

void drawPoint(const RasterState& state, Framebuffer& fb, const WindowVertex& v, float size,
               const float* flatVaryings) {
  PrimitiveSetup t;
  if (!setupPoint(state, fb, v, size, flatVaryings, t)) return;
  fragment::shadePrimitive(state, fb, t);
}

namespace {

// One triangle of the aapoint quad (no culling: the stage binds a
// rasterizer state without it), with the (s, t) planes of the aapoint shader.
void drawSmoothPointTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex* v[3],
                             const float st[3][2], float k, const float* flatVaryings) {
  drawStageTriangle(state, fb, v, flatVaryings,
                    [&](PrimitiveSetup& t, const PlaneSetup& ps, const int order[3]) {
                      const WindowVertex &a = *v[order[0]], &b = *v[order[1]], &c = *v[order[2]];
                      t.aaPoint = true;
                      // Not a polygon: no polygon stipple (piglit point-line-no-cull).
                      t.stipple = nullptr;
                      t.aaS = ps.plane(st[order[0]][0] * a.oneOverW, st[order[1]][0] * b.oneOverW,
                                       st[order[2]][0] * c.oneOverW);
                      t.aaT = ps.plane(st[order[0]][1] * a.oneOverW, st[order[1]][1] * b.oneOverW,
                                       st[order[2]][1] * c.oneOverW);
                      t.aaK = k;
                    });
}

}  // namespace

void drawSmoothPoint(const RasterState& state, Framebuffer& fb, const WindowVertex& v, float radius,
                     const float* flatVaryings) {
  // draw_pipe_aapoint.c, aapoint_point: k = (1 - 1/r)^2 computed as
  // 1 - 2/r + 1/r^2; the quad's corners at the centre -+ r, with (s, t) from
  // (-1, -1) to (1, 1); triangles (0, 1, 2) and (0, 2, 3).
  float k = 1.0f / radius;
  k = 1.0f - 2.0f * k + k * k;
  WindowVertex corner[4] = {v, v, v, v};
  corner[0].x = v.x - radius, corner[0].y = v.y - radius;
  corner[1].x = v.x + radius, corner[1].y = v.y - radius;
  corner[2].x = v.x + radius, corner[2].y = v.y + radius;
  corner[3].x = v.x - radius, corner[3].y = v.y + radius;
  static const float st[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  // The quad is not clipped: only the point's region bounds it.
  const RasterState inRegion = cutAtPointLineRegion(state);
  const WindowVertex* first[3] = {&corner[0], &corner[1], &corner[2]};
  const float firstSt[3][2] = {{st[0][0], st[0][1]}, {st[1][0], st[1][1]}, {st[2][0], st[2][1]}};
  drawSmoothPointTriangle(inRegion, fb, first, firstSt, k, flatVaryings);
  const WindowVertex* second[3] = {&corner[0], &corner[2], &corner[3]};
  const float secondSt[3][2] = {{st[0][0], st[0][1]}, {st[2][0], st[2][1]}, {st[3][0], st[3][1]}};
  drawSmoothPointTriangle(inRegion, fb, second, secondSt, k, flatVaryings);
}

}  // namespace glfixed::raster
