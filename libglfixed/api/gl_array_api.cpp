// The vertex array state (GL 2.1 §2.8): gl*Pointer, glEnableClientState,
// glClientActiveTexture, glInterleavedArrays, glGetPointerv, and the client
// attribute stack (§6.1.14). The draws are in gl_array_draw_api.cpp.
#include <initializer_list>

#include "api/api.h"
#include "api/gl_select_api.h"
#include "state/vertex_array_queries.h"

using namespace glfixed;

namespace {

bool oneOf(GLenum v, std::initializer_list<GLenum> allowed) {
  for (GLenum a : allowed)
    if (a == v) return true;
  return false;
}

// Validates and stores one array's pointer: a negative stride, a type or a
// size the array does not take is an error and changes nothing (GL 2.1 §2.8).
// `bgra`: the colour arrays also take the size GL_BGRA (EXT_vertex_array_bgra),
// of unsigned bytes only (else GL_INVALID_OPERATION, as Mesa).
template <typename Pick>
void setPointer(Pick which, GLint size, GLint minSize, GLint maxSize, GLenum type,
                std::initializer_list<GLenum> types, GLsizei stride, const void* pointer, bool bgra = false) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (stride < 0) return ctx->recordError(GL_INVALID_VALUE);
  // GL 3.0 §2.10 (ARB_vertex_array_object): a named vertex array object
  // takes no client memory, so a pointer without an array buffer is refused
  // (a null one is not); Mesa checks it so in compatibility contexts too.
  if (ctx->vertexArray.vertexArrayBinding != 0 && ctx->vertexArray.arrayBufferBinding == 0 && pointer)
    return ctx->recordError(GL_INVALID_OPERATION);
  if (!oneOf(type, types)) return ctx->recordError(GL_INVALID_ENUM);
  if (bgra && size == GL_BGRA) {
    if (type != GL_UNSIGNED_BYTE) return ctx->recordError(GL_INVALID_OPERATION);
  } else if (size < minSize || size > maxSize) {
    return ctx->recordError(GL_INVALID_VALUE);
  }
  ClientArray& a = which(ctx->vertexArray);
  a.size = size;
  a.type = type;
  a.stride = stride;
  a.pointer = pointer;
  a.bufferBinding = ctx->vertexArray.arrayBufferBinding;
  a.orphaned = false;
}

void setClientState(GLenum cap, bool enabled) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  // NV_primitive_restart is enabled as a client state (glEnable refuses it).
  if (cap == GL_PRIMITIVE_RESTART_NV) {
    ctx->vertexArray.primitiveRestart = enabled;
    return;
  }
  ClientArray* a = clientArrayOfCapability(ctx->vertexArray, cap);
  if (!a) return ctx->recordError(GL_INVALID_ENUM);
  a->enabled = enabled;
}

constexpr std::initializer_list<GLenum> kColorTypes = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                                       GL_INT,  GL_UNSIGNED_INT,  GL_FLOAT, GL_DOUBLE};

// One row of table 2.5 (glInterleavedArrays): which arrays the format has,
// their sizes, and the colour's type.
struct InterleavedFormat {
  GLenum format;
  bool texture, color, normal;
  GLint textureSize, colorSize, vertexSize;
  GLenum colorType;
};
constexpr InterleavedFormat kInterleavedFormats[] = {
    {GL_V2F, false, false, false, 0, 0, 2, 0},
    {GL_V3F, false, false, false, 0, 0, 3, 0},
    {GL_C4UB_V2F, false, true, false, 0, 4, 2, GL_UNSIGNED_BYTE},
    {GL_C4UB_V3F, false, true, false, 0, 4, 3, GL_UNSIGNED_BYTE},
    {GL_C3F_V3F, false, true, false, 0, 3, 3, GL_FLOAT},
    {GL_N3F_V3F, false, false, true, 0, 0, 3, 0},
    {GL_C4F_N3F_V3F, false, true, true, 0, 4, 3, GL_FLOAT},
    {GL_T2F_V3F, true, false, false, 2, 0, 3, 0},
    {GL_T4F_V4F, true, false, false, 4, 0, 4, 0},
    {GL_T2F_C4UB_V3F, true, true, false, 2, 4, 3, GL_UNSIGNED_BYTE},
    {GL_T2F_C3F_V3F, true, true, false, 2, 3, 3, GL_FLOAT},
    {GL_T2F_N3F_V3F, true, false, true, 2, 0, 3, 0},
    {GL_T2F_C4F_N3F_V3F, true, true, true, 2, 4, 3, GL_FLOAT},
    {GL_T4F_C4F_N3F_V4F, true, true, true, 4, 4, 4, GL_FLOAT},
};

void storeArray(ClientArray& a, bool enabled, GLint size, GLenum type, GLsizei stride, const void* pointer,
                GLuint binding) {
  a.enabled = enabled;
  if (!enabled) return;
  a.size = size;
  a.type = type;
  a.stride = stride;
  a.pointer = pointer;
  a.bufferBinding = binding;
  a.orphaned = false;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glVertexPointer(GLint size, GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.vertex; }, size, 2, 4, type,
             {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}, stride, pointer);
}
GLAPI void APIENTRY glNormalPointer(GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.normal; }, 3, 3, 3, type,
             {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}, stride, pointer);
}
GLAPI void APIENTRY glColorPointer(GLint size, GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.color; }, size, 3, 4, type, kColorTypes,
             stride, pointer, true);
}
GLAPI void APIENTRY glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.secondaryColor; }, size, 3, 3, type,
             kColorTypes, stride, pointer, true);
}
GLAPI void APIENTRY glFogCoordPointer(GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.fogCoord; }, 1, 1, 1, type,
             {GL_FLOAT, GL_DOUBLE}, stride, pointer);
}
GLAPI void APIENTRY glIndexPointer(GLenum type, GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.index; }, 1, 1, 1, type,
             {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}, stride, pointer);
}
GLAPI void APIENTRY glEdgeFlagPointer(GLsizei stride, const void* pointer) {
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.edgeFlag; }, 1, 1, 1, GL_UNSIGNED_BYTE,
             {GL_UNSIGNED_BYTE}, stride, pointer);
}
GLAPI void APIENTRY glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* pointer) {
  // The array of the client active texture unit (GL 2.1 §2.8).
  setPointer([](VertexArrayAttrib& v) -> ClientArray& { return v.activeTexCoord(); }, size, 1, 4, type,
             {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}, stride, pointer);
}

GLAPI void APIENTRY glEnableClientState(GLenum cap) { setClientState(cap, true); }
GLAPI void APIENTRY glDisableClientState(GLenum cap) { setClientState(cap, false); }

GLAPI void APIENTRY glClientActiveTexture(GLenum texture) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + kMaxTextureCoords)
    return ctx->recordError(GL_INVALID_ENUM);
  ctx->vertexArray.clientActiveTexture = texture;
}

GLAPI void APIENTRY glGetPointerv(GLenum pname, void** params) {
  Context* ctx = api::contextForQuery();
  if (!ctx || !params) return;
  // GL_SELECTION_BUFFER_POINTER and GL_FEEDBACK_BUFFER_POINTER (§5.2, §5.3).
  if (api::renderModePointer(*ctx, pname, params)) return;
  const ClientArray* a = clientArrayOfPointer(ctx->vertexArray, pname);
  if (!a) return ctx->recordError(GL_INVALID_ENUM);
  *params = const_cast<void*>(a->pointer);
}

// GL 2.1 §2.8, table 2.5: sets every array at once from one interleaved block.
GLAPI void APIENTRY glInterleavedArrays(GLenum format, GLsizei stride, const void* pointer) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (stride < 0) return ctx->recordError(GL_INVALID_VALUE);
  const InterleavedFormat* f = nullptr;
  for (const InterleavedFormat& row : kInterleavedFormats)
    if (row.format == format) f = &row;
  if (!f) return ctx->recordError(GL_INVALID_ENUM);
  const GLsizei floatBytes = sizeof(GLfloat);
  const GLsizei colorBytes =
      !f->color ? 0 : (f->colorType == GL_UNSIGNED_BYTE ? 4 : f->colorSize * floatBytes);
  const GLsizei pc = f->textureSize * floatBytes;
  const GLsizei pn = pc + colorBytes;
  const GLsizei pv = pn + (f->normal ? 3 * floatBytes : 0);
  const GLsizei s = stride != 0 ? stride : pv + f->vertexSize * floatBytes;
  // Offsets added as integers: with a buffer bound the pointer is an offset,
  // often 0, and arithmetic on a null pointer is undefined.
  const uintptr_t base = reinterpret_cast<uintptr_t>(pointer);
  auto at = [base](GLsizei offset) {
    return reinterpret_cast<const void*>(base + static_cast<uintptr_t>(offset));
  };
  VertexArrayAttrib& a = ctx->vertexArray;
  const GLuint binding = a.arrayBufferBinding;
  a.edgeFlag.enabled = false;
  a.index.enabled = false;
  a.secondaryColor.enabled = false;
  a.fogCoord.enabled = false;
  storeArray(a.activeTexCoord(), f->texture, f->textureSize, GL_FLOAT, s, pointer, binding);
  storeArray(a.color, f->color, f->colorSize, f->colorType, s, at(pc), binding);
  storeArray(a.normal, f->normal, 3, GL_FLOAT, s, at(pn), binding);
  storeArray(a.vertex, true, f->vertexSize, GL_FLOAT, s, at(pv), binding);
}

// GL 2.1 §6.1.14: the client attribute stack, one copy per group.
GLAPI void APIENTRY glPushClientAttrib(GLbitfield mask) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (ctx->clientAttribStack.size() >= static_cast<size_t>(kMaxClientAttribStackDepth))
    return ctx->recordError(GL_STACK_OVERFLOW);
  ClientAttribEntry e;
  e.mask = mask;
  if (mask & GL_CLIENT_PIXEL_STORE_BIT) e.pixelStore = ctx->pixelStore;
  if (mask & GL_CLIENT_VERTEX_ARRAY_BIT) e.vertexArray = ctx->vertexArray;
  ctx->clientAttribStack.push_back(e);
}

GLAPI void APIENTRY glPopClientAttrib(void) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (ctx->clientAttribStack.empty()) return ctx->recordError(GL_STACK_UNDERFLOW);
  ClientAttribEntry e = ctx->clientAttribStack.back();
  ctx->clientAttribStack.pop_back();
  // A buffer deleted since the push is not bound again (its name is free).
  auto live = [&](GLuint& name) {
    if (name != 0 && !ctx->buffers.find(name)) name = 0;
  };
  auto liveArray = [&](ClientArray& c) {
    if (c.bufferBinding != 0 && !ctx->buffers.find(c.bufferBinding)) {
      c.bufferBinding = 0;
      c.orphaned = true;
    }
  };
  if (e.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    live(e.pixelStore.pixelPackBufferBinding);
    live(e.pixelStore.pixelUnpackBufferBinding);
    ctx->pixelStore = e.pixelStore;
  }
  if (e.mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    VertexArrayAttrib& v = e.vertexArray;
    // The saved object is bound again and given the saved state. One
    // deleted since the push leaves the whole group as it is, without an
    // error (Mesa; reference/MESA_FACTS.md, "Vertex array objects").
    if (!ctx->vertexArrayObjects.bindable(v.vertexArrayBinding)) return;
    ctx->vertexArrayObjects.bind(ctx->vertexArray, v.vertexArrayBinding);
    live(v.arrayBufferBinding);
    live(v.elementArrayBufferBinding);
    for (ClientArray* c :
         {&v.vertex, &v.normal, &v.color, &v.secondaryColor, &v.fogCoord, &v.index, &v.edgeFlag})
      liveArray(*c);
    for (ClientArray& c : v.texCoord) liveArray(c);
    ctx->vertexArray = v;
  }
}

}  // extern "C"
