// Blending and the logic op (GL 2.1 §4.1.8, §4.1.10): glBlendFunc,
// glBlendFuncSeparate, glBlendEquation, glBlendEquationSeparate,
// glBlendColor, glLogicOp, and their EXT/INGR/ATI names. The fragment stage
// applies them (fragment/blend.inc).
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

// Table 4.2. Mesa (a GL 4.5 compatibility context) takes
// GL_SRC_ALPHA_SATURATE as a destination factor too, as GL 3.3 does.
bool isBlendFactor(GLenum f) {
  switch (f) {
    case GL_ZERO:
    case GL_ONE:
    case GL_SRC_COLOR:
    case GL_ONE_MINUS_SRC_COLOR:
    case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA:
    case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA:
    case GL_CONSTANT_COLOR:
    case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA:
    case GL_ONE_MINUS_CONSTANT_ALPHA:
    case GL_SRC_ALPHA_SATURATE: return true;
    default: return false;
  }
}

bool isBlendEquation(GLenum e) {
  return e == GL_FUNC_ADD || e == GL_FUNC_SUBTRACT || e == GL_FUNC_REVERSE_SUBTRACT || e == GL_MIN ||
         e == GL_MAX;
}

void setBlendFunc(Context& ctx, GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  if (!isBlendFactor(srcRGB) || !isBlendFactor(dstRGB) || !isBlendFactor(srcAlpha) ||
      !isBlendFactor(dstAlpha)) {
    ctx.recordError(GL_INVALID_ENUM);
    return;
  }
  ColorBufferAttrib& cb = ctx.colorBuffer;
  if (cb.blendSrcRGB == srcRGB && cb.blendDstRGB == dstRGB && cb.blendSrcAlpha == srcAlpha &&
      cb.blendDstAlpha == dstAlpha)
    return;
  api::beginStateChange(ctx, GL_COLOR_BUFFER_BIT);
  cb.blendSrcRGB = srcRGB;
  cb.blendDstRGB = dstRGB;
  cb.blendSrcAlpha = srcAlpha;
  cb.blendDstAlpha = dstAlpha;
}

void setBlendEquation(Context& ctx, GLenum rgb, GLenum alpha) {
  if (!isBlendEquation(rgb) || !isBlendEquation(alpha)) {
    ctx.recordError(GL_INVALID_ENUM);
    return;
  }
  ColorBufferAttrib& cb = ctx.colorBuffer;
  if (cb.blendEquationRGB == rgb && cb.blendEquationAlpha == alpha) return;
  api::beginStateChange(ctx, GL_COLOR_BUFFER_BIT);
  cb.blendEquationRGB = rgb;
  cb.blendEquationAlpha = alpha;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glBlendFunc(GLenum sfactor, GLenum dfactor) {
  if (api::compiled(&glBlendFunc, sfactor, dfactor)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) setBlendFunc(*ctx, sfactor, dfactor, sfactor, dfactor);
}

GLAPI void APIENTRY glBlendFuncSeparate(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  if (api::compiled(&glBlendFuncSeparate, srcRGB, dstRGB, srcAlpha, dstAlpha)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) setBlendFunc(*ctx, srcRGB, dstRGB, srcAlpha, dstAlpha);
}

GLAPI void APIENTRY glBlendEquation(GLenum mode) {
  if (api::compiled(&glBlendEquation, mode)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) setBlendEquation(*ctx, mode, mode);
}

GLAPI void APIENTRY glBlendEquationSeparate(GLenum modeRGB, GLenum modeAlpha) {
  if (api::compiled(&glBlendEquationSeparate, modeRGB, modeAlpha)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) setBlendEquation(*ctx, modeRGB, modeAlpha);
}

// Stored as given, as Mesa keeps it; glGet and the fragment stage clamp it
// to [0, 1] (the buffers are fixed-point).
GLAPI void APIENTRY glBlendColor(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  if (api::compiled(&glBlendColor, red, green, blue, alpha)) return;
  Context* ctx = api::contextForSetter();
  if (ctx)
    api::setState(*ctx, ctx->colorBuffer.blendColor, glm::vec4(red, green, blue, alpha), GL_COLOR_BUFFER_BIT);
}

GLAPI void APIENTRY glLogicOp(GLenum opcode) {
  if (api::compiled(&glLogicOp, opcode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (opcode < GL_CLEAR || opcode > GL_SET) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setState(*ctx, ctx->colorBuffer.logicOpMode, opcode, GL_COLOR_BUFFER_BIT);
}

// EXT_blend_color, EXT_blend_minmax, EXT_blend_func_separate,
// INGR_blend_func_separate, EXT_blend_equation_separate,
// ATI_blend_equation_separate: the same commands (api/gl_arb_aliases.cpp
// makes GetProcAddress know them).
GLAPI void APIENTRY glBlendColorEXT(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  glBlendColor(red, green, blue, alpha);
}
GLAPI void APIENTRY glBlendEquationEXT(GLenum mode) { glBlendEquation(mode); }
GLAPI void APIENTRY glBlendFuncSeparateEXT(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  glBlendFuncSeparate(srcRGB, dstRGB, srcAlpha, dstAlpha);
}
GLAPI void APIENTRY glBlendFuncSeparateINGR(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  glBlendFuncSeparate(srcRGB, dstRGB, srcAlpha, dstAlpha);
}
GLAPI void APIENTRY glBlendEquationSeparateEXT(GLenum modeRGB, GLenum modeAlpha) {
  glBlendEquationSeparate(modeRGB, modeAlpha);
}
GLAPI void APIENTRY glBlendEquationSeparateATI(GLenum modeRGB, GLenum modeAlpha) {
  glBlendEquationSeparate(modeRGB, modeAlpha);
}

}  // extern "C"
