// Internal to the rasterizer: one primitive, set up, and where its fragments
// go. llvmpipe rasterizes triangles, lines and points alike, as a convex
// polygon of 3 or 4 fixed-point edges with attribute planes
// (lp_setup_tri.c, lp_setup_line.c, lp_setup_point.c); only the set-up
// differs. triangle.cpp (and the line and point set-ups) fill these; the span
// shaders (scalar in triangle.cpp, AVX2 in shade_avx2.cpp) consume them and
// must give identical results.
#pragma once

#include <GL/gl.h>

#include <cmath>
#include <cstdint>

#include "raster/edge.h"
#include "raster/interpolate.h"
#include "raster/raster.h"

namespace glfixed::raster {

constexpr int kMaxEdges = 4;

struct PrimitiveSetup {
  Edge edge[kMaxEdges];
  int edgeCount = 3;            // 3: a triangle; 4: a line's or a point's quadrilateral
  Plane z, w;                   // window z; 1/w_clip
  Plane varying[kMaxVaryings];  // attribute * (1/w), for perspective correction
  float flat[kMaxVaryings];
  bool flatPrimary = false, flatSecondary = false;  // these take `flat`, uninterpolated
  int varyingCount = 4;
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // inclusive pixel bounds, llvmpipe (y-down) rows
  // Smooth points (raster/point.cpp): one of the two triangles of the draw
  // module's aapoint quad, whose fragment shader Mesa rewrites
  // (nir_lower_aapoint_fs): d = s^2 + t^2 from the interpolated (s, t) in
  // [-1, 1]; a fragment with d > 1 is discarded; else alpha is multiplied by
  // (1 - d) / (1 - k) where d <= k, and by 1 elsewhere (sic: Mesa's NIR pass
  // swaps the two, so the disc's inside is brightened and its rim kept).
  // Only the scalar shader has this rule; shadePrimitive sends these there.
  bool aaPoint = false;
  Plane aaS, aaT;  // s and t times 1/w, as a perspective input
  float aaK = 0;
  // GL_LINE_SMOOTH (raster/line.cpp): a triangle of the draw module's aaline
  // stage, whose fragment shader scales alpha by the line's coverage,
  // sat(coverageHalfWidth - |X|) * sat(coverageHalfLength - |Z|), X and Z
  // perspective-correct like the colours (planes of X/w, Z/w; `w` is set).
  bool lineCoverage = false;
  Plane coverageX, coverageZ;
  float coverageHalfWidth = 0, coverageHalfLength = 0;
  float coverageAlongScale = 1;  // lines shorter than a pixel: measured, see line.cpp
  // Polygon area: the polygon offset, added to z at every fragment (0:
  // none), and the polygon stipple (RasterState::polygonStipple; null: none).
  // A fragment in GL row y, column x is kept when bit 31 - x % 32 of row
  // y % 32 is set.
  float zOffset = 0;
  const uint32_t* stipple = nullptr;
};

// The aaline coverage factor of a fragment, `oow` being 1 / t.w there (both
// shaders compute exactly this).
inline float lineCoverageAt(const PrimitiveSetup& t, float px, float py, float oow) {
  auto saturate = [](float v) { return std::fmin(std::fmax(v, 0.0f), 1.0f); };
  const float across = saturate(t.coverageHalfWidth - std::fabs(t.coverageX.at(px, py) * oow));
  const float along = saturate(t.coverageHalfLength - std::fabs(t.coverageZ.at(px, py) * oow));
  return across * (along * t.coverageAlongScale);
}

// The framebuffer as the span shaders see it.
struct ShadeTarget {
  int height = 0;  // rows: llvmpipe row py is GL row height - 1 - py
  // colour
  const ColorBuffer* color = nullptr;
  int bytesPerPixel = 4, red = 0, green = 1, blue = 2, alpha = 3;
  bool colorWrite[4] = {true, true, true, true};
  bool anyColor = true, allColor = true;
  // depth (bits 0: no depth test)
  int depthBits = 0;
  void* depth = nullptr;  // row-major, GL rows, `depthWidth` values a row
  int depthWidth = 0;
  bool depthWrite = true;
  GLenum depthFunc = GL_LESS;
  bool secondary = false;  // add varyings 4..6 to 0..2
  // The polygon stipple the fragments pass (null: none): the setup's
  // (triangles), or the state's for every primitive while Mesa's stipple
  // shader stays bound (RasterState::stippleEveryPrimitive).
  const uint32_t* stipple = nullptr;
};

// Bounding box, edges and planes of a triangle with positive snapped area;
// false when it covers no pixel of the drawable region.
bool setupTriangle(const RasterState& state, const Framebuffer& fb, const FixedTriangle& fixed,
                   const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                   const float* flatVaryings, PrimitiveSetup& out);
// llvmpipe's polygon offset of a triangle (lp_state_setup.c): units scaled
// by the depth buffer's resolvable difference, the slope from the unsnapped
// window positions in setup order, every operation in single precision.
float polygonOffsetZ(const RasterState& state, int depthBits, const WindowVertex& v0, const WindowVertex& v1,
                     const WindowVertex& v2);
// The square of a non-smooth point (raster/point.cpp); false when it covers
// no pixel of the state's point and line region.
bool setupPoint(const RasterState& state, const Framebuffer& fb, const WindowVertex& v, float size,
                const float* flatVaryings, PrimitiveSetup& out);
// The quadrilateral and planes of a line (raster/line.cpp); false when it
// covers no pixel of the draw region.
bool setupLine(const RasterState& state, const Framebuffer& fb, const LineStyle& style,
               const WindowVertex& v1, const WindowVertex& v2, const float* flatVaryings,
               PrimitiveSetup& out);
ShadeTarget makeShadeTarget(const RasterState& state, Framebuffer& fb, const PrimitiveSetup& t);

// `state` with the point and line region as its drawable box: the quads of
// smooth points and lines are not clipped, only cut at that region.
inline RasterState cutAtPointLineRegion(const RasterState& state) {
  RasterState r = state;
  r.scissorX0 = state.pointLineRegion.x0;
  r.scissorY0 = state.pointLineRegion.y0;
  r.scissorX1 = state.pointLineRegion.x1;
  r.scissorY1 = state.pointLineRegion.y1;
  return r;
}

// Shades every fragment of a set-up primitive (the AVX2 shader where the CPU
// has it, else the scalar one).
void shadePrimitive(const RasterState& state, Framebuffer& fb, const PrimitiveSetup& t);

// Polygon stipple of one GL row: bit 31 - (x % 32) is pixel x (GL 2.1 §3.6.2).
inline uint32_t stippleRow(const uint32_t* stipple, int glY) { return stipple[glY & 31]; }
inline bool stipplePasses(uint32_t row, int x) { return (row >> (31 - (x & 31))) & 1u; }

// A triangle a draw-module stage makes (the quads of smooth points and smooth
// lines), whichever way it faces: snapped, put in counter-clockwise order
// keeping the provoking slot as drawTriangle does, set up with its 1/w plane
// (the stage's shader needs it even when every colour is flat); then
// `addPlanes(t, planes, order)` adds the stage's own planes, `order[i]` being
// the input vertex in setup slot i, and it is shaded.
template <typename AddPlanes>
void drawStageTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex* const v[3],
                       const float* flatVaryings, AddPlanes&& addPlanes) {
  FixedTriangle f;
  const int sign = snapTriangle(*v[0], *v[1], *v[2], f);
  if (sign == 0) return;
  int order[3] = {0, 1, 2};
  if (sign < 0) {
    if (state.firstVertexConvention)
      order[1] = 2, order[2] = 1;
    else
      order[0] = 1, order[1] = 0;
  }
  const FixedTriangle r = {{f.x[order[0]], f.x[order[1]], f.x[order[2]]},
                           {f.y[order[0]], f.y[order[1]], f.y[order[2]]}};
  const WindowVertex &a = *v[order[0]], &b = *v[order[1]], &c = *v[order[2]];
  PrimitiveSetup t;
  if (!setupTriangle(state, fb, r, a, b, c, flatVaryings, t)) return;
  const PlaneSetup planes(a.x, a.y, b.x, b.y, c.x, c.y);
  t.w = planes.plane(a.oneOverW, b.oneOverW, c.oneOverW);
  addPlanes(t, planes, order);
  shadePrimitive(state, fb, t);
}

// Calls span(py, lo, hi) for every row of the primitive with pixels inside,
// [lo, hi] being exactly the pixels inside on that row. (shade_avx2.cpp has
// the same loop written out, to keep it inside its target attribute.)
template <typename Span>
inline void forEachSpan(const PrimitiveSetup& t, Span&& span) {
  EdgeSpanStepper edge[kMaxEdges];
  for (int i = 0; i < t.edgeCount; ++i) edge[i] = EdgeSpanStepper(t.edge[i], t.y0);
  for (int py = t.y0; py <= t.y1; ++py) {
    int64_t lo = t.x0, hi = t.x1;
    for (int i = 0; i < t.edgeCount; ++i) edge[i].clip(lo, hi);
    if (lo <= hi) span(py, static_cast<int>(lo), static_cast<int>(hi));
    for (int i = 0; i < t.edgeCount; ++i) edge[i].nextRow();
  }
}

// Shades every pixel of the primitive, one fragment at a time.
void shadePrimitiveScalar(const PrimitiveSetup& t, const ShadeTarget& s);
// The same with AVX2 and FMA, eight fragments at a time, to the same bits.
// Call only when the CPU has both (haveAvx2Fma()).
void shadePrimitiveAvx2(const PrimitiveSetup& t, const ShadeTarget& s);
bool haveAvx2Fma();

}  // namespace glfixed::raster
