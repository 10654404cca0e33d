// Pixel rectangles in GL_RENDER (GL 2.1 §3.6.4 glDrawPixels, §3.7 glBitmap,
// §4.3.3 glCopyPixels): what each draws at the raster position, drawn as
// Mesa's state tracker draws them on llvmpipe (raster/pixel_rect.h).
#pragma once

#include <GL/gl.h>

#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9  // EXT_packed_depth_stencil (not in GL 2.1's gl.h)
#endif
#ifndef GL_UNSIGNED_INT_24_8
#define GL_UNSIGNED_INT_24_8 0x84FA
#endif

#include <cstdint>

#include "texture/unpack.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// A bitmap as Mesa keeps one after unpacking (and a display list stores
// it): rows of (width + 7) / 8 bytes, the most significant bit the leftmost
// pixel, row 0 the bottom row.
inline int bitmapRowBytes(int width) { return (width + 7) / 8; }

// glBitmap's fragments (§3.7): one for each set bit, at window (x + i, y + j)
// where x, y are the raster position minus the origin, floored as Mesa does
// (main/drawpix.c: floor(position + 0.0001 - origin)); the raster colour and
// depth, through the fragment operations. As Mesa does, a bitmap of at most
// 512 x 32 goes into the bitmap cache (state/bitmap_cache.h) and is drawn
// when the cache is flushed; `fromList` (a display list's bitmap, which Mesa
// keeps as a texture) flushes the cache and draws at once.
void drawBitmap(Context& ctx, int width, int height, float xorig, float yorig, const uint8_t* bits,
                bool fromList);

// A client image of glDrawPixels: `pixels` laid out as `layout` says (the
// unpack state at the call, or at list compile time).
struct PixelImage {
  int width = 0, height = 0;
  GLenum format = GL_RGBA, type = GL_UNSIGNED_BYTE;
  texture::ClientLayout layout;
  const uint8_t* pixels = nullptr;
};

// glDrawPixels of a colour format in GL_RENDER at the valid raster position
// (§3.6.4), as Mesa's st_DrawPixels draws it: the image becomes a texture
// sampled NEAREST by a quad from the rounded raster position, zoomed.
void drawColorPixels(Context& ctx, const PixelImage& image);

// glDrawPixels(GL_DEPTH_COMPONENT): the same quad, whose fragments take
// their depth from the image (depth scale and bias applied) and the raster
// colour; they go through the depth test and the other operations.
void drawDepthPixels(Context& ctx, const PixelImage& image);

// glDrawPixels(GL_STENCIL_INDEX) and glDrawPixels(GL_DEPTH_STENCIL,
// GL_UNSIGNED_INT_24_8) (§3.6.4, EXT_packed_depth_stencil): the same quad,
// whose fragments write the image's stencil values under the front stencil
// write mask (and its depths under the depth mask), whatever the stencil,
// depth and alpha tests; no colour. The scissor applies.
void drawStencilPixels(Context& ctx, const PixelImage& image);

// glCopyPixels(GL_DEPTH), (GL_STENCIL) and (GL_DEPTH_STENCIL) (§4.3.3): the
// source rectangle of the depth and stencil buffer, read whole first, drawn
// as the glDrawPixels of its values; GL_DEPTH's fragments have the current
// colour and go through the fragment operations.
void copyDepthStencilPixels(Context& ctx, int x, int y, int width, int height, GLenum type);

// glCopyPixels(GL_COLOR) (§4.3.3): the source rectangle of the read buffer,
// read whole first, drawn as glDrawPixels draws at the raster position.
void copyColorPixels(Context& ctx, int x, int y, int width, int height);

// Draws what the bitmap cache holds, with the state of now (Mesa's
// st_flush_bitmap_cache): before every draw, clear, read, copy and flush.
void flushBitmapCache(Context& ctx);

}  // namespace glfixed::pipeline
