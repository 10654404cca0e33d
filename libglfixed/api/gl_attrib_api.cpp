// The server attribute stack (GL 2.1 §6.1.14): glPushAttrib, glPopAttrib.
// Plain functions of their arguments, so that a display list can call them.
#include "api/api.h"
#include "state/framebuffer_binding.h"
#include "api/list_record.h"

using namespace glfixed;

extern "C" {

// Not a flush: Mesa only copies the state (scene attrib_pop_ends_draw).
GLAPI void APIENTRY glPushAttrib(GLbitfield mask) {
  if (api::compiled(&glPushAttrib, mask)) return;
  Context* ctx = api::contextForSetter();
  if (ctx && !ctx->attribStack.push(*ctx, mask)) ctx->recordError(GL_STACK_OVERFLOW);
}

// Mesa draws the buffered vertices first whatever the pop restores, even
// when nothing changed since the push, and even on underflow (scene
// attrib_pop_ends_draw).
GLAPI void APIENTRY glPopAttrib(void) {
  if (api::compiled(&glPopAttrib)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (!ctx->attribStack.pop(*ctx)) return ctx->recordError(GL_STACK_UNDERFLOW);
  // The draw and read buffers may have been restored.
  ctx->selectWindowBuffers();
  refreshFramebuffer(*ctx);
}

}  // extern "C"
