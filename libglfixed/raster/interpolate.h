// Attribute plane equations, computed as llvmpipe's setup code computes them
// (lp_state_setup.c: init_args, calc_coef4, apply_perspective_corr), and
// evaluated per pixel as its fragment code does (lp_bld_interp.c,
// attribs_update_simple). Every operation is single precision, in the same
// order; the per-pixel evaluation is two fused multiply-adds (llvm.fmuladd
// becomes an FMA on CPUs that have one, which is what the reference ran on).
#pragma once

#include <cmath>

namespace glfixed::raster {

// The plane of one scalar attribute: the value at pixel (px, py) (integer
// pixel indices in llvmpipe's space (y down, up in an object); the centre is implied) is
// fma(dady, py, fma(dadx, px, a0)).
struct Plane {
  float a0 = 0, dadx = 0, dady = 0;
  float at(float px, float py) const { return std::fma(dady, py, std::fma(dadx, px, a0)); }
};

// The triangle-wide factors every plane shares: computed from the unsnapped
// float window positions of the three vertices in setup order.
struct PlaneSetup {
  float dx01Ooa, dy01Ooa, dx20Ooa, dy20Ooa;  // edge vectors divided by the area
  float x0Centre, y0Centre;                  // vertex 0 relative to pixel (0, 0)'s centre

  PlaneSetup(float x0, float y0, float x1, float y1, float x2, float y2) {
    float dx01 = x0 - x1, dy01 = y0 - y1;
    float dx20 = x2 - x0, dy20 = y2 - y0;
    float e = dx01 * dy20, f = dy01 * dx20;
    float ooa = 1.0f / (e - f);
    dx01Ooa = dx01 * ooa;
    dy01Ooa = dy01 * ooa;
    dx20Ooa = dx20 * ooa;
    dy20Ooa = dy20 * ooa;
    x0Centre = x0 - 0.5f;
    y0Centre = y0 - 0.5f;
  }

  // a0, a1, a2: the attribute at the three vertices (already multiplied by
  // 1/w for a perspective-correct attribute).
  Plane plane(float a0, float a1, float a2) const {
    float da01 = a0 - a1, da20 = a2 - a0;
    Plane p;
    p.dadx = da01 * dy20Ooa - da20 * dy01Ooa;
    p.dady = da20 * dx01Ooa - da01 * dx20Ooa;
    p.a0 = a0 - (p.dadx * x0Centre + p.dady * y0Centre);
    return p;
  }
};

}  // namespace glfixed::raster
