#include "state/framebuffer_objects.h"

#include <algorithm>

namespace glfixed {

using namespace fbo_enums;

namespace {

// `storedAs`: the colour buffer layout it is drawn in (kBGRX: none, not drawable here).
RenderbufferFormat colorFormat(int r, int g, int b, int a, PixelFormat storedAs = PixelFormat::kBGRX) {
  RenderbufferFormat f;
  const bool drawable = storedAs != PixelFormat::kBGRX;
  f.kind = RenderbufferFormat::Kind::kColor;
  f.red = r;
  f.green = g;
  f.blue = b;
  f.alpha = a;
  // Fewer than 8 bits a channel: drawn as kUnormBits, 4 bytes a pixel.
  f.unormBits = !drawable && r > 2 && r < 8 && g < 8 && b < 8 && a < 8;
  // 10 bits (GL_RGB10_A2, GL_RGB10): 16-bit words, kUnormWideBits.
  f.unormWideBits = !drawable && r == 10 && g == 10 && b == 10;
  f.drawable = drawable || f.unormBits || f.unormWideBits;
  f.pixelFormat = drawable ? storedAs : PixelFormat::kRGBA;
  ColorBuffer c;
  c.setFormat(f.pixelFormat);
  f.bytesPerPixel = f.unormWideBits ? 8 : c.bytesPerPixel;
  return f;
}

}  // namespace

// The sizes are Mesa's for llvmpipe's chosen pipe formats (probed); the
// luminance and intensity formats get no format there (all sizes 0).
bool renderbufferFormat(GLenum internalFormat, RenderbufferFormat* out) {
  using Kind = RenderbufferFormat::Kind;
  RenderbufferFormat f;
  switch (internalFormat) {
    case GL_RGBA:
    case GL_RGBA8: f = colorFormat(8, 8, 8, 8, PixelFormat::kRGBA); break;
    case GL_RGB:
    case GL_RGB8: f = colorFormat(8, 8, 8, 0, PixelFormat::kRGBX); break;
    case GL_RGBA2:
    case GL_RGBA4: f = colorFormat(4, 4, 4, 4); break;
    case GL_RGB5_A1: f = colorFormat(5, 5, 5, 1); break;
    case 0x8D62: f = colorFormat(5, 6, 5, 0, PixelFormat::kRGB565); break;  // GL_RGB565: B5G6R5_UNORM
    case GL_R3_G3_B2: f = colorFormat(3, 3, 2, 0); break;
    case GL_RGB4: f = colorFormat(4, 4, 4, 0); break;
    case GL_RGB5: f = colorFormat(5, 5, 5, 0); break;
    case GL_RGB10: f = colorFormat(10, 10, 10, 0); break;
    case GL_RGB10_A2: f = colorFormat(10, 10, 10, 2); break;
    case GL_RGBA12:
    case GL_RGBA16: f = colorFormat(16, 16, 16, 16, PixelFormat::kRGBA16); break;
    case GL_RGB12:
    case GL_RGB16: f = colorFormat(16, 16, 16, 0, PixelFormat::kRGB16); break;
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8: f = colorFormat(0, 0, 0, 8); break;
    case GL_ALPHA12:
    case GL_ALPHA16: f = colorFormat(0, 0, 0, 16); break;
    case 0x8229: f = colorFormat(8, 0, 0, 0); break;  // GL_R8
    case 0x822B:  // GL_RG8: R8G8_UNORM, 2 bytes a pixel (reads (R, G, 0, 1))
    case 0x822C:  // GL_RG16: R16G16_UNORM, 4 bytes a pixel
      f = internalFormat == 0x822B ? colorFormat(8, 8, 0, 0) : colorFormat(16, 16, 0, 0);
      f.redGreen = f.drawable = true;
      f.bytesPerPixel = internalFormat == 0x822B ? 2 : 4;
      break;
    case 0x8C43:
    case 0x8C42: f = colorFormat(8, 8, 8, 8, PixelFormat::kRGBA); break;  // GL_SRGB8_ALPHA8, GL_SRGB_ALPHA: drawn linear (no GL_FRAMEBUFFER_SRGB)
    case 0x8814: f = colorFormat(32, 32, 32, 32, PixelFormat::kRGBA32F); break;  // GL_RGBA32F
    case 0x8815: f = colorFormat(32, 32, 32, 0, PixelFormat::kRGB32F); break;    // GL_RGB32F
    case 0x881B:  // GL_RGB16F
    case 0x881A:  // GL_RGBA16F: half floats, kFloat16
      f = colorFormat(16, 16, 16, internalFormat == 0x881A ? 16 : 0);
      f.halfFloat = f.drawable = true;
      f.bytesPerPixel = 8;
      break;
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16: f = colorFormat(0, 0, 0, 0); break;
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_COMPONENT24:
      f.kind = Kind::kDepth;
      f.depth = 24;
      f.drawable = true;
      f.bytesPerPixel = 4;  // Z24X8
      break;
    case GL_DEPTH_COMPONENT16:
      f.kind = Kind::kDepth;
      f.depth = 16;
      f.drawable = true;
      f.bytesPerPixel = 2;
      break;
    case GL_DEPTH_COMPONENT32:
    case 0x8CAC:  // GL_DEPTH_COMPONENT32F
      f.kind = Kind::kDepth;
      f.depth = 32;
      f.bytesPerPixel = 4;
      break;
    case GL_STENCIL_INDEX:
    case 0x8D46:
    case 0x8D47:
    case 0x8D48:
    case 0x8D49:  // STENCIL_INDEX1/4/8/16
      f.kind = Kind::kStencil;
      f.stencil = 8;
      f.drawable = true;
      f.bytesPerPixel = 1;
      break;
    case 0x84F9:
    case 0x88F0:  // GL_DEPTH_STENCIL, GL_DEPTH24_STENCIL8
      f.kind = Kind::kDepthStencil;
      f.depth = 24;
      f.stencil = 8;
      f.drawable = true;
      f.bytesPerPixel = 4;
      break;
    default: return false;
  }
  f.floatChannels = internalFormat == 0x8814 || internalFormat == 0x8815 || internalFormat == 0x881A ||
                    internalFormat == 0x881B;
  *out = f;
  return true;
}

Attachment* FramebufferObject::attachment(GLenum point) {
  if (point >= kColorAttachment0 && point < kColorAttachment0 + kMaxColorAttachments)
    return &color[point - kColorAttachment0];
  if (point == kDepthAttachment) return &depth;
  if (point == kStencilAttachment) return &stencil;
  return nullptr;
}

// Mesa's hash tables hand out the names after the highest one ever used
// (probed: with 5 and 6 bound, glGenFramebuffers gives 7).
void FramebufferObjects::generateFramebuffers(GLsizei n, GLuint* names) {
  for (GLsizei i = 0; i < n; ++i) {
    names[i] = ++maxFramebufferName_;
    reservedFramebuffers_.insert(names[i]);
  }
}

void FramebufferObjects::generateRenderbuffers(GLsizei n, GLuint* names) {
  for (GLsizei i = 0; i < n; ++i) {
    names[i] = ++maxRenderbufferName_;
    reservedRenderbuffers_.insert(names[i]);
  }
}

FramebufferObject* FramebufferObjects::obtainFramebuffer(GLuint name) {
  if (name == 0) return nullptr;
  std::unique_ptr<FramebufferObject>& p = framebuffers_[name];
  if (!p) {
    p = std::make_unique<FramebufferObject>();
    p->name = name;
    reservedFramebuffers_.erase(name);
    maxFramebufferName_ = std::max(maxFramebufferName_, name);
  }
  return p.get();
}

Renderbuffer* FramebufferObjects::obtainRenderbuffer(GLuint name) {
  if (name == 0) return nullptr;
  std::unique_ptr<Renderbuffer>& p = renderbuffers_[name];
  if (!p) {
    p = std::make_unique<Renderbuffer>();
    p->name = name;
    reservedRenderbuffers_.erase(name);
    maxRenderbufferName_ = std::max(maxRenderbufferName_, name);
  }
  return p.get();
}

FramebufferObject* FramebufferObjects::findFramebuffer(GLuint name) {
  auto it = framebuffers_.find(name);
  return it == framebuffers_.end() ? nullptr : it->second.get();
}

Renderbuffer* FramebufferObjects::findRenderbuffer(GLuint name) {
  auto it = renderbuffers_.find(name);
  return it == renderbuffers_.end() ? nullptr : it->second.get();
}

void FramebufferObjects::removeFramebuffer(GLuint name) {
  framebuffers_.erase(name);
  reservedFramebuffers_.erase(name);
}

void FramebufferObjects::removeRenderbuffer(GLuint name) {
  renderbuffers_.erase(name);
  reservedRenderbuffers_.erase(name);
}

texture::TextureImage* attachedImage(const Attachment& a, texture::TextureObjects& textures) {
  if (a.type != GL_TEXTURE) return nullptr;
  texture::TextureObject* t = textures.find(a.name);
  if (!t || a.level < 0 || a.level >= texture::kMaxTextureLevels) return nullptr;
  int face = 0;
  if (a.textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && a.textarget <= GL_TEXTURE_CUBE_MAP_POSITIVE_X + 5)
    face = static_cast<int>(a.textarget - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  return &t->face[face][a.level];
}

namespace {

enum class Point { kColor, kDepth, kStencil };

// The colour buffer layout of the texels of an RGBA or RGB texture
// (texture/texel_format.h: four stored channels): 8-bit ones as OSMesa's
// RGBA / RGBX bytes (sRGB ones too: written as they are without
// GL_FRAMEBUFFER_SRGB, probed), 16-bit ones as its 16-bit buffers, fewer
// bits as kUnormBits, 10 bits as kUnormWideBits. False for the formats not
// drawn into here (luminance, intensity and alpha textures).
bool colorTexelView(texture::TexelFormat f, ColorBuffer* c) {
  const texture::TexelFormatInfo& info = texture::texelFormatInfo(f);
  // ARB_texture_float: RGBA and RGB ones are drawn as the float
  // renderbuffers are (four floats or four halves a texel, an RGB one's
  // fourth unused); the float luminance, intensity and alpha ones are not
  // drawn into here (Mesa draws into them).
  if (info.floating) {
    if (info.baseFormat != GL_RGBA && info.baseFormat != GL_RGB) return false;
    if (info.bits[0] == 32) {
      c->setFormat(PixelFormat::kRGBA32F);
      if (info.baseFormat == GL_RGB) c->alpha = -1;
    } else {
      c->setHalfFloat(info.baseFormat == GL_RGBA);
    }
    return true;
  }
  // Alpha, luminance and luminance-alpha textures of 8 and 16 bits: the
  // fragment's red goes into the luminance (Mesa, probed: an L8 texture
  // reads back as (L, 0, 0, 1), A8 as (0, 0, 0, A)).
  const bool wideChannel = info.bytesPerChannel == 2 && info.bits[0] == 16;
  // Not one channel alone (A8, L8, A16, L16): there llvmpipe's colours differ
  // from its other formats' by 1 in the last bit on ~12% of the pixels of a
  // smooth triangle (probed, cause not found), so those are not drawn into here.
  const bool byteChannel = info.bytesPerChannel == 1 && info.bits[0] == 8 && !info.srgb;
  if ((wideChannel || byteChannel) && info.channels == 2) {
    const ChannelType type = wideChannel ? ChannelType::kUnorm16 : ChannelType::kUnorm8;
    const int bpp = info.bytesPerTexel;
    switch (info.baseFormat) {
      case GL_LUMINANCE_ALPHA:
        c->setChannels(type, bpp, 0, -1, -1, 1);
        c->luminance = true;
        return true;
      default: break;
    }
  }
  // LUMINANCE4_ALPHA4: 4-bit luminance and alpha in a byte each, drawn as
  // kUnormBits (llvmpipe's 8-bit blend, rounded to 4 bits).
  if (info.baseFormat == GL_LUMINANCE_ALPHA && info.channels == 2 && info.bytesPerChannel == 1 &&
      info.bits[0] == 4 && info.bits[1] == 4) {
    c->setUnormBits(4, 0, 0, 4);
    c->bytesPerPixel = info.bytesPerTexel;
    c->green = c->blue = -1;
    c->alpha = 1;
    c->luminance = true;
    return true;
  }
  if ((info.baseFormat != GL_RGBA && info.baseFormat != GL_RGB) || info.channels != 4) return false;
  const uint8_t* b = info.bits;
  const bool alpha = info.baseFormat == GL_RGBA;
  if (info.bytesPerChannel == 1 && b[0] == 8) {
    c->setFormat(alpha ? PixelFormat::kRGBA : PixelFormat::kRGBX);
  } else if (info.bytesPerChannel == 1 && b[0] > 2) {  // 3-3-2 ... 5-6-5
    c->setUnormBits(b[0], b[1], b[2], alpha ? b[3] : 0);
  } else if (info.bytesPerChannel == 2 && b[0] == 10) {  // RGB10A2, RGB10X2
    c->setUnormWideBits(b[0], b[1], b[2], alpha ? b[3] : 0);
  } else if (info.bytesPerChannel == 2 && b[0] == 16) {
    c->setFormat(PixelFormat::kRGBA16);  // RGBX16: four 16-bit channels, the fourth unused
    if (!alpha) c->alpha = -1;
  } else {
    return false;
  }
  return true;
}

bool colorTexelDrawable(texture::TexelFormat f) {
  ColorBuffer c;
  return colorTexelView(f, &c);
}

// GL 2.1 §3.8.10's mipmap completeness of `t` from its base level to its
// maximum level (or 1x1), whatever its filters: Mesa makes an attachment of a
// level past the base level INCOMPLETE_ATTACHMENT unless the texture has that
// whole chain (probed: a 16x16 texture with levels 0, 1 and 3 defined, or
// 0 and 1 only, cannot be drawn into at level 1 until GL_TEXTURE_MAX_LEVEL is 1).
bool mipmapChainComplete(texture::TextureObject& t) {
  const int base = t.params.baseLevel;
  if (base < 0 || base >= texture::kMaxTextureLevels) return false;
  const int faces = t.target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  const int dims = t.target == GL_TEXTURE_1D ? 1 : t.target == GL_TEXTURE_3D ? 3 : 2;
  const texture::TextureImage& b = t.level(0, base);
  if (!b.defined()) return false;
  int maxSize = std::max({b.width, dims >= 2 ? b.height : 1, dims >= 3 ? b.depth : 1});
  int log2 = 0;
  while ((maxSize >> log2) > 1) ++log2;
  const int last = std::min({base + log2, t.params.maxLevel, texture::kMaxTextureLevels - 1});
  for (int level = base; level <= last; ++level) {
    const int shift = level - base;
    const int w = std::max(b.width >> shift, 1), h = dims >= 2 ? std::max(b.height >> shift, 1) : 1;
    const int d = dims >= 3 ? std::max(b.depth >> shift, 1) : 1;
    for (int f = 0; f < faces; ++f) {
      const texture::TextureImage& img = t.level(f, level);
      if (!img.defined() || img.width != w || img.height != h || (dims >= 3 && img.depth != d) ||
          img.format != b.format)
        return false;
    }
  }
  return true;
}

// Mesa's test_attachment_completeness, and whether this library draws into it.
GLenum attachmentStatus(const Attachment& a, Point point, FramebufferObjects& objects,
                        texture::TextureObjects& textures, int* w, int* h, bool* drawable) {
  using Kind = RenderbufferFormat::Kind;
  if (a.type == GL_TEXTURE) {
    const texture::TextureImage* image = attachedImage(a, textures);
    if (!image || !image->defined()) return kIncompleteAttachment;
    if (a.layer >= image->depth) return kIncompleteAttachment;
    texture::TextureObject* t = textures.find(a.name);
    if (t && a.level > t->params.baseLevel && !mipmapChainComplete(*t)) return kIncompleteAttachment;
    const bool depthFormat = texture::isDepthFormat(image->format);
    switch (point) {
      case Point::kColor:
        if (depthFormat) return kIncompleteAttachment;
        *drawable = colorTexelDrawable(image->format);
        break;
      case Point::kDepth:
        if (!depthFormat) return kIncompleteAttachment;
        *drawable = image->format != texture::TexelFormat::Z32;
        break;
      case Point::kStencil:  // a depth-stencil texture only (EXT_packed_depth_stencil)
        if (image->format != texture::TexelFormat::Z24S8) return kIncompleteAttachment;
        *drawable = true;
        break;
    }
    *w = image->width;
    *h = image->height;
    return kComplete;
  }
  const Renderbuffer* rb = objects.findRenderbuffer(a.name);
  if (!rb || rb->width < 1 || rb->height < 1) return kIncompleteAttachment;
  const Kind k = rb->format.kind;
  const bool ok = point == Point::kColor   ? k == Kind::kColor
                  : point == Point::kDepth ? (k == Kind::kDepth || k == Kind::kDepthStencil)
                                           : (k == Kind::kStencil || k == Kind::kDepthStencil);
  if (!ok) return kIncompleteAttachment;
  *drawable = rb->format.drawable && rb->samples == 0;
  *w = rb->width;
  *h = rb->height;
  return kComplete;
}

}  // namespace

GLenum framebufferStatus(FramebufferObject& fb, FramebufferObjects& objects,
                         texture::TextureObjects& textures, int* width, int* height) {
  int minW = 1 << 30, minH = 1 << 30, images = 0;
  bool allDrawable = true;
  auto test = [&](const Attachment& a, Point p) -> GLenum {
    if (a.type == GL_NONE) return kComplete;
    int w = 0, h = 0;
    bool drawable = false;
    const GLenum s = attachmentStatus(a, p, objects, textures, &w, &h, &drawable);
    if (s != kComplete) return s;
    ++images;
    minW = std::min(minW, w);
    minH = std::min(minH, h);
    allDrawable = allDrawable && drawable;
    return kComplete;
  };
  // Mesa's order: depth, stencil, then the colour attachments.
  if (GLenum s = test(fb.depth, Point::kDepth); s != kComplete) return s;
  if (GLenum s = test(fb.stencil, Point::kStencil); s != kComplete) return s;
  for (const Attachment& a : fb.color)
    if (GLenum s = test(a, Point::kColor); s != kComplete) return s;
  if (images == 0) return kIncompleteMissingAttachment;
  // llvmpipe's state tracker (st_validate_framebuffer): depth and stencil
  // must be one buffer when both are attached.
  if (fb.depth.type != GL_NONE && fb.stencil.type != GL_NONE && !(fb.depth == fb.stencil))
    return kUnsupported;
  if (!allDrawable) return kUnsupported;  // formats this library does not draw into
  *width = minW;
  *height = minH;
  return kComplete;
}

bool colorView(const Attachment& a, FramebufferObjects& objects, texture::TextureObjects& textures,
               ColorBuffer* out) {
  ColorBuffer c;
  if (a.type == GL_TEXTURE) {
    texture::TextureImage* image = attachedImage(a, textures);
    if (!image || !image->defined() || a.layer >= image->depth) return false;
    if (!colorTexelView(image->format, &c)) return false;
    c.pixels = image->texels.data() + static_cast<size_t>(a.layer) * image->imageStride;
    c.width = image->width;
    c.height = image->height;
  } else if (a.type == kRenderbuffer) {
    Renderbuffer* rb = objects.findRenderbuffer(a.name);
    if (!rb || rb->format.kind != RenderbufferFormat::Kind::kColor || !rb->format.drawable || rb->width < 1)
      return false;
    const RenderbufferFormat& f = rb->format;
    if (f.halfFloat)
      c.setHalfFloat(f.alpha > 0);
    else if (f.redGreen)
      c.setChannels(f.red == 8 ? ChannelType::kUnorm8 : ChannelType::kUnorm16, f.bytesPerPixel, 0, 1, -1, -1);
    else if (f.unormBits)
      c.setUnormBits(f.red, f.green, f.blue, f.alpha);
    else if (f.unormWideBits)
      c.setUnormWideBits(f.red, f.green, f.blue, f.alpha);
    else
      c.setFormat(f.pixelFormat);
    c.pixels = rb->storage.data();
    c.width = rb->width;
    c.height = rb->height;
  } else {
    return false;
  }
  c.rowLength = c.width;
  c.yUp = true;
  c.floatMode = c.floatChannels();
  *out = c;
  return true;
}

void depthView(const FramebufferObject& fb, FramebufferObjects& objects, texture::TextureObjects& textures,
               DepthBuffer* out) {
  *out = DepthBuffer{};
  auto rbOf = [&](const Attachment& a) -> Renderbuffer* {
    return a.type == kRenderbuffer ? objects.findRenderbuffer(a.name) : nullptr;
  };
  // A texture's level as the buffer: Z24S8's words are the framebuffer's
  // Z24_UNORM_S8_UINT, its stencil used when it is the stencil attachment too.
  // At the stencil attachment alone: the words' stencil, no depth buffer
  // (Mesa: GL_DEPTH_BITS 0, no depth test).
  auto textureView = [&](const Attachment& a, bool asStencil, bool stencilOnly) {
    texture::TextureImage* image = attachedImage(a, textures);
    if (!image || !image->defined() || a.layer >= image->depth) return;
    const bool packed = image->format == texture::TexelFormat::Z24S8;
    const int bits = image->format == texture::TexelFormat::Z16 ? 16
                     : image->format == texture::TexelFormat::Z24 || packed ? 24
                                                                            : 0;
    if (bits == 0 || (asStencil && !packed)) return;
    uint8_t* words = image->texels.data() + static_cast<size_t>(a.layer) * image->imageStride;
    if (stencilOnly)
      out->viewPackedStencil(image->width, image->height, words);
    else
      out->view(image->width, image->height, bits, packed && asStencil ? 8 : 0, words, nullptr);
  };
  if (fb.depth.type == GL_TEXTURE) {
    textureView(fb.depth, fb.stencil == fb.depth, false);
    return;
  }
  if (fb.depth.type == GL_NONE && fb.stencil.type == GL_TEXTURE) {
    textureView(fb.stencil, true, true);
    return;
  }
  Renderbuffer* depth = rbOf(fb.depth);
  Renderbuffer* stencil = rbOf(fb.stencil);
  if (depth && depth->width > 0 && depth->format.drawable) {
    const bool packed = depth->format.kind == RenderbufferFormat::Kind::kDepthStencil;
    out->view(depth->width, depth->height, depth->format.depth, packed && stencil == depth ? 8 : 0,
              depth->storage.data(), nullptr);
    return;
  }
  if (stencil && stencil->width > 0 && stencil->format.drawable) {
    if (stencil->format.kind == RenderbufferFormat::Kind::kDepthStencil)
      out->viewPackedStencil(stencil->width, stencil->height, stencil->storage.data());
    else
      out->view(stencil->width, stencil->height, 0, 8, nullptr, stencil->storage.data());
  }
}

}  // namespace glfixed
