// The vertex arrays (GL 2.1 §2.8, tables 6.6-6.8): the GL_CLIENT_VERTEX_ARRAY_BIT
// group of glPushClientAttrib, one struct so that push and pop are a copy.
// Its arrays and element array binding are the state of the bound vertex
// array object (ARB_vertex_array_object, state/vertex_array_objects.h).
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed {

constexpr int kMaxTextureCoords = 8;  // GL_MAX_TEXTURE_COORDS, as Mesa

// One array: its format and where its elements are. With a buffer object
// bound when the pointer was given (bufferBinding != 0), `pointer` is an
// offset into that buffer (GL 2.1 §2.9.1).
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;  // as given; 0 means tightly packed
  const void* pointer = nullptr;
  GLuint bufferBinding = 0;
  // The buffer this array sourced was deleted: its binding reads 0 (GL 2.1
  // §2.9), but `pointer` is still an offset, not client memory; it reads as
  // zeros until a new pointer is given.
  bool orphaned = false;

  static ClientArray make(GLint size, GLenum type) {
    ClientArray a;
    a.size = size;
    a.type = type;
    return a;
  }
};

// What a vertex array object holds (ARB_vertex_array_object, GL 3.0 table
// 6.6-6.9 without GL_ARRAY_BUFFER_BINDING and GL_CLIENT_ACTIVE_TEXTURE, which
// stay context state, as in Mesa).
struct VertexArrayObjectState {
  ClientArray vertex = ClientArray::make(4, GL_FLOAT);
  ClientArray normal = ClientArray::make(3, GL_FLOAT);
  ClientArray color = ClientArray::make(4, GL_FLOAT);
  ClientArray secondaryColor = ClientArray::make(3, GL_FLOAT);
  ClientArray fogCoord = ClientArray::make(1, GL_FLOAT);
  ClientArray index = ClientArray::make(1, GL_FLOAT);
  ClientArray edgeFlag = ClientArray::make(1, GL_UNSIGNED_BYTE);  // stride and pointer only
  ClientArray texCoord[kMaxTextureCoords] = {ClientArray::make(4, GL_FLOAT), ClientArray::make(4, GL_FLOAT),
                                             ClientArray::make(4, GL_FLOAT), ClientArray::make(4, GL_FLOAT),
                                             ClientArray::make(4, GL_FLOAT), ClientArray::make(4, GL_FLOAT),
                                             ClientArray::make(4, GL_FLOAT), ClientArray::make(4, GL_FLOAT)};
  // Table 6.8 puts this binding in the vertex-array group; GL 3.0 in the object.
  GLuint elementArrayBufferBinding = 0;
};

struct VertexArrayAttrib : VertexArrayObjectState {
  GLenum clientActiveTexture = GL_TEXTURE0;
  GLuint arrayBufferBinding = 0;  // table 6.8, the vertex-array group
  // The bound vertex array object (0: the default one); its state is the
  // base class. glPushClientAttrib saves the name with the state, as Mesa.
  GLuint vertexArrayBinding = 0;
  // NV_primitive_restart: a client state (glEnableClientState), so in this
  // group, not in an object (Mesa's gl_array_attrib).
  bool primitiveRestart = false;
  GLuint primitiveRestartIndex = 0;

  ClientArray& activeTexCoord() { return texCoord[clientActiveTexture - GL_TEXTURE0]; }
  const ClientArray& activeTexCoord() const { return texCoord[clientActiveTexture - GL_TEXTURE0]; }
};

// The bytes one component of `type` takes (0: not an array type).
inline int componentBytes(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT: return 2;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

// The distance between two elements: the stride, or the element's size when 0.
// The components an element holds: GL_BGRA (EXT_vertex_array_bgra, colour
// arrays of unsigned bytes) is four, stored blue, green, red, alpha.
inline int componentCount(const ClientArray& a) { return a.size == GL_BGRA ? 4 : a.size; }

inline size_t effectiveStride(const ClientArray& a) {
  return a.stride != 0 ? static_cast<size_t>(a.stride)
                       : static_cast<size_t>(componentCount(a)) * componentBytes(a.type);
}

}  // namespace glfixed
