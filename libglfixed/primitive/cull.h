// Face orientation and culling (GL 2.1 §2.14.1, §3.5.1), as llvmpipe decides
// them: from the sign of the snapped, fixed-point area (raster::snapTriangle),
// per triangle after clipping. A zero area is never drawn.
//
// When Mesa runs its draw pipeline (a batch with a vertex outside the view
// volume, see assemble.h) and culling is on, the draw module culls first with
// a float determinant of the unsnapped window positions
// (draw_pipe_cull.c); a zero determinant counts as back-facing there.
#pragma once

#include <GL/gl.h>

namespace glfixed::primitive {

struct FaceRule {
  bool cullFace = false;
  GLenum cullFaceMode = GL_BACK;
  GLenum frontFace = GL_CCW;

  // areaSign: +1 counter-clockwise in GL window space, -1 clockwise.
  bool isFront(int areaSign) const { return (areaSign > 0) == (frontFace == GL_CCW); }
  bool culls(bool front) const {
    if (!cullFace) return false;
    if (cullFaceMode == GL_FRONT_AND_BACK) return true;
    return front ? cullFaceMode == GL_FRONT : cullFaceMode == GL_BACK;
  }
};

// draw_pipe_cull.c: det = (v0 - v2) x (v1 - v2) of window positions
// (llvmpipe's x, y: y down, or up in a framebuffer object). Returns true when the draw module drops the
// triangle.
bool drawModuleCulls(const FaceRule& rule, const float* w0, const float* w1, const float* w2);

}  // namespace glfixed::primitive
