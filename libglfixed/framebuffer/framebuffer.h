// The drawing surface as a context sees it: colour buffers (the memory an
// OSMesa program hands to OSMesaMakeCurrent, in one of its pixel formats, or
// the front and back buffers of a GLX or EGL surface, which the platform layer
// owns) and the depth buffer the context owns. Window coordinates: (0,0) is
// the lower left pixel.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "framebuffer/accum_buffer.h"

namespace glfixed {

// kBGRX: the 32-bit pixels of a depth-24 X11 TrueColor image (blue, green,
// red, one unused byte): a window without alpha bits.
// The formats after kBGRX are OSMesa's other buffer types as llvmpipe stores
// them (reference/MESA_FACTS.md, "OSMesa colour buffer types"): kRGB565 is a
// 16-bit word, red in the top 5 bits (B5G6R5_UNORM); kRGBA16/kRGB16 have 16-bit
// unorm channels, kRGBA32F/kRGB32F float ones, always in R, G, B(, A) order
// (Mesa stores OSMESA_BGRA and OSMESA_ARGB of those types as RGBA too).
enum class PixelFormat {
  kRGBA,
  kBGRA,
  kARGB,
  kRGB,
  kBGR,
  kBGRX,
  kRGBX,  // red, green, blue, an unused byte: the RGBX8 texels of an RGB texture or renderbuffer
  kRGB565,
  kRGBA16,
  kRGB16,
  kRGBA32F,
  kRGB32F
};

// How a ColorBuffer stores a channel. The fragment stage's 8-bit arithmetic
// serves kUnorm8, kRGB565 and kUnormBits (llvmpipe blends formats of at most
// 8 bits a channel in bytes); kUnorm16 blends in 16-bit fixed point, kFloat32
// in float (fragment/wide_color.inc). kUnormBits: each channel an unsigned
// value of bits[k] (< 8) bits in a byte of its own, as the texels of GL_RGBA4,
// GL_RGB5_A1, GL_R3_G3_B2... textures are kept (texture/texel_format.h), and
// so the renderbuffers of those formats. kUnormWideBits: each channel an
// unsigned value of bits[k] bits in a 16-bit word of its own (channel k at
// bytes 2k), as GL_RGB10_A2 and GL_RGB10 textures are kept: llvmpipe blends
// formats with a channel of 9 to 16 bits in its 16-bit type, so these take the
// wide path (wide_color.inc: widened to 16 bits at the load, cut at the write).
// kFloat16: half floats (GL_RGBA16F, GL_RGB16F renderbuffers), a 16-bit word
// a channel at bytes 2k, blended in float (floatToHalf: llvmpipe's store
// rounds toward zero).
enum class ChannelType : uint8_t { kUnorm8, kRGB565, kUnormBits, kUnorm16, kUnormWideBits, kFloat16, kFloat32 };

struct ColorBuffer {
  uint8_t* pixels = nullptr;  // client memory, not owned
  int width = 0, height = 0;
  int rowLength = 0;          // in pixels (OSMESA_ROW_LENGTH); >= width
  bool yUp = true;            // OSMESA_Y_UP: row 0 of memory is the bottom row
  PixelFormat format = PixelFormat::kRGBA;
  int bytesPerPixel = 4;
  // Byte offset of each channel inside a pixel (for kUnorm16 and kFloat32:
  // the channel's index, 0..3); alpha is -1 where not stored. Unused by kRGB565.
  int red = 0, green = 1, blue = 2, alpha = 3;
  ChannelType channels = ChannelType::kUnorm8;
  uint8_t bits[4] = {8, 8, 8, 8};  // kUnormBits: each channel's bits (0: not stored)

  void setFormat(PixelFormat f);
  // kUnormBits, one byte a channel (red, green, blue, alpha at bytes 0..3);
  // a channel of 0 bits is not stored (alpha reads 1).
  void setUnormBits(int r, int g, int b, int a);
  // kUnormWideBits, a 16-bit word a channel (8 bytes a pixel); a channel of
  // 0 bits is not stored (alpha reads 1).
  void setUnormWideBits(int r, int g, int b, int a);
  // kFloat16, four half floats a pixel (alpha not stored without `alpha`).
  void setHalfFloat(bool alpha);
  // 8- or 16-bit channels (`type` kUnorm8 or kUnorm16) at the given channel
  // indices (-1: not stored), `bytesPerPixel` in all: the texels of
  // alpha, luminance and luminance-alpha textures.
  void setChannels(ChannelType type, int bytesPerPixel, int r, int g, int b, int a);

 private:
  void setRgbaLayout(ChannelType type, int bytesPerPixel, bool withAlpha);

 public:
  // Luminance: GL_RED_BITS... report 0, as Mesa does for such attachments.
  bool luminance = false;
  // A framebuffer object's float attachment: Mesa's framebuffer is then in
  // float mode (GL_RGBA_FLOAT_MODE_ARB 1), so GL_CLAMP_READ_COLOR's
  // GL_FIXED_ONLY does not clamp glReadPixels (probed; OSMesa's float
  // buffers are not in float mode and clamp).
  bool floatMode = false;
  bool floatChannels() const { return channels == ChannelType::kFloat16 || channels == ChannelType::kFloat32; }
  // 16-bit or float channels: the fragment stage's wide path.
  bool wide() const { return channels >= ChannelType::kUnorm16; }
  bool hasAlpha() const { return alpha >= 0; }
  // Bits a channel (GL_RED_BITS...; alpha: 0 without alpha).
  int channelBits(int k) const;
  uint8_t* pixel(int x, int y) const {
    int row = yUp ? y : height - 1 - y;
    return pixels + (static_cast<size_t>(row) * rowLength + x) * bytesPerPixel;
  }
  // Bytes in and out: the 8-bit formats' own; others convert (5-6-5: bit
  // replication in, truncation out, as llvmpipe's 8-bit blend path does).
  // A colour channel not stored (an alpha or luminance attachment) reads 0,
  // alpha 1 (GL 3.0 §4.3.2: a luminance buffer reads as (L, 0, 0, 1)).
  void write(int x, int y, const uint8_t rgba[4]) const {
    if (channels != ChannelType::kUnorm8) return writeConverted(x, y, rgba);
    uint8_t* p = pixel(x, y);
    if (red >= 0) p[red] = rgba[0];
    if (green >= 0) p[green] = rgba[1];
    if (blue >= 0) p[blue] = rgba[2];
    if (alpha >= 0) p[alpha] = rgba[3];
  }
  void read(int x, int y, uint8_t rgba[4]) const {
    if (channels != ChannelType::kUnorm8) return readConverted(x, y, rgba);
    const uint8_t* p = pixel(x, y);
    rgba[0] = red >= 0 ? p[red] : 0;
    rgba[1] = green >= 0 ? p[green] : 0;
    rgba[2] = blue >= 0 ? p[blue] : 0;
    rgba[3] = alpha >= 0 ? p[alpha] : 255;
  }
  // Floats in and out, in the buffer's precision: unorm channels read as
  // v / max and are written rint(clamp(v) * max); float channels as they are
  // (a float buffer keeps clear colours outside [0, 1]). Alpha reads 1 where
  // not stored. `mask`: the channels written (null: all).
  void readFloat(int x, int y, float rgba[4]) const;
  // `halfUp`: a clear's rounding, llvmpipe's util_iround (v * max + 0.5,
  // truncated: 0.3 is 5 of 15 and 19661 of 65535, where rint gives 4 and
  // 19660; probed). Without it, 16-bit channels round to nearest even and
  // 10-bit ones are stored as fragments are (unorm16ToBits).
  void writeFloat(int x, int y, const float rgba[4], const bool* mask = nullptr, bool halfUp = false) const;

 private:
  void writeConverted(int x, int y, const uint8_t rgba[4]) const;
  void readConverted(int x, int y, uint8_t rgba[4]) const;
};

// Depth values are unsigned integers of `bits` bits (0 = no depth buffer,
// 16, or 24). Mesa's OSMesa hands out 2 bytes a value for 16 bits and 4 bytes
// a value for 24 bits (REFERENCE.md, "Depth and limits"); so do we.
// The stencil buffer (8 bits or none) lives here too, as Mesa allocates it
// (MESA_FACTS.md "Stencil"): with a 24-bit depth buffer it is the top byte of
// each 32-bit word (Z24_UNORM_S8_UINT, which OSMesaGetDepthBuffer hands out
// as it is); without a depth buffer it is a buffer of bytes of its own.
class DepthBuffer {
 public:
  DepthBuffer() = default;
  // A copy owns copies of the values; a copy of a view is a view of the same memory.
  DepthBuffer(const DepthBuffer& o) { *this = o; }
  DepthBuffer& operator=(const DepthBuffer& o);
  DepthBuffer(DepthBuffer&& o) noexcept { *this = std::move(o); }
  DepthBuffer& operator=(DepthBuffer&& o) noexcept;
  void resize(int width, int height, int bits, int stencilBits = 0);
  // Framebuffer objects: a view of memory the buffer does not own (a
  // renderbuffer's, a depth texture's level, or another DepthBuffer's), laid
  // out as resize would make it: `depth` holds 2 (16 bits) or 4 bytes (24
  // bits, the stencil in the top byte when packed) a value, `stencil8` one
  // byte a value without depth; rows of `width` values from the bottom up.
  void view(int width, int height, int bits, int stencilBits, void* depth, uint8_t* stencil8);
  // The stencil of Z24S8 words alone: a depth-stencil image at a framebuffer
  // object's stencil attachment with nothing at its depth attachment. The
  // buffer has no depth (bits() 0: no depth test, clear or read), the words'
  // depth bits are kept.
  void viewPackedStencil(int width, int height, void* words) {
    view(width, height, 24, 8, words, nullptr);
    depthless_ = true;
  }
  void viewOf(DepthBuffer& owner) {
    view(owner.width_, owner.height_, owner.bits_, owner.stencilBits_, owner.data(), owner.stencil8());
    depthless_ = owner.depthless_;
  }
  int bits() const { return depthless_ ? 0 : bits_; }
  int stencilBits() const { return stencilBits_; }
  // The stencil is the top byte of the depth words (else, with stencil
  // bits, in stencil8()).
  bool packedStencil() const { return stencilBits_ != 0 && bits_ == 24; }
  int width() const { return width_; }
  int height() const { return height_; }
  uint32_t maxValue() const { return bits_ == 16 ? 0xffffu : 0xffffffu; }
  int bytesPerValue() const { return bits_ == 16 ? 2 : 4; }
  void* data() { return bits_ == 16 ? static_cast<void*>(d16_) : static_cast<void*>(d32_); }
  uint8_t* stencil8() { return s8_; }  // the stencil without depth: one byte a pixel
  // The depth value (without the stencil byte).
  uint32_t get(int x, int y) const {
    size_t i = static_cast<size_t>(y) * width_ + x;
    return bits_ == 16 ? d16_[i] : d32_[i] & 0xffffffu;
  }
  // Sets the depth value, keeping the stencil byte.
  void set(int x, int y, uint32_t v) {
    size_t i = static_cast<size_t>(y) * width_ + x;
    if (bits_ == 16)
      d16_[i] = static_cast<uint16_t>(v);
    else
      d32_[i] = (d32_[i] & 0xff000000u) | (v & 0xffffffu);
  }
  uint32_t getStencil(int x, int y) const {
    size_t i = static_cast<size_t>(y) * width_ + x;
    return packedStencil() ? d32_[i] >> 24 : s8_[i];
  }
  // The stencil value, bits of `writeMask` only (GL 2.1 §4.2.2).
  void setStencil(int x, int y, uint32_t v, uint32_t writeMask) {
    size_t i = static_cast<size_t>(y) * width_ + x;
    const uint32_t old = getStencil(x, y);
    const uint32_t s = ((old & ~writeMask) | (v & writeMask)) & 0xffu;
    if (packedStencil())
      d32_[i] = (d32_[i] & 0xffffffu) | (s << 24);
    else
      s8_[i] = static_cast<uint8_t>(s);
  }
  // The values, to put back after a pass into one of several draw buffers.
  std::vector<uint8_t> saveValues() const;
  void restoreValues(const std::vector<uint8_t>& saved);
  void fill(uint32_t v);                                // depth, keeping the stencil
  void fillStencil(uint32_t v, uint32_t writeMask);      // stencil, keeping the depth

 private:
  void pointAtOwnStorage();
  size_t count() const { return static_cast<size_t>(width_) * height_; }
  int bits_ = 0, stencilBits_ = 0, width_ = 0, height_ = 0;  // bits_: the layout (24 when depthless_)
  bool isView_ = false;
  bool depthless_ = false;
  std::vector<uint16_t> own16_;
  std::vector<uint32_t> own32_;
  std::vector<uint8_t> own8_;
  uint16_t* d16_ = nullptr;
  uint32_t* d32_ = nullptr;
  uint8_t* s8_ = nullptr;
};

// The window-system surface behind a framebuffer (platform/surface.h), told
// what GL 2.1 leaves to the window system: glFlush and glFinish must bring
// what was drawn into the front buffer to the screen, and glViewport is where
// Mesa's X11 drivers look at the window's size again.
class SurfaceHooks {
 public:
  virtual ~SurfaceHooks() = default;
  virtual void frontBufferFlushed() = 0;
  virtual void viewportChanged() = 0;
};

struct Framebuffer {
  // Views of the surface's colour buffers; back.pixels is null when the
  // surface is single-buffered (OSMesa's always is). The read surface may be
  // another one (glXMakeContextCurrent): readFront and readBack.
  ColorBuffer front, back;
  ColorBuffer readFront, readBack;
  // The draw buffer (GL 2.1 §4.2.1) and the read buffer (§4.3.2), chosen by
  // selectBuffers from glDrawBuffer and glReadBuffer; pixels is null for
  // GL_NONE. Every stage draws into `color`; glReadPixels reads `read`.
  ColorBuffer color, read;
  DepthBuffer depth;
  AccumBuffer accum;
  SurfaceHooks* surface = nullptr;      // the draw surface; null for OSMesa
  SurfaceHooks* readSurface = nullptr;  // the read surface

  // A complete framebuffer object is bound (state/framebuffer_binding.h):
  // the views above are of its attachments, of objectWidth x objectHeight
  // pixels; `color` may have no pixels (a depth-only object) and still be drawn.
  bool object = false;
  int objectWidth = 0, objectHeight = 0;
  // glDrawBuffers: the object's draw buffers 1..7 that name an attachment;
  // the draws and glClear do them after `color`, from the same depth values
  // (Mesa's fixed-function fragment shader writes gl_FragColor, which goes to
  // every draw buffer).
  ColorBuffer moreColor[7];
  int moreColorCount = 0;

  bool bound() const { return color.pixels != nullptr || object; }
  bool hasSurface() const { return front.pixels != nullptr || object; }
  bool doubleBuffered() const { return back.pixels != nullptr; }
  int width() const { return object ? objectWidth : front.width; }
  int height() const { return object ? objectHeight : front.height; }
  // llvmpipe's row py is GL's row py: Mesa's state tracker renders a
  // framebuffer object as GL has it (y up, Y_0_BOTTOM), but flips a window
  // system buffer (OSMesa, a window: Y_0_TOP), whose row py is GL row
  // height - 1 - py. Snapping, the fill rule and float rounding happen in
  // llvmpipe's rows, so every stage asks the framebuffer being drawn.
  bool rowsUp() const { return object; }
  // The llvmpipe row of GL row y, and back (the same map).
  int llvmpipeRow(int y) const { return rowsUp() ? y : height() - 1 - y; }
  // The buffers GL_FRONT, GL_BACK, GL_LEFT... name here, as Mesa resolves
  // them (buffers.c): on a single-buffered surface every back buffer is the
  // front one; GL_LEFT and GL_FRONT_AND_BACK draw into both buffers but read
  // the front; there is no stereo and no auxiliary buffer (kMissing: an
  // invalid operation), and an unknown name is kUnknown (an invalid enum).
  enum class Buffers { kUnknown, kMissing, kNone, kFront, kBack, kBoth };
  Buffers buffersNamed(GLenum buffer, bool forReading) const;
  bool drawsIntoBoth(GLenum drawBuffer) const { return buffersNamed(drawBuffer, false) == Buffers::kBoth; }
  // Points `color` and `read` at the buffers GL state names; for kBoth
  // `color` is the back buffer, and the draws and glClear do the front one
  // too (pipeline/draw.cpp, api/gl_framebuffer_api.cpp).
  void selectBuffers(GLenum drawBuffer, GLenum readBuffer);
};

// A byte as an n-bit (n < 8) unsigned normalized value, as llvmpipe
// converts its 8-bit blend results: 5 and 6 bits keep the top bits, 4 bits
// round to nearest (probed on B4G4R4A4: byte 9 is 1 of 15, byte 15 of
// B5G5R5A1 1 of 31); fewer bits ((b >> n) * (2^n - 1) + 2^(7 - n)) >> (8 - n)
// (B2G3R3: bytes 21 and 24 give 0 and 1 of 7, 54 and 57 give 1 and 2; the
// 1-bit alpha of B5G5R5A1 rounds either way), the same rule as unorm16ToBits.
inline uint8_t byteToUnormBits(uint32_t byte, int bits) {
  if (bits >= 5) return static_cast<uint8_t>(byte >> (8 - bits));
  const uint32_t max = (1u << bits) - 1u;
  if (bits == 4) return static_cast<uint8_t>((byte * max + 127u) / 255u);
  return static_cast<uint8_t>(((byte >> bits) * max + (1u << (7 - bits))) >> (8 - bits));
}

// An n-bit (n < 8) unsigned normalized value as a byte by bit replication,
// llvmpipe's unpack to 8 bits (5 bits: 28 is 231, where rint(28 * 255 / 31)
// is 230; probed).
inline uint8_t unormBitsToByte(uint32_t v, int bits) {
  uint32_t out = 0;
  for (int shift = 8 - bits; shift > -bits; shift -= bits) out |= shift >= 0 ? v << shift : v >> -shift;
  return static_cast<uint8_t>(out);
}

// llvmpipe's conversion of its 16-bit blend type to an n-bit channel (n < 16),
// measured on R10G10B10A2 (MESA_FACTS.md "llvmpipe's n-bit channels"): with
// n >= 8 the top n bits (truncation: a fragment's 10-bit red is
// rint(c * 65535) >> 6); fewer bits ((v >> n) * (2^n - 1) + 2^(15 - n)) >>
// (16 - n) (2 bits: ((v >> 2) * 3 + 8192) >> 14).
inline uint32_t unorm16ToBits(uint32_t v, int bits) {
  if (bits >= 8) return v >> (16 - bits);
  return ((v >> bits) * ((1u << bits) - 1u) + (1u << (15 - bits))) >> (16 - bits);
}

// An n-bit (n < 16) channel widened to llvmpipe's 16-bit blend type by bit
// replication (10 bits: (v << 6) | (v >> 4)).
inline uint32_t bitsToUnorm16(uint32_t v, int bits) {
  uint32_t out = 0;
  for (int shift = 16 - bits; shift > -bits; shift -= bits) out |= shift >= 0 ? v << shift : v >> -shift;
  return out & 0xffffu;
}

// A float as a half float the way llvmpipe stores its float blend results
// into R16G16B16A16_FLOAT (probed: 1024 random pixels drawn, blended and
// cleared): rounded toward zero, denormals too, and magnitudes past the
// largest half (65504) saturate to it (120000 stores 65504) rather than
// becoming infinite. NaN stays NaN.
uint16_t floatToHalf(float v);
// Exact.
float halfToFloat(uint16_t h);

// Float [0,1] to an n-bit unsigned value as llvmpipe does it: a single-precision
// multiply, then round to nearest even (REFERENCE.md, "Colour").
uint8_t floatToUnorm8(float v);
uint32_t depthToUnorm(double z, int bits);

}  // namespace glfixed
