// Framebuffer and renderbuffer objects (EXT/ARB_framebuffer_object, GL 3.0
// §4.4): the objects, their name spaces (shared by contexts that share display
// lists, as Mesa shares them), the completeness rules as Mesa 22.3.6 applies
// them (MESA_FACTS.md "Framebuffer objects"), and the views of an object's
// attachments the stages draw into (framebuffer/framebuffer.h).
#pragma once

#include <GL/gl.h>

#include <array>
#include <map>
#include <memory>
#include <set>

#include "framebuffer/framebuffer.h"
#include "state/buffer_objects.h"  // DataStore
#include "texture/texture_objects.h"

namespace glfixed {

// The enums of the extensions, which gl.h does not have.
namespace fbo_enums {
constexpr GLenum kFramebuffer = 0x8D40, kReadFramebuffer = 0x8CA8, kDrawFramebuffer = 0x8CA9;
constexpr GLenum kRenderbuffer = 0x8D41;
constexpr GLenum kColorAttachment0 = 0x8CE0, kDepthAttachment = 0x8D00, kStencilAttachment = 0x8D20,
                 kDepthStencilAttachment = 0x821A;
constexpr GLenum kComplete = 0x8CD5, kIncompleteAttachment = 0x8CD6, kIncompleteMissingAttachment = 0x8CD7,
                 kIncompleteDimensions = 0x8CD9, kIncompleteFormats = 0x8CDA, kIncompleteDrawBuffer = 0x8CDB,
                 kIncompleteReadBuffer = 0x8CDC, kUnsupported = 0x8CDD, kUndefined = 0x8219;
constexpr GLenum kInvalidFramebufferOperation = 0x0506;
constexpr GLenum kFramebufferDefault = 0x8218;
}  // namespace fbo_enums

constexpr int kMaxColorAttachments = 8;  // GL_MAX_COLOR_ATTACHMENTS, GL_MAX_DRAW_BUFFERS (Mesa)
constexpr int kMaxRenderbufferSize = 16384;  // GL_MAX_RENDERBUFFER_SIZE (llvmpipe)
constexpr int kMaxSamples = 4;  // GL_MAX_SAMPLES (llvmpipe)

// What a renderbuffer's internal format makes it, and the sizes
// glGetRenderbufferParameteriv reports (Mesa's, measured).
struct RenderbufferFormat {
  enum class Kind { kColor, kDepth, kStencil, kDepthStencil };
  Kind kind = Kind::kColor;
  int red = 0, green = 0, blue = 0, alpha = 0, depth = 0, stencil = 0;
  // This library can draw into it: 8-bit, 5-6-5, 16-bit and 32-bit float
  // RGBA / RGB colour (stored as the OSMesa buffers of those types are,
  // `pixelFormat`), 16- or 24-bit depth, 8-bit stencil. Other formats Mesa
  // accepts make the framebuffer GL_FRAMEBUFFER_UNSUPPORTED here.
  bool drawable = false;
  PixelFormat pixelFormat = PixelFormat::kRGBA;
  bool floatChannels = false;  // GL_RGBA32F, GL_RGBA16F...: component type GL_FLOAT
  // Channels of fewer than 8 bits (GL_RGBA4, GL_RGB5_A1...): stored as the
  // textures of those formats are, a byte a channel (ChannelType::kUnormBits).
  bool unormBits = false;
  // 10-bit channels (GL_RGB10_A2, GL_RGB10): a 16-bit word a channel, 8
  // bytes a pixel, as those textures are (ChannelType::kUnormWideBits).
  bool unormWideBits = false;
  // GL_RGBA16F, GL_RGB16F: half floats, 8 bytes a pixel (ChannelType::kFloat16).
  bool halfFloat = false;
  // GL_RG8, GL_RG16: red and green only, 8 or 16 bits (ColorBuffer::setChannels).
  bool redGreen = false;
  int bytesPerPixel = 4;
};
// False for an enum glRenderbufferStorage refuses (GL_INVALID_ENUM).
bool renderbufferFormat(GLenum internalFormat, RenderbufferFormat* out);

struct Renderbuffer {
  GLuint name = 0;
  bool bound = false;  // glIsRenderbuffer: once bound
  GLenum internalFormat = GL_RGBA;
  RenderbufferFormat format;
  int width = 0, height = 0, samples = 0;
  DataStore storage;  // zero-filled: an undefined image
};

struct Attachment {
  GLenum type = GL_NONE;  // GL_NONE, GL_TEXTURE, kRenderbuffer
  GLuint name = 0;
  int level = 0;
  GLenum textarget = 0;  // the texture target (a cube face's own target)
  int layer = 0;         // 3D: the slice (zoffset)
  bool operator==(const Attachment& o) const {
    return type == o.type && name == o.name && level == o.level && textarget == o.textarget && layer == o.layer;
  }
};

struct FramebufferObject {
  GLuint name = 0;
  bool bound = false;
  std::array<Attachment, kMaxColorAttachments> color;
  Attachment depth, stencil;
  // The draw buffers (glDrawBuffers) and the read buffer: per object.
  std::array<GLenum, kMaxColorAttachments> drawBuffers{};
  GLenum readBuffer = fbo_enums::kColorAttachment0;
  FramebufferObject() {
    drawBuffers.fill(GL_NONE);
    drawBuffers[0] = fbo_enums::kColorAttachment0;
  }
  // The attachment a GL_*_ATTACHMENT names; null for anything else.
  Attachment* attachment(GLenum point);
};

class FramebufferObjects {
 public:
  void generateFramebuffers(GLsizei n, GLuint* names);
  void generateRenderbuffers(GLsizei n, GLuint* names);
  // Created if new (glBind*: any name may be bound in Mesa's compatibility
  // profile, generated or not).
  FramebufferObject* obtainFramebuffer(GLuint name);
  Renderbuffer* obtainRenderbuffer(GLuint name);
  FramebufferObject* findFramebuffer(GLuint name);
  Renderbuffer* findRenderbuffer(GLuint name);
  bool framebufferReserved(GLuint name) const { return reservedFramebuffers_.count(name) != 0; }
  bool renderbufferReserved(GLuint name) const { return reservedRenderbuffers_.count(name) != 0; }
  void removeFramebuffer(GLuint name);
  void removeRenderbuffer(GLuint name);
  // Every object's attachments of this texture / renderbuffer. (GL 3.0 §4.4.2
  // detaches only from the bound framebuffer; Mesa, measured, detaches only
  // from the bound ones too: see detachFromBound.)
  std::map<GLuint, std::unique_ptr<FramebufferObject>>& framebuffers() { return framebuffers_; }

 private:
  std::map<GLuint, std::unique_ptr<FramebufferObject>> framebuffers_;
  std::map<GLuint, std::unique_ptr<Renderbuffer>> renderbuffers_;
  std::set<GLuint> reservedFramebuffers_, reservedRenderbuffers_;
  GLuint maxFramebufferName_ = 0, maxRenderbufferName_ = 0;
};

// GL 3.0 §4.4.4 with Mesa's rules: the status of `fb`, and its size (the
// smallest attachment's) when complete.
GLenum framebufferStatus(FramebufferObject& fb, FramebufferObjects& objects, texture::TextureObjects& textures,
                         int* width, int* height);

// The view of a colour attachment (false: none, or not drawable).
bool colorView(const Attachment& a, FramebufferObjects& objects, texture::TextureObjects& textures,
               ColorBuffer* out);
// The view of the depth and stencil attachments (nothing attached: no bits).
void depthView(const FramebufferObject& fb, FramebufferObjects& objects, texture::TextureObjects& textures,
               DepthBuffer* out);

// The texture image a texture attachment names (null if none).
texture::TextureImage* attachedImage(const Attachment& a, texture::TextureObjects& textures);

}  // namespace glfixed
