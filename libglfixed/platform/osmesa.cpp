// The OSMesa off-screen API (Mesa's GL/osmesa.h ABI): contexts that render
// into a client buffer. Behaviour measured on Mesa 22.3 where the header is
// silent (REFERENCE.md, "Depth and limits"; the probe in tests/api).
#include <GL/osmesa.h>

#include <cstdio>
#include <cstring>

#include "api/entry_points.h"
#include "pipeline/immediate_mode.h"
#include "pipeline/pixel_rect.h"
#include "state/context.h"

using glfixed::Context;
using glfixed::PixelFormat;

// The opaque handle of osmesa.h is a pointer to this.
struct osmesa_context {
  Context context;
  GLenum osmesaFormat;             // OSMESA_RGBA, ... as created
  PixelFormat format;              // how the bound buffer stores it (by the type of OSMesaMakeCurrent)
  GLenum type = GL_UNSIGNED_BYTE;  // of the bound buffer
  int width = 0, height = 0;
  GLint userRowLength = 0;
  bool yUp = true;
  osmesa_context(GLenum osFormat, PixelFormat f, int depthBits, int stencilBits)
      : context(depthBits, stencilBits), osmesaFormat(osFormat), format(f) {}
};

namespace {

thread_local osmesa_context* tCurrent = nullptr;

bool pixelFormatOf(GLenum format, PixelFormat* out) {
  switch (format) {
    case OSMESA_RGBA: *out = PixelFormat::kRGBA; return true;
    case OSMESA_BGRA: *out = PixelFormat::kBGRA; return true;
    case OSMESA_ARGB: *out = PixelFormat::kARGB; return true;
    case OSMESA_RGB: *out = PixelFormat::kRGB; return true;
    case OSMESA_BGR: *out = PixelFormat::kBGR; return true;
    case OSMESA_RGB_565: *out = PixelFormat::kRGB565; return true;
    default: return false;  // colour index is not supported
  }
}

// The buffer a (format, type) pair of OSMesaMakeCurrent is, as Mesa's OSMesa
// picks llvmpipe's format (MESA_FACTS.md, "OSMesa colour buffer types"):
// 16-bit and float buffers are R, G, B, A in memory whatever the OSMesa
// format says (BGRA and ARGB too); OSMESA_BGR has only bytes (which Mesa
// refuses and we draw), OSMESA_RGB_565 only GL_UNSIGNED_SHORT_5_6_5.
bool bufferFormatOf(GLenum format, GLenum type, PixelFormat* out) {
  const bool withAlpha = format == OSMESA_RGBA || format == OSMESA_BGRA || format == OSMESA_ARGB;
  switch (type) {
    case GL_UNSIGNED_BYTE: return format != OSMESA_RGB_565 && pixelFormatOf(format, out);
    case GL_UNSIGNED_SHORT:
      if (!withAlpha && format != OSMESA_RGB) return false;
      *out = withAlpha ? PixelFormat::kRGBA16 : PixelFormat::kRGB16;
      return true;
    case GL_FLOAT:
      if (!withAlpha && format != OSMESA_RGB) return false;
      *out = withAlpha ? PixelFormat::kRGBA32F : PixelFormat::kRGB32F;
      return true;
    case GL_UNSIGNED_SHORT_5_6_5:
      if (format != OSMESA_RGB_565) return false;
      *out = PixelFormat::kRGB565;
      return true;
    default: return false;
  }
}

// Mesa's choice of depth buffer: with a stencil buffer any depth request gives
// 24 bits (a packed depth-stencil format); without one, 16..23 bits give 16,
// 24 and more give 24, and fewer than 16 give none. Any stencil request gives
// 8 bits, packed with a 24-bit depth, or alone without depth (probed).
int depthBitsFor(GLint depthBits, GLint stencilBits) {
  if (depthBits <= 0) return 0;
  if (stencilBits > 0) return 24;
  if (depthBits >= 24) return 24;
  if (depthBits >= 16) return 16;
  return 0;
}

// Points the context's colour buffer at the client memory with the current
// pixel-store settings.
void bindColorBuffer(osmesa_context& c, void* buffer) {
  glfixed::Framebuffer& fb = c.context.windowFramebuffer();
  glfixed::ColorBuffer& cb = fb.front;
  cb.setFormat(c.format);
  cb.pixels = static_cast<uint8_t*>(buffer);
  cb.width = c.width;
  cb.height = c.height;
  cb.rowLength = c.userRowLength > 0 ? c.userRowLength : c.width;
  cb.yUp = c.yUp;
  fb.back = glfixed::ColorBuffer{};  // OSMesa buffers are single-buffered
  fb.readFront = cb;
  fb.readBack = fb.back;
  fb.surface = fb.readSurface = nullptr;
  c.context.selectWindowBuffers();
}

}  // namespace

extern "C" {

GLAPI OSMesaContext APIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                    GLint accumBits, OSMesaContext sharelist) {
  PixelFormat f;
  if (!pixelFormatOf(format, &f)) {
    std::fprintf(stderr, "libglfixed: OSMesaCreateContext: unsupported format 0x%x\n", format);
    return nullptr;
  }
  osmesa_context* c = new (std::nothrow)
      osmesa_context(format, f, depthBitsFor(depthBits, stencilBits), stencilBits > 0 ? 8 : 0);
  if (!c) return nullptr;
  c->context.requestedAccum = accumBits > 0;
  if (sharelist) c->context.shareObjectsWith(sharelist->context);
  return c;
}

GLAPI OSMesaContext APIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  // Mesa asks for 24 depth and 8 stencil bits here.
  return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

GLAPI OSMesaContext APIENTRY OSMesaCreateContextAttribs(const int* attribList, OSMesaContext sharelist) {
  GLenum format = OSMESA_RGBA;
  GLint depthBits = 0, stencilBits = 0, accumBits = 0;
  GLint profile = OSMESA_COMPAT_PROFILE, major = 1, minor = 0;
  for (int i = 0; attribList && attribList[i]; i += 2) {
    const int value = attribList[i + 1];
    switch (attribList[i]) {
      case OSMESA_FORMAT: format = value; break;
      case OSMESA_DEPTH_BITS: depthBits = value; break;
      case OSMESA_STENCIL_BITS: stencilBits = value; break;
      case OSMESA_ACCUM_BITS: accumBits = value; break;
      case OSMESA_PROFILE: profile = value; break;
      case OSMESA_CONTEXT_MAJOR_VERSION: major = value; break;
      case OSMESA_CONTEXT_MINOR_VERSION: minor = value; break;
      default:
        std::fprintf(stderr, "libglfixed: OSMesaCreateContextAttribs: unknown attribute 0x%x\n", attribList[i]);
        return nullptr;
    }
  }
  // Only a compatibility context up to GL 2.1 can be had.
  if (profile != OSMESA_COMPAT_PROFILE || major > 2 || (major == 2 && minor > 1)) {
    std::fprintf(stderr, "libglfixed: OSMesaCreateContextAttribs: only GL <= 2.1 compatibility contexts\n");
    return nullptr;
  }
  return OSMesaCreateContextExt(format, depthBits, stencilBits, accumBits, sharelist);
}

GLAPI void APIENTRY OSMesaDestroyContext(OSMesaContext ctx) {
  if (!ctx) return;
  glfixed::pipeline::flushVertices(ctx->context);
  if (tCurrent == ctx) {
    tCurrent = nullptr;
    if (glfixed::currentContext() == &ctx->context) glfixed::setCurrentContext(nullptr);
  }
  delete ctx;
}

GLAPI GLboolean APIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type, GLsizei width,
                                           GLsizei height) {
  // What the current context still holds is drawn into its buffer first;
  // its cached bitmaps too when another context (or none) takes over, as
  // Mesa's _mesa_make_current flushes the old context. The same context on a
  // new buffer keeps them, and draws them there (measured).
  if (tCurrent) {
    glfixed::pipeline::flushVertices(tCurrent->context);
    if (tCurrent != ctx) glfixed::pipeline::flushBitmapCache(tCurrent->context);
  }
  if (!ctx && !buffer) {  // release the current context
    tCurrent = nullptr;
    glfixed::setCurrentContext(nullptr);
    return GL_TRUE;
  }
  if (!ctx || !buffer || width < 1 || height < 1 || width > glfixed::kMaxViewportSize ||
      height > glfixed::kMaxViewportSize)
    return GL_FALSE;
  PixelFormat bufferFormat;
  if (!bufferFormatOf(ctx->osmesaFormat, type, &bufferFormat)) {
    std::fprintf(stderr, "libglfixed: OSMesaMakeCurrent: unsupported format/type 0x%x/0x%x\n",
                 ctx->osmesaFormat, type);
    return GL_FALSE;
  }
  ctx->format = bufferFormat;
  ctx->type = type;
  ctx->width = width;
  ctx->height = height;
  bindColorBuffer(*ctx, buffer);
  glfixed::DepthBuffer& depth = ctx->context.windowFramebuffer().depth;
  if (depth.width() != width || depth.height() != height || depth.bits() != ctx->context.requestedDepthBits ||
      depth.stencilBits() != ctx->context.requestedStencilBits)
    depth.resize(width, height, ctx->context.requestedDepthBits, ctx->context.requestedStencilBits);
  glfixed::AccumBuffer& accum = ctx->context.windowFramebuffer().accum;
  if (accum.width() != width || accum.height() != height || accum.present() != ctx->context.requestedAccum)
    accum.resize(width, height, ctx->context.requestedAccum);
  ctx->context.sizeToFirstSurface(width, height, false);  // OSMesa buffers are single-buffered
  tCurrent = ctx;
  glfixed::setCurrentContext(&ctx->context);
  return GL_TRUE;
}

// Null when a GLX or EGL context was made current on this thread since.
GLAPI OSMesaContext APIENTRY OSMesaGetCurrentContext(void) {
  return tCurrent && glfixed::currentContext() == &tCurrent->context ? tCurrent : nullptr;
}

GLAPI void APIENTRY OSMesaPixelStore(GLint pname, GLint value) {
  osmesa_context* c = OSMesaGetCurrentContext();
  if (!c) return;
  switch (pname) {
    case OSMESA_ROW_LENGTH:
      if (value < 0) {
        c->context.recordError(GL_INVALID_VALUE);
        return;
      }
      c->userRowLength = value;
      break;
    case OSMESA_Y_UP:
      c->yUp = value != 0;
      break;
    default:
      c->context.recordError(GL_INVALID_ENUM);
      return;
  }
  bindColorBuffer(*c, c->context.windowFramebuffer().front.pixels);
}

GLAPI void APIENTRY OSMesaGetIntegerv(GLint pname, GLint* value) {
  osmesa_context* c = OSMesaGetCurrentContext();
  if (!value) return;
  switch (pname) {
    case OSMESA_MAX_WIDTH: case OSMESA_MAX_HEIGHT: *value = glfixed::kMaxViewportSize; return;
    default: break;
  }
  if (!c) return;
  switch (pname) {
    case OSMESA_WIDTH: *value = c->width; return;
    case OSMESA_HEIGHT: *value = c->height; return;
    case OSMESA_FORMAT: *value = static_cast<GLint>(c->osmesaFormat); return;
    case OSMESA_TYPE: *value = static_cast<GLint>(c->type); return;
    case OSMESA_ROW_LENGTH: *value = c->userRowLength; return;
    case OSMESA_Y_UP: *value = c->yUp ? 1 : 0; return;
    default: c->context.recordError(GL_INVALID_ENUM); return;
  }
}

GLAPI GLboolean APIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint* width, GLint* height,
                                              GLint* bytesPerValue, void** buffer) {
  if (!c || c->context.windowFramebuffer().depth.bits() == 0 || c->width == 0) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (bytesPerValue) *bytesPerValue = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  glfixed::pipeline::flushVertices(c->context);
  glfixed::DepthBuffer& d = c->context.windowFramebuffer().depth;
  if (width) *width = d.width();
  if (height) *height = d.height();
  if (bytesPerValue) *bytesPerValue = d.bytesPerValue();
  if (buffer) *buffer = d.data();
  return GL_TRUE;
}

GLAPI GLboolean APIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint* width, GLint* height, GLint* format,
                                              void** buffer) {
  if (!c || !c->context.windowFramebuffer().front.pixels) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (format) *format = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  glfixed::pipeline::flushVertices(c->context);
  if (width) *width = c->width;
  if (height) *height = c->height;
  if (format) *format = static_cast<GLint>(c->osmesaFormat);
  if (buffer) *buffer = c->context.windowFramebuffer().front.pixels;
  return GL_TRUE;
}

GLAPI OSMESAproc APIENTRY OSMesaGetProcAddress(const char* funcName) {
  return reinterpret_cast<OSMESAproc>(glfixed::api::procAddress(funcName));
}

// On Mesa 22.3.6 OSMesaColorClamp changes nothing that was measured: a
// float buffer receives unclamped fragment colours (a colour sum of 1.5)
// after OSMesaColorClamp(GL_TRUE) too (MESA_FACTS.md, "OSMesa colour buffer
// types"); so the context's clampFragmentColor stays false.
GLAPI void APIENTRY OSMesaColorClamp(GLboolean enable) { (void)enable; }

// Mesa's post-processing filters are not provided.
GLAPI void APIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char* filter, unsigned enableValue) {}

}  // extern "C"
