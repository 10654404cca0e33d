// Framebuffer and renderbuffer objects (EXT_framebuffer_object,
// ARB_framebuffer_object; GL 3.0 §4.4) with Mesa 22.3.6's errors (probed:
// MESA_FACTS.md "Framebuffer objects"). The objects and their completeness
// are state/framebuffer_objects.h; the bindings state/framebuffer_binding.h.
// None of these commands is compiled into a display list (Mesa executes them).
#include <algorithm>
#include <cstring>

#include "api/api.h"
#include "api/framebuffer_object_commands.h"
#include "api/list_record.h"
#include "pipeline/pixel_rect.h"
#include "state/framebuffer_binding.h"
#include "texture/texture_objects.h"

using namespace glfixed;
using namespace glfixed::fbo_enums;

namespace {

// GL_FRAMEBUFFER names both bindings; ARB's GL_DRAW_FRAMEBUFFER and
// GL_READ_FRAMEBUFFER one each (Mesa takes them from the EXT names too).
bool framebufferTarget(GLenum target, bool* draw, bool* read) {
  *draw = target == kFramebuffer || target == kDrawFramebuffer;
  *read = target == kFramebuffer || target == kReadFramebuffer;
  return *draw || *read;
}

// The object a target addresses (GL_FRAMEBUFFER: the draw one); null for the
// window system's. False (GL_INVALID_ENUM recorded) for an unknown target.
bool targetObject(Context& ctx, GLenum target, FramebufferObject** out) {
  bool draw, read;
  if (!framebufferTarget(target, &draw, &read)) {
    ctx.recordError(GL_INVALID_ENUM);
    return false;
  }
  *out = draw ? drawFramebufferObject(ctx) : readFramebufferObject(ctx);
  return true;
}

// Something was attached or detached, or an attached image changed: draws
// see it at their next refresh; the buffered vertices go into the old one.
void attachmentsChanging(Context& ctx) {
  pipeline::flushVertices(ctx);
  pipeline::flushBitmapCache(ctx);
}

void setAttachment(Context& ctx, FramebufferObject& fb, GLenum point, const Attachment& a) {
  attachmentsChanging(ctx);
  if (point == kDepthStencilAttachment) {
    fb.depth = a;
    fb.stencil = a;
  } else {
    *fb.attachment(point) = a;
  }
  refreshFramebuffer(ctx);
}

// The attachment point checks common to every glFramebuffer* command.
bool attachmentPointValid(Context& ctx, FramebufferObject& fb, GLenum point) {
  if (point == kDepthStencilAttachment || fb.attachment(point)) return true;
  // Mesa: GL_COLOR_ATTACHMENTn past the maximum is GL_INVALID_OPERATION,
  // any other name GL_INVALID_ENUM (probed).
  const bool pastMax = point >= kColorAttachment0 && point < kColorAttachment0 + 32;
  ctx.recordError(pastMax ? GL_INVALID_OPERATION : GL_INVALID_ENUM);
  return false;
}

int maxLevelsOf(GLenum target) {
  switch (target) {
    case GL_TEXTURE_3D: return 12;
    default: return texture::kMaxTextureLevels;
  }
}

// glFramebufferTexture1D/2D/3D and glFramebufferTextureLayer: `dims` 1, 2
// or 3, or 0 for the layer form (whose target comes from the texture).
void framebufferTexture(int dims, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                        GLint level, GLint layer) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  FramebufferObject* fb = nullptr;
  if (!targetObject(*ctx, target, &fb)) return;
  if (!fb) return ctx->recordError(GL_INVALID_OPERATION);  // the window system's framebuffer
  if (!attachmentPointValid(*ctx, *fb, attachment)) return;
  Attachment a;
  if (texture != 0) {
    texture::TextureObject* object = ctx->textures->find(texture);
    if (!object || object->target == 0) return ctx->recordError(GL_INVALID_OPERATION);
    if (dims == 0) {
      textarget = object->target;
      if (textarget != GL_TEXTURE_3D) return ctx->recordError(GL_INVALID_OPERATION);
    } else {
      const bool cubeFace =
          textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && textarget <= GL_TEXTURE_CUBE_MAP_POSITIVE_X + 5;
      const bool known = cubeFace || textarget == GL_TEXTURE_1D || textarget == GL_TEXTURE_2D ||
                         textarget == GL_TEXTURE_3D || textarget == GL_TEXTURE_CUBE_MAP;
      if (!known) return ctx->recordError(GL_INVALID_ENUM);  // probed
      const bool ok = dims == 1   ? textarget == GL_TEXTURE_1D
                      : dims == 2 ? (textarget == GL_TEXTURE_2D || cubeFace)
                                  : textarget == GL_TEXTURE_3D;
      if (!ok) return ctx->recordError(GL_INVALID_OPERATION);
      const GLenum objectTarget = cubeFace ? GL_TEXTURE_CUBE_MAP : textarget;
      if (object->target != objectTarget) return ctx->recordError(GL_INVALID_OPERATION);
    }
    if (level < 0 || level >= maxLevelsOf(textarget)) return ctx->recordError(GL_INVALID_VALUE);
    if (textarget == GL_TEXTURE_3D && (layer < 0 || layer >= texture::kMax3DTextureSize))
      return ctx->recordError(GL_INVALID_VALUE);
    a.type = GL_TEXTURE;
    a.name = texture;
    a.level = level;
    a.textarget = textarget;
    a.layer = textarget == GL_TEXTURE_3D ? layer : 0;
  }
  setAttachment(*ctx, *fb, attachment, a);
}

// Deleting a texture or renderbuffer detaches it from the bound framebuffers
// (GL 3.0 §4.4.2.2).
void detachFromBound(Context& ctx, GLenum type, GLuint name) {
  for (FramebufferObject* fb : {drawFramebufferObject(ctx), readFramebufferObject(ctx)}) {
    if (!fb) continue;
    auto detach = [&](Attachment& a) {
      if (a.type == type && a.name == name) {
        attachmentsChanging(ctx);
        a = Attachment{};
      }
    };
    for (Attachment& a : fb->color) detach(a);
    detach(fb->depth);
    detach(fb->stencil);
  }
}

// glGetFramebufferAttachmentParameteriv of the window system's framebuffer,
// as Mesa answers it (probed on OSMesa): its colour buffers (GL_FRONT_LEFT,
// GL_BACK_LEFT, GL_FRONT, GL_BACK; a single-buffered surface's back is its
// front), GL_DEPTH and GL_STENCIL are GL_FRAMEBUFFER_DEFAULT with their sizes
// (the depth and stencil attachments both report the depth and stencil bits),
// a buffer the surface lacks (a right buffer) GL_NONE and then
// GL_INVALID_OPERATION; OBJECT_NAME GL_INVALID_ENUM, and so the texture
// pnames on a buffer that is there.
void windowAttachmentParameter(Context& ctx, GLenum attachment, GLenum pname, GLint* params) {
  const bool colour = attachment == GL_FRONT_LEFT || attachment == GL_BACK_LEFT || attachment == GL_FRONT ||
                      attachment == GL_BACK;
  const bool right = attachment == GL_FRONT_RIGHT || attachment == GL_BACK_RIGHT;
  const bool depthStencil = attachment == GL_DEPTH || attachment == GL_STENCIL;
  if (!colour && !right && !depthStencil) return ctx.recordError(GL_INVALID_ENUM);
  const Framebuffer& win = ctx.windowFramebuffer();
  const bool present = colour ? win.front.pixels != nullptr
                       : depthStencil ? (attachment == GL_DEPTH ? win.depth.bits() : win.depth.stencilBits()) != 0
                                      : false;
  if (pname == 0x8CD0) {  // GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE
    *params = present ? static_cast<GLint>(kFramebufferDefault) : GL_NONE;
    return;
  }
  if (pname == 0x8CD1) return ctx.recordError(GL_INVALID_ENUM);  // OBJECT_NAME
  if (!present) return ctx.recordError(GL_INVALID_OPERATION);
  const bool known = pname == 0x8210 || pname == 0x8211 || (pname >= 0x8212 && pname <= 0x8217);
  if (!known) return ctx.recordError(GL_INVALID_ENUM);
  const ColorBuffer& c = win.front;
  int sizes[6] = {0, 0, 0, 0, 0, 0};
  if (colour)
    for (int k = 0; k < 4; ++k) sizes[k] = c.channelBits(k);
  else
    sizes[4] = win.depth.bits(), sizes[5] = win.depth.stencilBits();
  switch (pname) {
    case 0x8210: *params = GL_LINEAR; return;  // COLOR_ENCODING
    case 0x8211:                               // COMPONENT_TYPE
      *params = colour && c.channels == ChannelType::kFloat32 ? GL_FLOAT : 0x8C17;
      return;
    default: *params = sizes[pname - 0x8212]; return;
  }
}

void renderbufferStorage(GLenum target, GLsizei samples, GLenum internalFormat, GLsizei width, GLsizei height,
                         bool multisample) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (target != kRenderbuffer) return ctx->recordError(GL_INVALID_ENUM);
  RenderbufferFormat format;
  if (!renderbufferFormat(internalFormat, &format)) return ctx->recordError(GL_INVALID_ENUM);
  if (width < 0 || height < 0 || width > kMaxRenderbufferSize || height > kMaxRenderbufferSize)
    return ctx->recordError(GL_INVALID_VALUE);
  if (multisample && samples < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (multisample && samples > kMaxSamples) return ctx->recordError(GL_INVALID_OPERATION);  // Mesa
  Renderbuffer* rb = ctx->framebufferObjects->findRenderbuffer(ctx->fbo.renderbuffer);
  if (!rb) return ctx->recordError(GL_INVALID_OPERATION);  // renderbuffer 0
  attachmentsChanging(*ctx);
  // llvmpipe rounds a sample count up to the one it has (4, probed).
  const int actualSamples = samples > 0 ? kMaxSamples : 0;
  // Mesa reports no error even for 16384 x 16384 RGBA32F (probed): llvmpipe
  // allocates lazily. Only the formats drawn into here get memory (calloc:
  // untouched pages cost nothing); a calloc that fails is GL_OUT_OF_MEMORY.
  DataStore storage;
  bool fits = true;
  if (format.drawable) {
    try {
      storage.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * format.bytesPerPixel);
    } catch (const std::bad_alloc&) {
      fits = false;
    }
  }
  if (!fits) {
    rb->storage = DataStore{};
    rb->width = rb->height = 0;
    refreshFramebuffer(*ctx);
    return ctx->recordError(GL_OUT_OF_MEMORY);
  }
  rb->storage = std::move(storage);
  rb->internalFormat = internalFormat;
  rb->format = format;
  rb->width = width;
  rb->height = height;
  rb->samples = actualSamples;
  refreshFramebuffer(*ctx);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glGenFramebuffers(GLsizei n, GLuint* framebuffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!framebuffers || n == 0) return;
  ctx->framebufferObjects->generateFramebuffers(n, framebuffers);
}

GLAPI void APIENTRY glBindFramebuffer(GLenum target, GLuint framebuffer) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  bool draw, read;
  if (!framebufferTarget(target, &draw, &read)) return ctx->recordError(GL_INVALID_ENUM);
  // Mesa's compatibility profile binds names never generated too (probed,
  // for the EXT and the ARB command alike).
  if (framebuffer != 0) ctx->framebufferObjects->obtainFramebuffer(framebuffer)->bound = true;
  const GLuint newDraw = draw ? framebuffer : ctx->fbo.draw;
  const GLuint newRead = read ? framebuffer : ctx->fbo.read;
  if (newDraw == ctx->fbo.draw && newRead == ctx->fbo.read) return;
  attachmentsChanging(*ctx);
  ctx->markChanged(0, kDirtyAll);
  bindFramebuffers(*ctx, newDraw, newRead);
}

GLAPI void APIENTRY glDeleteFramebuffers(GLsizei n, const GLuint* framebuffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!framebuffers) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = framebuffers[i];
    if (name == 0) continue;
    // A bound framebuffer is unbound first: 0 takes its place (§4.4.1).
    if (ctx->fbo.draw == name || ctx->fbo.read == name) {
      attachmentsChanging(*ctx);
      bindFramebuffers(*ctx, ctx->fbo.draw == name ? 0 : ctx->fbo.draw,
                       ctx->fbo.read == name ? 0 : ctx->fbo.read);
    }
    ctx->framebufferObjects->removeFramebuffer(name);
  }
}

GLAPI GLboolean APIENTRY glIsFramebuffer(GLuint framebuffer) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  const FramebufferObject* fb = ctx->framebufferObjects->findFramebuffer(framebuffer);
  return fb && fb->bound ? GL_TRUE : GL_FALSE;
}

GLAPI GLenum APIENTRY glCheckFramebufferStatus(GLenum target) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return 0;
  FramebufferObject* fb = nullptr;
  if (!targetObject(*ctx, target, &fb)) return 0;
  if (!fb) return kComplete;  // the window system's framebuffer
  pipeline::flushVertices(*ctx);
  int w, h;
  return framebufferStatus(*fb, *ctx->framebufferObjects, *ctx->textures, &w, &h);
}

GLAPI void APIENTRY glFramebufferTexture1D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                           GLint level) {
  framebufferTexture(1, target, attachment, textarget, texture, level, 0);
}

GLAPI void APIENTRY glFramebufferTexture2D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                           GLint level) {
  framebufferTexture(2, target, attachment, textarget, texture, level, 0);
}

GLAPI void APIENTRY glFramebufferTexture3D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                           GLint level, GLint zoffset) {
  framebufferTexture(3, target, attachment, textarget, texture, level, zoffset);
}

GLAPI void APIENTRY glFramebufferTextureLayer(GLenum target, GLenum attachment, GLuint texture, GLint level,
                                              GLint layer) {
  framebufferTexture(0, target, attachment, 0, texture, level, layer);
}

GLAPI void APIENTRY glFramebufferRenderbuffer(GLenum target, GLenum attachment, GLenum renderbuffertarget,
                                              GLuint renderbuffer) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  FramebufferObject* fb = nullptr;
  if (!targetObject(*ctx, target, &fb)) return;
  if (renderbuffertarget != kRenderbuffer) return ctx->recordError(GL_INVALID_ENUM);
  if (!fb) return ctx->recordError(GL_INVALID_OPERATION);
  if (!attachmentPointValid(*ctx, *fb, attachment)) return;
  Attachment a;
  if (renderbuffer != 0) {
    // A name generated but never bound is no renderbuffer yet (probed).
    const Renderbuffer* rb = ctx->framebufferObjects->findRenderbuffer(renderbuffer);
    if (!rb) return ctx->recordError(GL_INVALID_OPERATION);
    a.type = kRenderbuffer;
    a.name = renderbuffer;
  }
  setAttachment(*ctx, *fb, attachment, a);
}

GLAPI void APIENTRY glGetFramebufferAttachmentParameteriv(GLenum target, GLenum attachment, GLenum pname,
                                                          GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  FramebufferObject* fb = nullptr;
  if (!targetObject(*ctx, target, &fb)) return;
  if (!fb) return windowAttachmentParameter(*ctx, attachment, pname, params);
  if (!attachmentPointValid(*ctx, *fb, attachment)) return;
  const Attachment& a = attachment == kDepthStencilAttachment ? fb->depth : *fb->attachment(attachment);
  if (attachment == kDepthStencilAttachment && !(fb->depth == fb->stencil))
    return ctx->recordError(GL_INVALID_OPERATION);
  switch (pname) {
    case 0x8CD0:  // GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE
      *params = static_cast<GLint>(a.type);
      return;
    case 0x8CD1:  // GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME
      *params = static_cast<GLint>(a.name);
      return;
    default: break;
  }
  if (a.type == GL_NONE) return ctx->recordError(GL_INVALID_OPERATION);
  switch (pname) {
    case 0x8CD2:  // GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
      if (a.type != GL_TEXTURE) break;
      *params = a.level;
      return;
    case 0x8CD3:  // GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
      if (a.type != GL_TEXTURE) break;
      *params =
          a.textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && a.textarget <= GL_TEXTURE_CUBE_MAP_POSITIVE_X + 5
              ? static_cast<GLint>(a.textarget)
              : 0;
      return;
    case 0x8CD4:  // GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET / _LAYER
      if (a.type != GL_TEXTURE) break;
      *params = a.layer;
      return;
    default: break;
  }
  // ARB_framebuffer_object's format queries: the attached image's sizes.
  int sizes[6] = {0, 0, 0, 0, 0, 0};  // red, green, blue, alpha, depth, stencil
  bool floatChannels = false;
  if (a.type == GL_TEXTURE) {
    const texture::TextureImage* image = attachedImage(a, *ctx->textures);
    if (image && image->defined()) {  // an undefined level: every size 0 (probed)
      const texture::ComponentSizes c = texture::componentSizes(image->format);
      const int v[6] = {c.red, c.green, c.blue, c.alpha, c.depth, c.stencil};
      std::copy(v, v + 6, sizes);
    }
  } else if (const Renderbuffer* rb = ctx->framebufferObjects->findRenderbuffer(a.name)) {
    const RenderbufferFormat& f = rb->format;
    floatChannels = f.floatChannels;
    const int v[6] = {f.red, f.green, f.blue, f.alpha, f.depth, f.stencil};
    std::copy(v, v + 6, sizes);
  }
  switch (pname) {
    case 0x8210: *params = GL_LINEAR; return;  // GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING
    case 0x8211:  // _COMPONENT_TYPE: unsigned normalized, float for the float renderbuffers (probed)
      // Of a depth-stencil image at the stencil attachment the depth's, of a
      // stencil-only one GL_INDEX; at GL_DEPTH_STENCIL_ATTACHMENT an error (probed).
      if (attachment == kDepthStencilAttachment) return ctx->recordError(GL_INVALID_OPERATION);
      *params = attachment == kStencilAttachment && sizes[4] == 0 ? 0x8222  // GL_INDEX
                : floatChannels                                 ? GL_FLOAT
                                                                : 0x8C17;
      return;
    case 0x8212:
    case 0x8213:
    case 0x8214:
    case 0x8215:
    case 0x8216:
    case 0x8217: *params = sizes[pname - 0x8212]; return;
    default: break;
  }
  ctx->recordError(GL_INVALID_ENUM);
}

GLAPI void APIENTRY glGenRenderbuffers(GLsizei n, GLuint* renderbuffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!renderbuffers || n == 0) return;
  ctx->framebufferObjects->generateRenderbuffers(n, renderbuffers);
}

GLAPI void APIENTRY glBindRenderbuffer(GLenum target, GLuint renderbuffer) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (target != kRenderbuffer) return ctx->recordError(GL_INVALID_ENUM);
  if (renderbuffer != 0) ctx->framebufferObjects->obtainRenderbuffer(renderbuffer)->bound = true;
  ctx->fbo.renderbuffer = renderbuffer;
}

GLAPI void APIENTRY glDeleteRenderbuffers(GLsizei n, const GLuint* renderbuffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!renderbuffers) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = renderbuffers[i];
    if (name == 0) continue;
    if (ctx->fbo.renderbuffer == name) ctx->fbo.renderbuffer = 0;
    detachFromBound(*ctx, kRenderbuffer, name);
    ctx->framebufferObjects->removeRenderbuffer(name);
  }
  refreshFramebuffer(*ctx);
}

GLAPI GLboolean APIENTRY glIsRenderbuffer(GLuint renderbuffer) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  const Renderbuffer* rb = ctx->framebufferObjects->findRenderbuffer(renderbuffer);
  return rb && rb->bound ? GL_TRUE : GL_FALSE;
}

GLAPI void APIENTRY glRenderbufferStorage(GLenum target, GLenum internalformat, GLsizei width,
                                          GLsizei height) {
  renderbufferStorage(target, 0, internalformat, width, height, false);
}

GLAPI void APIENTRY glRenderbufferStorageMultisample(GLenum target, GLsizei samples, GLenum internalformat,
                                                     GLsizei width, GLsizei height) {
  renderbufferStorage(target, samples, internalformat, width, height, true);
}

GLAPI void APIENTRY glGetRenderbufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (target != kRenderbuffer) return ctx->recordError(GL_INVALID_ENUM);
  const Renderbuffer* rb = ctx->framebufferObjects->findRenderbuffer(ctx->fbo.renderbuffer);
  if (!rb) return ctx->recordError(GL_INVALID_OPERATION);
  const bool haveFormat = rb->width > 0;
  switch (pname) {
    case 0x8D42: *params = rb->width; return;                               // GL_RENDERBUFFER_WIDTH
    case 0x8D43: *params = rb->height; return;                              // _HEIGHT
    case 0x8D44: *params = static_cast<GLint>(rb->internalFormat); return;  // _INTERNAL_FORMAT
    case 0x8CAB: *params = rb->samples; return;                             // _SAMPLES
    case 0x8D50: *params = haveFormat ? rb->format.red : 0; return;         // _RED_SIZE
    case 0x8D51: *params = haveFormat ? rb->format.green : 0; return;
    case 0x8D52: *params = haveFormat ? rb->format.blue : 0; return;
    case 0x8D53: *params = haveFormat ? rb->format.alpha : 0; return;
    case 0x8D54: *params = haveFormat ? rb->format.depth : 0; return;
    case 0x8D55: *params = haveFormat ? rb->format.stencil : 0; return;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
}

// glDrawBuffers (GL 2.0 §4.2.1) and the draw and read buffers of an object.
GLAPI void APIENTRY glDrawBuffers(GLsizei n, const GLenum* bufs) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (n < 1 || n > kMaxColorAttachments) return ctx->recordError(GL_INVALID_VALUE);
  if (!bufs) return;
  FramebufferObject* fb = drawFramebufferObject(*ctx);
  if (!fb) {
    // The window system's: one buffer, as glDrawBuffer names it.
    for (GLsizei i = 1; i < n; ++i)
      if (bufs[i] != GL_NONE) return ctx->recordError(GL_INVALID_OPERATION);
    return glDrawBuffer(bufs[0]);
  }
  for (GLsizei i = 0; i < n; ++i) {
    const GLenum b = bufs[i];
    if (b == GL_NONE) continue;
    if (b < kColorAttachment0 || b >= kColorAttachment0 + kMaxColorAttachments) {
      // Mesa: a window buffer name (GL_BACK) is GL_INVALID_ENUM here (probed),
      // an attachment past the maximum GL_INVALID_OPERATION.
      const bool pastMax = b >= kColorAttachment0 && b < kColorAttachment0 + 32;
      return ctx->recordError(pastMax ? GL_INVALID_OPERATION : GL_INVALID_ENUM);
    }
    for (GLsizei j = 0; j < i; ++j)
      if (bufs[j] == b) return ctx->recordError(GL_INVALID_OPERATION);
  }
  attachmentsChanging(*ctx);
  ctx->markChanged(GL_COLOR_BUFFER_BIT, 0);
  for (int i = 0; i < kMaxColorAttachments; ++i) fb->drawBuffers[i] = i < n ? bufs[i] : GL_NONE;
  ctx->colorBuffer.drawBuffer = fb->drawBuffers[0];
  refreshFramebuffer(*ctx);
}

// The EXT names (EXT_framebuffer_object, EXT_framebuffer_blit,
// EXT_framebuffer_multisample) and ARB_draw_buffers': Mesa gives them the
// same semantics as the ARB ones (it lets glBindFramebufferEXT bind any name,
// and takes GL_DRAW_FRAMEBUFFER / GL_READ_FRAMEBUFFER there too: probed).
GLAPI GLboolean APIENTRY glIsRenderbufferEXT(GLuint renderbuffer) { return glIsRenderbuffer(renderbuffer); }
GLAPI void APIENTRY glBindRenderbufferEXT(GLenum target, GLuint renderbuffer) {
  glBindRenderbuffer(target, renderbuffer);
}
GLAPI void APIENTRY glDeleteRenderbuffersEXT(GLsizei n, const GLuint* renderbuffers) {
  glDeleteRenderbuffers(n, renderbuffers);
}
GLAPI void APIENTRY glGenRenderbuffersEXT(GLsizei n, GLuint* renderbuffers) {
  glGenRenderbuffers(n, renderbuffers);
}
GLAPI void APIENTRY glRenderbufferStorageEXT(GLenum target, GLenum internalformat, GLsizei width,
                                             GLsizei height) {
  glRenderbufferStorage(target, internalformat, width, height);
}
GLAPI void APIENTRY glRenderbufferStorageMultisampleEXT(GLenum target, GLsizei samples, GLenum internalformat,
                                                        GLsizei width, GLsizei height) {
  glRenderbufferStorageMultisample(target, samples, internalformat, width, height);
}
GLAPI void APIENTRY glGetRenderbufferParameterivEXT(GLenum target, GLenum pname, GLint* params) {
  glGetRenderbufferParameteriv(target, pname, params);
}
GLAPI GLboolean APIENTRY glIsFramebufferEXT(GLuint framebuffer) { return glIsFramebuffer(framebuffer); }
GLAPI void APIENTRY glBindFramebufferEXT(GLenum target, GLuint framebuffer) {
  glBindFramebuffer(target, framebuffer);
}
GLAPI void APIENTRY glDeleteFramebuffersEXT(GLsizei n, const GLuint* framebuffers) {
  glDeleteFramebuffers(n, framebuffers);
}
GLAPI void APIENTRY glGenFramebuffersEXT(GLsizei n, GLuint* framebuffers) {
  glGenFramebuffers(n, framebuffers);
}
GLAPI GLenum APIENTRY glCheckFramebufferStatusEXT(GLenum target) { return glCheckFramebufferStatus(target); }
GLAPI void APIENTRY glFramebufferTexture1DEXT(GLenum target, GLenum attachment, GLenum textarget,
                                              GLuint texture, GLint level) {
  glFramebufferTexture1D(target, attachment, textarget, texture, level);
}
GLAPI void APIENTRY glFramebufferTexture2DEXT(GLenum target, GLenum attachment, GLenum textarget,
                                              GLuint texture, GLint level) {
  glFramebufferTexture2D(target, attachment, textarget, texture, level);
}
GLAPI void APIENTRY glFramebufferTexture3DEXT(GLenum target, GLenum attachment, GLenum textarget,
                                              GLuint texture, GLint level, GLint zoffset) {
  glFramebufferTexture3D(target, attachment, textarget, texture, level, zoffset);
}
GLAPI void APIENTRY glFramebufferRenderbufferEXT(GLenum target, GLenum attachment, GLenum renderbuffertarget,
                                                 GLuint renderbuffer) {
  glFramebufferRenderbuffer(target, attachment, renderbuffertarget, renderbuffer);
}
GLAPI void APIENTRY glGetFramebufferAttachmentParameterivEXT(GLenum target, GLenum attachment, GLenum pname,
                                                             GLint* params) {
  glGetFramebufferAttachmentParameteriv(target, attachment, pname, params);
}
GLAPI void APIENTRY glDrawBuffersARB(GLsizei n, const GLenum* bufs) { glDrawBuffers(n, bufs); }

}  // extern "C"

namespace glfixed::api {

// Deleting a texture detaches it from the bound framebuffers (called by glDeleteTextures).
void textureDeleted(Context& ctx, GLuint name) {
  detachFromBound(ctx, GL_TEXTURE, name);
  refreshFramebuffer(ctx);
}

}  // namespace glfixed::api
