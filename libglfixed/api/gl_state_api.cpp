// Capabilities and the per-fragment, viewport and polygon state entry points
// (GL 2.1 §2.11.1, §3.5.1, §4.1.6, §4.2.2, §5.1).
#include <algorithm>

#include "api/api.h"
#include "vertex/color_material.h"
#include "vertex/lighting_queries.h"

using namespace glfixed;

namespace {

bool isDepthFunc(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

// The capabilities the core owns; lighting capabilities belong to the
// lighting stage (vertex/lighting_queries.h). Null: not a core capability.
bool* coreCapability(Context& ctx, GLenum cap) {
  switch (cap) {
    case GL_DEPTH_TEST: return &ctx.depth.test;
    case GL_CULL_FACE: return &ctx.polygon.cullFace;
    case GL_DITHER: return &ctx.colorBuffer.dither;
    default: return nullptr;
  }
}

void setCapability(GLenum cap, bool enabled) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (bool* flag = coreCapability(*ctx, cap)) {
    if (*flag == enabled) return;  // no change: nothing is flushed
    pipeline::flushVertices(*ctx);
    *flag = enabled;
    return;
  }
  GLdouble current[16];
  int count = 0;
  if (getLightingState(*ctx, cap, current, &count) && count == 1 && (current[0] != 0) == enabled) return;
  pipeline::flushVertices(*ctx);
  if (!setLightingCapability(*ctx, cap, enabled)) ctx->recordError(GL_INVALID_ENUM);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glEnable(GLenum cap) { setCapability(cap, true); }
GLAPI void APIENTRY glDisable(GLenum cap) { setCapability(cap, false); }

GLAPI GLboolean APIENTRY glIsEnabled(GLenum cap) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  if (bool* flag = coreCapability(*ctx, cap)) return *flag ? GL_TRUE : GL_FALSE;
  GLdouble v[16];
  int count = 0;
  switch (cap) {  // the lighting capabilities, through the lighting stage's queries
    case GL_LIGHTING: case GL_COLOR_MATERIAL: case GL_NORMALIZE: case GL_RESCALE_NORMAL:
    case GL_LIGHT0: case GL_LIGHT1: case GL_LIGHT2: case GL_LIGHT3:
    case GL_LIGHT4: case GL_LIGHT5: case GL_LIGHT6: case GL_LIGHT7:
      if (getLightingState(*ctx, cap, v, &count) && count == 1) return v[0] != 0 ? GL_TRUE : GL_FALSE;
      break;
    default:
      break;
  }
  ctx->recordError(GL_INVALID_ENUM);
  return GL_FALSE;
}

// Like Mesa, the setters below return before flushing the buffered vertices
// when the value does not change (a redundant call does not cut a merged
// draw); glClearColor and glClearDepth never draw them (probed on Mesa 22.3).
GLAPI void APIENTRY glViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  // Sizes are clamped to GL_MAX_VIEWPORT_DIMS (GL 2.1 §2.11.1); the origin to
  // Mesa's GL_VIEWPORT_BOUNDS_RANGE, [-32768, 32767] (so x + width cannot overflow).
  ViewportAttrib& v = ctx->viewport;
  x = std::clamp(x, kViewportBoundsMin, kViewportBoundsMax);
  y = std::clamp(y, kViewportBoundsMin, kViewportBoundsMax);
  width = std::min(width, kMaxViewportSize);
  height = std::min(height, kMaxViewportSize);
  ctx->viewportInitialized = true;
  if (v.x == x && v.y == y && v.width == width && v.height == height) return;
  pipeline::flushVertices(*ctx);
  v.x = x;
  v.y = y;
  v.width = width;
  v.height = height;
}

GLAPI void APIENTRY glDepthRange(GLclampd zNear, GLclampd zFar) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const auto n = api::clamp01(zNear), f = api::clamp01(zFar);
  if (ctx->viewport.depthNear == n && ctx->viewport.depthFar == f) return;
  pipeline::flushVertices(*ctx);
  ctx->viewport.depthNear = n;
  ctx->viewport.depthFar = f;
}

GLAPI void APIENTRY glDepthFunc(GLenum func) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!isDepthFunc(func)) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (ctx->depth.func == func) return;
  pipeline::flushVertices(*ctx);
  ctx->depth.func = func;
}

GLAPI void APIENTRY glDepthMask(GLboolean flag) {
  Context* ctx = api::contextForQuery();
  if (!ctx || ctx->depth.writeMask == (flag != GL_FALSE)) return;
  pipeline::flushVertices(*ctx);
  ctx->depth.writeMask = flag != GL_FALSE;
}

GLAPI void APIENTRY glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  bool* m = ctx->colorBuffer.writeMask;
  const bool want[4] = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
  if (std::equal(want, want + 4, m)) return;
  pipeline::flushVertices(*ctx);
  std::copy(want, want + 4, m);
}

GLAPI void APIENTRY glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  ctx->colorBuffer.clearColor = glm::vec4(api::clamp01(r), api::clamp01(g), api::clamp01(b), api::clamp01(a));
}

GLAPI void APIENTRY glClearDepth(GLclampd depth) {
  Context* ctx = api::contextForQuery();
  if (ctx) ctx->depth.clearDepth = api::clamp01(depth);
}

GLAPI void APIENTRY glCullFace(GLenum mode) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (ctx->polygon.cullFaceMode == mode) return;
  pipeline::flushVertices(*ctx);
  ctx->polygon.cullFaceMode = mode;
}

GLAPI void APIENTRY glFrontFace(GLenum mode) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (mode != GL_CW && mode != GL_CCW) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (ctx->polygon.frontFace == mode) return;
  pipeline::flushVertices(*ctx);
  ctx->polygon.frontFace = mode;
  ctx->markDirty(kDirtyLighting);  // two-sided lighting picks faces by it
}

// GL 3.2 / ARB_provoking_vertex: which vertex gives a flat-shaded primitive its colour.
GLAPI void APIENTRY glProvokingVertex(GLenum mode) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (mode != GL_FIRST_VERTEX_CONVENTION && mode != GL_LAST_VERTEX_CONVENTION) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (ctx->lighting.provokingVertex == mode) return;
  pipeline::flushVertices(*ctx);
  ctx->lighting.provokingVertex = mode;
}
GLAPI void APIENTRY glProvokingVertexEXT(GLenum mode) { glProvokingVertex(mode); }

GLAPI void APIENTRY glHint(GLenum target, GLenum mode) {
  Context* ctx = api::contextOutsideBeginEnd();
  if (!ctx) return;
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: case GL_POINT_SMOOTH_HINT: case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT: case GL_FOG_HINT: case GL_GENERATE_MIPMAP_HINT:
    case GL_TEXTURE_COMPRESSION_HINT: case GL_FRAGMENT_SHADER_DERIVATIVE_HINT:
      return;  // hints change nothing here: every triangle is perspective-correct
    default:
      ctx->recordError(GL_INVALID_ENUM);
  }
}

// Rendering is synchronous: every command has completed when it returns.
GLAPI void APIENTRY glFlush(void) { api::contextOutsideBeginEnd(); }
GLAPI void APIENTRY glFinish(void) { api::contextOutsideBeginEnd(); }

}  // extern "C"
