// The pixel maps of glPixelMap (GL 2.1 §3.6.3, table 6.27): in no attribute
// group (Mesa's glPushAttrib(GL_PIXEL_MODE_BIT) keeps them too). Each starts
// with one entry, 0. Colour maps hold [0, 1], I_TO_I any value, S_TO_S
// integers (measured on Mesa: reference/MESA_FACTS.md "Pixel maps").
#pragma once

#include <GL/gl.h>

#include <array>
#include <cmath>

namespace glfixed {

inline constexpr int kMaxPixelMapTable = 256;  // GL_MAX_PIXEL_MAP_TABLE, Mesa's

struct PixelMap {
  int size = 1;
  std::array<float, kMaxPixelMapTable> values{};
  // Index lookup (§3.6.5): the index masked by size - 1 (a power of two).
  float atIndex(long long index) const { return values[static_cast<size_t>(index & (size - 1))]; }
  // Colour lookup as glReadPixels and glTexImage do it (Mesa's
  // _mesa_map_rgba): c clamped to [0, 1], entry round(c * (size - 1)).
  float atColor(float c) const {
    c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return values[static_cast<size_t>(std::lround(c * static_cast<float>(size - 1)))];
  }
};

struct PixelMaps {
  // GL_PIXEL_MAP_I_TO_I .. GL_PIXEL_MAP_A_TO_A, in enum order.
  std::array<PixelMap, 10> map;
  static bool isMap(GLenum m) { return m >= GL_PIXEL_MAP_I_TO_I && m <= GL_PIXEL_MAP_A_TO_A; }
  PixelMap& operator[](GLenum m) { return map[m - GL_PIXEL_MAP_I_TO_I]; }
  const PixelMap& operator[](GLenum m) const { return map[m - GL_PIXEL_MAP_I_TO_I]; }
  // A stencil index through GL_PIXEL_MAP_S_TO_S (§4.3.1/§3.6.5, applied when
  // GL_MAP_STENCIL is true), after the index shift and offset.
  long long mapStencil(long long index) const {
    return static_cast<long long>((*this)[GL_PIXEL_MAP_S_TO_S].atIndex(index));
  }
};

}  // namespace glfixed
