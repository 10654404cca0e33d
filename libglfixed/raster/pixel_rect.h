// Pixel rectangles as Mesa's state tracker draws them on llvmpipe: glBitmap
// and glDrawPixels become a screen-aligned quad (st_draw_quad: a fan of four
// vertices, (v0, v1, v2) then (v0, v2, v3)) whose fragments go through the
// ordinary fragment stage (GL 2.1 §3.6.4, §3.7).
#pragma once

#include "framebuffer/framebuffer.h"
#include "raster/raster.h"

namespace glfixed::raster {

// The quad st_draw_quad draws, in GL window coordinates (y up): corners
// (x0, y0) .. (x1, y1), depth `z` in [0, 1], texture coordinates of unit 0
// (s0, t0) at (x0, y1) to (s1, t1) at (x1, y0) as st_draw_quad pairs them,
// and a constant colour. Positions go through the state tracker's clip-space
// round trip (x / width * 2 - 1, then llvmpipe's viewport transform of the
// whole buffer) before set-up.
struct PixelQuad {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0, z = 0;
  float s0 = 0, t0 = 0, s1 = 1, t1 = 1;
  float color[4] = {1, 1, 1, 1};
  float secondary[4] = {0, 0, 0, 0};  // varyings 4..7 when state.varyingCount is 8 (the colour sum)
  bool texCoords = false;  // whether unit 0's coordinates are varyings
};
void drawPixelQuad(const RasterState& state, Framebuffer& fb, const PixelQuad& quad);

// A run of pixels [x0, x1) x [y0, y1) in GL window coordinates with integer
// corners, a constant colour and depth: one set bit row of a bitmap (the
// state tracker's quad covers exactly these pixels; its texture kills the
// others). Cut to the state's scissor region first, so far-off positions
// never reach the fixed-point set-up.
// `coords` non-null: unit 0's coordinates are those of the quad of window
// rectangle [x, x + width) x [y, y + height) going from 0 to 1 (Mesa's
// bitmap quad: s along x, t up), at the run's corners.
struct QuadTexCoords {
  float x = 0, y = 0, width = 1, height = 1;
};
void drawPixelRun(const RasterState& state, Framebuffer& fb, int x0, int y0, int x1, int y1, float z,
                  const float color[4], const float secondary[4], const QuadTexCoords* coords = nullptr);

}  // namespace glfixed::raster
