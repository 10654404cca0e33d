// Whole-framebuffer operations: glClear (GL 2.1 §4.2.3), glReadPixels (§4.3.2)
// and glPixelStore (§3.6.1).
#include <cmath>
#include <cstdint>
#include <cstring>

#include "api/api.h"
#include "api/list_record.h"
#include "framebuffer/read_pixels.h"

using namespace glfixed;

namespace {

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
  const GLbitfield known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~known) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  Framebuffer& fb = ctx->framebuffer;
  if (!fb.bound()) return;
  if (mask & GL_COLOR_BUFFER_BIT) clearColor(fb, ctx->colorBuffer);
  if ((mask & GL_DEPTH_BUFFER_BIT) && ctx->depth.writeMask && fb.depth.bits() > 0)
    fb.depth.fill(depthToUnorm(ctx->depth.clearDepth, fb.depth.bits()));
}

GLAPI void APIENTRY glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                                 GLvoid* pixels) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
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
  GLenum error = readPixels(ctx->framebuffer, ctx->pixelStore, x, y, width, height, format, type, pixels);
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
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST:
    case GL_PACK_IMAGE_HEIGHT: case GL_PACK_SKIP_IMAGES: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_IMAGES:
      if (param != 0 && pname != GL_PACK_IMAGE_HEIGHT && pname != GL_PACK_SKIP_IMAGES &&
          pname != GL_UNPACK_IMAGE_HEIGHT && pname != GL_UNPACK_SKIP_IMAGES)
        ctx->recordError(GL_INVALID_OPERATION);  // byte swapping is not implemented
      else if (param < 0)
        ctx->recordError(GL_INVALID_VALUE);
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

}  // extern "C"
