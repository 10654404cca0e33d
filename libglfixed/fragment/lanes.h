// The unit of work of the fragment stage: a block of eight fragments, two
// 2x2 quads side by side, as llvmpipe's fragment shader runs them (eight
// lanes of AVX2; its texture sampler takes level-of-detail differences
// within each quad).
//
// Lane order, in llvmpipe's window space (raster/raster.h): lane i is
// quad i / 4; inside a quad, i % 4 is 0 top-left, 1 top-right, 2 bottom-left,
// 3 bottom-right. A block whose top-left pixel is (x, y), x a multiple of 4
// and y even, holds pixel (x + 2 * (i / 4) + (i & 1), y + ((i >> 1) & 1)) in
// lane i. Every lane holds a value, inside the primitive or not (the pixels
// outside are llvmpipe's helper pixels: they feed the differences); the
// block's mask says which ones are written.
#pragma once

#include <cstdint>

namespace glfixed::fragment {

constexpr int kBlockLanes = 8;

inline int laneX(int lane) { return 2 * (lane >> 2) + (lane & 1); }
inline int laneY(int lane) { return (lane >> 1) & 1; }

struct Lanes {
  alignas(32) float v[kBlockLanes];
  float& operator[](int i) { return v[i]; }
  float operator[](int i) const { return v[i]; }
};

// An RGBA colour per lane, as floats (channel k: c[k]).
struct ColorLanes {
  Lanes c[4];
};

}  // namespace glfixed::fragment
