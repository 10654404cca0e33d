// Reading vertex array elements (GL 2.1 §2.8) into a VertexBatch: the one
// fetch behind glDrawArrays, glDrawElements, glArrayElement and (later) the
// display lists that capture arrays at compile time. It knows nothing of the
// entry points: resolve the enabled arrays once, then read elements.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "pipeline/vertex_batch.h"
#include "state/vertex_array_attrib.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// One enabled array, resolved to memory: element i starts at base + i·stride.
// An array in a buffer object may read only `limit` bytes from base; past
// that an element reads as zeros (never outside the buffer). Client memory
// is the program's to size: unbounded.
struct ArrayView {
  const uint8_t* base = nullptr;
  size_t stride = 0;
  size_t limit = SIZE_MAX;
  GLint size = 0;
  GLenum type = GL_FLOAT;
  bool normalized = false;  // table 2.9: integer colours and normals
  bool bgra = false;        // EXT_vertex_array_bgra: components 0 and 2 swapped
  // Element i; components the array lacks come from `fill`.
  glm::vec4 read(uint32_t i, glm::vec4 fill) const;
  // Element i's bytes, or null where it would read past the buffer's end.
  const uint8_t* elementBytes(uint32_t i) const;
};

// The enabled arrays, resolved. Draws fetch positions, normals and colours
// only: no stage reads the secondary colour, fog coordinate, colour index,
// edge flag or texture coordinates yet (glArrayElement passes them on as the
// current values they set).
struct ArraySources {
  bool vertex = false, normal = false, color = false;
  ArrayView vertexView, normalView, colorView;
  bool secondaryColor = false, fogCoord = false, index = false, edgeFlag = false;
  ArrayView secondaryColorView, fogCoordView, indexView, edgeFlagView;
  bool texCoord[kMaxTextureCoords] = {};
  ArrayView texCoordView[kMaxTextureCoords];
};

// Resolves the enabled arrays of `ctx` (buffer offsets to memory). Returns
// GL_INVALID_OPERATION if an enabled array sources a mapped buffer (GL 2.1
// §2.9), else GL_NO_ERROR.
GLenum resolveArrays(const Context& ctx, ArraySources& out);

// Appends elements first..first+count-1 / the elements indices[0..count) to
// `batch`: positions, normals and colours, the current normal and colour
// where the array is disabled, material index 0.
void appendRange(const ArraySources& src, const Context& ctx, uint32_t first, uint32_t count,
                 VertexBatch& batch);
void appendIndexed(const ArraySources& src, const Context& ctx, const uint32_t* indices, size_t count,
                   VertexBatch& batch);

}  // namespace glfixed::pipeline
