// Primitive assembly, clipping, culling and the viewport transform: turns the
// shaded vertices of one batch into window-space triangles for the rasterizer.
#pragma once

#include <GL/gl.h>

#include "framebuffer/framebuffer.h"
#include "pipeline/vertex_batch.h"
#include "raster/raster.h"

namespace glfixed::primitive {

struct PrimitiveState {
  GLenum mode = GL_TRIANGLES;
  bool flat = false;                  // GL_FLAT: the provoking vertex's colour
  bool firstVertexConvention = false; // glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)
  bool cullFace = false;
  GLenum cullFaceMode = GL_BACK;
  GLenum frontFace = GL_CCW;
  // Viewport (GL 2.1 §2.11.1).
  int viewportX = 0, viewportY = 0, viewportWidth = 0, viewportHeight = 0;
  double depthNear = 0, depthFar = 1;
  // How the batch was submitted. Mesa treats the ways differently: an indexed
  // draw splits quads otherwise (assemble.h), and glBegin/glEnd and display
  // lists turn a 3-vertex strip or fan into GL_TRIANGLES (vbo_exec.c,
  // vbo_try_prim_conversion), which moves a fan's first-vertex provoking
  // vertex.
  enum class Submission { kBeginEnd, kDrawArrays, kDrawElements, kDisplayList };
  Submission submission = Submission::kBeginEnd;
  raster::RasterState raster;  // depth test, scissor to the viewport, ...
};

// Draws every primitive of `vertices` (in the order GL_<mode> defines).
void drawPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, Framebuffer& fb);

}  // namespace glfixed::primitive
