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
  // More come with the internal formats (texture/texel_format.cpp lists them).
  Count
};

struct TexelFormatInfo {
  int bytesPerTexel;
  // Every channel is an unsigned normalized value of at most 8 bits:
  // llvmpipe's sampler may filter it in 8-bit fixed point (sampler.cpp).
  bool fitsUnorm8;
  GLenum baseFormat;  // GL_RGBA, GL_RGB, GL_LUMINANCE, ... (table 3.15)
};

const TexelFormatInfo& texelFormatInfo(TexelFormat format);

// One texel as 8-bit RGBA (only for fitsUnorm8 formats), the base format's
// mapping applied.
void decodeTexelUnorm8(TexelFormat format, const uint8_t* texel, uint8_t rgba[4]);
// One texel as float RGBA, converted as llvmpipe converts it for sampling
// (unorm n bits: unormToFloat), the base format's mapping applied.
void decodeTexelFloat(TexelFormat format, const uint8_t* texel, float rgba[4]);

// An n-bit unsigned normalized value (n <= 24) as a float, the way llvmpipe's
// sampler converts it (gallivm lp_build_unsigned_norm_to_float): the integer
// as a float times the float nearest to 1 / (2^n - 1), that scale computed in
// double. One rounding, after the product.
inline float unormToFloat(uint32_t value, int bits) {
  return static_cast<float>(value) * static_cast<float>(1.0 / static_cast<double>((1u << bits) - 1u));
}

}  // namespace glfixed::texture
