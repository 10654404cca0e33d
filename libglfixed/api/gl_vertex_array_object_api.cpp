// Vertex array objects (ARB_vertex_array_object; GL 3.0 §2.10): the objects
// are state/vertex_array_objects.h. These commands are not compiled into
// display lists (GL 3.0 §5.4): they run at once while a list compiles.
// Mesa's edges, measured: a generated name is a vertex array only once bound;
// binding a name never generated, or deleted, is GL_INVALID_OPERATION;
// deleting the bound object binds 0; 0 and unknown names are ignored by
// glDeleteVertexArrays (reference/MESA_FACTS.md, "Vertex array objects").
#include "api/api.h"

using namespace glfixed;

extern "C" {

GLAPI void APIENTRY glGenVertexArrays(GLsizei n, GLuint* arrays) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (arrays) ctx->vertexArrayObjects.generate(n, arrays);
}

GLAPI void APIENTRY glBindVertexArray(GLuint array) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!ctx->vertexArrayObjects.bindable(array)) return ctx->recordError(GL_INVALID_OPERATION);
  ctx->vertexArrayObjects.bind(ctx->vertexArray, array);
}

GLAPI void APIENTRY glDeleteVertexArrays(GLsizei n, const GLuint* arrays) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!arrays) return;
  for (GLsizei i = 0; i < n; ++i) ctx->vertexArrayObjects.remove(ctx->vertexArray, arrays[i]);
}

GLAPI GLboolean APIENTRY glIsVertexArray(GLuint array) {
  Context* ctx = api::contextForQuery();
  return ctx && ctx->vertexArrayObjects.isVertexArray(array) ? GL_TRUE : GL_FALSE;
}

}  // extern "C"
