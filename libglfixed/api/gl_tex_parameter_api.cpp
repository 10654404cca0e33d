// Texture parameters (GL 2.1 §3.8.4, table 6.23): glTexParameter{i,f}{v}
// and glGetTexParameter{i,f}v, on the texture bound to the target in the
// active unit.

#include <cmath>

#include "api/api.h"
#include "api/list_record.h"
#include "texture/texture_image.h"
#include "texture/texture_objects.h"

using namespace glfixed;
using texture::TextureObject;

namespace {

bool isMinFilter(GLenum v) {
  return v == GL_NEAREST || v == GL_LINEAR || v == GL_NEAREST_MIPMAP_NEAREST ||
         v == GL_LINEAR_MIPMAP_NEAREST || v == GL_NEAREST_MIPMAP_LINEAR || v == GL_LINEAR_MIPMAP_LINEAR;
}
bool isWrap(GLenum v) {
  return v == GL_CLAMP || v == GL_CLAMP_TO_EDGE || v == GL_CLAMP_TO_BORDER || v == GL_REPEAT ||
         v == GL_MIRRORED_REPEAT;
}
bool isCompareFunc(GLenum v) { return v >= GL_NEVER && v <= GL_ALWAYS; }  // EXT_shadow_funcs: all eight

TextureObject* boundForParameter(Context& ctx, GLenum target) {
  const int index = texture::targetIndex(target);
  if (index < 0) {
    ctx.recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  return &texture::boundObject(*ctx.textures, ctx.texture.binding[ctx.texture.activeUnit()], index);
}

// One parameter; `f` the values as floats, `asInt` the enum/integer reading
// of the first (glTexParameteri keeps the exact integer).
void setParameter(GLenum target, GLenum pname, const GLfloat* f, GLint asInt) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  TextureObject* object = boundForParameter(*ctx, target);
  if (!object) return;
  texture::SamplerParams p = object->params;
  bool generate = object->generateMipmap;
  float priority = object->priority;
  const GLenum e = static_cast<GLenum>(asInt);
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (!isMinFilter(e)) return ctx->recordError(GL_INVALID_ENUM);
      p.minFilter = e;
      break;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return ctx->recordError(GL_INVALID_ENUM);
      p.magFilter = e;
      break;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R:
      if (!isWrap(e)) return ctx->recordError(GL_INVALID_ENUM);
      (pname == GL_TEXTURE_WRAP_S ? p.wrapS : pname == GL_TEXTURE_WRAP_T ? p.wrapT : p.wrapR) = e;
      break;
    case GL_TEXTURE_BORDER_COLOR:
      p.borderColor = glm::vec4(f[0], f[1], f[2], f[3]);  // unclamped, as Mesa keeps it
      break;
    case GL_TEXTURE_MIN_LOD: p.minLod = f[0]; break;
    case GL_TEXTURE_MAX_LOD: p.maxLod = f[0]; break;
    case GL_TEXTURE_LOD_BIAS: p.lodBias = f[0]; break;
    case GL_TEXTURE_BASE_LEVEL:
      if (asInt < 0) return ctx->recordError(GL_INVALID_VALUE);
      p.baseLevel = asInt;
      break;
    case GL_TEXTURE_MAX_LEVEL:
      if (asInt < 0) return ctx->recordError(GL_INVALID_VALUE);
      p.maxLevel = asInt;
      break;
    case GL_TEXTURE_PRIORITY: priority = api::clamp01(f[0]); break;
    case GL_GENERATE_MIPMAP: generate = asInt != 0; break;
    case GL_TEXTURE_COMPARE_MODE:
      if (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE) return ctx->recordError(GL_INVALID_ENUM);
      p.compareMode = e;
      break;
    case GL_TEXTURE_COMPARE_FUNC:
      if (!isCompareFunc(e)) return ctx->recordError(GL_INVALID_ENUM);
      p.compareFunc = e;
      break;
    case GL_DEPTH_TEXTURE_MODE:
      if (e != GL_LUMINANCE && e != GL_INTENSITY && e != GL_ALPHA && e != GL_RED)
        return ctx->recordError(GL_INVALID_ENUM);
      p.depthTextureMode = e;
      break;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  const texture::SamplerParams& q = object->params;
  const bool same = p.minFilter == q.minFilter && p.magFilter == q.magFilter && p.wrapS == q.wrapS &&
                    p.wrapT == q.wrapT && p.wrapR == q.wrapR && p.borderColor == q.borderColor &&
                    p.minLod == q.minLod && p.maxLod == q.maxLod && p.lodBias == q.lodBias &&
                    p.baseLevel == q.baseLevel && p.maxLevel == q.maxLevel &&
                    p.compareMode == q.compareMode && p.compareFunc == q.compareFunc &&
                    p.depthTextureMode == q.depthTextureMode && generate == object->generateMipmap &&
                    priority == object->priority;
  if (same) return;
  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  object->params = p;
  object->generateMipmap = generate;
  object->priority = priority;
}

bool takesFourValues(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR; }

// The float values of one parameter for the queries; false: unknown pname.
bool parameterValues(const TextureObject& o, GLenum pname, GLfloat v[4], int& count, bool& isColor) {
  const texture::SamplerParams& p = o.params;
  count = 1;
  isColor = false;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: v[0] = GLfloat(p.minFilter); return true;
    case GL_TEXTURE_MAG_FILTER: v[0] = GLfloat(p.magFilter); return true;
    case GL_TEXTURE_WRAP_S: v[0] = GLfloat(p.wrapS); return true;
    case GL_TEXTURE_WRAP_T: v[0] = GLfloat(p.wrapT); return true;
    case GL_TEXTURE_WRAP_R: v[0] = GLfloat(p.wrapR); return true;
    case GL_TEXTURE_BORDER_COLOR:
      for (int i = 0; i < 4; ++i) v[i] = p.borderColor[i];
      count = 4;
      isColor = true;
      return true;
    case GL_TEXTURE_MIN_LOD: v[0] = p.minLod; return true;
    case GL_TEXTURE_MAX_LOD: v[0] = p.maxLod; return true;
    case GL_TEXTURE_LOD_BIAS: v[0] = p.lodBias; return true;
    case GL_TEXTURE_BASE_LEVEL: v[0] = GLfloat(p.baseLevel); return true;
    case GL_TEXTURE_MAX_LEVEL: v[0] = GLfloat(p.maxLevel); return true;
    case GL_TEXTURE_PRIORITY: v[0] = o.priority; return true;
    case GL_TEXTURE_RESIDENT: v[0] = 1; return true;
    case GL_GENERATE_MIPMAP: v[0] = o.generateMipmap ? 1 : 0; return true;
    case GL_TEXTURE_COMPARE_MODE: v[0] = GLfloat(p.compareMode); return true;
    case GL_TEXTURE_COMPARE_FUNC: v[0] = GLfloat(p.compareFunc); return true;
    case GL_DEPTH_TEXTURE_MODE: v[0] = GLfloat(p.depthTextureMode); return true;
    default: return false;
  }
}

// glGetTexParameter's common part: the values of `pname` of the texture bound
// to `target`; false (with the error recorded) when there are none.
bool queriedValues(GLenum target, GLenum pname, GLfloat v[4], int& count, bool& isColor) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return false;
  TextureObject* object = boundForParameter(*ctx, target);
  if (!object) return false;
  if (parameterValues(*object, pname, v, count, isColor)) return true;
  ctx->recordError(GL_INVALID_ENUM);
  return false;
}

}  // namespace

extern "C" {

// While a list is compiled Mesa takes the scalar calls as glTexParameterfv
// of (param, 0, 0, 0), the integer one converted to float, compiled and (in
// GL_COMPILE_AND_EXECUTE) run so: a list may set GL_TEXTURE_BORDER_COLOR
// through them, which outside a list is GL_INVALID_ENUM.
GLAPI void APIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat param) {
  const GLfloat asVector[4] = {param, 0, 0, 0};
  if (api::listCompiler(api::context())) return glTexParameterfv(target, pname, asVector);
  if (takesFourValues(pname)) {  // a vector parameter through the scalar command
    if (Context* ctx = api::contextForSetter()) ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  const GLfloat f[4] = {param, 0, 0, 0};
  setParameter(target, pname, f, static_cast<GLint>(param));
}

GLAPI void APIENTRY glTexParameteri(GLenum target, GLenum pname, GLint param) {
  const GLfloat asVector[4] = {static_cast<GLfloat>(param), 0, 0, 0};
  if (api::listCompiler(api::context())) return glTexParameterfv(target, pname, asVector);
  if (takesFourValues(pname)) {
    if (Context* ctx = api::contextForSetter()) ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  const GLfloat f[4] = {static_cast<GLfloat>(param), 0, 0, 0};
  setParameter(target, pname, f, param);
}

GLAPI void APIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (api::compiled(&glTexParameterfv, target, pname, api::copied(params, takesFourValues(pname) ? 4 : 1)))
    return;
  if (!params) return;
  GLfloat f[4] = {params[0], 0, 0, 0};
  if (takesFourValues(pname)) f[1] = params[1], f[2] = params[2], f[3] = params[3];
  setParameter(target, pname, f, static_cast<GLint>(params[0]));
}

GLAPI void APIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint* params) {
  if (api::compiled(&glTexParameteriv, target, pname, api::copied(params, takesFourValues(pname) ? 4 : 1)))
    return;
  if (!params) return;
  GLfloat f[4] = {static_cast<GLfloat>(params[0]), 0, 0, 0};
  if (takesFourValues(pname))  // §2.3.1 / table 2.10: integers map to [-1, 1]
    for (int i = 0; i < 4; ++i) f[i] = static_cast<GLfloat>(double(params[i]) / 2147483647.0);
  setParameter(target, pname, f, params[0]);
}

GLAPI void APIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  GLfloat v[4];
  int count;
  bool isColor;
  if (!queriedValues(target, pname, v, count, isColor)) return;
  if (params)
    for (int i = 0; i < count; ++i) params[i] = v[i];
}

GLAPI void APIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint* params) {
  GLfloat v[4];
  int count;
  bool isColor;
  if (!queriedValues(target, pname, v, count, isColor)) return;
  if (!params) return;
  for (int i = 0; i < count; ++i) {
    if (isColor) {  // §6.1.2: a colour maps [-1, 1] onto the integers
      const double scaled = double(v[i]) * 2147483647.0;
      params[i] = scaled >= 2147483647.0    ? 2147483647
                  : scaled <= -2147483648.0 ? -2147483647 - 1
                                            : GLint(scaled);
    } else {
      params[i] = static_cast<GLint>(std::lround(v[i]));
    }
  }
}

}  // extern "C"
