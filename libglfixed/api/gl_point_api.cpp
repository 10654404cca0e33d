// Point entry points (GL 2.1 §3.4): glPointSize and glPointParameter*. The
// errors and the order of checks are Mesa 22.3's (main/points.c, probed in
// tests/api/point_test.cpp): a value equal to the current one changes
// nothing; a size <= 0 is GL_INVALID_VALUE, but NaN and huge sizes are
// stored (they are clamped at draw time); the attenuation coefficients are
// not checked; GL_POINT_SPRITE_COORD_ORIGIN takes GL_LOWER_LEFT or
// GL_UPPER_LEFT, else GL_INVALID_VALUE.
#include <glm/glm.hpp>

#include "api/api.h"
#include "api/list_record.h"
#include "api/point_sprite_env.h"

using namespace glfixed;

// Point sprites (issue 14): GL_COORD_REPLACE through glTexEnv (point_sprite_env.h).
bool api::setPointSpriteEnv(Context& ctx, GLenum pname, GLint value) {
  if (pname != GL_COORD_REPLACE) {
    ctx.recordError(GL_INVALID_ENUM);
    return false;
  }
  if (value != GL_TRUE && value != GL_FALSE) {
    ctx.recordError(GL_INVALID_VALUE);
    return false;
  }
  api::setState(ctx, ctx.point.coordReplace[ctx.texture.activeUnit()], value == GL_TRUE, GL_POINT_BIT);
  return true;
}

bool api::getPointSpriteEnv(Context& ctx, GLenum pname, GLint* value) {
  if (pname != GL_COORD_REPLACE) {
    ctx.recordError(GL_INVALID_ENUM);
    return false;
  }
  if (value) *value = ctx.point.coordReplace[ctx.texture.activeUnit()] ? GL_TRUE : GL_FALSE;
  return true;
}

namespace {

// The number of values glPointParameter*v reads for `pname` (0: not a point parameter).
size_t pointParameterCount(GLenum pname) {
  switch (pname) {
    case GL_POINT_DISTANCE_ATTENUATION: return 3;
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
    case GL_POINT_SPRITE_COORD_ORIGIN: return 1;
    default: return 0;
  }
}

void pointParameter(Context& ctx, GLenum pname, const GLfloat* params) {
  PointAttrib& p = ctx.point;
  switch (pname) {
    case GL_POINT_DISTANCE_ATTENUATION:
      api::setState(ctx, p.distanceAttenuation, glm::vec3(params[0], params[1], params[2]), GL_POINT_BIT);
      return;
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE: {
      if (params[0] < 0.0f) return ctx.recordError(GL_INVALID_VALUE);
      float& field = pname == GL_POINT_SIZE_MIN   ? p.sizeMin
                     : pname == GL_POINT_SIZE_MAX ? p.sizeMax
                                                  : p.fadeThresholdSize;
      api::setState(ctx, field, params[0], GL_POINT_BIT);
      return;
    }
    case GL_POINT_SPRITE_COORD_ORIGIN: {
      const float v = params[0];
      const GLenum origin = (v >= 0.0f && v < 4294967296.0f) ? static_cast<GLenum>(v) : GL_NONE;
      if (origin != GL_LOWER_LEFT && origin != GL_UPPER_LEFT) return ctx.recordError(GL_INVALID_VALUE);
      api::setState(ctx, p.spriteCoordOrigin, origin, GL_POINT_BIT);
      return;
    }
    default: ctx.recordError(GL_INVALID_ENUM);
  }
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glPointSize(GLfloat size) {
  if (api::compiled(&glPointSize, size)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx || ctx->point.size == size) return;
  if (size <= 0.0f) return ctx->recordError(GL_INVALID_VALUE);
  api::setState(*ctx, ctx->point.size, size, GL_POINT_BIT);
}

GLAPI void APIENTRY glPointParameterfv(GLenum pname, const GLfloat* params) {
  if (api::compiled(&glPointParameterfv, pname, api::copied(params, pointParameterCount(pname)))) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (pointParameterCount(pname) == 0) return ctx->recordError(GL_INVALID_ENUM);
  if (!params) return;  // no GL error for a null pointer; Mesa would crash
  pointParameter(*ctx, pname, params);
}

GLAPI void APIENTRY glPointParameterf(GLenum pname, GLfloat param) {
  // A vector pname takes (param, 0, 0), as Mesa's glPointParameterf passes
  // a one-element array extended with zeros.
  const GLfloat params[3] = {param, 0.0f, 0.0f};
  glPointParameterfv(pname, params);
}

GLAPI void APIENTRY glPointParameteriv(GLenum pname, const GLint* params) {
  GLfloat f[3] = {0.0f, 0.0f, 0.0f};
  const size_t count = pointParameterCount(pname);
  if (params)
    for (size_t i = 0; i < count; ++i) f[i] = static_cast<GLfloat>(params[i]);
  glPointParameterfv(pname, params ? f : nullptr);
}

GLAPI void APIENTRY glPointParameteri(GLenum pname, GLint param) {
  const GLfloat params[3] = {static_cast<GLfloat>(param), 0.0f, 0.0f};
  glPointParameterfv(pname, params);
}

}  // extern "C"
