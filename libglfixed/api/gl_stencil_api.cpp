// The stencil test's state (GL 2.1 §4.1.5) and glClearStencil (§4.2.3):
// glStencilFunc, glStencilOp, glStencilMask and their GL 2.0 Separate forms,
// which set the front state, the back state or both (the fragment stage picks
// one by the primitive's facing: fragment/stencil_state.h);
// ATI_separate_stencil and EXT_stencil_two_side's glActiveStencilFaceEXT,
// with Mesa's three faces (StencilAttrib in state/attrib_groups.h).
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
// (Bit 2 is EXT_stencil_two_side's back face, which only the plain commands set.)
unsigned facesNamed(GLenum face) {
  switch (face) {
    case GL_FRONT: return 1;
    case GL_BACK: return 2;
    case GL_FRONT_AND_BACK: return 3;
    default: return 0;
  }
}

// Applies `change(face, index)` to the faces in `faces`; stores (and flushes) only when
// something differs, as every setter does.
template <typename Change>
void changeFaces(Context& ctx, unsigned faces, Change&& change) {
  std::array<StencilAttrib::Face, 3> next = ctx.stencil.face;
  for (int i = 0; i < 3; ++i)
    if (faces & (1u << i)) change(next[i], i);
  if (next == ctx.stencil.face) return;
  api::beginStateChange(ctx, GL_STENCIL_BUFFER_BIT, 0);
  ctx.stencil.face = next;
}

// The faces glStencilFunc, glStencilOp and glStencilMask set: front and
// back, or EXT_stencil_two_side's back face alone while it is the active one.
unsigned plainFaces(const Context& ctx) { return ctx.stencil.activeFace == 2 ? 4u : 3u; }

void stencilFunc(Context& ctx, unsigned faces, GLenum func, GLint ref, GLuint mask) {
  if (!isStencilFunc(func)) return ctx.recordError(GL_INVALID_ENUM);
  changeFaces(ctx, faces, [&](StencilAttrib::Face& f, int) {
    f.func = func;
    f.ref = ref;  // kept as given; queries and the test clamp it to the buffer's range
    f.valueMask = mask;
  });
}

void stencilOp(Context& ctx, unsigned faces, GLenum fail, GLenum depthFail, GLenum depthPass) {
  if (!isStencilOp(fail) || !isStencilOp(depthFail) || !isStencilOp(depthPass))
    return ctx.recordError(GL_INVALID_ENUM);
  changeFaces(ctx, faces, [&](StencilAttrib::Face& f, int) {
    f.fail = fail;
    f.depthFail = depthFail;
    f.depthPass = depthPass;
  });
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glStencilFunc(GLenum func, GLint ref, GLuint mask) {
  if (api::compiled(&glStencilFunc, func, ref, mask)) return;
  if (Context* ctx = api::contextForSetter()) stencilFunc(*ctx, plainFaces(*ctx), func, ref, mask);
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
  if (Context* ctx = api::contextForSetter()) stencilOp(*ctx, plainFaces(*ctx), fail, zfail, zpass);
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
    changeFaces(*ctx, plainFaces(*ctx), [&](StencilAttrib::Face& f, int) { f.writeMask = mask; });
}

GLAPI void APIENTRY glStencilMaskSeparate(GLenum face, GLuint mask) {
  if (api::compiled(&glStencilMaskSeparate, face, mask)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const unsigned faces = facesNamed(face);
  if (!faces) return ctx->recordError(GL_INVALID_ENUM);
  changeFaces(*ctx, faces, [&](StencilAttrib::Face& f, int) { f.writeMask = mask; });
}

// ATI_separate_stencil: one function for each face, the reference and mask
// for both (stencil.c sets faces [0] and [1]); the front function is checked
// first.
GLAPI void APIENTRY glStencilFuncSeparateATI(GLenum frontfunc, GLenum backfunc, GLint ref, GLuint mask) {
  if (api::compiled(&glStencilFuncSeparateATI, frontfunc, backfunc, ref, mask)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (!isStencilFunc(frontfunc) || !isStencilFunc(backfunc)) return ctx->recordError(GL_INVALID_ENUM);
  changeFaces(*ctx, 3, [&](StencilAttrib::Face& f, int i) {
    f.func = i == 0 ? frontfunc : backfunc;
    f.ref = ref;
    f.valueMask = mask;
  });
}

// glStencilOpSeparateATI is glStencilOpSeparate under its older name.
GLAPI void APIENTRY glStencilOpSeparateATI(GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass) {
  glStencilOpSeparate(face, sfail, dpfail, dppass);
}

// EXT_stencil_two_side: which face the plain commands and queries address.
// A display list records it (Mesa compiles it).
GLAPI void APIENTRY glActiveStencilFaceEXT(GLenum face) {
  if (api::compiled(&glActiveStencilFaceEXT, face)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (face != GL_FRONT && face != GL_BACK) return ctx->recordError(GL_INVALID_ENUM);
  api::setState(*ctx, ctx->stencil.activeFace, face == GL_FRONT ? 0 : 2, GL_STENCIL_BUFFER_BIT);
}

// A clear value draws nothing: stored without drawing the buffered vertices,
// as glClearDepth (Mesa 22.3 flushes for neither).
GLAPI void APIENTRY glClearStencil(GLint s) {
  if (api::compiled(&glClearStencil, s)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setStateWithoutFlush(*ctx, ctx->stencil.clearValue, s, GL_STENCIL_BUFFER_BIT);
}

}  // extern "C"
