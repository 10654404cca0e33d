// glPixelTransfer (GL 2.1 §3.6.3, table 6.26 group GL_PIXEL_MODE_BIT): the
// scale, bias, shift and map switches the pixel transfer operations read.
// Texture images apply the scale and bias (texture/unpack.cpp); the pixel
// maps (glPixelMap) are not implemented yet, so GL_MAP_COLOR and
// GL_MAP_STENCIL are stored and reported only.
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

extern "C" {

GLAPI void APIENTRY glPixelTransferf(GLenum pname, GLfloat param) {
  if (api::compiled(&glPixelTransferf, pname, param)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PixelModeAttrib& p = ctx->pixelMode;
  switch (pname) {
    case GL_MAP_COLOR: api::setState(*ctx, p.mapColor, param != 0, GL_PIXEL_MODE_BIT); return;
    case GL_MAP_STENCIL: api::setState(*ctx, p.mapStencil, param != 0, GL_PIXEL_MODE_BIT); return;
    case GL_INDEX_SHIFT:
      api::setState(*ctx, p.indexShift, static_cast<GLint>(param), GL_PIXEL_MODE_BIT);
      return;
    case GL_INDEX_OFFSET:
      api::setState(*ctx, p.indexOffset, static_cast<GLint>(param), GL_PIXEL_MODE_BIT);
      return;
    case GL_RED_SCALE: api::setState(*ctx, p.scale.r, param, GL_PIXEL_MODE_BIT); return;
    case GL_GREEN_SCALE: api::setState(*ctx, p.scale.g, param, GL_PIXEL_MODE_BIT); return;
    case GL_BLUE_SCALE: api::setState(*ctx, p.scale.b, param, GL_PIXEL_MODE_BIT); return;
    case GL_ALPHA_SCALE: api::setState(*ctx, p.scale.a, param, GL_PIXEL_MODE_BIT); return;
    case GL_RED_BIAS: api::setState(*ctx, p.bias.r, param, GL_PIXEL_MODE_BIT); return;
    case GL_GREEN_BIAS: api::setState(*ctx, p.bias.g, param, GL_PIXEL_MODE_BIT); return;
    case GL_BLUE_BIAS: api::setState(*ctx, p.bias.b, param, GL_PIXEL_MODE_BIT); return;
    case GL_ALPHA_BIAS: api::setState(*ctx, p.bias.a, param, GL_PIXEL_MODE_BIT); return;
    case GL_DEPTH_SCALE: api::setState(*ctx, p.depthScale, param, GL_PIXEL_MODE_BIT); return;
    case GL_DEPTH_BIAS: api::setState(*ctx, p.depthBias, param, GL_PIXEL_MODE_BIT); return;
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
}

// glPixelZoom (§3.6.4): stored as given, any value (0, negative, NaN);
// glDrawPixels and glCopyPixels read it.
GLAPI void APIENTRY glPixelZoom(GLfloat xfactor, GLfloat yfactor) {
  if (api::compiled(&glPixelZoom, xfactor, yfactor)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PixelModeAttrib& p = ctx->pixelMode;
  if (p.zoomX == xfactor && p.zoomY == yfactor) return;
  api::beginStateChange(*ctx, GL_PIXEL_MODE_BIT);
  p.zoomX = xfactor;
  p.zoomY = yfactor;
}

GLAPI void APIENTRY glPixelTransferi(GLenum pname, GLint param) {
  glPixelTransferf(pname, static_cast<GLfloat>(param));
}

}  // extern "C"
