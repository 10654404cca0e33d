// Shared by the thin extern "C" entry points: the order every entry point
// follows (DESIGN.md): find the context, refuse the call between glBegin and
// glEnd where §2.6.3 forbids it, validate, store.
#pragma once

#include <GL/gl.h>

#include "pipeline/immediate_mode.h"
#include "state/context.h"

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

// The same for a command that changes state or draws: like Mesa it ends the
// run of buffered glBegin/glEnd vertices first (Context::vbo).
inline Context* contextOutsideBeginEnd() {
  Context* ctx = contextForQuery();
  if (ctx) pipeline::flushVertices(*ctx);
  return ctx;
}

// Mesa's CLAMP: NaN fails `v > 0` and becomes 0 (glClearDepth(NaN) clears to
// 0, glDepthRange(NaN, 1) is (0, 1)), where a plain min/max would let it through.
inline float clamp01(float v) { return v > 0 ? (v > 1 ? 1 : v) : 0; }
inline double clamp01(double v) { return v > 0 ? (v > 1 ? 1 : v) : 0; }

}  // namespace glfixed::api
