// The triangle rasterizer: window-space triangles in, fragments out, with
// llvmpipe's coverage rules, depth test and perspective-correct colours.
#pragma once

#include <GL/gl.h>

#include "framebuffer/framebuffer.h"

namespace glfixed::raster {

// Primary RGBA, then secondary RGBA (separate specular colour).
constexpr int kMaxVaryings = 8;

struct WindowVertex {
  float x = 0, y = 0, z = 0;  // window coordinates, z in [0,1] after glDepthRange
  float oneOverW = 1;         // 1 / w_clip, for perspective-correct interpolation
  float varying[kMaxVaryings] = {};
};

struct RasterState {
  bool depthTest = false;
  GLenum depthFunc = GL_LESS;
  bool depthWrite = true;
  bool colorWrite[4] = {true, true, true, true};
  int varyingCount = 4;  // 4: primary colour; 8: primary + secondary, summed per fragment
  // Only pixels in [scissorX0, scissorX1) x [scissorY0, scissorY1) are written:
  // the viewport intersected with the buffer.
  int scissorX0 = 0, scissorY0 = 0, scissorX1 = 0, scissorY1 = 0;
};

// `flatVaryings` non-null: GL_FLAT, every fragment takes these values.
void drawTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex& v0, const WindowVertex& v1,
                  const WindowVertex& v2, const float* flatVaryings);

}  // namespace glfixed::raster
