// How Mesa's immediate mode (vbo_exec.c) groups glBegin/glEnd primitives into
// draws. It matters here because llvmpipe decides per draw whether to run
// the draw pipeline (any vertex outside the view volume), and that decision
// changes how every quad of the draw is split (assemble.h) and whether the
// draw module's float cull runs (cull.h).
//
// At glEnd, Mesa first turns a 3-vertex GL_TRIANGLE_STRIP or GL_TRIANGLE_FAN
// into GL_TRIANGLES (vbo_try_prim_conversion), then appends the primitive to
// the previous one when both have the same mode and the previous one is
// complete (vbo_merge_draws): GL_POINTS; GL_LINES, GL_TRIANGLES, GL_QUADS
// with a whole number of primitives. Nothing merges across a state change
// (every state change flushes the buffered vertices first), a full vertex
// buffer, or a growth of the vertex format (immediate_mode.cpp), which can
// also cut one glBegin/glEnd into two draws.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::primitive {

inline GLenum mesaConvertedMode(GLenum mode, uint32_t count) {
  if ((mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN) && count == 3) return GL_TRIANGLES;
  if (mode == GL_LINE_STRIP && count == 2) return GL_LINES;
  return mode;
}

// mode0/count0: the previous primitive after conversion; mode1: this one's
// mode after conversion.
inline bool mesaMergesPrimitives(GLenum mode0, uint32_t count0, GLenum mode1) {
  if (mode0 != mode1) return false;
  switch (mode0) {
    case GL_POINTS: return true;
    case GL_LINES: return count0 % 2 == 0;
    case GL_TRIANGLES: return count0 % 3 == 0;
    case GL_QUADS: return count0 % 4 == 0;
    default: return false;
  }
}

}  // namespace glfixed::primitive
