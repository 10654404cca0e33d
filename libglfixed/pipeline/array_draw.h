// glDrawArrays and glDrawElements after validation: fetch the arrays into
// VertexBatches and draw them in Mesa's segments, a few thousand vertices at
// a time, so that memory stays bounded for a draw of any length.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "pipeline/array_fetch.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// Elements first..first+count-1 as GL_<mode>.
void drawArrays(Context& ctx, const ArraySources& src, GLenum mode, uint32_t first, uint32_t count);

// The indices of an indexed draw, read where they lie (client memory or an
// element array buffer), never copied whole.
struct IndexList {
  const uint8_t* data = nullptr;  // the first index
  GLenum type = GL_UNSIGNED_INT;  // GL_UNSIGNED_BYTE, _SHORT or _INT
  uint32_t count = 0;
  // Where the list lies in its element array buffer, in indices: the
  // position of its first index and the buffer's size. Client memory is
  // unbounded. (Mesa draws a list whole only if it ends before the
  // buffer's last index: array_draw.cpp.)
  size_t firstInBuffer = 0;
  size_t bufferIndices = SIZE_MAX;
  // ARB_draw_elements_base_vertex: added to every index before the arrays
  // are read (the sum wraps as an unsigned 32-bit index).
  int32_t baseVertex = 0;
  uint32_t at(size_t i) const;  // the index as stored
  size_t indexBytes() const { return type == GL_UNSIGNED_BYTE ? 1 : (type == GL_UNSIGNED_SHORT ? 2 : 4); }
  uint32_t element(size_t i) const { return at(i) + static_cast<uint32_t>(baseVertex); }
};

// The range of the elements read (the indices plus the base vertex), as the
// program promised it (glDrawRangeElements) or as Mesa computes it; `valid`
// false: Mesa knows no range.
struct IndexBounds {
  bool valid = false;
  uint32_t min = 0, max = 0;
};

// The bounds Mesa knows for a glDrawElements or glMultiDrawElements: it
// computes them over every index of `lists` only when the vertex shader
// reads an array from client memory (st_atom_array.c,
// draw_needs_minmax_index); otherwise none.
IndexBounds elementBounds(const Context& ctx, const ArraySources& src, const IndexList* lists, size_t count);

// The elements `indices` as GL_<mode> (an indexed draw in Mesa's terms).
void drawElements(Context& ctx, const ArraySources& src, GLenum mode, const IndexList& indices,
                  const IndexBounds& bounds);

}  // namespace glfixed::pipeline
