// The viewport transform (GL 2.1 §2.11.1) computed the way Mesa 22.3 computes
// it for llvmpipe, in single precision:
//   - the state tracker builds scale and translate (main/viewport.c,
//     _mesa_get_viewport_xform) and, because an OSMesa buffer is a window
//     system buffer that gallium renders upside down, flips y:
//     scale_y = -h/2, translate_y = fbHeight - (y + h/2) (st_atom_viewport.c);
//   - the vertex shader's epilogue maps every vertex with
//     fma(x_clip * (1/w), scale, translate) (draw_llvm.c, generate_viewport);
//   - a vertex made by the clipper is mapped in plain C instead,
//     x_clip * (1/w) * scale + translate, unfused (draw_pipe_clip.c, interp).
// Window y is therefore measured down from the top of the buffer (raster.h).
// A framebuffer object is not flipped (Y_0_BOTTOM): scale_y = h/2,
// translate_y = y + h/2, window y measured up as GL's.
#pragma once

#include <glm/glm.hpp>

namespace glfixed::primitive {

struct ViewportTransform {
  float scale[3] = {1, 1, 1};
  float translate[3] = {0, 0, 0};

  // x, y, width, height as glViewport has them; near/far as glDepthRange has
  // them (Mesa stores both as floats, clamped to [0, 1]).
  static ViewportTransform make(int x, int y, int width, int height, double depthNear, double depthFar,
                                int framebufferHeight, bool flipY = true);

  // out = (x, y, z, 1/w) in window space, for a vertex from the vertex stage.
  void windowFromClip(const glm::vec4& clip, float out[4]) const;
  // The same for a vertex the clipper created.
  void windowFromClipUnfused(const glm::vec4& clip, float out[4]) const;
};

}  // namespace glfixed::primitive
