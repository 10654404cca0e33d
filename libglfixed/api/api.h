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

inline float clamp01(float v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }
inline double clamp01(double v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

}  // namespace glfixed::api
