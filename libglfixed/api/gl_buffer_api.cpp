// Buffer objects (GL 2.1 §2.9): names, data stores, mapping, queries, and
// the six binding points (array, element array, pixel pack and unpack, copy
// read and write). Ranges are mapped as ARB_map_buffer_range and copied as
// ARB_copy_buffer say (both GL 3.0/3.1 §2.10), with Mesa's errors in Mesa's
// order (reference/MESA_FACTS.md, "Buffer ranges and copies").
#include <cstring>
#include <new>
#include <stdexcept>

#include "api/api.h"

using namespace glfixed;

// GL 3.0's queries of a mapping (ARB_map_buffer_range has no names for them).
#ifndef GL_BUFFER_ACCESS_FLAGS
#define GL_BUFFER_ACCESS_FLAGS 0x911F
#define GL_BUFFER_MAP_LENGTH 0x9120
#define GL_BUFFER_MAP_OFFSET 0x9121
#endif

namespace {

// The binding point of `target`, or null (GL_INVALID_ENUM).
GLuint* bindingOf(Context& ctx, GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER: return &ctx.vertexArray.arrayBufferBinding;
    case GL_ELEMENT_ARRAY_BUFFER: return &ctx.vertexArray.elementArrayBufferBinding;
    case GL_PIXEL_PACK_BUFFER: return &ctx.pixelStore.pixelPackBufferBinding;
    case GL_PIXEL_UNPACK_BUFFER: return &ctx.pixelStore.pixelUnpackBufferBinding;
    case GL_COPY_READ_BUFFER: return &ctx.copyBuffer.read;
    case GL_COPY_WRITE_BUFFER: return &ctx.copyBuffer.write;
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
// Mesa lets glBufferSubData write outside a mapped range (GL 3.0 forbids
// either command on a mapped buffer); glGetBufferSubData it refuses while
// any range is mapped.
BufferObject* subDataBuffer(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size, bool writes) {
  BufferObject* b = boundBuffer(ctx, target);
  if (!b) return nullptr;
  if (offset < 0 || size < 0 || offset > b->size() || size > b->size() - offset) {
    ctx.recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  if (writes ? b->rangeMapped(offset, size) : b->mapped) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return b;
}

// glMapBuffer and glMapBufferRange after the buffer is found: the checks of
// GL 3.0 §2.10.1 in Mesa's order, then the mapping, which is the store
// itself. Nothing is discarded: the invalidate bits leave the old bytes,
// as llvmpipe does (what a range holds after them is undefined, and Mesa's
// mapping shows the old contents too); nor is anything to wait for, so
// GL_MAP_UNSYNCHRONIZED_BIT and an explicit flush change nothing either.
void* mapRange(Context& ctx, BufferObject& b, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  if (offset < 0 || length < 0) {
    ctx.recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  // GL 4.5 makes an empty range an error (Mesa's glMapBuffer of an empty
  // store too).
  if (length == 0) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  const GLbitfield kAccessBits = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT |
                                 GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT |
                                 GL_MAP_UNSYNCHRONIZED_BIT;
  // ARB_buffer_storage's GL_MAP_PERSISTENT_BIT and GL_MAP_COHERENT_BIT:
  // Mesa knows them, and refuses them later for a glBufferData store.
  const GLbitfield kStorageBits = 0x40 | 0x80;
  if (access & ~(kAccessBits | kStorageBits)) {
    ctx.recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  const bool read = access & GL_MAP_READ_BIT, write = access & GL_MAP_WRITE_BIT;
  if ((!read && !write) ||
      (read && (access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT))) ||
      ((access & GL_MAP_FLUSH_EXPLICIT_BIT) && !write) || (access & kStorageBits)) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  if (offset > b.size() || length > b.size() - offset) {
    ctx.recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  if (b.mapped) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  b.mapped = true;
  b.accessFlags = access;
  b.mapOffset = offset;
  b.mapLength = length;
  b.mapPointer = b.data.data() + offset;
  return b.mapPointer;
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
    unbind(ctx->copyBuffer.read);
    unbind(ctx->copyBuffer.write);
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
  b->unmap();
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
  BufferObject* b = subDataBuffer(*ctx, target, offset, size, true);
  if (b && data && size > 0) std::memcpy(b->data.data() + offset, data, static_cast<size_t>(size));
}

GLAPI void APIENTRY glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  BufferObject* b = subDataBuffer(*ctx, target, offset, size, false);
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
  // The whole store, with the flags GL 3.0 §2.10.1 gives each access.
  const GLbitfield flags = access == GL_READ_ONLY    ? GL_MAP_READ_BIT
                           : access == GL_WRITE_ONLY ? GL_MAP_WRITE_BIT
                                                     : GL_MAP_READ_BIT | GL_MAP_WRITE_BIT;
  return mapRange(*ctx, *b, 0, b->size(), flags);
}

GLAPI void* APIENTRY glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return nullptr;
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return nullptr;
  return mapRange(*ctx, *b, offset, length, access);
}

// Offsets are within the mapped range. The mapping is the store: there is
// nothing to copy back.
GLAPI void APIENTRY glFlushMappedBufferRange(GLenum target, GLintptr offset, GLsizeiptr length) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return;
  if (offset < 0 || length < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!b->mapped || !(b->accessFlags & GL_MAP_FLUSH_EXPLICIT_BIT)) return ctx->recordError(GL_INVALID_OPERATION);
  if (offset > b->mapLength || length > b->mapLength - offset) return ctx->recordError(GL_INVALID_VALUE);
}

// ARB_copy_buffer: any two binding points, the same buffer too if the
// ranges do not overlap. Not compiled into display lists (it runs at once,
// as glBufferSubData does; piglit arb_copy_buffer-dlist). Mesa refuses a
// mapped buffer even when the mapped range is elsewhere.
GLAPI void APIENTRY glCopyBufferSubData(GLenum readTarget, GLenum writeTarget, GLintptr readOffset,
                                        GLintptr writeOffset, GLsizeiptr size) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  BufferObject* src = boundBuffer(*ctx, readTarget);
  if (!src) return;
  BufferObject* dst = boundBuffer(*ctx, writeTarget);
  if (!dst) return;
  if (src->mapped || dst->mapped) return ctx->recordError(GL_INVALID_OPERATION);
  if (readOffset < 0 || writeOffset < 0 || size < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (size > src->size() || readOffset > src->size() - size || size > dst->size() ||
      writeOffset > dst->size() - size)
    return ctx->recordError(GL_INVALID_VALUE);
  if (src == dst && readOffset < writeOffset + size && writeOffset < readOffset + size)
    return ctx->recordError(GL_INVALID_VALUE);
  if (size > 0)
    std::memmove(dst->data.data() + writeOffset, src->data.data() + readOffset, static_cast<size_t>(size));
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
  b->unmap();
  return GL_TRUE;  // the store is never lost
}

GLAPI void APIENTRY glGetBufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  // Mesa's order: the buffer (GL_INVALID_OPERATION for 0) before the pname.
  BufferObject* b = boundBuffer(*ctx, target);
  if (!b) return;
  GLint value;
  switch (pname) {
    case GL_BUFFER_SIZE: value = static_cast<GLint>(b->size()); break;
    case GL_BUFFER_USAGE: value = static_cast<GLint>(b->usage); break;
    case GL_BUFFER_ACCESS: value = static_cast<GLint>(b->access()); break;
    case GL_BUFFER_MAPPED: value = b->mapped ? GL_TRUE : GL_FALSE; break;
    case GL_BUFFER_ACCESS_FLAGS: value = static_cast<GLint>(b->accessFlags); break;
    case GL_BUFFER_MAP_OFFSET: value = static_cast<GLint>(b->mapOffset); break;
    case GL_BUFFER_MAP_LENGTH: value = static_cast<GLint>(b->mapLength); break;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  if (params) *params = value;
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
