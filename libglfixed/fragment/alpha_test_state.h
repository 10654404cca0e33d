// The alpha test's per-draw state (GL 2.1 §4.1.4), as the fragment stage
// reads it (ShadeTarget::alphaTest; the code is fragment/alpha_test.inc).
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::fragment {

struct AlphaTestState {
  // GL_ALWAYS also stands for a disabled test: nothing is discarded.
  GLenum func = GL_ALWAYS;
  // The reference, clamped to [0, 1] by glAlphaFunc, as llvmpipe compares
  // it on an 8-bit colour buffer: converted to a byte like the fragment's
  // alpha (lp_build_alpha_test quantizes both to the buffer's unorm8).
  int32_t ref = 0;
  // The reference itself, for 16-bit and float buffers, where llvmpipe
  // compares floats (fragment/wide_color.inc).
  float refFloat = 0.0f;
  bool active() const { return func != GL_ALWAYS; }
};

// The byte llvmpipe compares for a reference in [0, 1]: rint(ref * 255).
AlphaTestState makeAlphaTest(bool enabled, GLenum func, float ref);

}  // namespace glfixed::fragment
