// glGet of the texture coordinate state (GL 2.1 tables 6.5, 6.26): the
// texture matrix of the active unit and its stack depth, and the transposed
// matrices of GL 1.3 (§6.1.2).
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"
#include "vertex/texcoord.h"

namespace glfixed::vertex {

namespace {
void matrix(const glm::mat4& m, bool transpose, GLdouble* out, int* count) {
  const glm::mat4 t = transpose ? glm::transpose(m) : m;
  for (int i = 0; i < 16; ++i) out[i] = glm::value_ptr(t)[i];
  *count = 16;
}
}  // namespace

bool getTexCoordState(const Context& ctx, GLenum pname, GLdouble* out, int* count) {
  const MatrixStack& texture = ctx.textureMatrix[ctx.texture.activeUnit()];
  *count = 1;
  switch (pname) {
    case GL_TEXTURE_MATRIX: matrix(texture.top(), false, out, count); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX: matrix(texture.top(), true, out, count); return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX: matrix(ctx.modelview.top(), true, out, count); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: matrix(ctx.projection.top(), true, out, count); return true;
    case GL_TEXTURE_STACK_DEPTH: out[0] = texture.depth(); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: out[0] = kMaxTextureStackDepth; return true;
    default: return false;
  }
}

}  // namespace glfixed::vertex
