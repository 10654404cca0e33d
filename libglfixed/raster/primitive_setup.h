// Internal to the rasterizer: one primitive, set up, and where its fragments
// go. llvmpipe rasterizes triangles, lines and points alike, as a convex
// polygon of 3 or 4 fixed-point edges with attribute planes
// (lp_setup_tri.c, lp_setup_line.c, lp_setup_point.c); only the set-up
// differs. triangle.cpp (and the line and point set-ups) fill these; the
// fragment stage (fragment/shade.h) shades them.
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
  // RasterState::texCoordUnits: bit u, varying[kTexCoordVarying + 4u ..]
  // holds unit u's s, t, r, q planes (always interpolated, with `w` set).
  uint32_t texCoordUnits = 0;
  // Fog: varying[kFogVarying] holds the fog distance's plane (with `w`).
  bool fog = false;
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // inclusive pixel bounds, llvmpipe rows (Framebuffer::rowsUp)
  // Smooth points (raster/point.cpp): one of the two triangles of the draw
  // module's aapoint quad, whose fragment shader Mesa rewrites
  // (nir_lower_aapoint_fs): d = s^2 + t^2 from the interpolated (s, t) in
  // [-1, 1]; a fragment with d > 1 is discarded; else alpha is multiplied by
  // (1 - d) / (1 - k) where d <= k, and by 1 elsewhere (sic: Mesa's NIR pass
  // swaps the two, so the disc's inside is brightened and its rim kept).
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
  // The primitive faces back: the stencil test uses the back state. Only
  // triangles face back (llvmpipe's lines and points, also those of
  // GL_LINE and GL_POINT polygons, face front: probed).
  bool backFacing = false;
};

}  // namespace glfixed::raster

namespace glfixed::fragment {
// Shades every fragment of a set-up primitive (fragment/shade.cpp).
void shadePrimitive(const raster::RasterState& state, Framebuffer& fb, const raster::PrimitiveSetup& t);
}  // namespace glfixed::fragment

namespace glfixed::raster {

// The texture coordinate planes of the units in state.texCoordUnits (and
// the 1/w plane they need): `plane(k)` makes varying k's plane.
template <typename MakePlane, typename MakeW>
inline void setTexCoordPlanes(const RasterState& state, PrimitiveSetup& t, MakeW&& makeW, MakePlane&& plane) {
  t.texCoordUnits = state.texCoordUnits;
  t.fog = state.fog.active();  // and the fog distance, the same way
  if (!t.texCoordUnits && !t.fog) return;
  t.w = makeW();
  for (int u = 0; u < kMaxTexCoordUnits; ++u)
    if (t.texCoordUnits & (1u << u))
      for (int k = kTexCoordVarying + 4 * u; k < kTexCoordVarying + 4 * u + 4; ++k) t.varying[k] = plane(k);
  if (t.fog) t.varying[kFogVarying] = plane(kFogVarying);
}

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
  // The stencil test's face: the aapoint stage's triangles face back, the
  // aaline stage's front, whatever their winding and glFrontFace (probed).
  t.backFacing = t.aaPoint;
  fragment::shadePrimitive(state, fb, t);
}

}  // namespace glfixed::raster
