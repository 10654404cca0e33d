// Texture images (GL 2.1 §3.8.1-3.8.3, §3.8.11 proxies, §6.1.4 queries):
// glTexImage1D/2D/3D, glTexSubImage1D/2D/3D, glCompressedTexImage*,
// glGetTexImage, glGetTexLevelParameter*, glGenerateMipmap. The errors and
// their order are Mesa's (probed, reference/MESA_FACTS.md "Textures").

#include <algorithm>

#include "api/api.h"
#include "api/list_record.h"
#include "api/pixel_buffer.h"
#include "api/tex_image_common.h"
#include "texture/internal_format.h"
#include "texture/texture_image.h"
#include "texture/texture_objects.h"
#include "texture/unpack.h"

using namespace glfixed;
using namespace glfixed::api::teximage;
using texture::TextureImage;
using texture::TextureObject;

namespace {

// The checks glTexImage and glTexSubImage share on format and type against
// the image's base format. EXT_packed_depth_stencil: a depth or
// depth-stencil image takes GL_DEPTH_COMPONENT and GL_DEPTH_STENCIL data (a
// depth image keeps the depth of GL_DEPTH_STENCIL data, a depth-stencil one
// gets an undefined stencil from GL_DEPTH_COMPONENT data, as on Mesa), a
// colour image neither.
GLenum checkFormats(GLenum base, GLenum format, GLenum type) {
  if (GLenum e = texture::checkFormatAndType(format, type)) return e;
  if (format == GL_STENCIL_INDEX) return GL_INVALID_OPERATION;
  const bool depthBase = base == GL_DEPTH_COMPONENT || base == GL_DEPTH_STENCIL;
  const bool depthData = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL;
  if (depthBase != depthData) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

// The base format of a stored image, GL_DEPTH_STENCIL for a depth-stencil one.
GLenum imageBase(const TextureImage& image) {
  return image.format == texture::TexelFormat::Z24S8 ? GL_DEPTH_STENCIL
                                                     : texture::texelFormatInfo(image.format).baseFormat;
}

// GL 2.1 §3.8.1: a one- or two-dimensional image ignores GL_UNPACK_SKIP_IMAGES
// (and glGetTexImage GL_PACK_SKIP_IMAGES); the skipped rows still count for a
// 1D image, as on Mesa (measured).
PixelStoreAttrib storeFor(const PixelStoreAttrib& s, int dims) {
  PixelStoreAttrib r = s;
  if (dims < 3) r.unpackSkipImages = r.packSkipImages = 0;
  return r;
}

void texImage(int dims, GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
              GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  ImageTarget t;
  if (!imageTarget(target, dims, true, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  if (border != 0 && border != 1) return ctx->recordError(GL_INVALID_VALUE);
  if (width < 0 || height < 0 || depth < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (GLenum e = texture::checkFormatAndType(format, type)) return ctx->recordError(e);
  const GLenum base = texture::baseInternalFormat(internalFormat);
  if (base == 0) return ctx->recordError(GL_INVALID_VALUE);
  if (GLenum e = checkFormats(base, format, type)) return ctx->recordError(e);
  if ((base == GL_DEPTH_COMPONENT || base == GL_DEPTH_STENCIL) && t.index == 2)
    return ctx->recordError(GL_INVALID_OPERATION);  // no 3D depth textures (Mesa)
  if (t.index == 3 && width != height) return ctx->recordError(GL_INVALID_VALUE);  // cube faces are square

  // The stored size: Mesa strips the border before llvmpipe sees the image.
  const int b = border;
  const int w = width - 2 * b;
  const int h = dims >= 2 ? height - 2 * b : 1;
  const int d = dims == 3 ? depth - 2 * b : 1;
  const int limit = maxSize(t.index) >> level;
  const bool legal =
      w >= 0 && h >= 0 && d >= 0 && w <= limit && (dims < 2 || h <= limit) && (dims < 3 || d <= limit);
  const texture::TexelFormat stored = texture::chooseTexelFormat(internalFormat, format, type);
  const bool fits = texture::llvmpipeImageBytes(stored, w, h, d) <= texture::kMaxImageBytes;
  TextureObject& object = targetObject(*ctx, t);
  TextureImage& image = object.face[t.face][level];
  if (t.proxy) {  // §3.8.11: a proxy that cannot be made is all zero, no error
    if (legal && fits)
      texture::defineProxyImage(image, internalFormat, stored, w, h, d);
    else
      image = TextureImage();
    return;
  }
  if (!legal) return ctx->recordError(GL_INVALID_VALUE);
  if (!fits) return ctx->recordError(GL_OUT_OF_MEMORY);

  const texture::ClientLayout layout =
      texture::unpackLayout(storeFor(ctx->pixelStore, dims), width, height, format, type);
  GLenum error;
  const uint8_t* source =
      api::pixelBufferMemory(*ctx, ctx->pixelStore.pixelUnpackBufferBinding,
                             static_cast<const uint8_t*>(pixels), layout.extent(width, height, depth), error);
  if (error) return ctx->recordError(error);

  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  if (!texture::defineImage(image, internalFormat, stored, w, h, d))
    return ctx->recordError(GL_OUT_OF_MEMORY);
  if (source && image.defined()) {
    texture::ClientLayout inner = layout;  // skip the border texels
    inner.start += size_t(b) * layout.groupBytes + (dims >= 2 ? size_t(b) * layout.rowStride : 0) +
                   (dims == 3 ? size_t(b) * layout.imageStride : 0);
    texture::unpackImage(inner, source, format, type, ctx->pixelMode, w, h, d, image, 0, 0, 0,
                         &ctx->pixelMaps);
  }
  maybeGenerateMipmaps(*ctx, object, t, level);
}

void texSubImage(int dims, GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei width,
                 GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  ImageTarget t;
  if (!imageTarget(target, dims, false, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  if (GLenum e = texture::checkFormatAndType(format, type)) return ctx->recordError(e);
  TextureObject& object = targetObject(*ctx, t);
  TextureImage& image = object.face[t.face][level];
  if (!image.defined()) return ctx->recordError(GL_INVALID_OPERATION);
  if (GLenum e = checkFormats(imageBase(image), format, type))
    return ctx->recordError(e);
  if (width < 0 || height < 0 || depth < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (x < 0 || y < 0 || z < 0 || int64_t(x) + width > image.width || int64_t(y) + height > image.height ||
      int64_t(z) + depth > image.depth)
    return ctx->recordError(GL_INVALID_VALUE);
  const texture::ClientLayout layout =
      texture::unpackLayout(storeFor(ctx->pixelStore, dims), width, height, format, type);
  GLenum error;
  const uint8_t* source =
      api::pixelBufferMemory(*ctx, ctx->pixelStore.pixelUnpackBufferBinding,
                             static_cast<const uint8_t*>(pixels), layout.extent(width, height, depth), error);
  if (error) return ctx->recordError(error);
  if (!source || width == 0 || height == 0 || depth == 0) return;
  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  texture::unpackImage(layout, source, format, type, ctx->pixelMode, width, height, depth, image, x, y, z,
                       &ctx->pixelMaps);
  maybeGenerateMipmaps(*ctx, object, t, level);
}

// The bytes a glTexImage command reads, for its display list copy (§5.4:
// the image is captured at compile time). 0 without data or with a pixel
// unpack buffer (then the offset is recorded as is).
size_t compiledBytes(int dims, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                     const void* pixels) {
  Context* ctx = currentContext();
  if (!ctx || !pixels || ctx->pixelStore.pixelUnpackBufferBinding) return 0;
  if (width < 0 || height < 0 || depth < 0 || texture::checkFormatAndType(format, type)) return 0;
  return texture::unpackLayout(storeFor(ctx->pixelStore, dims), width, height, format, type)
      .extent(width, height, depth);
}

// §5.4: the proxy commands are executed at once, never compiled.
bool isProxy(GLenum target) {
  return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D || target == GL_PROXY_TEXTURE_3D ||
         target == GL_PROXY_TEXTURE_CUBE_MAP;
}

// A compiled image command: the client image is copied with the unpack
// state in effect now, and replayed with the default unpack state (the copy
// is tightly at its start, with the same row layout).
template <typename Replay>
bool compiledImage(size_t bytes, const void* pixels, Replay&& replay) {
  Context* ctx = currentContext();
  pipeline::ListCompiler* list = api::listCompiler(ctx);
  if (!list) return false;
  if (list->insideBeginEnd()) {
    list->recordError(*ctx, GL_INVALID_OPERATION);
    return true;
  }
  std::vector<uint8_t> copy;
  if (bytes) copy.assign(static_cast<const uint8_t*>(pixels), static_cast<const uint8_t*>(pixels) + bytes);
  const PixelStoreAttrib store = ctx->pixelStore;
  const bool hasData = pixels != nullptr;
  list->record([replay, copy = std::move(copy), store, hasData, pixels] {
    Context* now = currentContext();
    if (!now) return;
    // Run with the compile-time unpack state and no unpack buffer, unless
    // the data was in one (then its offset and the buffer bound now).
    const PixelStoreAttrib saved = now->pixelStore;
    const bool fromBuffer = hasData && copy.empty() && store.pixelUnpackBufferBinding;
    now->pixelStore = store;
    if (!fromBuffer)
      now->pixelStore.pixelUnpackBufferBinding = 0;
    else
      now->pixelStore.pixelUnpackBufferBinding = saved.pixelUnpackBufferBinding;
    replay(fromBuffer ? pixels : (copy.empty() ? nullptr : static_cast<const void*>(copy.data())));
    now->pixelStore = saved;
  });
  return !list->executes();
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glTexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                                 GLint border, GLenum format, GLenum type, const void* pixels) {
  if (!isProxy(target) &&
      compiledImage(compiledBytes(1, width, 1, 1, format, type, pixels), pixels, [=](const void* p) {
        glTexImage1D(target, level, internalformat, width, border, format, type, p);
      }))
    return;
  texImage(1, target, level, internalformat, width, 1, 1, border, format, type, pixels);
}

GLAPI void APIENTRY glTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                                 GLsizei height, GLint border, GLenum format, GLenum type,
                                 const void* pixels) {
  if (!isProxy(target) &&
      compiledImage(compiledBytes(2, width, height, 1, format, type, pixels), pixels, [=](const void* p) {
        glTexImage2D(target, level, internalformat, width, height, border, format, type, p);
      }))
    return;
  texImage(2, target, level, internalformat, width, height, 1, border, format, type, pixels);
}

GLAPI void APIENTRY glTexImage3D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                                 GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                                 const void* pixels) {
  if (!isProxy(target) &&
      compiledImage(compiledBytes(3, width, height, depth, format, type, pixels), pixels, [=](const void* p) {
        glTexImage3D(target, level, internalformat, width, height, depth, border, format, type, p);
      }))
    return;
  texImage(3, target, level, internalformat, width, height, depth, border, format, type, pixels);
}

GLAPI void APIENTRY glTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                                    GLenum type, const void* pixels) {
  if (compiledImage(compiledBytes(1, width, 1, 1, format, type, pixels), pixels,
                    [=](const void* p) { glTexSubImage1D(target, level, xoffset, width, format, type, p); }))
    return;
  texSubImage(1, target, level, xoffset, 0, 0, width, 1, 1, format, type, pixels);
}

GLAPI void APIENTRY glTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                                    GLsizei height, GLenum format, GLenum type, const void* pixels) {
  if (compiledImage(compiledBytes(2, width, height, 1, format, type, pixels), pixels, [=](const void* p) {
        glTexSubImage2D(target, level, xoffset, yoffset, width, height, format, type, p);
      }))
    return;
  texSubImage(2, target, level, xoffset, yoffset, 0, width, height, 1, format, type, pixels);
}

GLAPI void APIENTRY glTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                                    GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                                    const void* pixels) {
  if (compiledImage(compiledBytes(3, width, height, depth, format, type, pixels), pixels, [=](const void* p) {
        glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, p);
      }))
    return;
  texSubImage(3, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}

// The generic compressed formats (GL_COMPRESSED_RGB, ...) have no
// compressed data format of their own, so glCompressedTexImage refuses them
// (Mesa: GL_INVALID_ENUM), as it refuses every uncompressed format; this
// library offers no specific compressed format.
GLAPI void APIENTRY glCompressedTexImage1D(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                           GLint border, GLsizei imageSize, const void* data) {
  if (api::compiled(&glCompressedTexImage1D, target, level, internalformat, width, border, imageSize,
                    static_cast<const void*>(nullptr)))
    return;
  if (Context* ctx = api::contextForSetter()) ctx->recordError(GL_INVALID_ENUM);
  (void)data;
}
GLAPI void APIENTRY glCompressedTexImage2D(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                           GLsizei height, GLint border, GLsizei imageSize,
                                           const void* data) {
  if (api::compiled(&glCompressedTexImage2D, target, level, internalformat, width, height, border, imageSize,
                    static_cast<const void*>(nullptr)))
    return;
  if (Context* ctx = api::contextForSetter()) ctx->recordError(GL_INVALID_ENUM);
  (void)data;
}
GLAPI void APIENTRY glCompressedTexImage3D(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                           GLsizei height, GLsizei depth, GLint border, GLsizei imageSize,
                                           const void* data) {
  if (api::compiled(&glCompressedTexImage3D, target, level, internalformat, width, height, depth, border,
                    imageSize, static_cast<const void*>(nullptr)))
    return;
  if (Context* ctx = api::contextForSetter()) ctx->recordError(GL_INVALID_ENUM);
  (void)data;
}

GLAPI void APIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  ImageTarget t;
  const int dims = target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
  if (!imageTarget(target, dims, false, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  if (GLenum e = texture::checkFormatAndType(format, type)) return ctx->recordError(e);
  if (type == GL_BITMAP || format == GL_COLOR_INDEX) return ctx->recordError(GL_INVALID_OPERATION);
  const TextureImage& image = targetObject(*ctx, t).face[t.face][level];
  // A depth-stencil image reads as GL_DEPTH_STENCIL, GL_DEPTH_COMPONENT or
  // GL_STENCIL_INDEX, a depth image as GL_DEPTH_COMPONENT only, a colour
  // image as neither (Mesa).
  const GLenum base = imageBase(image);
  const bool depthImage = base == GL_DEPTH_COMPONENT || base == GL_DEPTH_STENCIL;
  if ((format == GL_STENCIL_INDEX || format == GL_DEPTH_STENCIL) && image.defined() && base != GL_DEPTH_STENCIL)
    return ctx->recordError(GL_INVALID_OPERATION);
  if (!image.defined()) return;  // nothing is written
  if (depthImage != (format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL || format == GL_STENCIL_INDEX))
    return ctx->recordError(GL_INVALID_OPERATION);
  const texture::ClientLayout layout =
      texture::packLayout(storeFor(ctx->pixelStore, dims), image.width, image.height, format, type);
  const size_t extent = layout.extent(image.width, image.height, image.depth);
  uint8_t* out = static_cast<uint8_t*>(pixels);
  if (const GLuint name = ctx->pixelStore.pixelPackBufferBinding) {
    BufferObject* b = ctx->buffers.find(name);
    const size_t offset = reinterpret_cast<uintptr_t>(pixels);
    if (!b || b->mapped || offset > b->data.size() || extent > b->data.size() - offset)
      return ctx->recordError(GL_INVALID_OPERATION);
    out = b->data.data() + offset;
  }
  if (!out) return;
  pipeline::flushVertices(*ctx);
  texture::packImage(image, layout, format, type, out);
}

GLAPI void APIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params);

GLAPI void APIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  if (!params) return;
  GLint v = 0;
  Context* ctx = currentContext();
  const GLenum before = ctx ? ctx->takeError() : GL_NO_ERROR;
  glGetTexLevelParameteriv(target, level, pname, &v);
  const GLenum error = ctx ? ctx->takeError() : GL_NO_ERROR;
  if (ctx && before) ctx->recordError(before);
  if (error) {
    if (ctx) ctx->recordError(error);
    return;
  }
  *params = static_cast<GLfloat>(v);
}

namespace {
GLint componentType(const TextureImage& image, int size) {
  if (size == 0) return GL_NONE;
  return texture::texelFormatInfo(image.format).floating ? GL_FLOAT : GL_UNSIGNED_NORMALIZED_ARB;
}
}  // namespace

GLAPI void APIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  ImageTarget t;
  const int dims = target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D   ? 1
                   : target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D ? 3
                                                                              : 2;
  if (!imageTarget(target, dims, true, t)) return ctx->recordError(GL_INVALID_ENUM);
  if (level < 0 || level >= maxLevels(t.index)) return ctx->recordError(GL_INVALID_VALUE);
  const TextureImage& image = targetObject(*ctx, t).face[t.face][level];
  const texture::ComponentSizes sizes =
      image.defined() ? texture::componentSizes(image.format) : texture::ComponentSizes();
  GLint v = 0;
  switch (pname) {
    case GL_TEXTURE_WIDTH: v = image.width; break;
    case GL_TEXTURE_HEIGHT: v = image.height; break;
    case GL_TEXTURE_DEPTH: v = image.depth; break;
    case GL_TEXTURE_BORDER:
      v = 0;
      break;  // Mesa strips the border: always 0
    // An undefined level reports GL_RGBA (Mesa; GL 2.1's table 6.24 says 1).
    case GL_TEXTURE_INTERNAL_FORMAT:
      v = image.defined() ? texture::reportedInternalFormat(image.internalFormat) : GL_RGBA;
      break;
    case GL_TEXTURE_RED_SIZE: v = sizes.red; break;
    case GL_TEXTURE_GREEN_SIZE: v = sizes.green; break;
    case GL_TEXTURE_BLUE_SIZE: v = sizes.blue; break;
    case GL_TEXTURE_ALPHA_SIZE: v = sizes.alpha; break;
    case GL_TEXTURE_LUMINANCE_SIZE: v = sizes.luminance; break;
    case GL_TEXTURE_INTENSITY_SIZE: v = sizes.intensity; break;
    case GL_TEXTURE_DEPTH_SIZE: v = sizes.depth; break;
    case 0x88F1: v = sizes.stencil; break;  // GL_TEXTURE_STENCIL_SIZE (EXT_packed_depth_stencil)
    case GL_TEXTURE_COMPRESSED: v = GL_FALSE; break;  // stored uncompressed
    // ARB_texture_float: a component's type, GL_NONE where it has no bits
    // (Mesa gives GL_UNSIGNED_NORMALIZED_ARB for the other formats).
    case GL_TEXTURE_RED_TYPE_ARB: v = componentType(image, sizes.red); break;
    case GL_TEXTURE_GREEN_TYPE_ARB: v = componentType(image, sizes.green); break;
    case GL_TEXTURE_BLUE_TYPE_ARB: v = componentType(image, sizes.blue); break;
    case GL_TEXTURE_ALPHA_TYPE_ARB: v = componentType(image, sizes.alpha); break;
    case GL_TEXTURE_LUMINANCE_TYPE_ARB: v = componentType(image, sizes.luminance); break;
    case GL_TEXTURE_INTENSITY_TYPE_ARB: v = componentType(image, sizes.intensity); break;
    case GL_TEXTURE_DEPTH_TYPE_ARB: v = componentType(image, sizes.depth); break;
    case GL_TEXTURE_COMPRESSED_IMAGE_SIZE:
      // Not a compressed image (GL 2.1 §6.1.3).
      return ctx->recordError(GL_INVALID_OPERATION);
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  if (params) *params = v;
}

// glGenerateMipmap (GL 3.0, ARB_framebuffer_object; exported because
// xscreensaver's hacks import it): the levels below the base level from it.
GLAPI void APIENTRY glGenerateMipmap(GLenum target) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const int index = texture::targetIndex(target);
  if (index < 0) return ctx->recordError(GL_INVALID_ENUM);
  TextureObject& object =
      texture::boundObject(*ctx->textures, ctx->texture.binding[ctx->texture.activeUnit()], index);
  const int base = object.params.baseLevel;
  if (base >= maxLevels(index)) return;
  const int faces = index == 3 ? 6 : 1;
  if (index == 3) {  // a cube map must be cube complete at its base level (Mesa)
    const TextureImage& first = object.face[0][base];
    for (int f = 0; f < 6; ++f) {
      const TextureImage& img = object.face[f][base];
      if (!img.defined() || img.width != first.width || img.format != first.format)
        return ctx->recordError(GL_INVALID_OPERATION);
    }
  }
  if (!object.face[0][base].defined()) return;
  // No mipmaps of a depth-stencil texture (Mesa; GL_GENERATE_MIPMAP makes them).
  if (object.face[0][base].format == texture::TexelFormat::Z24S8) return ctx->recordError(GL_INVALID_OPERATION);
  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  for (int f = 0; f < faces; ++f)
    if (!texture::generateMipmaps(object, f, base, maxLevels(index)))
      return ctx->recordError(GL_OUT_OF_MEMORY);
}

GLAPI void APIENTRY glGenerateMipmapEXT(GLenum target) { glGenerateMipmap(target); }

}  // extern "C"
