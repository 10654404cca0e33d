// Shared by the thin extern "C" entry points: the order every entry point
// follows (DESIGN.md): find the context, refuse the call between glBegin and
// glEnd where §2.6.3 forbids it, validate, return if unchanged, flush, mark,
// store.
#pragma once

#include <GL/gl.h>

#include "pipeline/immediate_mode.h"
#include "state/context.h"
#include "state/framebuffer_binding.h"

namespace glfixed::api {

// The current context, or null: a call with no current context does nothing.
inline Context* context() { return currentContext(); }

// For a query: the current context if the call may run now; null (after
// recording GL_INVALID_OPERATION when inside glBegin/glEnd) if it must do
// nothing.
inline Context* contextForQuery() {
  Context* ctx = currentContext();
  if (ctx && ctx->insideBeginEnd) {
    ctx->recordError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return ctx;
}

// For a setter: the same check; the setter then validates its arguments and
// calls setState (or beginStateChange), which flushes only if the value changes.
inline Context* contextForSetter() { return contextForQuery(); }

// For a command that draws, reads the framebuffer or always ends the run of
// buffered glBegin/glEnd vertices in Mesa (matrix operations, glClear,
// glReadPixels, glFlush): the same check, then the buffered vertices are drawn.
// With a framebuffer object bound, its views are rebuilt here too
// (state/framebuffer_binding.h).
inline Context* contextFlushed() {
  Context* ctx = contextForQuery();
  if (ctx) {
    pipeline::flushVertices(*ctx);
    if (ctx->objectBound()) refreshFramebuffer(*ctx);
  }
  return ctx;
}

// The order of every setter (DESIGN.md; Mesa's main/*.c): after validation,
// a value equal to the current one changes nothing and flushes nothing, so a
// redundant call between glBegin/glEnd pairs keeps them one draw (scene
// redundant_state_keeps_draw). Otherwise the buffered vertices are drawn with
// the old state, the glPushAttrib group and the derived state's dirty bits are
// marked, and the value is stored.
inline void beginStateChange(Context& ctx, GLbitfield attribGroup, uint32_t dirty = 0) {
  pipeline::flushVertices(ctx);
  ctx.markChanged(attribGroup, dirty);
}
template <typename T>
bool setState(Context& ctx, T& field, const T& value, GLbitfield attribGroup, uint32_t dirty = 0) {
  if (field == value) return false;
  beginStateChange(ctx, attribGroup, dirty);
  field = value;
  return true;
}

// Mesa's CLAMP: NaN fails `v > 0` and becomes 0 (glClearDepth(NaN) clears to
// 0, glDepthRange(NaN, 1) is (0, 1)), where a plain min/max would let it through.
// For state that no draw reads (the clear values, the matrix mode): Mesa
// stores it without drawing the buffered vertices (scene
// state_change_cuts_draw); the group is still marked for glPopAttrib.
template <typename T>
bool setStateWithoutFlush(Context& ctx, T& field, const T& value, GLbitfield attribGroup) {
  if (field == value) return false;
  ctx.markChanged(attribGroup, 0);
  field = value;
  return true;
}

inline float clamp01(float v) { return v > 0 ? (v > 1 ? 1 : v) : 0; }
inline double clamp01(double v) { return v > 0 ? (v > 1 ? 1 : v) : 0; }

}  // namespace glfixed::api
