// Capabilities and the per-fragment, viewport and polygon state entry points
// (GL 2.1 §2.11.1, §3.5.1, §4.1.6, §4.2.2, §5.1).
#include "api/api.h"
#include "api/list_record.h"
#include "vertex/color_material.h"
#include "vertex/lighting_queries.h"

using namespace glfixed;

namespace {

bool isDepthFunc(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

// The capabilities the core owns; lighting capabilities belong to the
// lighting stage (vertex/lighting_queries.h). Null: not a core capability.
// The glPushAttrib groups a capability belongs to besides GL_ENABLE_BIT.
GLbitfield capabilityGroup(GLenum cap) {
  switch (cap) {
    case GL_DEPTH_TEST: return GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT;
    case GL_CULL_FACE: return GL_ENABLE_BIT | GL_POLYGON_BIT;
    case GL_DITHER: return GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT;
    default: return GL_ENABLE_BIT;
  }
}

bool isLightingCapability(GLenum cap) {
  switch (cap) {
    case GL_LIGHTING: case GL_COLOR_MATERIAL: case GL_NORMALIZE: case GL_RESCALE_NORMAL:
    case GL_LIGHT0: case GL_LIGHT1: case GL_LIGHT2: case GL_LIGHT3:
    case GL_LIGHT4: case GL_LIGHT5: case GL_LIGHT6: case GL_LIGHT7:
      return true;
    default:
      return false;
  }
}

GLenum* hintState(Context& ctx, GLenum target) {
  HintAttrib& h = ctx.hint;
  switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: return &h.perspectiveCorrection;
    case GL_POINT_SMOOTH_HINT: return &h.pointSmooth;
    case GL_LINE_SMOOTH_HINT: return &h.lineSmooth;
    case GL_POLYGON_SMOOTH_HINT: return &h.polygonSmooth;
    case GL_FOG_HINT: return &h.fog;
    case GL_GENERATE_MIPMAP_HINT: return &h.generateMipmap;
    case GL_TEXTURE_COMPRESSION_HINT: return &h.textureCompression;
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: return &h.fragmentShaderDerivative;
    default: return nullptr;
  }
}

bool* coreCapability(Context& ctx, GLenum cap) {
  switch (cap) {
    case GL_DEPTH_TEST: return &ctx.depth.test;
    case GL_CULL_FACE: return &ctx.polygon.cullFace;
    case GL_DITHER: return &ctx.colorBuffer.dither;
    default: return nullptr;
  }
}

void setCapability(GLenum cap, bool enabled) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (bool* flag = coreCapability(*ctx, cap)) {
    api::setState(*ctx, *flag, enabled, capabilityGroup(cap));
    return;
  }
  GLdouble current[16];
  int count = 0;
  if (getLightingState(*ctx, cap, current, &count) && count == 1 && (current[0] != 0) == enabled) return;
  if (!isLightingCapability(cap)) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::beginStateChange(*ctx, GL_ENABLE_BIT | GL_LIGHTING_BIT | (cap == GL_NORMALIZE || cap == GL_RESCALE_NORMAL ? GL_TRANSFORM_BIT : 0));
  setLightingCapability(*ctx, cap, enabled);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glEnable(GLenum cap) {
  if (api::compiled(&glEnable, cap)) return;
  setCapability(cap, true);
}
GLAPI void APIENTRY glDisable(GLenum cap) {
  if (api::compiled(&glDisable, cap)) return;
  setCapability(cap, false);
}

GLAPI GLboolean APIENTRY glIsEnabled(GLenum cap) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  if (bool* flag = coreCapability(*ctx, cap)) return *flag ? GL_TRUE : GL_FALSE;
  GLdouble v[16];
  int count = 0;
  // The lighting capabilities, through the lighting stage's queries.
  if (isLightingCapability(cap) && getLightingState(*ctx, cap, v, &count) && count == 1)
    return v[0] != 0 ? GL_TRUE : GL_FALSE;
  ctx->recordError(GL_INVALID_ENUM);
  return GL_FALSE;
}

GLAPI void APIENTRY glViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  if (api::compiled(&glViewport, x, y, width, height)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  ctx->viewportInitialized = true;
  // Sizes are clamped to GL_MAX_VIEWPORT_DIMS (GL 2.1 §2.11.1).
  ViewportAttrib v = ctx->viewport;
  v.x = x;
  v.y = y;
  v.width = std::min(width, kMaxViewportSize);
  v.height = std::min(height, kMaxViewportSize);
  api::setState(*ctx, ctx->viewport, v, GL_VIEWPORT_BIT);
}

GLAPI void APIENTRY glDepthRange(GLclampd zNear, GLclampd zFar) {
  if (api::compiled(&glDepthRange, zNear, zFar)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  ViewportAttrib v = ctx->viewport;
  v.depthNear = api::clamp01(zNear);
  v.depthFar = api::clamp01(zFar);
  api::setState(*ctx, ctx->viewport, v, GL_VIEWPORT_BIT);
}

GLAPI void APIENTRY glDepthFunc(GLenum func) {
  if (api::compiled(&glDepthFunc, func)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (!isDepthFunc(func)) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setState(*ctx, ctx->depth.func, func, GL_DEPTH_BUFFER_BIT);
}

GLAPI void APIENTRY glDepthMask(GLboolean flag) {
  if (api::compiled(&glDepthMask, flag)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setState(*ctx, ctx->depth.writeMask, flag != GL_FALSE, GL_DEPTH_BUFFER_BIT);
}

GLAPI void APIENTRY glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  if (api::compiled(&glColorMask, r, g, b, a)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const std::array<bool, 4> mask{r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
  api::setState(*ctx, ctx->colorBuffer.writeMask, mask, GL_COLOR_BUFFER_BIT);
}

GLAPI void APIENTRY glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  if (api::compiled(&glClearColor, r, g, b, a)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const glm::vec4 c(api::clamp01(r), api::clamp01(g), api::clamp01(b), api::clamp01(a));
  api::setState(*ctx, ctx->colorBuffer.clearColor, c, GL_COLOR_BUFFER_BIT);
}

GLAPI void APIENTRY glClearDepth(GLclampd depth) {
  if (api::compiled(&glClearDepth, depth)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setState(*ctx, ctx->depth.clearDepth, api::clamp01(depth), GL_DEPTH_BUFFER_BIT);
}

GLAPI void APIENTRY glCullFace(GLenum mode) {
  if (api::compiled(&glCullFace, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setState(*ctx, ctx->polygon.cullFaceMode, mode, GL_POLYGON_BIT);
}

GLAPI void APIENTRY glFrontFace(GLenum mode) {
  if (api::compiled(&glFrontFace, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_CW && mode != GL_CCW) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  // Two-sided lighting picks faces by it: the lighting constants are rebuilt.
  api::setState(*ctx, ctx->polygon.frontFace, mode, GL_POLYGON_BIT, kDirtyLighting);
}

// GL 3.2 / ARB_provoking_vertex: which vertex gives a flat-shaded primitive its colour.
GLAPI void APIENTRY glProvokingVertex(GLenum mode) {
  if (api::compiled(&glProvokingVertex, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_FIRST_VERTEX_CONVENTION && mode != GL_LAST_VERTEX_CONVENTION) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setState(*ctx, ctx->lighting.provokingVertex, mode, GL_LIGHTING_BIT);
}
GLAPI void APIENTRY glProvokingVertexEXT(GLenum mode) { glProvokingVertex(mode); }

GLAPI void APIENTRY glHint(GLenum target, GLenum mode) {
  if (api::compiled(&glHint, target, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  GLenum* hint = hintState(*ctx, target);
  if (!hint) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  // Hints change no pixel here (every triangle is perspective-correct), but
  // they are state: queried, pushed with GL_HINT_BIT, and they flush as Mesa does.
  api::setState(*ctx, *hint, mode, GL_HINT_BIT);
}

// Rendering is synchronous: every command has completed when it returns.
GLAPI void APIENTRY glFlush(void) { api::contextFlushed(); }
GLAPI void APIENTRY glFinish(void) { api::contextFlushed(); }

}  // extern "C"
