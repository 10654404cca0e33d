// The stored texel formats (texel_format.h): their layout, component sizes
// and decoding. Which GL internal format lands in which of them is
// texture/internal_format.cpp.
#include "texture/texel_format.h"

#include <cmath>
#include <cstring>

namespace glfixed::texture {

namespace {

// bytesPerTexel, fitsUnorm8, baseFormat, channels, bytesPerChannel, bits.
const TexelFormatInfo kInfo[] = {
    {4, true, GL_RGBA, 4, 1, {8, 8, 8, 8}},                // RGBA8
    {4, true, GL_RGB, 4, 1, {8, 8, 8, 0}},                 // RGBX8
    {1, true, GL_LUMINANCE, 1, 1, {8, 0, 0, 0}},           // L8
    {1, true, GL_ALPHA, 1, 1, {8, 0, 0, 0}},               // A8
    {1, true, GL_INTENSITY, 1, 1, {8, 0, 0, 0}},           // I8
    {2, true, GL_LUMINANCE_ALPHA, 2, 1, {8, 8, 0, 0}},     // L8A8
    {2, true, GL_LUMINANCE_ALPHA, 2, 1, {4, 4, 0, 0}},     // L4A4
    {4, true, GL_RGBA, 4, 1, {4, 4, 4, 4}},                // RGBA4
    {4, true, GL_RGB, 4, 1, {4, 4, 4, 0}},                 // RGBX4
    {4, true, GL_RGB, 4, 1, {5, 5, 5, 0}},                 // RGB5X1
    {4, true, GL_RGBA, 4, 1, {5, 5, 5, 1}},                // RGB5A1
    {4, true, GL_RGB, 4, 1, {5, 6, 5, 0}},                 // R5G6B5
    {4, true, GL_RGB, 4, 1, {3, 3, 2, 0}},                 // R3G3B2
    {8, false, GL_RGB, 4, 2, {10, 10, 10, 0}},             // RGB10X2
    {8, false, GL_RGBA, 4, 2, {10, 10, 10, 2}},            // RGB10A2
    {8, false, GL_RGBA, 4, 2, {16, 16, 16, 16}},           // RGBA16
    {8, false, GL_RGB, 4, 2, {16, 16, 16, 0}},             // RGBX16
    {2, false, GL_LUMINANCE, 1, 2, {16, 0, 0, 0}},         // L16
    {2, false, GL_ALPHA, 1, 2, {16, 0, 0, 0}},             // A16
    {2, false, GL_INTENSITY, 1, 2, {16, 0, 0, 0}},         // I16
    {4, false, GL_LUMINANCE_ALPHA, 2, 2, {16, 16, 0, 0}},  // L16A16
    {2, false, GL_DEPTH_COMPONENT, 1, 2, {16, 0, 0, 0}},   // Z16
    {4, false, GL_DEPTH_COMPONENT, 1, 4, {24, 0, 0, 0}},   // Z24
    {4, false, GL_DEPTH_COMPONENT, 1, 4, {32, 0, 0, 0}},   // Z32
    {4, false, GL_DEPTH_COMPONENT, 1, 4, {24, 0, 0, 0}},   // Z24S8 (the stencil byte is not a channel)
    {4, true, GL_RGBA, 4, 1, {8, 8, 8, 8}, true},          // SRGBA8
    {4, true, GL_RGB, 4, 1, {8, 8, 8, 0}, true},           // SRGBX8
    {1, true, GL_LUMINANCE, 1, 1, {8, 0, 0, 0}, true},     // SL8
    {2, true, GL_LUMINANCE_ALPHA, 2, 1, {8, 8, 0, 0}, true},  // SL8A8
    {16, false, GL_RGBA, 4, 4, {32, 32, 32, 32}, false, true},     // RGBA32F
    {16, false, GL_RGB, 4, 4, {32, 32, 32, 0}, false, true},       // RGBX32F
    {4, false, GL_ALPHA, 1, 4, {32, 0, 0, 0}, false, true},        // A32F
    {4, false, GL_INTENSITY, 1, 4, {32, 0, 0, 0}, false, true},    // I32F
    {4, false, GL_LUMINANCE, 1, 4, {32, 0, 0, 0}, false, true},    // L32F
    {8, false, GL_LUMINANCE_ALPHA, 2, 4, {32, 32, 0, 0}, false, true},  // L32A32F
    {8, false, GL_RGBA, 4, 2, {16, 16, 16, 16}, false, true},      // RGBA16F
    {8, false, GL_RGB, 4, 2, {16, 16, 16, 0}, false, true},        // RGBX16F
    {2, false, GL_ALPHA, 1, 2, {16, 0, 0, 0}, false, true},        // A16F
    {2, false, GL_INTENSITY, 1, 2, {16, 0, 0, 0}, false, true},    // I16F
    {2, false, GL_LUMINANCE, 1, 2, {16, 0, 0, 0}, false, true},    // L16F
    {4, false, GL_LUMINANCE_ALPHA, 2, 2, {16, 16, 0, 0}, false, true},  // L16A16F
};
static_assert(sizeof(kInfo) / sizeof(kInfo[0]) == static_cast<size_t>(TexelFormat::Count),
              "one row per TexelFormat");

// n bits (n <= 8) widened to 8 by repeating the bits: exact for n = 1, 2,
// 4, 8; for 3, 5 and 6 it can be one below round(v * 255 / (2^n - 1))
// (5 bits: 3 -> 24, not 25). Not probed against llvmpipe's sampler, which
// owns how it reads these formats (texture/sampler.cpp).
uint8_t widenTo8(uint32_t v, int bits) {
  if (bits >= 8) return static_cast<uint8_t>(v);
  uint32_t out = 0;
  for (int shift = 8 - bits; shift > -bits; shift -= bits) out |= shift >= 0 ? v << shift : v >> -shift;
  return static_cast<uint8_t>(out);
}

// An sRGB-encoded 8-bit value decoded to linear the way llvmpipe does
// (gallivm lp_build_srgb_to_linear): not the exact formula but v / (12.6 *
// 255) up to 15 and above it a cubic in v / 255 (0.3012 x^3 + 0.6935 x^2 +
// 0.0030 x + 0.0023, the 1/255 folded into the coefficients), in float.
float srgbToLinear(uint32_t v) {
  const float x = static_cast<float>(v);
  if (x <= 15.0f) return x * (1.0f / (12.6f * 255.0f));
  const float c0 = 0.0023f, c1 = float(double(0.0030f / 255.0f)), c2 = float(double(0.6935f / (255.0f * 255.0f))),
              c3 = float(double(0.3012f / (255.0f * 255.0f * 255.0f)));
  return ((c3 * x + c2) * x + c1) * x + c0;
}

// Whether stored channel i of an sRGB format is a colour (not alpha).
bool isSrgbColour(const TexelFormatInfo& info, int i) {
  return info.srgb && !((info.baseFormat == GL_RGBA && i == 3) || (info.baseFormat == GL_LUMINANCE_ALPHA && i == 1));
}

// The base format's mapping of stored channels c[0..] to RGBA (table 3.21).
template <typename T>
void expand(GLenum base, const T c[4], T one, T out[4]) {
  switch (base) {
    case GL_RGBA: out[0] = c[0], out[1] = c[1], out[2] = c[2], out[3] = c[3]; break;
    case GL_RGB: out[0] = c[0], out[1] = c[1], out[2] = c[2], out[3] = one; break;
    case GL_ALPHA: out[0] = out[1] = out[2] = T(0), out[3] = c[0]; break;
    case GL_LUMINANCE:
    case GL_DEPTH_COMPONENT: out[0] = out[1] = out[2] = c[0], out[3] = one; break;
    case GL_LUMINANCE_ALPHA: out[0] = out[1] = out[2] = c[0], out[3] = c[1]; break;
    case GL_INTENSITY: out[0] = out[1] = out[2] = out[3] = c[0]; break;
    default: out[0] = out[1] = out[2] = T(0), out[3] = one; break;
  }
}

}  // namespace

const TexelFormatInfo& texelFormatInfo(TexelFormat format) { return kInfo[static_cast<size_t>(format)]; }

uint32_t storedChannel(TexelFormat format, const uint8_t* texel, int c) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  const uint8_t* p = texel + c * info.bytesPerChannel;
  switch (info.bytesPerChannel) {
    case 1: return p[0];
    case 2: return uint32_t(p[0]) | uint32_t(p[1]) << 8;
    default:
      if (format == TexelFormat::Z24S8) return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16;
      return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  }
}

ComponentSizes componentSizes(TexelFormat format) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  ComponentSizes s;
  switch (info.baseFormat) {
    case GL_RGBA: s.alpha = info.bits[3]; [[fallthrough]];
    case GL_RGB: s.red = info.bits[0], s.green = info.bits[1], s.blue = info.bits[2]; break;
    case GL_ALPHA: s.alpha = info.bits[0]; break;
    case GL_LUMINANCE: s.luminance = info.bits[0]; break;
    case GL_LUMINANCE_ALPHA: s.luminance = info.bits[0], s.alpha = info.bits[1]; break;
    case GL_INTENSITY: s.intensity = info.bits[0]; break;
    case GL_DEPTH_COMPONENT: s.depth = info.bits[0]; break;
  }
  if (format == TexelFormat::Z24S8) s.stencil = 8;
  return s;
}

void decodeTexelUnorm8(TexelFormat format, const uint8_t* texel, uint8_t rgba[4]) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  uint8_t c[4] = {0, 0, 0, 0};
  for (int i = 0; i < info.channels; ++i)
    if (isSrgbColour(info, i))
      c[i] = static_cast<uint8_t>(std::nearbyint(srgbToLinear(storedChannel(format, texel, i)) * 255.0f));
    else if (info.bits[i])
      c[i] = widenTo8(storedChannel(format, texel, i), info.bits[i]);
  expand<uint8_t>(info.baseFormat, c, 255, rgba);
}

uint16_t floatToHalf(float f) {
  uint32_t x;
  std::memcpy(&x, &f, 4);
  const uint16_t sign = static_cast<uint16_t>((x >> 16) & 0x8000u);
  const uint32_t absBits = x & 0x7fffffffu;
  if (absBits > 0x7f800000u) return static_cast<uint16_t>(sign | 0x7e00u | ((absBits >> 13) & 0x3ffu));  // NaN
  if (absBits == 0x7f800000u) return static_cast<uint16_t>(sign | 0x7c00u);                                // inf
  const int exp = static_cast<int>(absBits >> 23) - 127;
  if (exp > 15) return static_cast<uint16_t>(sign | 0x7bffu);  // past 65504: the largest half
  if (exp >= -14) return static_cast<uint16_t>(sign | uint32_t(exp + 15) << 10 | (absBits & 0x7fffffu) >> 13);
  if (exp < -25) return sign;
  // A denormal half: the mantissa with its implicit one, shifted, truncated.
  const uint32_t mant = (absBits & 0x7fffffu) | 0x800000u;
  return static_cast<uint16_t>(sign | mant >> (-exp - 1));
}

uint16_t floatToHalfNearest(float f) {
  uint32_t x;
  std::memcpy(&x, &f, 4);
  const uint16_t sign = static_cast<uint16_t>((x >> 16) & 0x8000u);
  const uint32_t absBits = x & 0x7fffffffu;
  if (absBits > 0x7f800000u) return static_cast<uint16_t>(sign | 0x7e00u | ((absBits >> 13) & 0x3ffu));  // NaN
  if (absBits >= 0x477ff000u) return static_cast<uint16_t>(sign | 0x7c00u);  // 65520 and up: infinity
  if (absBits >= 0x38800000u) {  // a normal half (2^-14 and up)
    uint32_t m = absBits - (112u << 23);
    m += 0xfffu + ((m >> 13) & 1u);
    return static_cast<uint16_t>(sign | m >> 13);
  }
  // A denormal half, in units of 2^-24: the scaling is exact, the rounding to even.
  const float units = std::nearbyint(std::fabs(f) * 16777216.0f);
  return static_cast<uint16_t>(sign | static_cast<uint32_t>(units));
}

float halfToFloat(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000u) << 16;
  const uint32_t exp = (h >> 10) & 0x1fu, mant = h & 0x3ffu;
  uint32_t x;
  if (exp == 0x1f) {
    x = sign | 0x7f800000u | mant << 13;
  } else if (exp == 0) {
    const float v = static_cast<float>(mant) * (1.0f / 16777216.0f);  // mant * 2^-24, exact
    return sign ? -v : v;
  } else {
    x = sign | (exp + 112) << 23 | mant << 13;
  }
  float f;
  std::memcpy(&f, &x, 4);
  return f;
}

float storedFloat(TexelFormat format, const uint8_t* texel, int c) {
  const uint32_t v = storedChannel(format, texel, c);
  if (texelFormatInfo(format).bits[c] == 16) return halfToFloat(static_cast<uint16_t>(v));
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}

void decodeTexelFloat(TexelFormat format, const uint8_t* texel, float rgba[4]) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  float c[4] = {0, 0, 0, 0};
  for (int i = 0; i < info.channels; ++i) {
    if (!info.bits[i]) continue;
    if (info.floating) {
      c[i] = storedFloat(format, texel, i);
      continue;
    }
    const uint32_t v = storedChannel(format, texel, i);
    if (isSrgbColour(info, i)) {
      c[i] = srgbToLinear(v);
      continue;
    }
    c[i] = info.bits[i] == 32 ? unorm32ToFloat(v) : unormToFloat(v, info.bits[i]);
  }
  expand<float>(info.baseFormat, c, 1.0f, rgba);
}

}  // namespace glfixed::texture
