// Triangle set-up: snapping, bounding box, edges, attribute planes and
// polygon offset, in llvmpipe's window space (y down, or up in a framebuffer
// object: see raster.h); the fragments are shaded by the fragment stage
// (fragment/shade.h).
// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fragment/shade.h"
#include "raster/edge.h"
#include "raster/interpolate.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"

namespace glfixed::raster {

int snapTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, FixedTriangle& out) {
  const WindowVertex* v[3] = {&v0, &v1, &v2};
  for (int i = 0; i < 3; ++i) {
    out.x[i] = snapToFixed(v[i]->x);
    out.y[i] = snapToFixed(v[i]->y);
  }
  int64_t area = fixedArea(out);
  return area > 0 ? 1 : (area < 0 ? -1 : 0);
}

float polygonOffsetZ(const RasterState& state, int depthBits, const WindowVertex& v0, const WindowVertex& v1,
                     const WindowVertex& v2) {
  if (!state.polygonOffset) return 0.0f;
  // The units in depth-buffer steps: (float)(units * mrd * 2) in double, mrd
  // 1/(2^bits - 1); no depth buffer counts as 24 bits (lp_state_setup.c,
  // lp_make_setup_variant_key; u_format.c, util_get_depth_format_mrd).
  const double mrd = depthBits == 16 ? 1.0 / 65535.0 : 1.0 / 16777215.0;
  const float units = static_cast<float>(double(state.offsetUnits) * mrd * 2);
  const float scale = state.offsetFactor;
  if (!(scale != 0.0f || units != 0.0f)) return 0.0f;
  // The area as the attribute planes compute it, then the z slopes from the
  // cross product of the edges (v0 - v1) and (v2 - v0).
  const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y, dz01 = v0.z - v1.z;
  const float dx20 = v2.x - v0.x, dy20 = v2.y - v0.y, dz20 = v2.z - v0.z;
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  const float a = dz20 * dy01 - dy20 * dz01;
  const float b = dx20 * dz01 - dz20 * dx01;
  const float dzdx = std::fabs(a * ooa), dzdy = std::fabs(b * ooa);
  // An unordered compare: a NaN slope in x is kept.
  const float maxSlope = !(dzdx <= dzdy) ? dzdx : dzdy;
  const float mult = maxSlope * scale;
  return units + mult;  // GL 2.1 has no offset clamp (Mesa's is 0: none)
}

bool setupTriangle(const RasterState& state, const Framebuffer& fb, const FixedTriangle& fixed,
                   const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                   const float* flatVaryings, PrimitiveSetup& t) {
  // Bounding box as llvmpipe computes it (x1 exclusive of a right vertex on a
  // pixel centre; with the bottom-edge rule y0 exclusive of a top one, else
  // y1 exclusive of a bottom one: llvmpipe's `adj`).
  const int32_t adj = state.bottomEdgeRule ? 1 : 0;
  const int32_t minX = std::min({fixed.x[0], fixed.x[1], fixed.x[2]});
  const int32_t maxX = std::max({fixed.x[0], fixed.x[1], fixed.x[2]});
  const int32_t minY = std::min({fixed.y[0], fixed.y[1], fixed.y[2]});
  const int32_t maxY = std::max({fixed.y[0], fixed.y[1], fixed.y[2]});
  t.x0 = minX >> kSubpixelBits;
  t.x1 = (maxX - 1) >> kSubpixelBits;
  t.y0 = (minY + adj) >> kSubpixelBits;
  t.y1 = (maxY - 1 + adj) >> kSubpixelBits;
  // The drawable region: the scissor (GL window space, y up) in llvmpipe rows.
  const LlvmpipeRows rows = llvmpipeRows(fb, state.scissorY0, state.scissorY1);
  t.x0 = std::max({t.x0, state.scissorX0, 0});
  t.x1 = std::min({t.x1, state.scissorX1 - 1, fb.width() - 1});
  t.y0 = static_cast<int>(std::max<int64_t>(t.y0, rows.first));
  t.y1 = static_cast<int>(std::min<int64_t>(t.y1, rows.last));
  if (t.x0 > t.x1 || t.y0 > t.y1) return false;

  t.edgeCount = 3;
  for (int i = 0; i < 3; ++i) t.edge[i] = Edge::make(fixed, i, state.bottomEdgeRule);

  t.varyingCount = state.varyingCount == 8 ? 8 : 4;
  const PlaneSetup ps(v0.x, v0.y, v1.x, v1.y, v2.x, v2.y);
  t.z = ps.plane(v0.z, v1.z, v2.z);
  t.zOffset = polygonOffsetZ(state, fb.depth.bits(), v0, v1, v2);
  t.stipple = state.polygonStipple;
  t.flatPrimary = flatVaryings && (state.flatGroups & RasterState::kPrimaryGroup);
  t.flatSecondary = flatVaryings && (state.flatGroups & RasterState::kSecondaryGroup);
  if (flatVaryings)
    for (int k = 0; k < t.varyingCount; ++k) t.flat[k] = flatVaryings[k];
  if (!t.flatPrimary || (t.varyingCount == 8 && !t.flatSecondary)) {
    t.w = ps.plane(v0.oneOverW, v1.oneOverW, v2.oneOverW);
    for (int k = 0; k < t.varyingCount; ++k) {
      if (k < 4 ? t.flatPrimary : t.flatSecondary) continue;
      t.varying[k] =
          ps.plane(v0.varying[k] * v0.oneOverW, v1.varying[k] * v1.oneOverW, v2.varying[k] * v2.oneOverW);
    }
  }
  setTexCoordPlanes(
      state, t, [&] { return ps.plane(v0.oneOverW, v1.oneOverW, v2.oneOverW); },
      [&](int k) {
        return ps.plane(v0.varying[k] * v0.oneOverW, v1.varying[k] * v1.oneOverW, v2.varying[k] * v2.oneOverW);
      });
  return true;
}

void rasterCcwTriangle(const RasterState& state, Framebuffer& fb, const FixedTriangle& fixed,
                       const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                       const float* flatVaryings, bool backFacing) {
  PrimitiveSetup t;
  if (!setupTriangle(state, fb, fixed, v0, v1, v2, flatVaryings, t)) return;
  t.backFacing = backFacing;
  fragment::shadePrimitive(state, fb, t);
}

void drawTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex& v0, const WindowVertex& v1,
                  const WindowVertex& v2, const float* flatVaryings) {
  FixedTriangle f;
  const int sign = snapTriangle(v0, v1, v2, f);
  const bool backFacing = (sign > 0) != (state.frontFace == GL_CCW);
  if (sign > 0) {
    rasterCcwTriangle(state, fb, f, v0, v1, v2, flatVaryings, backFacing);
  } else if (sign < 0) {
    // llvmpipe swaps two vertices so that the provoking one keeps its slot.
    if (state.firstVertexConvention) {
      FixedTriangle r = {{f.x[0], f.x[2], f.x[1]}, {f.y[0], f.y[2], f.y[1]}};
      rasterCcwTriangle(state, fb, r, v0, v2, v1, flatVaryings, backFacing);
    } else {
      FixedTriangle r = {{f.x[1], f.x[0], f.x[2]}, {f.y[1], f.y[0], f.y[2]}};
      rasterCcwTriangle(state, fb, r, v1, v0, v2, flatVaryings, backFacing);
    }
  }
}

}  // namespace glfixed::raster
