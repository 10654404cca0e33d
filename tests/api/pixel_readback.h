// Helpers of the pixel-rectangle API tests (pixel_rect_test.cpp,
// draw_pixels_test.cpp): a one-unit-a-pixel projection, a black clear, and
// the whole buffer read back as RGBA bytes.
#pragma once

#include <array>
#include <vector>

#include "gl_test_fixture.h"

namespace glfx_test {

inline void PixelProjection() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

inline std::vector<unsigned char> ReadAll() {
  std::vector<unsigned char> v(kWidth * kHeight * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, v.data());
  return v;
}

inline std::array<int, 4> At(const std::vector<unsigned char>& p, int x, int y) {
  const unsigned char* q = p.data() + (static_cast<size_t>(y) * kWidth + x) * 4;
  return {q[0], q[1], q[2], q[3]};
}

inline void ClearBlack() {
  glClearColor(0, 0, 0, 0);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// How many pixels of a ReadAll() are exactly c.
inline int CountColored(const std::vector<unsigned char>& p, std::array<int, 4> c) {
  int n = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) n += At(p, x, y) == c;
  return n;
}

}  // namespace glfx_test
