// glTexEnv* and glGetTexEnv* (GL 2.1 §3.8.13, §3.8.8 and §3.4: the texture
// environment of the active unit, its level-of-detail bias, and a point
// sprite's GL_COORD_REPLACE). The errors and their order are Mesa 22.3's
// (main/texenv.c, checked on Mesa by tests/api/texenv_test.cpp):
// - the target first (GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL,
//   GL_POINT_SPRITE), then the pname: else GL_INVALID_ENUM;
// - a mode, combiner function, source or operand that is not one of GL's is
//   GL_INVALID_ENUM; DOT3 only for GL_COMBINE_RGB; GL_SRC_COLOR and
//   GL_ONE_MINUS_SRC_COLOR not for an alpha operand; GL_TEXTUREn only for
//   n < GL_MAX_TEXTURE_UNITS; GL_REPLACE_EXT stores GL_REPLACE;
// - a scale other than 1, 2 or 4 is GL_INVALID_VALUE, and GL_COORD_REPLACE
//   other than GL_TRUE or GL_FALSE;
// - an enum given as a float is truncated to an integer first, as Mesa does;
// - the colour is clamped to [0,1] when set; glTexEnviv's and glGetTexEnviv's
//   colours are converted as Mesa's INT_TO_FLOAT and FLOAT_TO_INT do.
// Mesa accepts a unit past GL_MAX_TEXTURE_UNITS here (GL_INVALID_OPERATION
// only past its combined image units); glActiveTexture keeps the active unit
// below GL_MAX_TEXTURE_UNITS, so no unit here is past it.
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

constexpr GLenum kReplaceExt = 0x8062;                         // GL_REPLACE_EXT
constexpr GLenum kDot3RgbExt = 0x8740, kDot3RgbaExt = 0x8741;  // EXT_texture_env_dot3

// A float parameter as the integer Mesa reads it ((GLint) v; x86 gives
// INT_MIN out of range).
GLint truncated(GLfloat v) {
  if (!(v > -2147483649.0f && v < 2147483648.0f)) return INT32_MIN;
  return static_cast<GLint>(v);
}

// Mesa's INT_TO_FLOAT (float arithmetic, then a double multiply) and FLOAT_TO_INT.
float intToFloat(GLint i) {
  return static_cast<float>((2.0f * static_cast<float>(i) + 1.0f) * (1.0f / 4294967294.0));
}
GLint colorToInt(float c) {
  const double v = 2147483647.0 * static_cast<double>(c);
  if (!(v > -2147483649.0 && v < 2147483648.0)) return INT32_MIN;
  return static_cast<GLint>(v);
}

// How many values glTexEnv*v reads for (target, pname).
size_t texEnvCount(GLenum target, GLenum pname) {
  return target == GL_TEXTURE_ENV && pname == GL_TEXTURE_ENV_COLOR ? 4 : 1;
}

bool isCombinerFunction(GLenum pname, GLenum mode) {
  switch (mode) {
    case GL_REPLACE:
    case GL_MODULATE:
    case GL_ADD:
    case GL_ADD_SIGNED:
    case GL_INTERPOLATE:
    case GL_SUBTRACT: return true;
    case GL_DOT3_RGB:
    case GL_DOT3_RGBA:
    case kDot3RgbExt:
    case kDot3RgbaExt: return pname == GL_COMBINE_RGB;
    default: return false;
  }
}

bool isCombinerSource(GLenum source) {
  switch (source) {
    case GL_TEXTURE:
    case GL_CONSTANT:
    case GL_PRIMARY_COLOR:
    case GL_PREVIOUS: return true;
    default:  // crossbar (GL 1.4): any unit the library has
      return source >= GL_TEXTURE0 && source < GL_TEXTURE0 + kMaxTextureUnits;
  }
}

void textureEnv(Context& ctx, GLenum pname, const GLfloat* params) {
  TexEnvAttrib& env = ctx.texture.env[ctx.texture.activeUnit()];
  const GLenum value = static_cast<GLenum>(truncated(params[0]));
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: {
      const GLenum mode = value == kReplaceExt ? GL_REPLACE : value;
      if (mode != GL_MODULATE && mode != GL_BLEND && mode != GL_DECAL && mode != GL_REPLACE &&
          mode != GL_ADD && mode != GL_COMBINE)
        return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, env.mode, mode, GL_TEXTURE_BIT);
      return;
    }
    case GL_TEXTURE_ENV_COLOR: {
      const glm::vec4 color(api::clamp01(params[0]), api::clamp01(params[1]), api::clamp01(params[2]),
                            api::clamp01(params[3]));
      api::setState(ctx, env.color, color, GL_TEXTURE_BIT);
      return;
    }
    case GL_COMBINE_RGB:
    case GL_COMBINE_ALPHA:
      if (!isCombinerFunction(pname, value)) return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, pname == GL_COMBINE_RGB ? env.combineRGB : env.combineAlpha, value, GL_TEXTURE_BIT);
      return;
    case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB:
    case GL_SOURCE2_RGB:
      if (!isCombinerSource(value)) return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, env.sourceRGB[pname - GL_SOURCE0_RGB], value, GL_TEXTURE_BIT);
      return;
    case GL_SOURCE0_ALPHA:
    case GL_SOURCE1_ALPHA:
    case GL_SOURCE2_ALPHA:
      if (!isCombinerSource(value)) return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, env.sourceAlpha[pname - GL_SOURCE0_ALPHA], value, GL_TEXTURE_BIT);
      return;
    case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB:
    case GL_OPERAND2_RGB:
      if (value != GL_SRC_COLOR && value != GL_ONE_MINUS_SRC_COLOR && value != GL_SRC_ALPHA &&
          value != GL_ONE_MINUS_SRC_ALPHA)
        return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, env.operandRGB[pname - GL_OPERAND0_RGB], value, GL_TEXTURE_BIT);
      return;
    case GL_OPERAND0_ALPHA:
    case GL_OPERAND1_ALPHA:
    case GL_OPERAND2_ALPHA:
      if (value != GL_SRC_ALPHA && value != GL_ONE_MINUS_SRC_ALPHA) return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, env.operandAlpha[pname - GL_OPERAND0_ALPHA], value, GL_TEXTURE_BIT);
      return;
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE: {
      const float scale = params[0];  // compared as a float: 2.5 is an error, not 2
      if (scale != 1.0f && scale != 2.0f && scale != 4.0f) return ctx.recordError(GL_INVALID_VALUE);
      api::setState(ctx, pname == GL_RGB_SCALE ? env.rgbScale : env.alphaScale, scale, GL_TEXTURE_BIT);
      return;
    }
    default: ctx.recordError(GL_INVALID_ENUM);
  }
}

void texEnv(Context& ctx, GLenum target, GLenum pname, const GLfloat* params) {
  const int unit = ctx.texture.activeUnit();
  switch (target) {
    case GL_TEXTURE_ENV: return textureEnv(ctx, pname, params);
    case GL_TEXTURE_FILTER_CONTROL:
      if (pname != GL_TEXTURE_LOD_BIAS) return ctx.recordError(GL_INVALID_ENUM);
      api::setState(ctx, ctx.texture.env[unit].lodBias, params[0], GL_TEXTURE_BIT);
      return;
    case GL_POINT_SPRITE: {
      if (pname != GL_COORD_REPLACE) return ctx.recordError(GL_INVALID_ENUM);
      const GLint v = truncated(params[0]);
      if (v != GL_TRUE && v != GL_FALSE) return ctx.recordError(GL_INVALID_VALUE);
      api::setState(ctx, ctx.point.coordReplace[unit], v == GL_TRUE, GL_POINT_BIT);
      return;
    }
    default: ctx.recordError(GL_INVALID_ENUM);
  }
}

// The integer state of GL_TEXTURE_ENV (all but the colour); -1 with
// GL_INVALID_ENUM recorded for a pname that is not one.
GLint textureEnvInteger(Context& ctx, const TexEnvAttrib& env, GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: return static_cast<GLint>(env.mode);
    case GL_COMBINE_RGB: return static_cast<GLint>(env.combineRGB);
    case GL_COMBINE_ALPHA: return static_cast<GLint>(env.combineAlpha);
    case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB:
    case GL_SOURCE2_RGB: return static_cast<GLint>(env.sourceRGB[pname - GL_SOURCE0_RGB]);
    case GL_SOURCE0_ALPHA:
    case GL_SOURCE1_ALPHA:
    case GL_SOURCE2_ALPHA: return static_cast<GLint>(env.sourceAlpha[pname - GL_SOURCE0_ALPHA]);
    case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB:
    case GL_OPERAND2_RGB: return static_cast<GLint>(env.operandRGB[pname - GL_OPERAND0_RGB]);
    case GL_OPERAND0_ALPHA:
    case GL_OPERAND1_ALPHA:
    case GL_OPERAND2_ALPHA: return static_cast<GLint>(env.operandAlpha[pname - GL_OPERAND0_ALPHA]);
    case GL_RGB_SCALE: return static_cast<GLint>(env.rgbScale);
    case GL_ALPHA_SCALE: return static_cast<GLint>(env.alphaScale);
    default: ctx.recordError(GL_INVALID_ENUM); return -1;
  }
}

// glGetTexEnv{f,i}v: `T` the type of the values written.
template <typename T>
void getTexEnv(GLenum target, GLenum pname, T* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const int unit = ctx->texture.activeUnit();
  const TexEnvAttrib& env = ctx->texture.env[unit];
  switch (target) {
    case GL_TEXTURE_ENV:
      if (pname == GL_TEXTURE_ENV_COLOR) {
        if (!params) return;
        for (int k = 0; k < 4; ++k) {
          if constexpr (std::is_same_v<T, GLint>)
            params[k] = colorToInt(env.color[k]);
          else
            params[k] = env.color[k];
        }
        return;
      } else {
        const GLint v = textureEnvInteger(*ctx, env, pname);
        if (v >= 0 && params) *params = static_cast<T>(v);
      }
      return;
    case GL_TEXTURE_FILTER_CONTROL:
      if (pname != GL_TEXTURE_LOD_BIAS) return ctx->recordError(GL_INVALID_ENUM);
      if (!params) return;
      if constexpr (std::is_same_v<T, GLint>)
        *params = truncated(env.lodBias);
      else
        *params = env.lodBias;
      return;
    case GL_POINT_SPRITE:
      if (pname != GL_COORD_REPLACE) return ctx->recordError(GL_INVALID_ENUM);
      if (params) *params = static_cast<T>(ctx->point.coordReplace[unit] ? 1 : 0);
      return;
    default: ctx->recordError(GL_INVALID_ENUM);
  }
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (api::compiled(&glTexEnvfv, target, pname, api::copied(params, texEnvCount(target, pname)))) return;
  Context* ctx = api::contextForSetter();
  if (!ctx || !params) return;  // no GL error for a null pointer; Mesa would crash
  texEnv(*ctx, target, pname, params);
}

GLAPI void APIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat param) {
  const GLfloat params[4] = {param, 0.0f, 0.0f, 0.0f};
  glTexEnvfv(target, pname, params);
}

GLAPI void APIENTRY glTexEnvi(GLenum target, GLenum pname, GLint param) {
  const GLfloat params[4] = {static_cast<GLfloat>(param), 0.0f, 0.0f, 0.0f};
  glTexEnvfv(target, pname, params);
}

GLAPI void APIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint* params) {
  if (!params) return glTexEnvfv(target, pname, nullptr);
  GLfloat f[4] = {static_cast<GLfloat>(params[0]), 0.0f, 0.0f, 0.0f};
  if (pname == GL_TEXTURE_ENV_COLOR)  // as Mesa: whatever the target
    for (int k = 0; k < 4; ++k) f[k] = intToFloat(params[k]);
  glTexEnvfv(target, pname, f);
}

GLAPI void APIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* params) {
  getTexEnv(target, pname, params);
}

GLAPI void APIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint* params) {
  getTexEnv(target, pname, params);
}

}  // extern "C"
