// How a texture image is stored: the format llvmpipe stores a GL internal
// format in (Mesa's state tracker picks the first pipe format the driver
// supports from its list for that internal format, st_format.c), which
// decides the precision sampling sees. One texel of each format is read back
// as RGBA with the GL base format's mapping applied (GL 2.1 table 3.21:
// luminance is (L, L, L, 1), alpha (0, 0, 0, A), intensity (I, I, I, I), ...).
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::texture {

enum class TexelFormat : uint8_t {
  RGBA8,  // bytes r, g, b, a
  RGBX8,  // bytes r, g, b, unused (alpha reads 1)
  L8,
  A8,
  I8,
  L8A8,
  // The rest of the formats llvmpipe stores GL 2.1's internal formats in
  // (texture/texel_format.cpp; reference/MESA_FACTS.md "Textures: storage").
  // Every channel is kept in its own 1, 2 or 4 bytes (little-endian), holding
  // the n-bit value the pipe format holds: the precision is llvmpipe's, the
  // bit packing is not.
  L4A4,     // GL_LUMINANCE4_ALPHA4
  RGBA4,    // GL_RGBA2, GL_RGBA4, GL_RGBA + 4_4_4_4
  RGBX4,    // GL_RGB4
  RGB5X1,   // GL_RGB5
  RGB5A1,   // GL_RGB5_A1
  R5G6B5,   // GL_RGB + 5_6_5
  R3G3B2,   // GL_R3_G3_B2
  RGB10X2,  // GL_RGB10
  RGB10A2,  // GL_RGB10_A2
  RGBA16,   // GL_RGBA12, GL_RGBA16, GL_RGBA + GL_UNSIGNED_SHORT
  RGBX16,   // GL_RGB12, GL_RGB16
  L16,
  A16,
  I16,
  L16A16,
  Z16,  // depth, one channel: 2 bytes
  Z24,  // 4 bytes, the value in the low 24 bits
  Z32,  // 4 bytes, 32-bit unsigned normalized
  // GL_DEPTH_STENCIL, GL_DEPTH24_STENCIL8 (EXT_packed_depth_stencil): Z24's
  // word with the stencil index in the top byte, the layout of the
  // framebuffer's Z24_UNORM_S8_UINT (framebuffer/framebuffer.h), so an
  // attached texture is drawn into as a depth-stencil buffer. Its one channel
  // is the depth: sampled as Z24 is (llvmpipe samples Z24_UNORM_S8_UINT's depth).
  Z24S8,
  // sRGB-encoded 8-bit colour channels (alpha linear), decoded to linear
  // when sampled (EXT_texture_sRGB; Mesa decodes them: MESA_FACTS.md
  // "Textures: sampling").
  SRGBA8,  // GL_SRGB_ALPHA, GL_SRGB8_ALPHA8
  SRGBX8,  // GL_SRGB, GL_SRGB8
  SL8,     // GL_SLUMINANCE, GL_SLUMINANCE8
  SL8A8,   // GL_SLUMINANCE_ALPHA, GL_SLUMINANCE8_ALPHA8
  // ARB_texture_float: channels held as IEEE floats of 32 or 16 bits
  // (llvmpipe's R32G32B32A32_FLOAT ..., R16G16B16A16_FLOAT ...), unclamped.
  RGBA32F,
  RGBX32F,  // GL_RGB32F_ARB (alpha reads 1)
  A32F,
  I32F,
  L32F,
  L32A32F,
  RGBA16F,
  RGBX16F,  // GL_RGB16F_ARB
  A16F,
  I16F,
  L16F,
  L16A16F,
  Count
};

struct TexelFormatInfo {
  int bytesPerTexel;
  // Every channel is an unsigned normalized value of at most 8 bits:
  // llvmpipe's sampler may filter it in 8-bit fixed point (sampler.cpp).
  bool fitsUnorm8;
  GLenum baseFormat;  // GL_RGBA, GL_RGB, GL_LUMINANCE, ... (table 3.15)
  int channels;        // stored channels (an RGB format stores an unused fourth)
  int bytesPerChannel; // 1, 2 or 4
  uint8_t bits[4];     // the bits of each stored channel (0: unused)
  bool srgb = false;   // colour channels (not alpha) are sRGB-encoded
  bool floating = false;  // channels are floats of `bits` bits (ARB_texture_float)
};

// The component sizes glGetTexLevelParameter reports (GL_TEXTURE_RED_SIZE ...).
struct ComponentSizes {
  int red = 0, green = 0, blue = 0, alpha = 0, luminance = 0, intensity = 0, depth = 0, stencil = 0;
};
ComponentSizes componentSizes(TexelFormat format);

// The stored value of channel `c` of one texel (Z24S8's depth without the
// stencil byte).
uint32_t storedChannel(TexelFormat format, const uint8_t* texel, int c);

const TexelFormatInfo& texelFormatInfo(TexelFormat format);

// A depth format (base format GL_DEPTH_COMPONENT: Z16, Z24, Z32, Z24S8).
inline bool isDepthFormat(TexelFormat format) {
  return format == TexelFormat::Z16 || format == TexelFormat::Z24 || format == TexelFormat::Z32 ||
         format == TexelFormat::Z24S8;
}
// The stencil index of a Z24S8 texel.
inline uint8_t texelStencil(const uint8_t* texel) { return texel[3]; }

// One texel as 8-bit RGBA (only for fitsUnorm8 formats), the base format's
// mapping applied.
void decodeTexelUnorm8(TexelFormat format, const uint8_t* texel, uint8_t rgba[4]);
// One texel as float RGBA, converted as llvmpipe converts it for sampling
// (unorm n bits: unormToFloat), the base format's mapping applied.
void decodeTexelFloat(TexelFormat format, const uint8_t* texel, float rgba[4]);

// A float as a half (IEEE binary16) the way Mesa stores it in a 16F texture:
// rounded toward zero, a finite value past the largest half giving 65504
// (measured: 1 + 3/2048 stores 1 + 1/1024, 70000 stores 65504).
uint16_t floatToHalf(float f);
// A float as a half rounded to nearest, ties to even, a value from 65520
// up giving infinity: how Mesa packs GL_HALF_FLOAT_ARB client data
// (glGetTexImage; measured: 1 + 3/2048 gives 1 + 2/1024).
uint16_t floatToHalfNearest(float f);
// A half as a float (exact).
float halfToFloat(uint16_t h);
// Channel `c` of a texel of a floating format, as a float.
float storedFloat(TexelFormat format, const uint8_t* texel, int c);

// An n-bit unsigned normalized value (n <= 24) as a float, the way llvmpipe's
// sampler converts it (gallivm lp_build_unsigned_norm_to_float): the integer
// as a float times the float nearest to 1 / (2^n - 1), that scale computed in
// double. One rounding, after the product.
inline float unormToFloat(uint32_t value, int bits) {
  return static_cast<float>(value) * static_cast<float>(1.0 / static_cast<double>((1u << bits) - 1u));
}

// A 32-bit unsigned normalized value as llvmpipe's sampler converts it
// (lp_build_unsigned_norm_to_float, wider than the mantissa): the top 23
// bits as a fraction of 2^23 (exact), times the float nearest to
// 2^23 / (2^23 - 1). 0xffffffff gives 1.0.
inline float unorm32ToFloat(uint32_t value) {
  return static_cast<float>(value >> 9) * (1.0f / 8388608.0f) * static_cast<float>(8388608.0 / 8388607.0);
}

}  // namespace glfixed::texture
