// glDrawArrays and glDrawElements after validation: fetch the arrays into a
// VertexBatch and draw it, a long draw in bounded chunks.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "pipeline/array_fetch.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// Elements first..first+count-1 as GL_<mode>.
void drawArrays(Context& ctx, const ArraySources& src, GLenum mode, uint32_t first, uint32_t count);

// The elements `indices` as GL_<mode> (an indexed draw in Mesa's terms).
void drawElements(Context& ctx, const ArraySources& src, GLenum mode, const std::vector<uint32_t>& indices);

}  // namespace glfixed::pipeline
