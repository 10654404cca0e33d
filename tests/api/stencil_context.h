// The OSMesa context the stencil API tests draw in (stencil_test.cpp,
// stencil_pixels_test.cpp): RGBA with the depth and stencil bits asked for,
// an orthographic projection of one unit a pixel.
#pragma once

#include <vector>

#include "gl_test_fixture.h"

namespace glfx_test {

// A context with `depth` and `stencil` bits on a kWidth x kHeight buffer,
// one unit a pixel.
class StencilContext {
 public:
  StencilContext(int depth, int stencil) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, depth, stencil, 0, NULL);
    buffer_.assign(kWidth * kHeight * 4, 0);
    ok_ = ctx_ && OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kWidth, kHeight) == GL_TRUE;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }
  ~StencilContext() {
    if (!ctx_) return;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  bool ok() const { return ok_; }
  OSMesaContext get() const { return ctx_; }
  const unsigned char* pixel(int x, int y) {
    glFinish();
    return &buffer_[4 * (y * kWidth + x)];
  }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
  bool ok_ = false;
};

// The stencil value at (x, y) read back in every index type glReadPixels
// takes (with the current pixel transfer).
struct StencilInEveryType {
  GLubyte ub = 0;
  GLbyte b = 0;
  GLushort us = 0;
  GLshort s = 0;
  GLuint ui = 0;
  GLint i = 0;
  GLfloat f = 0;
};
inline StencilInEveryType ReadStencilInEveryType(int x, int y) {
  StencilInEveryType v;
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v.ub);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_BYTE, &v.b);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, &v.us);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_SHORT, &v.s);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, &v.ui);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_INT, &v.i);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &v.f);
  return v;
}

}  // namespace glfx_test
