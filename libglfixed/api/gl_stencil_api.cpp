// The stencil test's state (GL 2.1 §4.1.5) and glClearStencil (§4.2.3):
// glStencilFunc, glStencilOp, glStencilMask and their GL 2.0 Separate forms,
// which set the front state, the back state or both (the fragment stage picks
// one by the primitive's facing: fragment/stencil_state.h).
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

bool isStencilFunc(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

bool isStencilOp(GLenum op) {
  switch (op) {
    case GL_KEEP:
    case GL_ZERO:
    case GL_REPLACE:
    case GL_INCR:
    case GL_DECR:
    case GL_INVERT:
    case GL_INCR_WRAP:
    case GL_DECR_WRAP: return true;
    default: return false;
  }
}

// The faces a Separate command names: bit 0 front, bit 1 back; 0 for a bad name.
unsigned facesNamed(GLenum face) {
  switch (face) {
    case GL_FRONT: return 1;
    case GL_BACK: return 2;
    case GL_FRONT_AND_BACK: return 3;
    default: return 0;
  }
}

// Applies `change` to the faces in `faces`; stores (and flushes) only when
// something differs, as every setter does.
template <typename Change>
void changeFaces(Context& ctx, unsigned faces, Change&& change) {
  StencilAttrib::Face next[2] = {ctx.stencil.face[0], ctx.stencil.face[1]};
  for (int i = 0; i < 2; ++i)
    if (faces & (1u << i)) change(next[i]);
  if (next[0] == ctx.stencil.face[0] && next[1] == ctx.stencil.face[1]) return;
  api::beginStateChange(ctx, GL_STENCIL_BUFFER_BIT, 0);
  ctx.stencil.face[0] = next[0];
  ctx.stencil.face[1] = next[1];
}

void stencilFunc(Context& ctx, unsigned faces, GLenum func, GLint ref, GLuint mask) {
  if (!isStencilFunc(func)) return ctx.recordError(GL_INVALID_ENUM);
  changeFaces(ctx, faces, [&](StencilAttrib::Face& f) {
    f.func = func;
    f.ref = ref;  // kept as given; queries and the test clamp it to the buffer's range
    f.valueMask = mask;
  });
}

void stencilOp(Context& ctx, unsigned faces, GLenum fail, GLenum depthFail, GLenum depthPass) {
  if (!isStencilOp(fail) || !isStencilOp(depthFail) || !isStencilOp(depthPass))
    return ctx.recordError(GL_INVALID_ENUM);
  changeFaces(ctx, faces, [&](StencilAttrib::Face& f) {
    f.fail = fail;
    f.depthFail = depthFail;
    f.depthPass = depthPass;
  });
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glStencilFunc(GLenum func, GLint ref, GLuint mask) {
  if (api::compiled(&glStencilFunc, func, ref, mask)) return;
  if (Context* ctx = api::contextForSetter()) stencilFunc(*ctx, 3, func, ref, mask);
}

GLAPI void APIENTRY glStencilFuncSeparate(GLenum face, GLenum func, GLint ref, GLuint mask) {
  if (api::compiled(&glStencilFuncSeparate, face, func, ref, mask)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const unsigned faces = facesNamed(face);
  if (!faces) return ctx->recordError(GL_INVALID_ENUM);
  stencilFunc(*ctx, faces, func, ref, mask);
}

GLAPI void APIENTRY glStencilOp(GLenum fail, GLenum zfail, GLenum zpass) {
  if (api::compiled(&glStencilOp, fail, zfail, zpass)) return;
  if (Context* ctx = api::contextForSetter()) stencilOp(*ctx, 3, fail, zfail, zpass);
}

GLAPI void APIENTRY glStencilOpSeparate(GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass) {
  if (api::compiled(&glStencilOpSeparate, face, sfail, dpfail, dppass)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const unsigned faces = facesNamed(face);
  if (!faces) return ctx->recordError(GL_INVALID_ENUM);
  stencilOp(*ctx, faces, sfail, dpfail, dppass);
}

GLAPI void APIENTRY glStencilMask(GLuint mask) {
  if (api::compiled(&glStencilMask, mask)) return;
  if (Context* ctx = api::contextForSetter())
    changeFaces(*ctx, 3, [&](StencilAttrib::Face& f) { f.writeMask = mask; });
}

GLAPI void APIENTRY glStencilMaskSeparate(GLenum face, GLuint mask) {
  if (api::compiled(&glStencilMaskSeparate, face, mask)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const unsigned faces = facesNamed(face);
  if (!faces) return ctx->recordError(GL_INVALID_ENUM);
  changeFaces(*ctx, faces, [&](StencilAttrib::Face& f) { f.writeMask = mask; });
}

// A clear value draws nothing: stored without drawing the buffered vertices,
// as glClearDepth (Mesa 22.3 flushes for neither).
GLAPI void APIENTRY glClearStencil(GLint s) {
  if (api::compiled(&glClearStencil, s)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setStateWithoutFlush(*ctx, ctx->stencil.clearValue, s, GL_STENCIL_BUFFER_BIT);
}

}  // extern "C"
