#include "state/vertex_array_queries.h"

#include "state/context.h"

namespace glfixed {

ClientArray* clientArrayOfCapability(VertexArrayAttrib& a, GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return &a.vertex;
    case GL_NORMAL_ARRAY: return &a.normal;
    case GL_COLOR_ARRAY: return &a.color;
    case GL_SECONDARY_COLOR_ARRAY: return &a.secondaryColor;
    case GL_FOG_COORD_ARRAY: return &a.fogCoord;
    case GL_INDEX_ARRAY: return &a.index;
    case GL_EDGE_FLAG_ARRAY: return &a.edgeFlag;
    case GL_TEXTURE_COORD_ARRAY: return &a.activeTexCoord();
    default: return nullptr;
  }
}

const ClientArray* clientArrayOfCapability(const VertexArrayAttrib& a, GLenum cap) {
  return clientArrayOfCapability(const_cast<VertexArrayAttrib&>(a), cap);
}

const ClientArray* clientArrayOfPointer(const VertexArrayAttrib& a, GLenum pname) {
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: return &a.vertex;
    case GL_NORMAL_ARRAY_POINTER: return &a.normal;
    case GL_COLOR_ARRAY_POINTER: return &a.color;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: return &a.secondaryColor;
    case GL_FOG_COORD_ARRAY_POINTER: return &a.fogCoord;
    case GL_INDEX_ARRAY_POINTER: return &a.index;
    case GL_EDGE_FLAG_ARRAY_POINTER: return &a.edgeFlag;
    case GL_TEXTURE_COORD_ARRAY_POINTER: return &a.activeTexCoord();
    default: return nullptr;
  }
}

namespace {

enum class Field { kEnabled, kSize, kType, kStride, kBinding };

struct ArrayQuery {
  GLenum pname;
  GLenum capability;
  Field field;
};

// pname -> (array, field): one row per query of tables 6.6-6.8.
constexpr ArrayQuery kArrayQueries[] = {
    {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY, Field::kEnabled},
    {GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY, Field::kSize},
    {GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY, Field::kType},
    {GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY, Field::kStride},
    {GL_VERTEX_ARRAY_BUFFER_BINDING, GL_VERTEX_ARRAY, Field::kBinding},
    {GL_NORMAL_ARRAY, GL_NORMAL_ARRAY, Field::kEnabled},
    {GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY, Field::kType},
    {GL_NORMAL_ARRAY_STRIDE, GL_NORMAL_ARRAY, Field::kStride},
    {GL_NORMAL_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY, Field::kBinding},
    {GL_COLOR_ARRAY, GL_COLOR_ARRAY, Field::kEnabled},
    {GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY, Field::kSize},
    {GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY, Field::kType},
    {GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY, Field::kStride},
    {GL_COLOR_ARRAY_BUFFER_BINDING, GL_COLOR_ARRAY, Field::kBinding},
    {GL_SECONDARY_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY, Field::kEnabled},
    {GL_SECONDARY_COLOR_ARRAY_SIZE, GL_SECONDARY_COLOR_ARRAY, Field::kSize},
    {GL_SECONDARY_COLOR_ARRAY_TYPE, GL_SECONDARY_COLOR_ARRAY, Field::kType},
    {GL_SECONDARY_COLOR_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY, Field::kStride},
    {GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, GL_SECONDARY_COLOR_ARRAY, Field::kBinding},
    {GL_FOG_COORD_ARRAY, GL_FOG_COORD_ARRAY, Field::kEnabled},
    {GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY, Field::kType},
    {GL_FOG_COORD_ARRAY_STRIDE, GL_FOG_COORD_ARRAY, Field::kStride},
    {GL_FOG_COORD_ARRAY_BUFFER_BINDING, GL_FOG_COORD_ARRAY, Field::kBinding},
    {GL_INDEX_ARRAY, GL_INDEX_ARRAY, Field::kEnabled},
    {GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY, Field::kType},
    {GL_INDEX_ARRAY_STRIDE, GL_INDEX_ARRAY, Field::kStride},
    {GL_INDEX_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY, Field::kBinding},
    {GL_EDGE_FLAG_ARRAY, GL_EDGE_FLAG_ARRAY, Field::kEnabled},
    {GL_EDGE_FLAG_ARRAY_STRIDE, GL_EDGE_FLAG_ARRAY, Field::kStride},
    {GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, GL_EDGE_FLAG_ARRAY, Field::kBinding},
    {GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY, Field::kEnabled},
    {GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY, Field::kSize},
    {GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY, Field::kType},
    {GL_TEXTURE_COORD_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY, Field::kStride},
    {GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, GL_TEXTURE_COORD_ARRAY, Field::kBinding},
};

}  // namespace

bool getVertexArrayState(const Context& ctx, GLenum pname, GLdouble* out, int* count) {
  *count = 1;
  const VertexArrayAttrib& a = ctx.vertexArray;
  switch (pname) {
    case GL_CLIENT_ACTIVE_TEXTURE: out[0] = a.clientActiveTexture; return true;
    case GL_MAX_TEXTURE_COORDS: out[0] = kMaxTextureCoords; return true;
    case GL_ARRAY_BUFFER_BINDING: out[0] = a.arrayBufferBinding; return true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING: out[0] = a.elementArrayBufferBinding; return true;
    case GL_VERTEX_ARRAY_BINDING: out[0] = a.vertexArrayBinding; return true;
    case GL_PRIMITIVE_RESTART_NV: out[0] = a.primitiveRestart; return true;
    case GL_PRIMITIVE_RESTART_INDEX_NV: out[0] = a.primitiveRestartIndex; return true;
    case GL_PIXEL_PACK_BUFFER_BINDING: out[0] = ctx.pixelStore.pixelPackBufferBinding; return true;
    case GL_PIXEL_UNPACK_BUFFER_BINDING: out[0] = ctx.pixelStore.pixelUnpackBufferBinding; return true;
    case GL_COPY_READ_BUFFER: out[0] = ctx.copyBuffer.read; return true;  // = GL_COPY_READ_BUFFER_BINDING
    case GL_COPY_WRITE_BUFFER: out[0] = ctx.copyBuffer.write; return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: out[0] = double(ctx.clientAttribStack.size()); return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: out[0] = kMaxClientAttribStackDepth; return true;
    // Recommended sizes only (GL 2.1 §2.8): any count may be drawn.
    case GL_MAX_ELEMENTS_VERTICES:
    case GL_MAX_ELEMENTS_INDICES: out[0] = 3000; return true;
    default: break;
  }
  for (const ArrayQuery& q : kArrayQueries) {
    if (q.pname != pname) continue;
    const ClientArray& c = *clientArrayOfCapability(a, q.capability);
    switch (q.field) {
      case Field::kEnabled: out[0] = c.enabled; break;
      case Field::kSize: out[0] = c.size; break;
      case Field::kType: out[0] = c.type; break;
      case Field::kStride: out[0] = c.stride; break;
      case Field::kBinding: out[0] = c.bufferBinding; break;
    }
    return true;
  }
  return false;
}

}  // namespace glfixed
