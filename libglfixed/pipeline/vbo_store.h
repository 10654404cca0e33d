// Mesa's immediate-mode vertex store (vbo_exec_draw.c, vbo_exec_api.c,
// vbo_exec.c), modelled only as far as it decides where Mesa cuts a long
// glBegin/glEnd into draws: llvmpipe decides per draw whether to clip, and
// that changes quad splits and culling (primitive/assemble.h).
//
// Mesa writes vertices into a 512 KiB buffer, each vertex_size floats (the
// position's and every per-vertex attribute's components). After a flush the
// next vertices go on in the same buffer; a new one is started when fewer than
// 1024 bytes would be left. The buffer holds max = (512 KiB - used) / (4 *
// vertex_size) - 1 vertices from the last flush on; the vertex that reaches
// max wraps: what is buffered is drawn and the open primitive goes on in the
// next draw, some of its vertices copied over (vbo_copy_vertices, see
// copiedVertices below). A growing vertex format wraps the same way.
// Measured on Mesa 22.3.6: scene vbo_wrap_quads, and MESA_FACTS.md.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::pipeline {

struct VboStore {
  static constexpr uint32_t kBufferBytes = 512 * 1024;  // Mesa's glBeginEndBufferSize
  static constexpr uint32_t kMaxPrimitives = 64;        // VBO_MAX_PRIM: glEnd flushes at 64
  uint32_t bytesUsed = 0;    // of the current buffer, by the vertices before the last flush
  uint32_t vertexCount = 0;  // vertices written since the last flush
  uint32_t primCount = 0;    // primitives since the last flush, after merging
  GLenum lastMode = 0;       // the last primitive's mode and vertex count, for merging
  uint32_t lastCount = 0;
  // Mesa hands the primitives of a flush to the draw module in runs of one
  // mode (st_draw_gallium_multimode). A run other than the first whose first
  // primitive has no vertex draws nothing at all (measured: glBegin(GL_QUADS)
  // with a quad, an empty glBegin/glEnd(GL_POLYGON), then polygons: the
  // polygons are not drawn; without the quads they are).
  GLenum runMode = 0;
  uint32_t runIndex = 0;       // 0: the flush's first run
  uint32_t runFirstCount = 0;  // the run's first primitive's vertices, merges included
  uint32_t runDraws = 0;       // primitives in the run, after merging
  bool runSuppressed() const { return runIndex > 0 && runFirstCount == 0; }
  // The open GL_LINE_LOOP has wrapped (Mesa's begin marker is 0): its batch
  // starts with the copy of the loop's first vertex. Each later piece is
  // drawn as a line strip without that copy, and glEnd draws the rest as a
  // strip with the first vertex appended (vbo_exec_wrap_buffers, _mesa_End).
  bool openLoopWrapped = false;

  uint32_t maxVertices(uint32_t vertexFloats) const {
    if (vertexFloats == 0) return 0;
    const uint32_t n = (kBufferBytes - bytesUsed) / (vertexFloats * 4);
    return n == 0 ? 0 : n - 1;  // one spare for GL_LINE_LOOP's closing vertex
  }
  // vbo_exec_vtx_flush: the vertices written stay used in the buffer.
  void flushed(uint32_t vertexFloats) {
    bytesUsed += vertexCount * vertexFloats * 4;
    if (kBufferBytes <= bytesUsed + 1024) bytesUsed = 0;  // a new buffer
    vertexCount = 0;
    primCount = 0;
  }
};

// vbo_copy_vertices: when an open primitive of `count` vertices wraps, Mesa
// draws its first `drawn` vertices and starts the next draw with the last
// `copied` ones (for fans and polygons: the first vertex and the last one).
struct WrapSplit {
  uint32_t drawn = 0;
  uint32_t copied = 0;
  bool keepFirst = false;  // fans and polygons: the copy is vertex 0 and the last vertex
};
inline WrapSplit wrapSplit(GLenum mode, uint32_t count) {
  WrapSplit s{count, 0, false};
  switch (mode) {
    case GL_POINTS: break;
    case GL_LINES: s.copied = count % 2; break;
    case GL_TRIANGLES: s.copied = count % 3; break;
    case GL_QUADS: s.copied = count % 4; break;
    case GL_LINE_STRIP: s.copied = count < 1 ? count : 1; break;
    case GL_LINE_LOOP:  // the piece is drawn as a line strip (VboStore::openLoopWrapped)
    case GL_TRIANGLE_FAN:
    case GL_POLYGON:
      s.copied = count < 2 ? count : 2;
      s.keepFirst = count >= 2;
      break;
    case GL_TRIANGLE_STRIP:
      s.drawn = count - count % 2;  // an even number of triangles keeps the facing
      s.copied = count <= 1 ? count : 2 + count % 2;
      break;
    case GL_QUAD_STRIP: s.copied = count <= 1 ? count : 2 + count % 2; break;
    default: break;
  }
  return s;
}

}  // namespace glfixed::pipeline
