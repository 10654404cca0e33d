// glDrawPixels(GL_DEPTH_COMPONENT) (GL 2.1 §3.6.4): Mesa's state tracker
// draws the image as a quad whose fragment shader writes the depth it
// samples from the image (st_cb_drawpixels.c, NEAREST, clamp to edge).
#pragma once

namespace glfixed::fragment {

struct DepthImageState {
  // The depth each texel gives the fragment, as the shader reads it (in
  // [0, 1]); row 0 is t = 0. Null: the fragment's own interpolated depth.
  const float* depth = nullptr;
  int width = 0, height = 0;
};

}  // namespace glfixed::fragment
