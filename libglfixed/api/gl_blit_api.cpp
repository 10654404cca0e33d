// glBlitFramebuffer (EXT_framebuffer_blit, GL 3.0 §4.3.3): a rectangle of the
// read framebuffer into one of the draw framebuffer, scaled and flipped as the
// two rectangles say, cut by the scissor box. llvmpipe blits by drawing a
// textured quad (util_blitter): each destination pixel centre maps to a
// source coordinate; NEAREST takes the texel under it, LINEAR filters the
// 2x2 around it in llvmpipe's 8-bit fixed point, clamped to the edge.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "api/api.h"
#include "api/framebuffer_object_commands.h"
#include "api/list_record.h"
#include "pipeline/pixel_rect.h"
#include "state/framebuffer_binding.h"

using namespace glfixed;
using namespace glfixed::fbo_enums;

namespace {

// The depth (and stencil) buffer of the read framebuffer.
DepthBuffer readDepth(Context& ctx) {
  DepthBuffer d;
  if (FramebufferObject* r = readFramebufferObject(ctx))
    depthView(*r, *ctx.framebufferObjects, *ctx.textures, &d);
  else
    d.viewOf(ctx.windowFramebuffer().depth);
  return d;
}

// One axis of the blit: for destination pixel i (from the rectangle's own
// start), the source coordinate of its centre, in source pixels.
struct Axis {
  int s0, s1, d0, d1;
  double scale() const { return static_cast<double>(s1 - s0) / static_cast<double>(d1 - d0); }
  float source(int d) const { return static_cast<float>(s0 + (static_cast<double>(d) + 0.5 - d0) * scale()); }
};

int clampInt(int v, int lo, int hi) { return v < lo ? lo : (v > hi ? hi : v); }

// lp_build_lerp on 8-bit values with a weight 0..255 (texture/sampler.cpp's).
int lerp8(int w, int a, int b) { return (a + ((w * (b - a) * 128 + 16384) >> 15)) & 255; }

}  // namespace

extern "C" {

GLAPI void APIENTRY glBlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                      GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter) {
  if (api::compiled(&glBlitFramebuffer, srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter))
    return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  const GLbitfield known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
  if (mask & ~known) return ctx->recordError(GL_INVALID_VALUE);
  if (filter != GL_NEAREST && filter != GL_LINEAR) return ctx->recordError(GL_INVALID_ENUM);
  if (filter == GL_LINEAR && (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)))
    return ctx->recordError(GL_INVALID_OPERATION);
  refreshFramebuffer(*ctx);
  if (ctx->fbo.drawStatus != kComplete || ctx->fbo.readStatus != kComplete)
    return ctx->recordError(kInvalidFramebufferOperation);
  pipeline::flushBitmapCache(*ctx);
  Framebuffer& fb = ctx->framebuffer;
  DepthBuffer srcDepth = readDepth(*ctx);
  DepthBuffer& dstDepth = fb.depth;
  // Depth and stencil need the same format on both sides (GL 3.0 §4.3.3).
  if ((mask & GL_DEPTH_BUFFER_BIT) && srcDepth.bits() && dstDepth.bits() &&
      srcDepth.bits() != dstDepth.bits())
    return ctx->recordError(GL_INVALID_OPERATION);
  if (srcX0 == srcX1 || srcY0 == srcY1 || dstX0 == dstX1 || dstY0 == dstY1) return;
  const Axis ax{srcX0, srcX1, dstX0, dstX1}, ay{srcY0, srcY1, dstY0, dstY1};
  // The destination box, cut to the buffer and the scissor box.
  int x0 = std::min(dstX0, dstX1), x1 = std::max(dstX0, dstX1);
  int y0 = std::min(dstY0, dstY1), y1 = std::max(dstY0, dstY1);
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, fb.width());
  y1 = std::min(y1, fb.height());
  if (ctx->scissor.test) {
    const ScissorAttrib& s = ctx->scissor;
    x0 = std::max(x0, s.x);
    y0 = std::max(y0, s.y);
    x1 = static_cast<int>(std::min<long long>(x1, static_cast<long long>(s.x) + s.width));
    y1 = static_cast<int>(std::min<long long>(y1, static_cast<long long>(s.y) + s.height));
  }
  if (x0 >= x1 || y0 >= y1) return;
  const int w = x1 - x0, h = y1 - y0;
  const ColorBuffer src = fb.read;
  const int srcW = src.pixels ? src.width : srcDepth.width();
  const int srcH = src.pixels ? src.height : srcDepth.height();
  // Source pixels outside the read buffer give nothing: those destination
  // pixels are left alone (Mesa clips the rectangles first).
  auto inside = [](int v, int n) { return v >= 0 && v < n; };
  if ((mask & GL_COLOR_BUFFER_BIT) && src.pixels && fb.color.pixels) {
    std::vector<uint8_t> out(static_cast<size_t>(w) * h * 4);
    std::vector<uint8_t> write(static_cast<size_t>(w) * h, 0);
    for (int j = 0; j < h; ++j) {
      const float sy = ay.source(y0 + j);
      for (int i = 0; i < w; ++i) {
        const float sx = ax.source(x0 + i);
        uint8_t* o = &out[(static_cast<size_t>(j) * w + i) * 4];
        if (filter == GL_NEAREST) {
          const int px = static_cast<int>(std::floor(sx)), py = static_cast<int>(std::floor(sy));
          if (!inside(px, src.width) || !inside(py, src.height)) continue;
          src.read(px, py, o);
        } else {
          if (!(sx >= std::min(srcX0, srcX1) && sx < std::max(srcX0, srcX1))) continue;
          // 8-bit weights: the coordinate times 256, less half a texel.
          const int cx = static_cast<int>(std::lrint(sx * 256.0f)) - 128;
          const int cy = static_cast<int>(std::lrint(sy * 256.0f)) - 128;
          const int ix = cx >> 8, iy = cy >> 8, wx = cx & 255, wy = cy & 255;
          uint8_t t[4][4];
          const int xs[2] = {clampInt(ix, 0, srcW - 1), clampInt(ix + 1, 0, srcW - 1)};
          const int ys[2] = {clampInt(iy, 0, srcH - 1), clampInt(iy + 1, 0, srcH - 1)};
          src.read(xs[0], ys[0], t[0]);
          src.read(xs[1], ys[0], t[1]);
          src.read(xs[0], ys[1], t[2]);
          src.read(xs[1], ys[1], t[3]);
          for (int k = 0; k < 4; ++k)
            o[k] = static_cast<uint8_t>(lerp8(wy, lerp8(wx, t[0][k], t[1][k]), lerp8(wx, t[2][k], t[3][k])));
        }
        write[static_cast<size_t>(j) * w + i] = 1;
      }
    }
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        if (!write[static_cast<size_t>(j) * w + i]) continue;
        // A blit bypasses the fragment operations but the scissor test (§4.3.3).
        fb.color.write(x0 + i, y0 + j, &out[(static_cast<size_t>(j) * w + i) * 4]);
      }
  }
  const bool depth = (mask & GL_DEPTH_BUFFER_BIT) && srcDepth.bits() && dstDepth.bits();
  const bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && srcDepth.stencilBits() && dstDepth.stencilBits();
  if (depth || stencil) {
    std::vector<int64_t> d(static_cast<size_t>(w) * h, -1), s(static_cast<size_t>(w) * h, -1);
    for (int j = 0; j < h; ++j) {
      const int py = static_cast<int>(std::floor(ay.source(y0 + j)));
      for (int i = 0; i < w; ++i) {
        const int px = static_cast<int>(std::floor(ax.source(x0 + i)));
        if (!inside(px, srcDepth.width()) || !inside(py, srcDepth.height())) continue;
        if (depth) d[static_cast<size_t>(j) * w + i] = srcDepth.get(px, py);
        if (stencil) s[static_cast<size_t>(j) * w + i] = srcDepth.getStencil(px, py);
      }
    }
    const uint32_t stencilMask = 0xffu;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const size_t k = static_cast<size_t>(j) * w + i;
        if (depth && d[k] >= 0) dstDepth.set(x0 + i, y0 + j, static_cast<uint32_t>(d[k]));
        if (stencil && s[k] >= 0)
          dstDepth.setStencil(x0 + i, y0 + j, static_cast<uint32_t>(s[k]), stencilMask);
      }
  }
}

GLAPI void APIENTRY glBlitFramebufferEXT(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                         GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask,
                                         GLenum filter) {
  glBlitFramebuffer(srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter);
}

}  // extern "C"
