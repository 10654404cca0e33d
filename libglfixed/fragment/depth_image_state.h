// glDrawPixels(GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_DEPTH_STENCIL) and
// glCopyPixels(GL_DEPTH, GL_STENCIL, GL_DEPTH_STENCIL) (GL 2.1 §3.6.4,
// §4.3.3): Mesa's state tracker draws the image as a quad whose fragment
// shader writes the depth and/or the stencil value it samples from the image
// (st_cb_drawpixels.c, NEAREST, clamp to edge; the stencil through llvmpipe's
// stencil export).
#pragma once

#include <cstdint>

namespace glfixed::fragment {

struct DepthImageState {
  // The depth each texel gives the fragment, as the shader reads it (in
  // [0, 1]); row 0 is t = 0. Null: the fragment's own interpolated depth.
  const float* depth = nullptr;
  // The stencil value each texel gives the fragment (the same rows); it
  // replaces the stencil reference of the GL_REPLACE operation. Null: the
  // reference of the stencil state.
  const uint8_t* stencil = nullptr;
  int width = 0, height = 0;
};

}  // namespace glfixed::fragment
