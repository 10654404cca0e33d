// Capabilities and the per-fragment, viewport and polygon state entry points
// (GL 2.1 §2.11.1, §3.5.1, §4.1.6, §4.2.2, §5.1).
#include <algorithm>

#include "api/api.h"
#include "pipeline/pixel_rect.h"
#include "api/list_record.h"
#include "state/capabilities.h"
#include "state/vertex_array_queries.h"
#include "vertex/color_material.h"

using namespace glfixed;

namespace {

bool isDepthFunc(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

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

// glEnable/glDisable through the capability table (state/capabilities.h):
// only a change flushes, as in Mesa (scene redundant_state_keeps_draw).
void setCapability(GLenum cap, bool enabled) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const Capability* c = findCapability(cap);
  if (!c) {
    // EXT_vertex_array enables the arrays with glEnable; Mesa's compatibility
    // contexts still do (as glEnableClientState: no flush, not in
    // GL_ENABLE_BIT), and piglit's gl-1.1-color-material-array relies on it.
    if (ClientArray* a = clientArrayOfCapability(ctx->vertexArray, cap)) {
      a->enabled = enabled;
      return;
    }
  }
  if (!c || !c->settable) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  bool& flag = c->flag(*ctx);
  if (flag == enabled) return;
  pipeline::flushVertices(*ctx);
  storeCapability(*ctx, *c, enabled);
  // Enabling GL_COLOR_MATERIAL makes the material take the current colour at once.
  if (cap == GL_COLOR_MATERIAL && enabled) trackColorMaterial(*ctx);
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
  const Capability* c = findCapability(cap);
  if (c) return c->flag(*ctx) ? GL_TRUE : GL_FALSE;
  // The client-state arrays (glEnableClientState) answer glIsEnabled too (§6.1.1).
  if (const ClientArray* a = clientArrayOfCapability(ctx->vertexArray, cap))
    return a->enabled ? GL_TRUE : GL_FALSE;
  if (cap == GL_PRIMITIVE_RESTART_NV) return ctx->vertexArray.primitiveRestart ? GL_TRUE : GL_FALSE;
  ctx->recordError(GL_INVALID_ENUM);
  return GL_FALSE;
}

// Like Mesa, the setters below return before flushing the buffered vertices
// when the value does not change (a redundant call does not cut a merged
// draw); glClearColor and glClearDepth never draw them (probed on Mesa 22.3).
GLAPI void APIENTRY glViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  if (api::compiled(&glViewport, x, y, width, height)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  ctx->viewportInitialized = true;
  // Sizes are clamped to GL_MAX_VIEWPORT_DIMS (GL 2.1 §2.11.1); the origin to
  // Mesa's GL_VIEWPORT_BOUNDS_RANGE, [-32768, 32767] (so x + width cannot overflow).
  ViewportAttrib v = ctx->viewport;
  v.x = std::clamp(x, kViewportBoundsMin, kViewportBoundsMax);
  v.y = std::clamp(y, kViewportBoundsMin, kViewportBoundsMax);
  v.width = std::min(width, kMaxViewportSize);
  v.height = std::min(height, kMaxViewportSize);
  api::setState(*ctx, ctx->viewport, v, GL_VIEWPORT_BIT);
  // Where Mesa's X11 drivers look at the window's size again (drisw's
  // invalidate_on_gl_viewport): a resized window gets buffers of its size.
  if (SurfaceHooks* surface = ctx->framebuffer.surface) {  // null while an object is the draw framebuffer
    pipeline::flushVertices(*ctx);
    surface->viewportChanged();
  }
}

// Clip planes and scissor: the scissor box (GL 2.1 §4.1.2), stored as given;
// only a change flushes (Mesa's _mesa_set_scissor).
GLAPI void APIENTRY glScissor(GLint x, GLint y, GLsizei width, GLsizei height) {
  if (api::compiled(&glScissor, x, y, width, height)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  ScissorAttrib& s = ctx->scissor;
  if (s.x == x && s.y == y && s.width == width && s.height == height) return;
  api::beginStateChange(*ctx, GL_SCISSOR_BIT);
  s.x = x;
  s.y = y;
  s.width = width;
  s.height = height;
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

// The alpha test (GL 2.1 §4.1.4): the reference is clamped to [0, 1] when
// stored (a NaN becomes 0, as Mesa's CLAMP does).
GLAPI void APIENTRY glAlphaFunc(GLenum func, GLclampf ref) {
  if (api::compiled(&glAlphaFunc, func, ref)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (!isDepthFunc(func)) {  // the same eight functions
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  ColorBufferAttrib& c = ctx->colorBuffer;
  const float clamped = api::clamp01(ref);
  if (c.alphaFunc == func && c.alphaRef == clamped) return;
  api::beginStateChange(*ctx, GL_COLOR_BUFFER_BIT);
  c.alphaFunc = func;
  c.alphaRef = clamped;
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
  api::setStateWithoutFlush(*ctx, ctx->colorBuffer.clearColor, c, GL_COLOR_BUFFER_BIT);
  ctx->colorBuffer.clearColorUnclamped = glm::vec4(r, g, b, a);
}

// Colour-index state of an RGBA context (GL 2.1 §4.2.2, §4.2.3): stored and
// queried only. Mesa keeps the clear index as an unsigned integer (7.5 reads
// back 7); values it cannot hold are stored as 0 here.
GLAPI void APIENTRY glClearIndex(GLfloat c) {
  if (api::compiled(&glClearIndex, c)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const float index = c >= 0.0f && c < 4294967296.0f ? static_cast<float>(static_cast<uint32_t>(c)) : 0.0f;
  api::setStateWithoutFlush(*ctx, ctx->colorBuffer.clearIndex, index, GL_COLOR_BUFFER_BIT);
}

GLAPI void APIENTRY glIndexMask(GLuint mask) {
  if (api::compiled(&glIndexMask, mask)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setState(*ctx, ctx->colorBuffer.indexWriteMask, mask, GL_COLOR_BUFFER_BIT);
}

GLAPI void APIENTRY glClearDepth(GLclampd depth) {
  if (api::compiled(&glClearDepth, depth)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setStateWithoutFlush(*ctx, ctx->depth.clearDepth, api::clamp01(depth), GL_DEPTH_BUFFER_BIT);
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
// What was drawn into a window's front buffer reaches the screen here (GL 2.1
// §5.5); a double-buffered window shows its back buffer at the swap.
namespace {
void flushToSurface() {
  Context* ctx = api::contextFlushed();
  if (ctx) pipeline::flushBitmapCache(*ctx);  // st_flush
  if (!ctx || !ctx->windowFramebuffer().surface) return;
  const Framebuffer& fb = ctx->windowFramebuffer();
  const bool frontDrawn = fb.color.pixels == fb.front.pixels || fb.drawsIntoBoth(ctx->windowDrawBuffer());
  if (frontDrawn) fb.surface->frontBufferFlushed();
}
}  // namespace
GLAPI void APIENTRY glFlush(void) { flushToSurface(); }
GLAPI void APIENTRY glFinish(void) { flushToSurface(); }

}  // extern "C"
