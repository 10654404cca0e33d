// Drawing from vertex arrays (GL 2.1 §2.8): glArrayElement, glDrawArrays,
// glDrawElements, glDrawRangeElements, glMultiDrawArrays, glMultiDrawElements,
// and their base-vertex forms (ARB_draw_elements_base_vertex).
// Each validates, ends the run of buffered glBegin/glEnd vertices (Mesa
// flushes them before an array draw), then hands the draw to
// pipeline/array_draw.h.
#include <algorithm>
#include <cstring>
#include <new>
#include <stdexcept>
#include <vector>

#include "api/api.h"
#include "api/list_record.h"
#include "pipeline/array_draw.h"
#include "pipeline/thread_scratch.h"

using namespace glfixed;

namespace {

bool isPrimitiveMode(GLenum mode) { return mode <= GL_POLYGON; }
bool isIndexType(GLenum type) {
  return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
}

// The context of an array draw, after the checks every draw shares: null
// (with the error recorded) if it must not draw.
Context* drawContext(GLenum mode, GLsizei count) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return nullptr;
  if (!isPrimitiveMode(mode)) {
    ctx->recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  if (count < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return nullptr;
  }
  return ctx;
}

// Resolves the arrays; GL_INVALID_OPERATION if one sources a mapped buffer.
bool resolve(Context& ctx, pipeline::ArraySources& src) {
  const GLenum error = pipeline::resolveArrays(ctx, src);
  if (error != GL_NO_ERROR) ctx.recordError(error);
  return error == GL_NO_ERROR;
}

// The `count` indices of `type` in client memory or, with an element array
// buffer bound, in that buffer at offset `indices`; indices past the
// buffer's end are not read (the draw ends there); `baseVertex` is added to
// each (ARB_draw_elements_base_vertex). False: the buffer is mapped.
bool indexList(Context& ctx, GLsizei count, GLenum type, const void* indices, pipeline::IndexList& out,
               GLint baseVertex = 0) {
  out = pipeline::IndexList();
  out.type = type;
  out.baseVertex = baseVertex;
  const size_t bytes = out.indexBytes();
  if (const GLuint name = ctx.vertexArray.elementArrayBufferBinding) {
    const BufferObject* b = ctx.buffers.find(name);
    if (b && b->mapped) {
      ctx.recordError(GL_INVALID_OPERATION);
      return false;
    }
    const size_t offset = reinterpret_cast<uintptr_t>(indices);
    const size_t size = b ? b->data.size() : 0;
    const size_t available = offset >= size ? 0 : (size - offset) / bytes;
    out.count = static_cast<uint32_t>(std::min(static_cast<size_t>(count), available));
    out.data = out.count > 0 ? b->data.data() + offset : nullptr;
    out.firstInBuffer = offset / bytes;
    out.bufferIndices = size / bytes;
  } else if (indices) {
    out.data = static_cast<const uint8_t*>(indices);
    out.count = static_cast<uint32_t>(count);
  }
  return true;
}

// NV_primitive_restart: the runs of `list` between its restart indices
// (compared as given, before the base vertex), each a list of its own, as
// Mesa's draw module draws them; without restart, `list` itself.
void appendRestartRuns(const Context& ctx, const pipeline::IndexList& list, std::vector<pipeline::IndexList>& out) {
  if (!ctx.vertexArray.primitiveRestart) return out.push_back(list);
  const GLuint restart = ctx.vertexArray.primitiveRestartIndex;
  const size_t bytes = list.indexBytes();
  uint32_t start = 0;
  for (uint32_t i = 0; i <= list.count; ++i) {
    if (i < list.count && list.at(i) != restart) continue;
    if (i > start) {
      pipeline::IndexList run = list;
      run.data = list.data + start * bytes;
      run.count = i - start;
      run.firstInBuffer = list.firstInBuffer + start;
      out.push_back(run);
    }
    start = i + 1;
  }
}

// Runs a draw; a batch too large to allocate is GL_OUT_OF_MEMORY, never an
// exception out of the entry point.
template <typename Draw>
void guarded(Context& ctx, Draw draw) {
  try {
    draw();
  } catch (const std::bad_alloc&) {
    ctx.recordError(GL_OUT_OF_MEMORY);
  } catch (const std::length_error&) {
    ctx.recordError(GL_OUT_OF_MEMORY);
  }
}

// `range`: the bounds glDrawRangeElements promised, if Mesa takes them.
void drawElements(Context& ctx, GLenum mode, GLsizei count, GLenum type, const void* indices,
                  const pipeline::IndexBounds* range = nullptr, GLint baseVertex = 0) {
  pipeline::ArraySources src;
  if (!resolve(ctx, src)) return;
  pipeline::IndexList list;
  if (!indexList(ctx, count, type, indices, list, baseVertex)) return;
  pipeline::flushVertices(ctx);
  struct SiteRuns {};
  std::vector<pipeline::IndexList>& runs = pipeline::threadScratch<std::vector<pipeline::IndexList>, SiteRuns>();
  guarded(ctx, [&] {
    runs.clear();
    appendRestartRuns(ctx, list, runs);
    // The bounds Mesa computes leave the restart indices out.
    const pipeline::IndexBounds bounds = range ? *range : pipeline::elementBounds(ctx, src, runs.data(), runs.size());
    for (const pipeline::IndexList& run : runs) pipeline::drawElements(ctx, src, mode, run, bounds);
  });
}

// glArrayElement issues the glColor, glNormal and glVertex command of each
// array's own type and size (GL 2.1 §2.8), so that integers convert as those
// commands convert them (Mesa's immediate-mode conversions, not its vertex
// fetch's). `bytes` null: past a buffer's end, zeros.
template <typename T>
void readComponents(const uint8_t* bytes, int size, T* out) {
  for (int c = 0; c < 4; ++c) out[c] = T(0);
  if (bytes) std::memcpy(out, bytes, sizeof(T) * static_cast<size_t>(std::min(size, 4)));
}

template <typename T, typename C3, typename C4>
void colorAs(const uint8_t* bytes, int size, C3 color3, C4 color4) {
  T v[4];
  readComponents(bytes, size, v);
  if (size == 3)
    color3(v);
  else
    color4(v);
}

// EXT_vertex_array_bgra's unsigned bytes, in GL's order.
const uint8_t* bgraToRgba(const uint8_t* p, uint8_t (&rgba)[4]) {
  if (!p) return nullptr;
  rgba[0] = p[2];
  rgba[1] = p[1];
  rgba[2] = p[0];
  rgba[3] = p[3];
  return rgba;
}

void arrayColor(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  uint8_t rgba[4];
  if (a.bgra) p = bgraToRgba(p, rgba);
  switch (a.type) {
    case GL_BYTE: return colorAs<GLbyte>(p, a.size, glColor3bv, glColor4bv);
    case GL_UNSIGNED_BYTE: return colorAs<GLubyte>(p, a.size, glColor3ubv, glColor4ubv);
    case GL_SHORT: return colorAs<GLshort>(p, a.size, glColor3sv, glColor4sv);
    case GL_UNSIGNED_SHORT: return colorAs<GLushort>(p, a.size, glColor3usv, glColor4usv);
    case GL_INT: return colorAs<GLint>(p, a.size, glColor3iv, glColor4iv);
    case GL_UNSIGNED_INT: return colorAs<GLuint>(p, a.size, glColor3uiv, glColor4uiv);
    case GL_FLOAT: return colorAs<GLfloat>(p, a.size, glColor3fv, glColor4fv);
    case GL_DOUBLE: return colorAs<GLdouble>(p, a.size, glColor3dv, glColor4dv);
    default: return;
  }
}

template <typename T, typename N>
void normalAs(const uint8_t* bytes, N normal3) {
  T v[4];
  readComponents(bytes, 3, v);
  normal3(v);
}

void arrayNormal(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  switch (a.type) {
    case GL_BYTE: return normalAs<GLbyte>(p, glNormal3bv);
    case GL_SHORT: return normalAs<GLshort>(p, glNormal3sv);
    case GL_INT: return normalAs<GLint>(p, glNormal3iv);
    case GL_FLOAT: return normalAs<GLfloat>(p, glNormal3fv);
    case GL_DOUBLE: return normalAs<GLdouble>(p, glNormal3dv);
    default: return;
  }
}

template <typename T, typename V2, typename V3, typename V4>
void vertexAs(const uint8_t* bytes, int size, V2 v2, V3 v3, V4 v4) {
  T v[4];
  readComponents(bytes, size, v);
  if (size == 2)
    v2(v);
  else if (size == 3)
    v3(v);
  else
    v4(v);
}

void arrayVertex(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  switch (a.type) {
    case GL_SHORT: return vertexAs<GLshort>(p, a.size, glVertex2sv, glVertex3sv, glVertex4sv);
    case GL_INT: return vertexAs<GLint>(p, a.size, glVertex2iv, glVertex3iv, glVertex4iv);
    case GL_FLOAT: return vertexAs<GLfloat>(p, a.size, glVertex2fv, glVertex3fv, glVertex4fv);
    case GL_DOUBLE: return vertexAs<GLdouble>(p, a.size, glVertex2dv, glVertex3dv, glVertex4dv);
    default: return;
  }
}

void arraySecondaryColor(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  uint8_t rgba[4];
  if (a.bgra) p = bgraToRgba(p, rgba);
  auto none = [](const void*) {};
  switch (a.type) {
    case GL_BYTE: return colorAs<GLbyte>(p, 3, glSecondaryColor3bv, none);
    case GL_UNSIGNED_BYTE: return colorAs<GLubyte>(p, 3, glSecondaryColor3ubv, none);
    case GL_SHORT: return colorAs<GLshort>(p, 3, glSecondaryColor3sv, none);
    case GL_UNSIGNED_SHORT: return colorAs<GLushort>(p, 3, glSecondaryColor3usv, none);
    case GL_INT: return colorAs<GLint>(p, 3, glSecondaryColor3iv, none);
    case GL_UNSIGNED_INT: return colorAs<GLuint>(p, 3, glSecondaryColor3uiv, none);
    case GL_FLOAT: return colorAs<GLfloat>(p, 3, glSecondaryColor3fv, none);
    case GL_DOUBLE: return colorAs<GLdouble>(p, 3, glSecondaryColor3dv, none);
    default: return;
  }
}

// The scalar arrays: fog coordinate, colour index, edge flag.
template <typename T, typename F>
void scalarAs(const uint8_t* bytes, F set) {
  T v[4];
  readComponents(bytes, 1, v);
  set(v);
}

void arrayFogCoord(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  if (a.type == GL_DOUBLE) return scalarAs<GLdouble>(p, glFogCoorddv);
  return scalarAs<GLfloat>(p, glFogCoordfv);
}

void arrayIndex(const pipeline::ArrayView& a, uint32_t i) {
  const uint8_t* p = a.elementBytes(i);
  switch (a.type) {
    case GL_UNSIGNED_BYTE: return scalarAs<GLubyte>(p, glIndexubv);
    case GL_SHORT: return scalarAs<GLshort>(p, glIndexsv);
    case GL_INT: return scalarAs<GLint>(p, glIndexiv);
    case GL_FLOAT: return scalarAs<GLfloat>(p, glIndexfv);
    case GL_DOUBLE: return scalarAs<GLdouble>(p, glIndexdv);
    default: return;
  }
}

void arrayEdgeFlag(const pipeline::ArrayView& a, uint32_t i) {
  scalarAs<GLboolean>(a.elementBytes(i), glEdgeFlagv);
}

template <typename T, typename M1, typename M2, typename M3, typename M4>
void texCoordAs(const uint8_t* bytes, int size, GLenum unit, M1 m1, M2 m2, M3 m3, M4 m4) {
  T v[4];
  readComponents(bytes, size, v);
  switch (size) {
    case 1: return m1(unit, v);
    case 2: return m2(unit, v);
    case 3: return m3(unit, v);
    default: return m4(unit, v);
  }
}

void arrayTexCoord(const pipeline::ArrayView& a, uint32_t i, GLenum unit) {
  const uint8_t* p = a.elementBytes(i);
  switch (a.type) {
    case GL_SHORT:
      return texCoordAs<GLshort>(p, a.size, unit, glMultiTexCoord1sv, glMultiTexCoord2sv, glMultiTexCoord3sv,
                                 glMultiTexCoord4sv);
    case GL_INT:
      return texCoordAs<GLint>(p, a.size, unit, glMultiTexCoord1iv, glMultiTexCoord2iv, glMultiTexCoord3iv,
                               glMultiTexCoord4iv);
    case GL_FLOAT:
      return texCoordAs<GLfloat>(p, a.size, unit, glMultiTexCoord1fv, glMultiTexCoord2fv, glMultiTexCoord3fv,
                                 glMultiTexCoord4fv);
    case GL_DOUBLE:
      return texCoordAs<GLdouble>(p, a.size, unit, glMultiTexCoord1dv, glMultiTexCoord2dv, glMultiTexCoord3dv,
                                  glMultiTexCoord4dv);
    default: return;
  }
}

// Element e as the glEdgeFlag, glTexCoord, ..., glColor, glNormal and
// glVertex calls it stands for (GL 2.1 §2.8).
void arrayElement(const pipeline::ArraySources& src, uint32_t e) {
  if (src.edgeFlag) arrayEdgeFlag(src.edgeFlagView, e);
  for (int u = 0; u < kMaxTextureCoords; ++u)
    if (src.texCoord[u]) arrayTexCoord(src.texCoordView[u], e, GL_TEXTURE0 + u);
  if (src.fogCoord) arrayFogCoord(src.fogCoordView, e);
  if (src.index) arrayIndex(src.indexView, e);
  if (src.secondaryColor) arraySecondaryColor(src.secondaryColorView, e);
  if (src.color) arrayColor(src.colorView, e);
  if (src.normal) arrayNormal(src.normalView, e);
  if (src.vertex) arrayVertex(src.vertexView, e);  // last: it emits the vertex
}

// ---- In a display list (§5.4) -----------------------------------------------
// A draw is compiled as the glBegin/glEnd it stands for, its elements read
// now through glArrayElement's calls into the list's vertex node (Mesa's
// save_DrawArrays, save_DrawElements): it merges with the glBegin/glEnd
// pairs around it as they merge with each other. Errors are compiled.

// The enabled arrays, or a compiled error if one sources a mapped buffer.
bool resolveForList(pipeline::ListCompiler& list, pipeline::ArraySources& src) {
  if (pipeline::resolveArrays(*currentContext(), src) == GL_NO_ERROR) return true;
  list.recordError(*currentContext(), GL_INVALID_OPERATION);
  return false;
}

void compileDrawArrays(pipeline::ListCompiler& list, GLenum mode, GLint first, GLsizei count) {
  Context& ctx = *currentContext();
  if (!isPrimitiveMode(mode)) return list.recordError(ctx, GL_INVALID_ENUM);
  if (count < 0 || first < 0) return list.recordError(ctx, GL_INVALID_VALUE);
  pipeline::ArraySources src;
  if (!resolveForList(list, src)) return;
  list.begin(mode, true);
  for (GLsizei i = 0; i < count; ++i)
    arrayElement(src, static_cast<uint32_t>(first) + static_cast<uint32_t>(i));
  list.end();
}

void compileDrawElements(pipeline::ListCompiler& list, GLenum mode, GLsizei count, GLenum type,
                         const void* indices, GLint baseVertex = 0) {
  Context& ctx = *currentContext();
  if (!isPrimitiveMode(mode)) return list.recordError(ctx, GL_INVALID_ENUM);
  if (count < 0) return list.recordError(ctx, GL_INVALID_VALUE);
  if (!isIndexType(type)) return list.recordError(ctx, GL_INVALID_ENUM);
  pipeline::ArraySources src;
  if (!resolveForList(list, src)) return;
  if (const BufferObject* b = ctx.buffers.find(ctx.vertexArray.elementArrayBufferBinding); b && b->mapped)
    return list.recordError(ctx, GL_INVALID_OPERATION);
  pipeline::IndexList elements;  // read where they lie, as a draw reads them
  if (!indexList(ctx, count, type, indices, elements, baseVertex)) return;
  // Restart as enabled now: the list keeps the primitives it compiled.
  const bool restart = ctx.vertexArray.primitiveRestart;
  const GLuint restartIndex = ctx.vertexArray.primitiveRestartIndex;
  list.begin(mode, true);
  for (uint32_t i = 0; i < elements.count; ++i) {
    if (restart && elements.at(i) == restartIndex)
      list.restartPrimitive();
    else
      arrayElement(src, elements.element(i));
  }
  list.end();
}

}  // namespace

extern "C" {

// Inside glBegin/glEnd, element i is the glColor, glNormal and glVertex calls
// it stands for (GL 2.1 §2.8), through the immediate-mode path.
// In a list, those calls are compiled with the element's values (inside the
// list's glBegin/glEnd they join its vertex node).
GLAPI void APIENTRY glArrayElement(GLint i) {
  Context* ctx = api::context();
  if (!ctx || i < 0) return;
  // NV_primitive_restart: the restart index is a glPrimitiveRestartNV.
  if (ctx->vertexArray.primitiveRestart && static_cast<GLuint>(i) == ctx->vertexArray.primitiveRestartIndex)
    return glPrimitiveRestartNV();
  pipeline::ArraySources src;
  if (pipeline::ListCompiler* list = api::listCompiler(ctx)) {
    if (resolveForList(*list, src)) arrayElement(src, static_cast<uint32_t>(i));
    return;
  }
  if (!resolve(*ctx, src)) return;
  arrayElement(src, static_cast<uint32_t>(i));
}

GLAPI void APIENTRY glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  if (api::compiledDraw([&](pipeline::ListCompiler& l) { compileDrawArrays(l, mode, first, count); })) return;
  Context* ctx = drawContext(mode, count);
  if (!ctx) return;
  if (first < 0) return ctx->recordError(GL_INVALID_VALUE);
  pipeline::ArraySources src;
  if (!resolve(*ctx, src)) return;
  pipeline::flushVertices(*ctx);
  guarded(*ctx, [&] {
    pipeline::drawArrays(*ctx, src, mode, static_cast<uint32_t>(first), static_cast<uint32_t>(count));
  });
}

GLAPI void APIENTRY glDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  glDrawElementsBaseVertex(mode, count, type, indices, 0);
}

// ARB_draw_elements_base_vertex (GL 3.2 §2.8.2): the base vertex is added to
// every index; in a list it is compiled as the vertices it reads now, as
// glDrawElements is (Mesa's save_DrawElementsBaseVertex).
GLAPI void APIENTRY glDrawElementsBaseVertex(GLenum mode, GLsizei count, GLenum type, const void* indices,
                                             GLint basevertex) {
  if (api::compiledDraw(
          [&](pipeline::ListCompiler& l) { compileDrawElements(l, mode, count, type, indices, basevertex); }))
    return;
  Context* ctx = drawContext(mode, count);
  if (!ctx) return;
  if (!isIndexType(type)) return ctx->recordError(GL_INVALID_ENUM);
  drawElements(*ctx, mode, count, type, indices, nullptr, basevertex);
}

// The range is a promise about the indices (GL 2.1 §2.8). Mesa passes it to
// its draw module as the index bounds (which decide how the draw is split:
// pipeline/array_draw.cpp), clamped to the index type's largest value, and
// ignores it when it starts at 2,000,000,000 or more or ends past INT_MAX
// (main/draw.c).
GLAPI void APIENTRY glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                        const void* indices) {
  glDrawRangeElementsBaseVertex(mode, start, end, count, type, indices, 0);
}

// The range is of the indices as stored; the elements read are those plus
// the base vertex (a range whose first element would be negative is dropped).
GLAPI void APIENTRY glDrawRangeElementsBaseVertex(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                                  GLenum type, const void* indices, GLint basevertex) {
  // Mesa's save_DrawRangeElements: the checks, then compiled as glDrawElements.
  if (api::compiledDraw([&](pipeline::ListCompiler& l) {
        if (isPrimitiveMode(mode) && count >= 0 && isIndexType(type) && end < start)
          return l.recordError(*currentContext(), GL_INVALID_VALUE);
        compileDrawElements(l, mode, count, type, indices, basevertex);
      }))
    return;
  Context* ctx = drawContext(mode, count);
  if (!ctx) return;
  if (end < start) return ctx->recordError(GL_INVALID_VALUE);
  if (!isIndexType(type)) return ctx->recordError(GL_INVALID_ENUM);
  if (static_cast<GLint>(end) < 0 || start >= 2000000000u)
    return drawElements(*ctx, mode, count, type, indices, nullptr, basevertex);
  const GLuint largest = type == GL_UNSIGNED_BYTE ? 0xffu : (type == GL_UNSIGNED_SHORT ? 0xffffu : ~0u);
  const int64_t first = int64_t(std::min(start, largest)) + basevertex;
  const int64_t last = int64_t(std::min(end, largest)) + basevertex;
  if (first < 0 || last > int64_t(UINT32_MAX))
    return drawElements(*ctx, mode, count, type, indices, nullptr, basevertex);
  const pipeline::IndexBounds range{true, uint32_t(first), uint32_t(last)};
  drawElements(*ctx, mode, count, type, indices, &range, basevertex);
}

// Each draw of a multi-draw is a draw of its own (Mesa hands them to the
// draw module one by one).
GLAPI void APIENTRY glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count,
                                      GLsizei drawcount) {
  // Mesa's save_MultiDrawArrays: the checks, then each draw compiled as glDrawArrays.
  if (api::compiledDraw([&](pipeline::ListCompiler& l) {
        Context& c = *currentContext();
        if (!isPrimitiveMode(mode)) return l.recordError(c, GL_INVALID_ENUM);
        if (drawcount < 0) return l.recordError(c, GL_INVALID_VALUE);
        if (drawcount == 0 || !first || !count) return;
        for (GLsizei i = 0; i < drawcount; ++i)
          if (count[i] < 0 || first[i] < 0) return l.recordError(c, GL_INVALID_VALUE);
        for (GLsizei i = 0; i < drawcount; ++i)
          if (count[i] > 0) compileDrawArrays(l, mode, first[i], count[i]);
      }))
    return;
  Context* ctx = drawContext(mode, drawcount);
  if (!ctx || drawcount == 0 || !first || !count) return;
  for (GLsizei i = 0; i < drawcount; ++i)
    if (count[i] < 0 || first[i] < 0) return ctx->recordError(GL_INVALID_VALUE);
  pipeline::ArraySources src;
  if (!resolve(*ctx, src)) return;
  pipeline::flushVertices(*ctx);
  guarded(*ctx, [&] {
    for (GLsizei i = 0; i < drawcount; ++i)
      pipeline::drawArrays(*ctx, src, mode, static_cast<uint32_t>(first[i]), static_cast<uint32_t>(count[i]));
  });
}

GLAPI void APIENTRY glMultiDrawElements(GLenum mode, const GLsizei* count, GLenum type,
                                        const void* const* indices, GLsizei drawcount) {
  glMultiDrawElementsBaseVertex(mode, count, type, indices, drawcount, nullptr);
}

// Each list with its own base vertex (`basevertex` null: all 0).
GLAPI void APIENTRY glMultiDrawElementsBaseVertex(GLenum mode, const GLsizei* count, GLenum type,
                                                  const void* const* indices, GLsizei drawcount,
                                                  const GLint* basevertex) {
  auto base = [basevertex](GLsizei i) { return basevertex ? basevertex[i] : 0; };
  if (api::compiledDraw([&](pipeline::ListCompiler& l) {
        Context& c = *currentContext();
        if (!isPrimitiveMode(mode)) return l.recordError(c, GL_INVALID_ENUM);
        if (drawcount < 0) return l.recordError(c, GL_INVALID_VALUE);
        if (!isIndexType(type)) return l.recordError(c, GL_INVALID_ENUM);
        if (drawcount == 0 || !count || !indices) return;
        for (GLsizei i = 0; i < drawcount; ++i)
          if (count[i] > 0) compileDrawElements(l, mode, count[i], type, indices[i], base(i));
      }))
    return;
  Context* ctx = drawContext(mode, drawcount);
  if (!ctx) return;
  if (!isIndexType(type)) return ctx->recordError(GL_INVALID_ENUM);
  if (drawcount == 0 || !count || !indices) return;
  for (GLsizei i = 0; i < drawcount; ++i)
    if (count[i] < 0) return ctx->recordError(GL_INVALID_VALUE);
  pipeline::ArraySources src;
  if (!resolve(*ctx, src)) return;
  struct SiteLists {};
  std::vector<pipeline::IndexList>& lists = pipeline::threadScratch<std::vector<pipeline::IndexList>, SiteLists>();
  guarded(*ctx, [&] { lists.resize(static_cast<size_t>(drawcount)); });
  if (lists.size() != static_cast<size_t>(drawcount)) return;
  for (GLsizei i = 0; i < drawcount; ++i)
    if (!indexList(*ctx, count[i], type, indices[i], lists[i], base(i))) return;
  pipeline::flushVertices(*ctx);
  // One draw of several to Mesa's draw module: the index bounds it computes
  // are those of all the lists together.
  struct SiteRuns {};
  std::vector<pipeline::IndexList>& runs = pipeline::threadScratch<std::vector<pipeline::IndexList>, SiteRuns>();
  guarded(*ctx, [&] {
    runs.clear();
    for (const pipeline::IndexList& list : lists) appendRestartRuns(*ctx, list, runs);
    const pipeline::IndexBounds bounds = pipeline::elementBounds(*ctx, src, runs.data(), runs.size());
    for (const pipeline::IndexList& run : runs) pipeline::drawElements(*ctx, src, mode, run, bounds);
  });
}

}  // extern "C"
