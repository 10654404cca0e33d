// Buffer objects (GL 2.1 §2.9): names, data stores, mapping, queries, and
// the four binding points (array, element array, pixel pack and unpack).
#include <cstring>
#include <new>
#include <stdexcept>

#include "api/api.h"

using namespace glfixed;

namespace {

// The binding point of `target`, or null (GL_INVALID_ENUM).
GLuint* bindingOf(Context& ctx, GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER: return &ctx.vertexArray.arrayBufferBinding;
    case GL_ELEMENT_ARRAY_BUFFER: return &ctx.vertexArray.elementArrayBufferBinding;
    case GL_PIXEL_PACK_BUFFER: return &ctx.pixelStore.pixelPackBufferBinding;
    case GL_PIXEL_UNPACK_BUFFER: return &ctx.pixelStore.pixelUnpackBufferBinding;
    default: return nullptr;
  }
}

// The buffer bound to `target`: null with GL_INVALID_ENUM for a bad target,
// GL_INVALID_OPERATION when 0 is bound.
BufferObject* boundBuffer(Context& ctx, GLenum target) {
  GLuint* binding = bindingOf(ctx, target);
  if (!binding) {
    ctx.recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  BufferObject* b = ctx.buffers.find(*binding);
  if (!b) ctx.recordError(GL_INVALID_OPERATION);
  return b;
}

bool isUsage(GLenum usage) {
  switch (usage) {
    case GL_STREAM_DRAW:
    case GL_STREAM_READ:
    case GL_STREAM_COPY:
    case GL_STATIC_DRAW:
    case GL_STATIC_READ:
    case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW:
    case GL_DYNAMIC_READ:
    case GL_DYNAMIC_COPY: return true;
    default: return false;
  }
}

// The checks glBufferSubData and glGetBufferSubData share (GL 2.1 §2.9).
BufferObject* subDataBuffer(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size) {
  BufferObject* b = boundBuffer(ctx, target);
  if (!b) return nullptr;
  if (offset < 0 || size < 0 || offset > b->size() || size > b->size() - offset) {
    ctx.recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  if (b->mapped) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return b;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glGenBuffers(GLsizei n, GLuint* buffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (buffers) ctx->buffers.generate(n, buffers);
}

GLAPI void APIENTRY glBindBuffer(GLenum target, GLuint buffer) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  GLuint* binding = bindingOf(*ctx, target);
  if (!binding) return ctx->recordError(GL_INVALID_ENUM);
  // GL 2.1: any name may be bound; a new one becomes a new object (also a
  // deleted one: only core profiles refuse names glGenBuffers did not give).
  ctx->buffers.bind(buffer);
  *binding = buffer;
}

GLAPI void APIENTRY glDeleteBuffers(GLsizei n, const GLuint* buffers) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!buffers) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = buffers[i];
    if (name == 0 || !ctx->buffers.find(name)) continue;
    // Every binding of the deleted object in this context reverts to 0 (§2.9).
    VertexArrayAttrib& v = ctx->vertexArray;
    auto unbind = [name](GLuint& binding) {
      if (binding == name) binding = 0;
    };
    unbind(v.arrayBufferBinding);
    unbind(v.elementArrayBufferBinding);
    unbind(ctx->pixelStore.pixelPackBufferBinding);
    unbind(ctx->pixelStore.pixelUnpackBufferBinding);
    auto orphan = [name](ClientArray& c) {
      if (c.bufferBinding != name) return;
      c.bufferBinding = 0;
      c.orphaned = true;
    };
    for (ClientArray* c :
         {&v.vertex, &v.normal, &v.color, &v.secondaryColor, &v.fogCoord, &v.index, &v.edgeFlag})
      orphan(*c);
    for (ClientArray& c : v.texCoord) orphan(c);
    ctx->buffers.remove(name);
  }
}

GLAPI GLboolean APIENTRY glIsBuffer(GLuint buffer) {
  Context* ctx = api::contextForQuery();
  return ctx && ctx->buffers.find(buffer) ? GL_TRUE : GL_FALSE;
}

GLAPI void APIENTRY glBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!bindingOf(*ctx, target)) return ctx->recordError(GL_INVALID_ENUM);
  if (size < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!isUsage(usage)) return ctx->recordError(GL_INVALID_ENUM);
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return;
  // A new data store: a mapping of the old one ends (§2.9).
  b->mapped = false;
  b->mapPointer = nullptr;
  b->access = GL_READ_WRITE;
  b->usage = usage;
  try {
    DataStore store(static_cast<size_t>(size));  // zeros (StoreAllocator)
    if (data && size > 0) std::memcpy(store.data(), data, static_cast<size_t>(size));
    b->data.swap(store);
  } catch (const std::bad_alloc&) {
    b->data.clear();
    ctx->recordError(GL_OUT_OF_MEMORY);
  } catch (const std::length_error&) {
    b->data.clear();
    ctx->recordError(GL_OUT_OF_MEMORY);
  }
}

GLAPI void APIENTRY glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  BufferObject* b = subDataBuffer(*ctx, target, offset, size);
  if (b && data && size > 0) std::memcpy(b->data.data() + offset, data, static_cast<size_t>(size));
}

GLAPI void APIENTRY glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  BufferObject* b = subDataBuffer(*ctx, target, offset, size);
  if (b && data && size > 0) std::memcpy(data, b->data.data() + offset, static_cast<size_t>(size));
}

GLAPI void* APIENTRY glMapBuffer(GLenum target, GLenum access) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return nullptr;
  if (!bindingOf(*ctx, target)) {
    ctx->recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    ctx->recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return nullptr;
  if (b->mapped) {
    ctx->recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  b->mapped = true;
  b->access = access;
  // The store is the mapping: a zero-size buffer maps to a non-null pointer too.
  static uint8_t emptyStore;
  b->mapPointer = b->data.empty() ? &emptyStore : b->data.data();
  return b->mapPointer;
}

GLAPI GLboolean APIENTRY glUnmapBuffer(GLenum target) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return GL_FALSE;
  if (!b->mapped) {
    ctx->recordError(GL_INVALID_OPERATION);
    return GL_FALSE;
  }
  b->mapped = false;
  b->mapPointer = nullptr;
  return GL_TRUE;  // the store is never lost
}

GLAPI void APIENTRY glGetBufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!bindingOf(*ctx, target)) return ctx->recordError(GL_INVALID_ENUM);
  if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS &&
      pname != GL_BUFFER_MAPPED)
    return ctx->recordError(GL_INVALID_ENUM);
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b || !params) return;
  switch (pname) {
    case GL_BUFFER_SIZE: *params = static_cast<GLint>(b->size()); break;
    case GL_BUFFER_USAGE: *params = static_cast<GLint>(b->usage); break;
    case GL_BUFFER_ACCESS: *params = static_cast<GLint>(b->access); break;
    case GL_BUFFER_MAPPED: *params = b->mapped ? GL_TRUE : GL_FALSE; break;
  }
}

GLAPI void APIENTRY glGetBufferPointerv(GLenum target, GLenum pname, void** params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!bindingOf(*ctx, target) || pname != GL_BUFFER_MAP_POINTER) return ctx->recordError(GL_INVALID_ENUM);
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b || !params) return;
  *params = b->mapPointer;
}

}  // extern "C"
