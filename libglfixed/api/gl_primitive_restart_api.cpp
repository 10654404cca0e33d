// NV_primitive_restart: glPrimitiveRestartNV ends the open glBegin's
// primitive and begins another of its mode; with GL_PRIMITIVE_RESTART_NV
// enabled (glEnableClientState), an index equal to the restart index does
// the same in glDrawElements and its kin (the index as given, before a base
// vertex is added) and in glArrayElement, not in glDrawArrays (Mesa alike:
// reference/MESA_FACTS.md, "Primitive restart"). The index draws use
// api/gl_array_draw_api.cpp.
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

extern "C" {

GLAPI void APIENTRY glPrimitiveRestartNV(void) {
  Context* ctx = currentContext();
  if (!ctx) return;
  if (pipeline::ListCompiler* list = api::listCompiler(ctx)) {
    // Outside the list's glBegin/glEnd Mesa compiles nothing, with no
    // error. (GL_COMPILE_AND_EXECUTE feeds the list's vertices back later.)
    if (list->insideBeginEnd()) list->restartPrimitive();
    return;
  }
  if (!ctx->insideBeginEnd) return ctx->recordError(GL_INVALID_OPERATION);
  const GLenum mode = ctx->beginEndMode;
  glEnd();
  glBegin(mode);
}

// Not compiled into lists: it runs at once (Mesa).
GLAPI void APIENTRY glPrimitiveRestartIndexNV(GLuint index) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  ctx->vertexArray.primitiveRestartIndex = index;
}

}  // extern "C"
