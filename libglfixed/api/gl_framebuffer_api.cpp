// Whole-framebuffer operations: glClear (GL 2.1 §4.2.3), glReadPixels (§4.3.2)
// and glPixelStore (§3.6.1).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "api/api.h"
#include "pipeline/pixel_rect.h"
#include "api/list_record.h"
#include "framebuffer/read_pixels.h"
#include "raster/depth.h"
#include "state/framebuffer_binding.h"

using namespace glfixed;

namespace {

// Clip planes and scissor: what glClear writes with GL_SCISSOR_TEST (§4.1.2,
// §4.2.3). Mesa's st_Clear clears directly only when the scissor box covers
// the whole buffer; otherwise it draws a quad over the box (clear_with_quad),
// whose colour comes out as the direct clear's, but whose depth is the
// vertex z (float)(d * 2 - 1), mapped by the viewport fma(z, 0.5, 0.5) and
// converted as a fragment's depth (probed: 0.1 gives 0x199999, 1/3 0x555554).
PixelBox clearBox(const Context& ctx, bool* byQuad) {
  const Framebuffer& fb = ctx.framebuffer;
  const ScissorAttrib& s = ctx.scissor;
  *byQuad = s.test && (s.x > 0 || s.y > 0 || static_cast<long long>(s.x) + s.width < fb.width() ||
                       static_cast<long long>(s.y) + s.height < fb.height());
  return scissoredBox(fb, s);
}

uint32_t quadClearDepth(double clearDepth, int bits) {
  const float z = static_cast<float>(clearDepth * 2.0 - 1.0);
  return raster::depthToUnorm(std::fma(z, 0.5f, 0.5f), bits);
}

// Mesa's glPixelStoref rounds with lroundf (halves away from zero) and keeps
// the low 32 bits of the long: NaN, infinities and anything past the long's
// range give 0 (x86's "integer indefinite" is LONG_MIN, whose low half is 0);
// 3e9 wraps to a negative value (GL_INVALID_VALUE), -3e9 to a positive one.
GLint mesaRoundToInt(float f) {
  if (!(std::fabs(f) < 9.2233720368547758e18f)) return 0;
  return static_cast<GLint>(static_cast<uint32_t>(static_cast<uint64_t>(std::llround(f))));
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glClear(GLbitfield mask) {
  if (api::compiled(&glClear, mask)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  pipeline::flushBitmapCache(*ctx);  // st_Clear
  const GLbitfield known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~known) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  // A framebuffer object: an incomplete one clears nothing (GL 3.0 §4.4.4).
  if (ctx->objectBound() && !drawFramebufferComplete(*ctx)) return;
  Framebuffer& fb = ctx->framebuffer;
  if (!fb.hasSurface()) return;
  bool byQuad = false;
  const PixelBox box = clearBox(*ctx, &byQuad);
  if (mask & GL_COLOR_BUFFER_BIT) {
    clearColor(fb.color, ctx->colorBuffer, box);
    for (int i = 0; i < fb.moreColorCount; ++i) clearColor(fb.moreColor[i], ctx->colorBuffer, box);
    if (fb.drawsIntoBoth(ctx->colorBuffer.drawBuffer))
      clearColor(fb.front, ctx->colorBuffer, box);
  }
  if (mask & GL_ACCUM_BUFFER_BIT) {
    const glm::vec4& c = ctx->accum.clearValue;
    const float value[4] = {c.r, c.g, c.b, c.a};
    fb.accum.clear(box, value);
  }
  if ((mask & GL_DEPTH_BUFFER_BIT) && ctx->depth.writeMask && fb.depth.bits() > 0) {
    if (byQuad)
      clearDepth(fb, quadClearDepth(ctx->depth.clearDepth, fb.depth.bits()), box);
    else
      fb.depth.fill(depthToUnorm(ctx->depth.clearDepth, fb.depth.bits()));
  }
  // §4.2.3: the stencil under the front write mask (Mesa clears with the
  // front face's mask whatever the back one says: probed).
  const uint32_t stencilWriteMask = ctx->stencil.face[0].writeMask & 0xffu;
  if ((mask & GL_STENCIL_BUFFER_BIT) && stencilWriteMask && fb.depth.stencilBits() > 0) {
    const uint32_t value = static_cast<uint32_t>(ctx->stencil.clearValue) & 0xffu;
    if (byQuad)
      clearStencil(fb, value, stencilWriteMask, box);
    else
      fb.depth.fillStencil(value, stencilWriteMask);
  }
}

GLAPI void APIENTRY glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                                 GLvoid* pixels) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  pipeline::flushBitmapCache(*ctx);  // st_ReadPixels
  if (width < 0 || height < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  if (ctx->objectBound() && !readFramebufferComplete(*ctx)) return;
  if (const GLuint name = ctx->pixelStore.pixelPackBufferBinding) {
    // GL 2.1 §4.3.5: `pixels` is an offset into the pixel pack buffer, and
    // the whole image must fit in it.
    const GLenum formatError = readPixels(ctx->framebuffer, ctx->pixelStore, x, y, 0, 0, format, type, nullptr);
    if (formatError != GL_NO_ERROR) return ctx->recordError(formatError);
    BufferObject* b = ctx->buffers.find(name);
    const size_t offset = reinterpret_cast<uintptr_t>(pixels);
    const size_t bytes = packedImageBytes(ctx->pixelStore, width, height, format, type);
    if (!b || b->mapped || offset > b->data.size() || bytes > b->data.size() - offset)
      return ctx->recordError(GL_INVALID_OPERATION);
    if (bytes == 0) return;
    pixels = b->data.data() + offset;
  }
  GLenum error = readPixels(ctx->framebuffer, ctx->pixelStore, x, y, width, height, format, type, pixels,
                            ctx->pixelMode, &ctx->pixelMaps);
  if (error != GL_NO_ERROR) ctx->recordError(error);
}

// Client state: it never flushes the buffered vertices (nor does Mesa's).
GLAPI void APIENTRY glPixelStorei(GLenum pname, GLint param) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PixelStoreAttrib& p = ctx->pixelStore;
  GLint* target = nullptr;
  bool alignment = false;
  switch (pname) {
    case GL_PACK_ALIGNMENT: target = &p.packAlignment; alignment = true; break;
    case GL_UNPACK_ALIGNMENT: target = &p.unpackAlignment; alignment = true; break;
    case GL_PACK_ROW_LENGTH: target = &p.packRowLength; break;
    case GL_PACK_SKIP_PIXELS: target = &p.packSkipPixels; break;
    case GL_PACK_SKIP_ROWS: target = &p.packSkipRows; break;
    case GL_UNPACK_ROW_LENGTH: target = &p.unpackRowLength; break;
    case GL_UNPACK_SKIP_PIXELS: target = &p.unpackSkipPixels; break;
    case GL_UNPACK_SKIP_ROWS: target = &p.unpackSkipRows; break;
    // Textures: the 3D image layout, and the byte order of unpacked texture
    // images (texture/unpack.cpp). glDrawPixels and the pack side do not
    // swap bytes yet, nor does anything honour LSB_FIRST: still an error.
    case GL_PACK_IMAGE_HEIGHT: target = &p.packImageHeight; break;
    case GL_PACK_SKIP_IMAGES: target = &p.packSkipImages; break;
    case GL_UNPACK_IMAGE_HEIGHT: target = &p.unpackImageHeight; break;
    case GL_UNPACK_SKIP_IMAGES: target = &p.unpackSkipImages; break;
    case GL_UNPACK_SWAP_BYTES:
      p.unpackSwapBytes = param != 0;
      return;
    case GL_PACK_INVERT_MESA:
      p.packInvert = static_cast<GLboolean>(param);
      return;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_UNPACK_LSB_FIRST:
      if (param != 0) ctx->recordError(GL_INVALID_OPERATION);  // not implemented
      return;
    default:
      ctx->recordError(GL_INVALID_ENUM);
      return;
  }
  if (alignment ? (param != 1 && param != 2 && param != 4 && param != 8) : param < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  *target = param;
}

GLAPI void APIENTRY glPixelStoref(GLenum pname, GLfloat param) {
  glPixelStorei(pname, mesaRoundToInt(param));
}


// The colour buffers of the window-system surface (GL 2.1 §4.2.1, §4.3.2),
// with Mesa's rules (Framebuffer::buffersNamed): an unknown name is
// GL_INVALID_ENUM, a buffer the surface lacks GL_INVALID_OPERATION; the name
// is kept as given (GL_BACK stays GL_BACK on a single-buffered surface).
namespace {

// With a framebuffer object bound (GL 3.0 §4.2.1): GL_NONE or one of its
// colour attachments; any window buffer name, or an attachment past the
// maximum, is GL_INVALID_OPERATION, anything else GL_INVALID_ENUM.
bool objectBufferNameError(Context& ctx, GLenum buffer) {
  using namespace fbo_enums;
  if (buffer == GL_NONE || (buffer >= kColorAttachment0 && buffer < kColorAttachment0 + kMaxColorAttachments))
    return false;
  if (ctx.windowFramebuffer().buffersNamed(buffer, false) == Framebuffer::Buffers::kUnknown)
    ctx.recordError(GL_INVALID_ENUM);
  else
    ctx.recordError(GL_INVALID_OPERATION);
  return true;
}

bool colorBufferNameError(Context& ctx, GLenum buffer, bool forReading) {
  switch (ctx.windowFramebuffer().buffersNamed(buffer, forReading)) {
    case Framebuffer::Buffers::kUnknown: ctx.recordError(GL_INVALID_ENUM); return true;
    case Framebuffer::Buffers::kMissing: ctx.recordError(GL_INVALID_OPERATION); return true;
    default: return false;
  }
}

}  // namespace

GLAPI void APIENTRY glDrawBuffer(GLenum buf) {
  if (api::compiled(&glDrawBuffer, buf)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (FramebufferObject* fb = drawFramebufferObject(*ctx)) {
    if (objectBufferNameError(*ctx, buf)) return;
    pipeline::flushVertices(*ctx);
    pipeline::flushBitmapCache(*ctx);
    ctx->markChanged(GL_COLOR_BUFFER_BIT, 0);
    fb->drawBuffers.fill(GL_NONE);
    fb->drawBuffers[0] = buf;
    ctx->colorBuffer.drawBuffer = buf;
    return refreshFramebuffer(*ctx);
  }
  if (colorBufferNameError(*ctx, buf, false)) return;
  if (ctx->colorBuffer.drawBuffer != buf) pipeline::flushBitmapCache(*ctx);  // into the old buffer
  if (api::setState(*ctx, ctx->colorBuffer.drawBuffer, buf, GL_COLOR_BUFFER_BIT)) {
    ctx->selectWindowBuffers();
    refreshFramebuffer(*ctx);
  }
}

GLAPI void APIENTRY glReadBuffer(GLenum src) {
  if (api::compiled(&glReadBuffer, src)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (FramebufferObject* fb = readFramebufferObject(*ctx)) {
    if (objectBufferNameError(*ctx, src)) return;
    pipeline::flushVertices(*ctx);
    ctx->markChanged(GL_PIXEL_MODE_BIT, 0);
    fb->readBuffer = src;
    ctx->pixelMode.readBuffer = src;
    return refreshFramebuffer(*ctx);
  }
  if (colorBufferNameError(*ctx, src, true)) return;
  if (api::setState(*ctx, ctx->pixelMode.readBuffer, src, GL_PIXEL_MODE_BIT)) {
    ctx->selectWindowBuffers();
    refreshFramebuffer(*ctx);
  }
}

}  // extern "C"
