// Line set-up (GL 2.1 §3.5) as llvmpipe's lp_setup_line.c does it: a line
// becomes a quadrilateral of 4 fixed-point edges with attribute planes taken
// along the line, rasterized by the one fragment stage (shadePrimitive).
//   - Aliased lines: the width rounds to an integer; an x-major line is
//     widened vertically, a y-major one horizontally, with square-cut ends
//     moved by the "diamond exit" rule so that the first endpoint's pixel is
//     drawn and the last one's is not.
//   - Rectangular lines (GL_LINE_SMOOTH): the true rectangle of the line,
//     of the unrounded width, ends cut flat at the endpoints.
// Every float operation here must round exactly as llvmpipe's C code does:
// forbid contracting a * b + c into a fused multiply-add.
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "raster/edge.h"
#include "raster/fixed_point.h"
#include "raster/interpolate.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"

namespace glfixed::raster {

namespace {

// (int)f as x86's cvttss2si does it: toward zero; NaN and values out of
// range give INT32_MIN.
inline int32_t truncateToInt32(float v) {
#if defined(__SSE2__)
  return _mm_cvtt_ss2si(_mm_set_ss(v));
#else
  if (!(v >= -2147483648.0f && v < 2147483648.0f)) return INT32_MIN;
  return static_cast<int32_t>(v);
#endif
}

// Mesa's util_iround on x86-64: half away from zero, through a float
// addition (u_math.h). Not the round-to-even of the triangle snap.
inline int32_t iround(float f) { return truncateToInt32(f >= 0.0f ? f + 0.5f : f - 0.5f); }

inline int32_t subpixelSnap(float a) { return iround(static_cast<float>(kFixedOne) * a); }

inline bool nonNegative(float x) { return x >= 0; }  // lp_setup_line.c's sign()

inline float fractionOf(float f) { return f - std::floor(f); }

// linear_coef: the plane of `a1` at v1 and `a2` at v2 along the line.
struct LinePlanes {
  float dx, dy, oneOverArea;
  float x1, y1;  // v1, pixel centre offset removed
  Plane plane(float a1, float a2) const {
    const float da21 = a1 - a2;
    Plane p;
    p.dadx = da21 * dx * oneOverArea;
    p.dady = da21 * dy * oneOverArea;
    p.a0 = a1 - (p.dadx * x1 + p.dady * y1);
    return p;
  }
};

// The end rules of an aliased line (lp_setup_line.c, the non-rectangular
// branch): fills x[4], y[4] and the interpolation direction.
void aliasedLineCorners(const WindowVertex& v1in, const WindowVertex& v2in, float width, float& infoDx,
                        float& infoDy, int32_t x[4], int32_t y[4]) {
  const WindowVertex* v1 = &v1in;
  const WindowVertex* v2 = &v2in;
  const float dx = v1->x - v2->x;
  const float dy = v1->y - v2->y;
  float xOffset = 0, yOffset = 0, xOffsetEnd = 0, yOffsetEnd = 0;
  const float x1diff = v1->x - std::floor(v1->x) - 0.5f;
  const float y1diff = v1->y - std::floor(v1->y) - 0.5f;
  float x2diff = v2->x - std::floor(v2->x) - 0.5f;
  float y2diff = v2->y - std::floor(v2->y) - 0.5f;
  const int32_t fixedWidth = iround(width) * kFixedOne;
  bool drawStart, drawEnd;

  if (std::fabs(dx) >= std::fabs(dy)) {  // x-major
    const float dydx = dy / dx;
    if (y2diff == -0.5f && dy < 0.0f) y2diff = 0.5f;
    // Diamond exit rule, start point.
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f)
      drawStart = true;
    else if (nonNegative(x1diff) == nonNegative(-dx))
      drawStart = false;
    else if (nonNegative(-y1diff) != nonNegative(dy))
      drawStart = true;
    else {
      const float yIntersect = fractionOf(v1->y) + x1diff * dydx;
      drawStart = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    // End point.
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f)
      drawEnd = false;
    else if (nonNegative(x2diff) != nonNegative(-dx))
      drawEnd = false;
    else if (nonNegative(-y2diff) == nonNegative(dy))
      drawEnd = true;
    else {
      const float yIntersect = fractionOf(v2->y) + x2diff * dydx;
      drawEnd = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    infoDx *= 1.0f + dydx * dydx;
    infoDy = 0.0f;
    if (dx < 0.0f) {
      std::swap(v1, v2);
      const bool willDrawStart = x1diff <= 0.f;  // left edge
      if (willDrawStart != drawStart) {
        xOffsetEnd = -x1diff - 0.5f;
        yOffsetEnd = xOffsetEnd * dydx;
      }
      const bool willDrawEnd = x2diff > 0.f;  // right edge
      if (willDrawEnd != drawEnd) {
        xOffset = -x2diff - 0.5f;
        yOffset = xOffset * dydx;
      }
    } else {
      const bool willDrawStart = x1diff > 0.f;  // right edge
      if (willDrawStart != drawStart) {
        xOffset = -x1diff + 0.5f;
        yOffset = xOffset * dydx;
      }
      const bool willDrawEnd = x2diff <= 0.f;  // left edge
      if (willDrawEnd != drawEnd) {
        xOffsetEnd = -x2diff + 0.5f;
        yOffsetEnd = xOffsetEnd * dydx;
      }
    }
    x[0] = subpixelSnap(v1->x + xOffset - 0.5f);
    x[1] = subpixelSnap(v2->x + xOffsetEnd - 0.5f);
    x[2] = x[1];
    x[3] = x[0];
    y[0] = subpixelSnap(v1->y + yOffset - 0.5f) - fixedWidth / 2;
    y[1] = subpixelSnap(v2->y + yOffsetEnd - 0.5f) - fixedWidth / 2;
    y[2] = subpixelSnap(v2->y + yOffsetEnd - 0.5f) + fixedWidth / 2;
    y[3] = subpixelSnap(v1->y + yOffset - 0.5f) + fixedWidth / 2;
  } else {  // y-major
    const float dxdy = dx / dy;
    if (x2diff == -0.5f && dx < 0.0f) x2diff = 0.5f;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f)
      drawStart = true;
    else if (nonNegative(-y1diff) == nonNegative(dy))
      drawStart = false;
    else if (nonNegative(x1diff) != nonNegative(-dx))
      drawStart = true;
    else {
      const float xIntersect = fractionOf(v1->x) + y1diff * dxdy;
      drawStart = xIntersect < 1.0f && xIntersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f)
      drawEnd = false;
    else if (nonNegative(-y2diff) != nonNegative(dy))
      drawEnd = false;
    else if (nonNegative(x2diff) == nonNegative(-dx))
      drawEnd = true;
    else {
      const float xIntersect = fractionOf(v2->x) + y2diff * dxdy;
      drawEnd = xIntersect < 1.0f && xIntersect >= 0.0f;
    }
    infoDx = 0.0f;
    infoDy *= 1.0f + dxdy * dxdy;
    // GL's bottom-left fill convention (llvmpipe's bottom_edge_rule).
    if (dy > 0.0f) {
      std::swap(v1, v2);
      const bool willDrawStart = y1diff >= 0.f, willDrawEnd = y2diff < 0.f;
      if (willDrawStart != drawStart) {  // bottom edge
        yOffsetEnd = -y1diff + 0.5f;
        xOffsetEnd = yOffsetEnd * dxdy;
      }
      if (willDrawEnd != drawEnd) {  // top edge
        yOffset = -y2diff + 0.5f;
        xOffset = yOffset * dxdy;
      }
    } else {
      const bool willDrawStart = y1diff < 0.f, willDrawEnd = y2diff >= 0.f;
      if (willDrawStart != drawStart) {  // top edge
        yOffset = -y1diff - 0.5f;
        xOffset = yOffset * dxdy;
      }
      if (willDrawEnd != drawEnd) {  // bottom edge
        yOffsetEnd = -y2diff - 0.5f;
        xOffsetEnd = yOffsetEnd * dxdy;
      }
    }
    x[0] = subpixelSnap(v1->x + xOffset - 0.5f) - fixedWidth / 2;
    x[1] = subpixelSnap(v2->x + xOffsetEnd - 0.5f) - fixedWidth / 2;
    x[2] = subpixelSnap(v2->x + xOffsetEnd - 0.5f) + fixedWidth / 2;
    x[3] = subpixelSnap(v1->x + xOffset - 0.5f) + fixedWidth / 2;
    y[0] = subpixelSnap(v1->y + yOffset - 0.5f);
    y[1] = subpixelSnap(v2->y + yOffsetEnd - 0.5f);
    y[2] = y[1];
    y[3] = y[0];
  }
}

}  // namespace

bool setupLine(const RasterState& state, const Framebuffer& fb, const LineStyle& style,
               const WindowVertex& v1, const WindowVertex& v2, const float* flatVaryings, PrimitiveSetup& t) {
  if (!std::isfinite(v1.x) || !std::isfinite(v1.y) || !std::isfinite(v2.x) || !std::isfinite(v2.y))
    return false;
  const float dx = v1.x - v2.x;
  const float dy = v1.y - v2.y;
  const float area = dx * dx + dy * dy;
  if (area == 0) return false;  // a zero-length line draws nothing
  LinePlanes info{dx, dy, 1.0f / area, v1.x - 0.5f, v1.y - 0.5f};

  int32_t x[4], y[4];
  if (style.rectangular) {
    const float scale = (style.width * 0.5f) / std::sqrt(area);
    // (A half-width beyond a million pixels cannot come from a clamped width;
    // refusing it keeps the fixed-point sums below in range.)
    if (!(std::fabs(dx * scale) < 1e6f && std::fabs(dy * scale) < 1e6f)) return false;
    const int32_t tx = subpixelSnap(-dy * scale);
    const int32_t ty = subpixelSnap(+dx * scale);
    const int32_t x1 = subpixelSnap(v1.x - 0.5f), x2 = subpixelSnap(v2.x - 0.5f);
    const int32_t y1 = subpixelSnap(v1.y - 0.5f), y2 = subpixelSnap(v2.y - 0.5f);
    x[0] = x1 - tx;
    x[1] = x2 - tx;
    x[2] = x2 + tx;
    x[3] = x1 + tx;
    y[0] = y1 - ty;
    y[1] = y2 - ty;
    y[2] = y2 + ty;
    y[3] = y1 + ty;
  } else {
    // MAX2(1.0, width): NaN compares false and gives 1.
    const float width = 1.0 > style.width ? 1.0f : style.width;
    aliasedLineCorners(v1, v2, width, info.dx, info.dy, x, y);
  }

  // Bounding box (lp_setup_line.c; `adj` 1 for the bottom-left fill
  // convention), in pixels.
  const int64_t adj = state.bottomEdgeRule ? 1 : 0;
  const int64_t minX = std::min({x[0], x[1], x[2], x[3]}), maxX = std::max({x[0], x[1], x[2], x[3]});
  const int64_t minY = std::min({y[0], y[1], y[2], y[3]}), maxY = std::max({y[0], y[1], y[2], y[3]});
  const int64_t bx0 = (minX + (kFixedOne - 1)) >> kSubpixelBits;
  const int64_t bx1 = ((maxX + (kFixedOne - 1)) >> kSubpixelBits) - 1;
  const int64_t by0 = (minY + (kFixedOne - 1) + adj) >> kSubpixelBits;
  const int64_t by1 = ((maxY + (kFixedOne - 1) + adj) >> kSubpixelBits) - 1;
  // The draw region: the framebuffer (and the scissor box, when there is one),
  // llvmpipe rows. A line is not cut at the viewport.
  const WindowRegion& region = state.pointLineRegion;
  const int64_t rx0 = std::max(0, region.x0), rx1 = std::min(fb.width(), region.x1) - 1;
  const LlvmpipeRows rows = llvmpipeRows(fb, region.y0, region.y1);
  const int64_t ry0 = rows.first, ry1 = rows.last;
  const int64_t cx0 = std::max(bx0, rx0), cx1 = std::min(bx1, rx1);
  const int64_t cy0 = std::max(by0, ry0), cy1 = std::min(by1, ry1);
  if (cx0 > cx1 || cy0 > cy1) return false;
  t.x0 = static_cast<int>(cx0);
  t.x1 = static_cast<int>(cx1);
  t.y0 = static_cast<int>(cy0);
  t.y1 = static_cast<int>(cy1);

  t.edgeCount = 4;
  for (int i = 0; i < 4; ++i) t.edge[i] = Edge::make(x, y, 4, i, state.bottomEdgeRule);

  t.varyingCount = state.varyingCount == 8 ? 8 : 4;
  t.z = info.plane(v1.z, v2.z);
  t.flatPrimary = flatVaryings && (state.flatGroups & RasterState::kPrimaryGroup);
  t.flatSecondary = flatVaryings && (state.flatGroups & RasterState::kSecondaryGroup);
  if (flatVaryings)
    for (int k = 0; k < t.varyingCount; ++k) t.flat[k] = flatVaryings[k];
  if (!t.flatPrimary || (t.varyingCount == 8 && !t.flatSecondary)) {
    t.w = info.plane(v1.oneOverW, v2.oneOverW);
    for (int k = 0; k < t.varyingCount; ++k) {
      if (k < 4 ? t.flatPrimary : t.flatSecondary) continue;
      t.varying[k] = info.plane(v1.varying[k] * v1.oneOverW, v2.varying[k] * v2.oneOverW);
    }
  }
  setTexCoordPlanes(
      state, t, [&] { return info.plane(v1.oneOverW, v2.oneOverW); },
      [&](int k) { return info.plane(v1.varying[k] * v1.oneOverW, v2.varying[k] * v2.oneOverW); });
  return true;
}

namespace {

// One triangle of a smooth line, with the aaline stage's coverage attribute
// (x across, z along the line) at its vertices.
void drawCoverageTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex* v[3],
                          const float across[3], const float along[3], float halfWidth, float halfLength,
                          const float* flatVaryings) {
  drawStageTriangle(
      state, fb, v, flatVaryings, [&](PrimitiveSetup& t, const PlaneSetup& ps, const int order[3]) {
        const float w[3] = {v[order[0]]->oneOverW, v[order[1]]->oneOverW, v[order[2]]->oneOverW};
        t.lineCoverage = true;
        t.stipple = nullptr;  // not a polygon: no polygon stipple (piglit point-line-no-cull)
        t.coverageX = ps.plane(across[order[0]] * w[0], across[order[1]] * w[1], across[order[2]] * w[2]);
        t.coverageZ = ps.plane(along[order[0]] * w[0], along[order[1]] * w[1], along[order[2]] * w[2]);
        t.coverageHalfWidth = halfWidth;
        t.coverageHalfLength = halfLength;
        // A line shorter than a pixel comes out fainter along its length, by
        // length / halfLength (fitted to probes of 0.25, 0.5 and 0.75 pixel lines
        // at eight sub-pixel offsets; longer lines are not scaled).
        const float length = 2.0f * halfLength - 1.0f;
        t.coverageAlongScale = length < halfLength ? length / halfLength : 1.0f;
      });
}

}  // namespace

// GL_LINE_SMOOTH: the draw module's aaline stage (draw_pipe_aaline.c,
// aaline_line): the line becomes a rectangle half a pixel longer at each end
// and `halfWidth` wide on each side, drawn as two triangles; the fragment
// shader scales alpha by the coverage (PrimitiveSetup::lineCoverage).
void drawSmoothLine(const RasterState& lineState, Framebuffer& fb, float width, const WindowVertex& v0,
                    const WindowVertex& v1, const float* flatVaryings) {
  if (!std::isfinite(v0.x) || !std::isfinite(v0.y) || !std::isfinite(v1.x) || !std::isfinite(v1.y)) return;
  const float halfWidth = width <= 1.0 ? 1.0f : 0.5f * width + 0.5f;
  const float dx = v1.x - v0.x;
  const float dy = v1.y - v0.y;
  const float a = std::atan2(dy, dx);
  const float cosA = std::cos(a), sinA = std::sin(a);
  const float halfLength = 0.5f * std::sqrt(dx * dx + dy * dy) + 0.5f;
  const float tw = halfWidth, tl = 0.5f;
  WindowVertex q[4] = {v0, v0, v1, v1};
  q[0].x += (-tl * cosA - tw * sinA);
  q[0].y += (-tl * sinA + tw * cosA);
  q[1].x += (-tl * cosA - -tw * sinA);
  q[1].y += (-tl * sinA + -tw * cosA);
  q[2].x += (tl * cosA - tw * sinA);
  q[2].y += (tl * sinA + tw * cosA);
  q[3].x += (tl * cosA - -tw * sinA);
  q[3].y += (tl * sinA + -tw * cosA);
  const float across[4] = {-halfWidth, halfWidth, -halfWidth, halfWidth};
  const float along[4] = {-halfLength, -halfLength, halfLength, halfLength};
  // The triangles are not clipped again: they are cut at the draw region.
  const RasterState state = cutAtPointLineRegion(lineState);
  const int tris[2][3] = {{2, 1, 0}, {3, 1, 2}};
  for (const auto& tri : tris) {
    const WindowVertex* v[3] = {&q[tri[0]], &q[tri[1]], &q[tri[2]]};
    const float x[3] = {across[tri[0]], across[tri[1]], across[tri[2]]};
    const float z[3] = {along[tri[0]], along[tri[1]], along[tri[2]]};
    drawCoverageTriangle(state, fb, v, x, z, halfWidth, halfLength, flatVaryings);
  }
}

void drawLine(const RasterState& state, Framebuffer& fb, const LineStyle& style, const WindowVertex& v1,
              const WindowVertex& v2, const float* flatVaryings) {
  PrimitiveSetup t;
  if (setupLine(state, fb, style, v1, v2, flatVaryings, t)) fragment::shadePrimitive(state, fb, t);
}

}  // namespace glfixed::raster
