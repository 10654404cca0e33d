// Point sprites (GL 2.0 §3.3.1, GL 2.1 §3.4): the texture coordinates of a
// unit with GL_COORD_REPLACE, as llvmpipe's point setup makes them
// (lp_setup_point.c, texcoord_coef): planes a0 + x dadx + y dady in
// llvmpipe's window space (y down from the top, or up in a framebuffer
// object; pixel centres at +0.5), s from 0 to 1 across the point's square,
// t from 0 to 1 down it for GL_UPPER_LEFT (up it for GL_LOWER_LEFT) in
// llvmpipe's rows (the state tracker swaps the origin for an object), r = 0,
// q = 1.
#pragma once

#include <GL/gl.h>

namespace glfixed::primitive {

struct SpritePlane {
  float a0 = 0, dadx = 0, dady = 0;
};

struct SpriteCoordPlanes {
  SpritePlane s, t, r, q;
};

// The planes for a sprite centred at window (x, y) (in llvmpipe's rows, as it sees
// it: raster/raster.h) of `size` pixels (the size the point is drawn with,
// before llvmpipe's 255 clamp, which this applies); `origin` is
// GL_POINT_SPRITE_COORD_ORIGIN. `oneOverW` is the point's 1/w: with
// `perspective` (a texture coordinate input, which llvmpipe interpolates
// perspective-correct) every coefficient is pre-multiplied by it, and the
// rasterizer divides the interpolated value by the interpolated 1/w, as
// for any perspective varying.
SpriteCoordPlanes spriteCoordPlanes(float x, float y, float size, GLenum origin, float oneOverW,
                                    bool perspective = true);

// The width llvmpipe gives a sprite's square, in 1/256 pixel: the snapped
// size, at least one pixel (not rounded to whole pixels as a legacy point).
int spriteFixedWidth(float size);

}  // namespace glfixed::primitive
