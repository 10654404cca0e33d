// Whole-framebuffer operations: glClear (GL 2.1 §4.2.3), glReadPixels (§4.3.2)
// and glPixelStore (§3.6.1).
#include <cstring>

#include "api/api.h"
#include "api/list_record.h"
#include "framebuffer/read_pixels.h"

using namespace glfixed;

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
  glPixelStorei(pname, static_cast<GLint>(param + (param >= 0 ? 0.5f : -0.5f)));
}

}  // extern "C"
