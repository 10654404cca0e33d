// The client memory of a pixel command (GL 2.1 §4.3.5): the pointer itself,
// or, with a pixel pack or unpack buffer bound, an offset into that buffer.
// Shared by every command that reads or writes pixels through them.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "state/context.h"

namespace glfixed::api {

// `extent` bytes from `pointer` in the buffer named `bufferName` (0: client
// memory, `pointer` itself). Null with `error` set to GL_INVALID_OPERATION
// when the buffer is mapped or the bytes run past its end; null without
// error for a null client pointer.
template <typename Byte>
Byte* pixelBufferMemory(Context& ctx, GLuint bufferName, Byte* pointer, size_t extent, GLenum& error) {
  error = GL_NO_ERROR;
  if (!bufferName) return pointer;
  BufferObject* b = ctx.buffers.find(bufferName);
  const size_t offset = reinterpret_cast<uintptr_t>(pointer);
  if (!b || b->mapped || offset > b->data.size() || extent > b->data.size() - offset) {
    error = GL_INVALID_OPERATION;
    return nullptr;
  }
  return reinterpret_cast<Byte*>(b->data.data() + offset);
}

}  // namespace glfixed::api
