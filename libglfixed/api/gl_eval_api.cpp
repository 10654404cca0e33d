// Evaluators (GL 2.1 §5.1): glMap1/glMap2, glGetMap, glMapGrid, glEvalCoord,
// glEvalPoint, glEvalMesh. The commands are plain functions (eval_commands.h);
// the extern "C" entry points gather arguments and call them.
#include <cmath>
#include <type_traits>

#include "api/api.h"
#include "api/eval_commands.h"
#include "api/list_record.h"
#include "pipeline/evaluator.h"

using namespace glfixed;

namespace glfixed::api {

namespace {

// Mesa's order of checks (main/eval.c): the domain, the order, the target,
// the stride (Mesa looks at a null glMap1 pointer before the target; here it
// comes last, which only matters when two arguments are wrong at once).
bool checkMapArguments(Context& ctx, GLenum target, bool twoD, float u1, float u2, GLint ustride,
                       GLint uorder, float v1, float v2, GLint vstride, GLint vorder,
                       const std::vector<float>& points) {
  const int k = evalComponents(target);
  GLenum error = GL_NO_ERROR;
  if (u1 == u2 || (twoD && v1 == v2))
    error = GL_INVALID_VALUE;
  else if (uorder < 1 || uorder > kMaxEvalOrder || (twoD && (vorder < 1 || vorder > kMaxEvalOrder)))
    error = GL_INVALID_VALUE;
  else if (k == 0)
    error = GL_INVALID_ENUM;
  else if (ustride < k || (twoD && vstride < k))
    error = GL_INVALID_VALUE;
  else if (twoD ? !isMap2Target(target) : !isMap1Target(target))  // a map of the other dimension
    error = GL_INVALID_ENUM;
  else if (points.empty())  // a null pointer (Mesa accepts it for glMap2, then reads nothing)
    error = GL_INVALID_VALUE;
  if (error != GL_NO_ERROR) ctx.recordError(error);
  return error == GL_NO_ERROR;
}

void storeMap(Context& ctx, GLenum target, float u1, float u2, GLint uorder, float v1, float v2, GLint vorder,
              std::vector<float> points) {
  pipeline::flushVertices(ctx);  // buffered vertices were evaluated with the old map
  EvalMap& m = *ctx.evalMaps.find(target);
  m.uorder = uorder;
  m.vorder = vorder;
  m.u1 = u1;
  m.u2 = u2;
  m.v1 = v1;
  m.v2 = v2;
  m.points = std::move(points);
}

// Sends one evaluated vertex down the glVertex path. Like Mesa's vbo
// (vbo_exec_api.c, EvalCoord), every attribute a map generates first joins
// the vertex format, as glColor/glNormal would make it, whether or not a
// vertex follows; the vertex then carries the evaluated values, and the
// current values are put back: glEvalCoord never changes them.
void emit(Context& ctx, const pipeline::EvaluatedVertex& e) {
  if (ctx.insideBeginEnd || ctx.vbo.verticesBuffered) {
    if (e.hasNormal) pipeline::normalBecomesVertexData(ctx);
    if (e.hasColor) pipeline::colorBecomesVertexData(ctx, 4);  // GL_MAP*_COLOR_4: four components
  }
  if (!e.hasVertex) return;
  const CurrentAttrib saved = ctx.current;
  if (e.hasColor) ctx.current.color = e.color;
  if (e.hasNormal) ctx.current.normal = e.normal;
  if (e.hasTexCoord) ctx.current.texCoord[0] = e.texCoord;
  glVertex4f(e.position.x, e.position.y, e.position.z, e.position.w);
  ctx.current = saved;
}

bool hasVertexMap(const std::array<bool, kEvalTargets>& enabled) {
  return enabled[GL_MAP1_VERTEX_3 - GL_MAP1_COLOR_4] || enabled[GL_MAP1_VERTEX_4 - GL_MAP1_COLOR_4];
}

// glEvalCoord and glEvalPoint in a list (§5.4). Between the list's glBegin
// and glEnd the vertex node ends there, and the rest of that glBegin/glEnd
// is compiled as commands (Mesa's save module: dlist_fallback).
template <typename... A>
bool compiledEvaluation(void (*fn)(A...), A... args) {
  pipeline::ListCompiler* list = listCompiler(currentContext());
  if (!list) return false;
  if (list->insideBeginEnd()) list->fallBackToCommands();
  return compiledCompound(fn, args...);
}

}  // namespace

void map1(GLenum target, float u1, float u2, GLint stride, GLint order, std::vector<float> points) {
  // The points were gathered by the caller: a list keeps them (§5.4).
  if (compiled(&map1, target, u1, u2, stride, order, points)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  if (!checkMapArguments(*ctx, target, false, u1, u2, stride, order, 0, 1, 0, 1, points)) return;
  storeMap(*ctx, target, u1, u2, order, 0, 1, 1, std::move(points));
}

void map2(GLenum target, float u1, float u2, GLint ustride, GLint uorder, float v1, float v2, GLint vstride,
          GLint vorder, std::vector<float> points) {
  if (compiled(&map2, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  if (!checkMapArguments(*ctx, target, true, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    return;
  storeMap(*ctx, target, u1, u2, uorder, v1, v2, vorder, std::move(points));
}

void mapGrid1(GLint un, float u1, float u2) {
  if (compiled(&mapGrid1, un, u1, u2)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  if (un < 1) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  pipeline::flushVertices(*ctx);
  ctx->eval.grid1Segments = un;
  ctx->eval.grid1U1 = u1;
  ctx->eval.grid1U2 = u2;
}

void mapGrid2(GLint un, float u1, float u2, GLint vn, float v1, float v2) {
  if (compiled(&mapGrid2, un, u1, u2, vn, v1, v2)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  if (un < 1 || vn < 1) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  pipeline::flushVertices(*ctx);
  EvalAttrib& e = ctx->eval;
  e.grid2USegments = un;
  e.grid2U1 = u1;
  e.grid2U2 = u2;
  e.grid2VSegments = vn;
  e.grid2V1 = v1;
  e.grid2V2 = v2;
}

void evalCoord1(float u) {
  if (compiledEvaluation(&evalCoord1, u)) return;
  Context* ctx = currentContext();
  if (ctx) emit(*ctx, pipeline::evaluate1(ctx->eval, ctx->evalMaps, u));
}

void evalCoord2(float u, float v) {
  if (compiledEvaluation(&evalCoord2, u, v)) return;
  Context* ctx = currentContext();
  if (ctx) emit(*ctx, pipeline::evaluate2(ctx->eval, ctx->evalMaps, u, v));
}

// §5.1: glEvalPoint1(i) is glEvalCoord1(i * du + u1), du = (u2 - u1) / n, in float.
void evalPoint1(GLint i) {
  if (compiledEvaluation(&evalPoint1, i)) return;
  Context* ctx = currentContext();
  if (!ctx) return;
  const EvalAttrib& e = ctx->eval;
  const float du = (e.grid1U2 - e.grid1U1) / static_cast<float>(e.grid1Segments);
  evalCoord1(static_cast<float>(i) * du + e.grid1U1);
}

void evalPoint2(GLint i, GLint j) {
  if (compiledEvaluation(&evalPoint2, i, j)) return;
  Context* ctx = currentContext();
  if (!ctx) return;
  const EvalAttrib& e = ctx->eval;
  const float du = (e.grid2U2 - e.grid2U1) / static_cast<float>(e.grid2USegments);
  const float dv = (e.grid2V2 - e.grid2V1) / static_cast<float>(e.grid2VSegments);
  evalCoord2(static_cast<float>(i) * du + e.grid2U1, static_cast<float>(j) * dv + e.grid2V1);
}

// glEvalMesh is glBegin/glEvalCoord.../glEnd, the parameter stepped by adding
// du each time (Mesa's loop, whose sums are the floats that count).
void evalMesh1(GLenum mode, GLint i1, GLint i2) {
  if (compiledCompound(&evalMesh1, mode, i1, i2)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  GLenum primitive;
  switch (mode) {
    case GL_POINT: primitive = GL_POINTS; break;
    case GL_LINE: primitive = GL_LINE_STRIP; break;
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
  const EvalAttrib& e = ctx->eval;
  if (!hasVertexMap(e.map1Enabled)) return;
  const float du = (e.grid1U2 - e.grid1U1) / static_cast<float>(e.grid1Segments);
  float u = e.grid1U1 + static_cast<float>(i1) * du;
  glBegin(primitive);
  for (long long i = i1; i <= i2; ++i, u += du) evalCoord1(u);  // 64-bit: i2 may be INT_MAX
  glEnd();
}

void evalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  if (compiledCompound(&evalMesh2, mode, i1, i2, j1, j2)) return;
  Context* ctx = contextForQuery();
  if (!ctx) return;
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  const EvalAttrib& e = ctx->eval;
  if (!hasVertexMap(e.map2Enabled)) return;
  const float du = (e.grid2U2 - e.grid2U1) / static_cast<float>(e.grid2USegments);
  const float dv = (e.grid2V2 - e.grid2V1) / static_cast<float>(e.grid2VSegments);
  const float u1 = e.grid2U1 + static_cast<float>(i1) * du;
  const float v1 = e.grid2V1 + static_cast<float>(j1) * dv;
  float u, v;
  long long i, j;  // 64-bit: i2 or j2 may be INT_MAX
  switch (mode) {
    case GL_POINT:
      glBegin(GL_POINTS);
      for (v = v1, j = j1; j <= j2; ++j, v += dv)
        for (u = u1, i = i1; i <= i2; ++i, u += du) evalCoord2(u, v);
      glEnd();
      break;
    case GL_LINE:  // the rows, then the columns, each a line strip
      for (v = v1, j = j1; j <= j2; ++j, v += dv) {
        glBegin(GL_LINE_STRIP);
        for (u = u1, i = i1; i <= i2; ++i, u += du) evalCoord2(u, v);
        glEnd();
      }
      for (u = u1, i = i1; i <= i2; ++i, u += du) {
        glBegin(GL_LINE_STRIP);
        for (v = v1, j = j1; j <= j2; ++j, v += dv) evalCoord2(u, v);
        glEnd();
      }
      break;
    default:  // GL_FILL: one triangle strip per row of the grid
      for (v = v1, j = j1; j < j2; ++j, v += dv) {
        glBegin(GL_TRIANGLE_STRIP);
        for (u = u1, i = i1; i <= i2; ++i, u += du) {
          evalCoord2(u, v);
          evalCoord2(u, v + dv);
        }
        glEnd();
      }
      break;
  }
}

bool getEvalState(const Context& ctx, GLenum pname, GLdouble* out, int* count) {
  const EvalAttrib& e = ctx.eval;
  auto set = [&](std::initializer_list<double> values) {
    *count = 0;
    for (double d : values) out[(*count)++] = d;
    return true;
  };
  if (isMap1Target(pname)) return set({double(e.map1Enabled[evalSlot(pname)])});
  if (isMap2Target(pname)) return set({double(e.map2Enabled[evalSlot(pname)])});
  switch (pname) {
    case GL_AUTO_NORMAL: return set({double(e.autoNormal)});
    case GL_MAX_EVAL_ORDER: return set({double(kMaxEvalOrder)});
    case GL_MAP1_GRID_DOMAIN: return set({e.grid1U1, e.grid1U2});
    case GL_MAP1_GRID_SEGMENTS: return set({double(e.grid1Segments)});
    case GL_MAP2_GRID_DOMAIN: return set({e.grid2U1, e.grid2U2, e.grid2V1, e.grid2V2});
    case GL_MAP2_GRID_SEGMENTS: return set({double(e.grid2USegments), double(e.grid2VSegments)});
    default: return false;
  }
}

}  // namespace glfixed::api

namespace {

// glGetMap (§6.1.10): GL_COEFF, GL_ORDER or GL_DOMAIN of one map.
template <typename T>
void getMap(GLenum target, GLenum query, T* v) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const EvalMap* m = ctx->evalMaps.find(target);
  if (!m) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (query != GL_COEFF && query != GL_ORDER && query != GL_DOMAIN) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  const bool twoD = isMap2Target(target);
  // Integers round to the nearest, halves away from zero (Mesa: lroundf).
  auto put = [](float f) { return std::is_integral<T>::value ? T(std::lround(f)) : T(f); };
  switch (query) {
    case GL_COEFF:
      for (size_t i = 0; i < m->points.size(); ++i) v[i] = put(m->points[i]);
      break;
    case GL_ORDER:
      v[0] = T(m->uorder);
      if (twoD) v[1] = T(m->vorder);
      break;
    default:
      v[0] = put(m->u1);
      v[1] = put(m->u2);
      if (twoD) {
        v[2] = put(m->v1);
        v[3] = put(m->v2);
      }
      break;
  }
}

template <typename T>
void map1(GLenum target, T u1, T u2, GLint stride, GLint order, const T* points) {
  api::map1(target, static_cast<float>(u1), static_cast<float>(u2), stride, order,
            api::gatherMapPoints(target, stride, order, 0, 1, points));
}

template <typename T>
void map2(GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2, GLint vstride, GLint vorder,
          const T* points) {
  api::map2(target, static_cast<float>(u1), static_cast<float>(u2), ustride, uorder, static_cast<float>(v1),
            static_cast<float>(v2), vstride, vorder,
            api::gatherMapPoints(target, ustride, uorder, vstride, vorder, points));
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                            const GLfloat* points) {
  map1(target, u1, u2, stride, order, points);
}
GLAPI void APIENTRY glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                            const GLdouble* points) {
  map1(target, u1, u2, stride, order, points);
}
GLAPI void APIENTRY glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1,
                            GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
GLAPI void APIENTRY glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder, GLdouble v1,
                            GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

GLAPI void APIENTRY glGetMapfv(GLenum target, GLenum query, GLfloat* v) { getMap(target, query, v); }
GLAPI void APIENTRY glGetMapdv(GLenum target, GLenum query, GLdouble* v) { getMap(target, query, v); }
GLAPI void APIENTRY glGetMapiv(GLenum target, GLenum query, GLint* v) { getMap(target, query, v); }

GLAPI void APIENTRY glMapGrid1f(GLint un, GLfloat u1, GLfloat u2) { api::mapGrid1(un, u1, u2); }
GLAPI void APIENTRY glMapGrid1d(GLint un, GLdouble u1, GLdouble u2) {
  api::mapGrid1(un, static_cast<float>(u1), static_cast<float>(u2));
}
GLAPI void APIENTRY glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  api::mapGrid2(un, u1, u2, vn, v1, v2);
}
GLAPI void APIENTRY glMapGrid2d(GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
  api::mapGrid2(un, static_cast<float>(u1), static_cast<float>(u2), vn, static_cast<float>(v1),
                static_cast<float>(v2));
}

GLAPI void APIENTRY glEvalCoord1f(GLfloat u) { api::evalCoord1(u); }
GLAPI void APIENTRY glEvalCoord1d(GLdouble u) { api::evalCoord1(static_cast<float>(u)); }
GLAPI void APIENTRY glEvalCoord1fv(const GLfloat* u) {
  if (u) api::evalCoord1(u[0]);
}
GLAPI void APIENTRY glEvalCoord1dv(const GLdouble* u) {
  if (u) api::evalCoord1(static_cast<float>(u[0]));
}
GLAPI void APIENTRY glEvalCoord2f(GLfloat u, GLfloat v) { api::evalCoord2(u, v); }
GLAPI void APIENTRY glEvalCoord2d(GLdouble u, GLdouble v) {
  api::evalCoord2(static_cast<float>(u), static_cast<float>(v));
}
GLAPI void APIENTRY glEvalCoord2fv(const GLfloat* u) {
  if (u) api::evalCoord2(u[0], u[1]);
}
GLAPI void APIENTRY glEvalCoord2dv(const GLdouble* u) {
  if (u) api::evalCoord2(static_cast<float>(u[0]), static_cast<float>(u[1]));
}
GLAPI void APIENTRY glEvalPoint1(GLint i) { api::evalPoint1(i); }
GLAPI void APIENTRY glEvalPoint2(GLint i, GLint j) { api::evalPoint2(i, j); }
GLAPI void APIENTRY glEvalMesh1(GLenum mode, GLint i1, GLint i2) { api::evalMesh1(mode, i1, i2); }
GLAPI void APIENTRY glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  api::evalMesh2(mode, i1, i2, j1, j2);
}

}  // extern "C"
