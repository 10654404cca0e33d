// Occlusion queries (GL 2.1 §4.1.7; GL 1.5 and ARB_occlusion_query): the
// objects are state/query_objects.h, and the fragment stage counts. What
// Mesa does at the edges, measured: glIsQuery is false for a generated name
// until its first glBeginQuery; a name glGenQueries never gave may begin a
// query; deleting the active query ends it; asking for the result of the
// active query, or of one never begun, is GL_INVALID_OPERATION before a bad
// pname is GL_INVALID_ENUM. Results are always available at glEndQuery.
#include <cstdint>

#include "api/api.h"
#include "api/list_record.h"
#include "pipeline/pixel_rect.h"

using namespace glfixed;

namespace {

constexpr GLint kQueryCounterBits = 64;  // llvmpipe's GL_QUERY_COUNTER_BITS

// The query object whose result glGetQueryObject* may read, or null after
// recording GL_INVALID_OPERATION.
QueryObject* finishedQuery(Context& ctx, GLuint id) {
  QueryObject* q = id ? ctx.queries.find(id) : nullptr;
  if (!q || !q->everActive || ctx.queries.active() == id) {
    ctx.recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return q;
}

// GL_QUERY_RESULT or GL_QUERY_RESULT_AVAILABLE of a finished query, the
// count saturated at `most` (Mesa's clamp to the type's largest value).
template <typename T>
void getQueryObject(GLuint id, GLenum pname, T* params, uint64_t most) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  QueryObject* q = finishedQuery(*ctx, id);
  if (!q) return;
  T value;
  switch (pname) {
    case GL_QUERY_RESULT: value = static_cast<T>(q->samplesPassed > most ? most : q->samplesPassed); break;
    case GL_QUERY_RESULT_AVAILABLE: value = GL_TRUE; break;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  if (params) *params = value;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glGenQueries(GLsizei n, GLuint* ids) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (ids) ctx->queries.generate(n, ids);
}

GLAPI void APIENTRY glDeleteQueries(GLsizei n, const GLuint* ids) {
  Context* ctx = api::contextFlushed();  // the active query counts what was drawn before
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!ids) return;
  if (ctx->queries.active()) pipeline::flushBitmapCache(*ctx);
  for (GLsizei i = 0; i < n; ++i) ctx->queries.remove(ids[i]);
}

GLAPI GLboolean APIENTRY glIsQuery(GLuint id) {
  Context* ctx = api::contextForQuery();
  return ctx && ctx->queries.isQuery(id) ? GL_TRUE : GL_FALSE;
}

GLAPI void APIENTRY glBeginQuery(GLenum target, GLuint id) {
  if (api::compiled(&glBeginQuery, target, id)) return;
  Context* ctx = api::contextFlushed();  // what was drawn before is not counted
  if (!ctx) return;
  if (target != GL_SAMPLES_PASSED) return ctx->recordError(GL_INVALID_ENUM);
  if (id == 0 || ctx->queries.active() != 0) return ctx->recordError(GL_INVALID_OPERATION);
  pipeline::flushBitmapCache(*ctx);  // st_BeginQuery: cached bitmaps are drawn first
  ctx->queries.begin(id);
}

GLAPI void APIENTRY glEndQuery(GLenum target) {
  if (api::compiled(&glEndQuery, target)) return;
  Context* ctx = api::contextFlushed();  // the buffered vertices are counted
  if (!ctx) return;
  if (target != GL_SAMPLES_PASSED) return ctx->recordError(GL_INVALID_ENUM);
  if (ctx->queries.active() == 0) return ctx->recordError(GL_INVALID_OPERATION);
  pipeline::flushBitmapCache(*ctx);  // and counted (st_EndQuery)
  ctx->queries.end();
}

GLAPI void APIENTRY glGetQueryiv(GLenum target, GLenum pname, GLint* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (target != GL_SAMPLES_PASSED) return ctx->recordError(GL_INVALID_ENUM);
  GLint value;
  switch (pname) {
    case GL_CURRENT_QUERY: value = static_cast<GLint>(ctx->queries.active()); break;
    case GL_QUERY_COUNTER_BITS: value = kQueryCounterBits; break;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  if (params) *params = value;
}

GLAPI void APIENTRY glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params) {
  getQueryObject(id, pname, params, INT32_MAX);
}

GLAPI void APIENTRY glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint* params) {
  getQueryObject(id, pname, params, UINT32_MAX);
}

// ARB_occlusion_query's names for the same commands.
GLAPI void APIENTRY glGenQueriesARB(GLsizei n, GLuint* ids) { glGenQueries(n, ids); }
GLAPI void APIENTRY glDeleteQueriesARB(GLsizei n, const GLuint* ids) { glDeleteQueries(n, ids); }
GLAPI GLboolean APIENTRY glIsQueryARB(GLuint id) { return glIsQuery(id); }
GLAPI void APIENTRY glBeginQueryARB(GLenum target, GLuint id) { glBeginQuery(target, id); }
GLAPI void APIENTRY glEndQueryARB(GLenum target) { glEndQuery(target); }
GLAPI void APIENTRY glGetQueryivARB(GLenum target, GLenum pname, GLint* params) {
  glGetQueryiv(target, pname, params);
}
GLAPI void APIENTRY glGetQueryObjectivARB(GLuint id, GLenum pname, GLint* params) {
  glGetQueryObjectiv(id, pname, params);
}
GLAPI void APIENTRY glGetQueryObjectuivARB(GLuint id, GLenum pname, GLuint* params) {
  glGetQueryObjectuiv(id, pname, params);
}

}  // extern "C"
