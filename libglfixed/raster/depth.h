// Fragment depth: float window z to the depth buffer's unsigned integers and
// the depth test, as llvmpipe's generated fragment code does it
// (gallivm lp_bld_conv.c, lp_build_clamped_float_to_unsigned_norm).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <cstring>

#include "raster/fixed_point.h"

namespace glfixed::raster {

// 24 bits: z * 16777215 in single precision, then round to nearest even.
inline uint32_t depthToUnorm24(float z) {
  float scaled = z * 16777215.0f;
  return static_cast<uint32_t>(roundToInt32(scaled));
}

// 16 bits: llvmpipe's "magic number" conversion, z * (65535/65536) + 128 in
// single precision; the low 16 bits of the sum's mantissa are the result. The
// float add rounds to 1/65536, to nearest even.
inline uint32_t depthToUnorm16(float z) {
  float scaled = z * (65535.0f / 65536.0f);
  float biased = scaled + 128.0f;
  uint32_t bits;
  std::memcpy(&bits, &biased, sizeof bits);
  return bits & 0xffffu;
}

// z clamped to [0, 1] first (llvmpipe clamps fragment depth for unorm
// buffers), with x86 minps/maxps semantics: min(z, 1) then max(., 0), so NaN
// becomes 1.
inline uint32_t depthToUnorm(float z, int bits) {
  z = z < 1.0f ? z : 1.0f;
  z = z > 0.0f ? z : 0.0f;
  return bits == 16 ? depthToUnorm16(z) : depthToUnorm24(z);
}

inline bool depthPasses(GLenum func, uint32_t fragment, uint32_t stored) {
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return fragment < stored;
    case GL_EQUAL: return fragment == stored;
    case GL_LEQUAL: return fragment <= stored;
    case GL_GREATER: return fragment > stored;
    case GL_NOTEQUAL: return fragment != stored;
    case GL_GEQUAL: return fragment >= stored;
    default: return true;  // GL_ALWAYS
  }
}

}  // namespace glfixed::raster
