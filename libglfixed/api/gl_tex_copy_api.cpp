// Texture images from the framebuffer (GL 2.1 §3.8.2): glCopyTexImage1D/2D
// and glCopyTexSubImage1D/2D/3D read the read buffer (or the depth buffer
// for a depth texture) as glReadPixels would, then store the pixels as
// glTexImage stores client data (pixel transfer applied). Pixels outside
// the framebuffer read as 0, as Mesa gives them. Mesa's errors (probed):
// internal formats 1-4 and proxies are GL_INVALID_ENUM here.
#include <cstring>
#include <vector>

#include "api/api.h"
#include "state/framebuffer_binding.h"
#include "pipeline/pixel_rect.h"
#include "api/list_record.h"
#include "api/tex_image_common.h"
#include "texture/internal_format.h"
#include "texture/unpack.h"

using namespace glfixed;
using namespace glfixed::api::teximage;
using texture::TextureImage;

namespace {

// What a copy reads: the read buffer's colour, the depth buffer, or depth
// and stencil (a depth-stencil texture, EXT_packed_depth_stencil).
enum class Source { kColor, kDepth, kDepthStencil };

Source sourceOf(texture::TexelFormat format) {
  if (format == texture::TexelFormat::Z24S8) return Source::kDepthStencil;
  return texture::isDepthFormat(format) ? Source::kDepth : Source::kColor;
}

// The framebuffer's pixels of a box as tightly packed client data:
// RGBA bytes, 32-bit depth values, or GL_UNSIGNED_INT_24_8 depth-stencil words.
GLenum readBox(const Framebuffer& fb, Source source, int x, int y, int width, int height,
               std::vector<uint8_t>& out, texture::ClientLayout& layout) {
  const bool depth = source != Source::kColor;
  out.assign(size_t(width) * height * 4, 0);
  layout = texture::ClientLayout();
  layout.groupBytes = 4;
  layout.elementBytes = depth ? 4 : 1;
  layout.rowStride = size_t(width) * 4;
  layout.imageStride = layout.rowStride * height;
  const int fbWidth = depth ? fb.depth.width() : fb.read.width;
  const int fbHeight = depth ? fb.depth.height() : fb.read.height;
  for (int j = 0; j < height; ++j) {
    const int sy = y + j;
    if (sy < 0 || sy >= fbHeight) continue;
    for (int i = 0; i < width; ++i) {
      const int sx = x + i;
      if (sx < 0 || sx >= fbWidth) continue;
      uint8_t* p = out.data() + (size_t(j) * width + i) * 4;
      if (source == Source::kDepthStencil) {
        const uint32_t v = fb.depth.get(sx, sy);
        const uint32_t depth24 = fb.depth.bits() == 16 ? (v << 8) | (v >> 8) : v;
        const uint32_t word = depth24 << 8 | fb.depth.getStencil(sx, sy);
        std::memcpy(p, &word, 4);
      } else if (depth) {
        // The depth value widened to 32 bits by repeating its bits.
        const uint32_t v = fb.depth.get(sx, sy);
        const uint32_t wide = fb.depth.bits() == 16 ? (v << 16) | v : (v << 8) | (v >> 16);
        std::memcpy(p, &wide, 4);
      } else {
        fb.read.read(sx, sy, p);
      }
    }
  }
  return GL_NO_ERROR;
}

// Called with the buffer to read known to exist.
void copyInto(Context& ctx, TextureImage& image, int xo, int yo, int zo, int x, int y, int width,
              int height) {
  pipeline::flushVertices(ctx);  // what is buffered is drawn before the read
  const Source source = sourceOf(image.format);
  std::vector<uint8_t> pixels;
  texture::ClientLayout layout;
  if (GLenum e = readBox(ctx.framebuffer, source, x, y, width, height, pixels, layout))
    return ctx.recordError(e);
  api::beginStateChange(ctx, GL_TEXTURE_BIT);
  const GLenum format = source == Source::kColor   ? GL_RGBA
                        : source == Source::kDepth ? GL_DEPTH_COMPONENT
                                                   : GL_DEPTH_STENCIL;
  const GLenum type = source == Source::kColor   ? GL_UNSIGNED_BYTE
                      : source == Source::kDepth ? GL_UNSIGNED_INT
                                                 : GL_UNSIGNED_INT_24_8;
  texture::unpackImage(layout, pixels.data(), format, type, ctx.pixelMode, width, height, 1, image, xo, yo, zo,
                       &ctx.pixelMaps);  // the colour maps too (measured)
}

// A depth-stencil texture needs both buffers (GL_INVALID_OPERATION otherwise).
bool hasSourceBuffer(const Framebuffer& fb, Source source) {
  switch (source) {
    case Source::kColor: return fb.read.pixels != nullptr;
    case Source::kDepth: return fb.depth.bits() != 0;
    default: return fb.depth.bits() != 0 && fb.depth.stencilBits() != 0;
  }
}

void copyTexImage(int dims, GLenum target, GLint level, GLenum internalFormat, GLint x, GLint y,
                  GLsizei width, GLsizei height, GLint border) {
  Context* ctx = api::contextForSetter();
  if (ctx) pipeline::flushBitmapCache(*ctx);  // st_CopyTexImage reads what the cache holds
  if (!ctx) return;
  ImageTarget t;
  if (!imageTarget(target, dims, false, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  const GLint internal = static_cast<GLint>(internalFormat);
  const GLenum base = internal >= 1 && internal <= 4 ? 0 : texture::baseInternalFormat(internal);
  if (base == 0) return ctx->recordError(GL_INVALID_ENUM);
  if (border != 0 && border != 1) return ctx->recordError(GL_INVALID_VALUE);
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (t.index == 3 && width != height) return ctx->recordError(GL_INVALID_VALUE);
  const int w = width - 2 * border, h = dims == 2 ? height - 2 * border : 1;
  const int limit = maxSize(t.index) >> level;
  if (w < 0 || h < 0 || w > limit || h > limit) return ctx->recordError(GL_INVALID_VALUE);
  const bool depth = base == GL_DEPTH_COMPONENT || base == GL_DEPTH_STENCIL;
  if (ctx->objectBound() && !readFramebufferComplete(*ctx)) return;  // GL 3.0 §4.4.4
  // The stored format as for client data of the framebuffer's type.
  const texture::TexelFormat stored = texture::chooseTexelFormat(
      internal, depth ? GL_DEPTH_COMPONENT : GL_RGBA, depth ? GL_UNSIGNED_INT : GL_UNSIGNED_BYTE);
  if (!hasSourceBuffer(ctx->framebuffer, sourceOf(stored))) return ctx->recordError(GL_INVALID_OPERATION);
  if (texture::llvmpipeImageBytes(stored, w, h, 1) > texture::kMaxImageBytes)
    return ctx->recordError(GL_OUT_OF_MEMORY);
  pipeline::flushVertices(*ctx);
  texture::TextureObject& object = targetObject(*ctx, t);
  TextureImage& image = object.face[t.face][level];
  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  if (!texture::defineImage(image, internal, stored, w, h, 1)) return ctx->recordError(GL_OUT_OF_MEMORY);
  if (image.defined()) copyInto(*ctx, image, 0, 0, 0, x + border, y + (dims == 2 ? border : 0), w, h);
  maybeGenerateMipmaps(*ctx, object, t, level);
}

void copyTexSubImage(int dims, GLenum target, GLint level, GLint xo, GLint yo, GLint zo, GLint x, GLint y,
                     GLsizei width, GLsizei height) {
  Context* ctx = api::contextForSetter();
  if (ctx) pipeline::flushBitmapCache(*ctx);
  if (!ctx) return;
  ImageTarget t;
  if (!imageTarget(target, dims, false, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  texture::TextureObject& object = targetObject(*ctx, t);
  TextureImage& image = object.face[t.face][level];
  if (!image.defined()) return ctx->recordError(GL_INVALID_OPERATION);
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (xo < 0 || yo < 0 || zo < 0 || int64_t(xo) + width > image.width ||
      int64_t(yo) + height > image.height || zo >= image.depth)
    return ctx->recordError(GL_INVALID_VALUE);
  if (ctx->objectBound() && !readFramebufferComplete(*ctx)) return;  // GL 3.0 §4.4.4
  if (!hasSourceBuffer(ctx->framebuffer, sourceOf(image.format))) return ctx->recordError(GL_INVALID_OPERATION);
  if (width == 0 || height == 0) return;
  copyInto(*ctx, image, xo, yo, zo, x, y, width, height);
  maybeGenerateMipmaps(*ctx, object, t, level);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                     GLsizei width, GLint border) {
  if (api::compiled(&glCopyTexImage1D, target, level, internalformat, x, y, width, border)) return;
  copyTexImage(1, target, level, internalformat, x, y, width, 1, border);
}

GLAPI void APIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                     GLsizei width, GLsizei height, GLint border) {
  if (api::compiled(&glCopyTexImage2D, target, level, internalformat, x, y, width, height, border)) return;
  copyTexImage(2, target, level, internalformat, x, y, width, height, border);
}

GLAPI void APIENTRY glCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                                        GLsizei width) {
  if (api::compiled(&glCopyTexSubImage1D, target, level, xoffset, x, y, width)) return;
  copyTexSubImage(1, target, level, xoffset, 0, 0, x, y, width, 1);
}

GLAPI void APIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                                        GLint y, GLsizei width, GLsizei height) {
  if (api::compiled(&glCopyTexSubImage2D, target, level, xoffset, yoffset, x, y, width, height)) return;
  copyTexSubImage(2, target, level, xoffset, yoffset, 0, x, y, width, height);
}

GLAPI void APIENTRY glCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (api::compiled(&glCopyTexSubImage3D, target, level, xoffset, yoffset, zoffset, x, y, width, height))
    return;
  copyTexSubImage(3, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

}  // extern "C"
