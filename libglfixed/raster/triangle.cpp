// Triangle rasterization: bounding box, exact edge spans, per-fragment depth
// test and colour, all in llvmpipe's y-down window space (see raster.h).
// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/depth.h"
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

namespace {

// The reference for the AVX2 shader: one fragment at a time.
void shadeSpanScalar(const PrimitiveSetup& t, const ShadeTarget& s, int py, int lo, int hi) {
  const int glY = s.height - 1 - py;
  const float fpy = static_cast<float>(py);
  uint8_t* colorRow = s.color->pixel(0, glY);
  uint32_t* depth32 =
      s.depthBits == 24 ? static_cast<uint32_t*>(s.depth) + size_t(glY) * s.depthWidth : nullptr;
  uint16_t* depth16 =
      s.depthBits == 16 ? static_cast<uint16_t*>(s.depth) + size_t(glY) * s.depthWidth : nullptr;
  const uint32_t stipple = s.stipple ? stippleRow(s.stipple, glY) : ~0u;
  for (int px = lo; px <= hi; ++px) {
    const float fpx = static_cast<float>(px);
    if (!stipplePasses(stipple, px)) continue;  // polygon stipple: the fragment is discarded
    // Smooth points: the aapoint shader's discard and alpha factor (primitive_setup.h).
    float aaFactor = 1.0f;
    if (t.aaPoint) {
      const float oowAa = 1.0f / t.w.at(fpx, fpy);
      const float ps = t.aaS.at(fpx, fpy) * oowAa, pt = t.aaT.at(fpx, fpy) * oowAa;
      const float d = ps * ps + pt * pt;
      if (1.0f < d) continue;
      const float coverage = (1.0f / (1.0f - t.aaK)) * (1.0f - d);
      aaFactor = t.aaK >= d ? coverage : 1.0f;
    }
    if (s.depthBits) {
      const uint32_t z = depthToUnorm(t.z.at(fpx, fpy) + t.zOffset, s.depthBits);
      const uint32_t stored = depth32 ? depth32[px] : depth16[px];
      if (!depthPasses(s.depthFunc, z, stored)) continue;
      if (s.depthWrite) {
        if (depth32)
          depth32[px] = z;
        else
          depth16[px] = static_cast<uint16_t>(z);
      }
    }
    if (!s.anyColor) continue;
    float c[kMaxVaryings] = {};
    const bool smooth = !t.flatPrimary || (s.secondary && !t.flatSecondary) || t.lineCoverage;
    const float oow = smooth ? 1.0f / t.w.at(fpx, fpy) : 0.0f;
    for (int k = 0; k < t.varyingCount; ++k) {
      const bool flat = k < 4 ? t.flatPrimary : t.flatSecondary;
      c[k] = flat ? t.flat[k] : t.varying[k].at(fpx, fpy) * oow;
    }
    // GL_LINE_SMOOTH: the aaline stage's coverage scales alpha (lines only).
    if (t.lineCoverage) c[3] = c[3] * lineCoverageAt(t, fpx, fpy, oow);
    if (s.secondary) {  // GL 2.1 §3.9: colour sum, rgb only
      c[0] += c[4];
      c[1] += c[5];
      c[2] += c[6];
    }
    if (t.aaPoint) c[3] = c[3] * aaFactor;
    const uint8_t rgba[4] = {colorToUnorm8(c[0]), colorToUnorm8(c[1]), colorToUnorm8(c[2]),
                             colorToUnorm8(c[3])};
    uint8_t* p = colorRow + size_t(px) * s.bytesPerPixel;
    const int offset[4] = {s.red, s.green, s.blue, s.alpha};
    for (int k = 0; k < 4; ++k)
      if (s.colorWrite[k] && offset[k] >= 0) p[offset[k]] = rgba[k];
  }
}

}  // namespace

void shadePrimitiveScalar(const PrimitiveSetup& t, const ShadeTarget& s) {
  forEachSpan(t, [&](int py, int lo, int hi) { shadeSpanScalar(t, s, py, lo, hi); });
}

namespace {
const bool kUseAvx2 = haveAvx2Fma();
}  // namespace

ShadeTarget makeShadeTarget(const RasterState& state, Framebuffer& fb, const PrimitiveSetup& t) {
  ShadeTarget s;
  s.height = fb.height();
  s.color = &fb.color;
  s.bytesPerPixel = fb.color.bytesPerPixel;
  s.red = fb.color.red;
  s.green = fb.color.green;
  s.blue = fb.color.blue;
  s.alpha = fb.color.alpha;
  for (int k = 0; k < 4; ++k) s.colorWrite[k] = state.colorWrite[k];
  s.anyColor = state.colorWrite[0] || state.colorWrite[1] || state.colorWrite[2] || state.colorWrite[3];
  s.allColor = state.colorWrite[0] && state.colorWrite[1] && state.colorWrite[2] && state.colorWrite[3];
  if (state.depthTest && fb.depth.bits() != 0) {
    s.depthBits = fb.depth.bits();
    s.depth = fb.depth.data();
    s.depthWidth = fb.depth.width();
    s.depthWrite = state.depthWrite;
    s.depthFunc = state.depthFunc;
  }
  s.secondary = t.varyingCount == 8;
  s.stipple = t.stipple ? t.stipple : (state.stippleEveryPrimitive ? state.polygonStipple : nullptr);
  return s;
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
  // pixel centre, y0 exclusive of a top one, for GL's bottom-left rule).
  const int32_t minX = std::min({fixed.x[0], fixed.x[1], fixed.x[2]});
  const int32_t maxX = std::max({fixed.x[0], fixed.x[1], fixed.x[2]});
  const int32_t minY = std::min({fixed.y[0], fixed.y[1], fixed.y[2]});
  const int32_t maxY = std::max({fixed.y[0], fixed.y[1], fixed.y[2]});
  t.x0 = minX >> kSubpixelBits;
  t.x1 = (maxX - 1) >> kSubpixelBits;
  t.y0 = (minY + 1) >> kSubpixelBits;
  t.y1 = maxY >> kSubpixelBits;
  // The drawable region: the scissor (GL window space, y up) in llvmpipe rows.
  const int height = fb.height();
  t.x0 = std::max({t.x0, state.scissorX0, 0});
  t.x1 = std::min({t.x1, state.scissorX1 - 1, fb.width() - 1});
  t.y0 = std::max({t.y0, height - state.scissorY1, 0});
  t.y1 = std::min({t.y1, height - 1 - state.scissorY0, height - 1});
  if (t.x0 > t.x1 || t.y0 > t.y1) return false;

  t.edgeCount = 3;
  for (int i = 0; i < 3; ++i) t.edge[i] = Edge::make(fixed, i);

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
  return true;
}

void shadePrimitive(const RasterState& state, Framebuffer& fb, const PrimitiveSetup& t) {
  const ShadeTarget target = makeShadeTarget(state, fb, t);
  if (kUseAvx2 && !t.aaPoint)  // smooth points: the scalar shader only (primitive_setup.h)
    shadePrimitiveAvx2(t, target);
  else
    shadePrimitiveScalar(t, target);
}

void rasterCcwTriangle(const RasterState& state, Framebuffer& fb, const FixedTriangle& fixed,
                       const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                       const float* flatVaryings) {
  PrimitiveSetup t;
  if (!setupTriangle(state, fb, fixed, v0, v1, v2, flatVaryings, t)) return;
  shadePrimitive(state, fb, t);
}

void drawTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex& v0, const WindowVertex& v1,
                  const WindowVertex& v2, const float* flatVaryings) {
  FixedTriangle f;
  const int sign = snapTriangle(v0, v1, v2, f);
  if (sign > 0) {
    rasterCcwTriangle(state, fb, f, v0, v1, v2, flatVaryings);
  } else if (sign < 0) {
    // llvmpipe swaps two vertices so that the provoking one keeps its slot.
    if (state.firstVertexConvention) {
      FixedTriangle r = {{f.x[0], f.x[2], f.x[1]}, {f.y[0], f.y[2], f.y[1]}};
      rasterCcwTriangle(state, fb, r, v0, v2, v1, flatVaryings);
    } else {
      FixedTriangle r = {{f.x[1], f.x[0], f.x[2]}, {f.y[1], f.y[0], f.y[2]}};
      rasterCcwTriangle(state, fb, r, v1, v0, v2, flatVaryings);
    }
  }
}

}  // namespace glfixed::raster
