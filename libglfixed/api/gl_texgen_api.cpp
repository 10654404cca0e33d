// Texture coordinate generation (GL 2.1 §2.11.4): glTexGen and glGetTexGen
// for the active texture unit. The eye plane is stored as Mesa stores it
// (texgen.c): the plane as floats, times Mesa's float inverse of the
// modelview at the time of the call (vertex/lighting_matrix.h), as a row
// vector (primitive::transformPlane), compared bit for bit with the old one.
// Every float operation here must round as Mesa's C does: no fused
// multiply-adds.
#pragma GCC optimize("fp-contract=off")

#include "api/api.h"
#include "api/list_record.h"
#include "primitive/clip.h"
#include "vertex/lighting_matrix.h"

using namespace glfixed;

namespace {

// GL_S..GL_Q -> 0..3, or -1 (GL_INVALID_ENUM).
int coordIndex(GLenum coord) {
  switch (coord) {
    case GL_S: return 0;
    case GL_T: return 1;
    case GL_R: return 2;
    case GL_Q: return 3;
    default: return -1;
  }
}

// Whether `mode` is a generation mode for coordinate c (§2.11.4): the sphere
// map only for s and t, the reflection and normal maps not for q.
bool modeAllowed(GLenum mode, int c) {
  switch (mode) {
    case GL_OBJECT_LINEAR:
    case GL_EYE_LINEAR: return true;
    case GL_SPHERE_MAP: return c < 2;
    case GL_REFLECTION_MAP:
    case GL_NORMAL_MAP: return c < 3;
    default: return false;
  }
}

// The setter behind every glTexGen: `params` holds one value for
// GL_TEXTURE_GEN_MODE, four for the planes. §2.11.4 gives the scalar calls
// GL_TEXTURE_GEN_MODE only, but Mesa takes a plane from them too, as
// (param, 0, 0, 0) without an error, as it (and this library) does for
// glLightf and glFogf: the scalar calls pass that vector.
void texGen(GLenum coord, GLenum pname, const float* params) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const int c = coordIndex(coord);
  if (c < 0) return ctx->recordError(GL_INVALID_ENUM);
  TexGenAttrib::Coord& g = ctx->texture.texgen[ctx->texture.activeUnit()].coord[c];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const GLenum mode = static_cast<GLenum>(static_cast<GLint>(params[0]));
      if (!modeAllowed(mode, c)) return ctx->recordError(GL_INVALID_ENUM);
      api::setState(*ctx, g.mode, mode, GL_TEXTURE_BIT);
      return;
    }
    case GL_OBJECT_PLANE:
      api::setState(*ctx, g.objectPlane, glm::vec4(params[0], params[1], params[2], params[3]),
                    GL_TEXTURE_BIT);
      return;
    case GL_EYE_PLANE: {
      const glm::mat4 objectFromEye = vertex::analyseModelview(ctx->modelview.top()).inverse;
      const glm::vec4 plane =
          primitive::transformPlane(glm::vec4(params[0], params[1], params[2], params[3]), objectFromEye);
      api::setState(*ctx, g.eyePlane, plane, GL_TEXTURE_BIT);
      return;
    }
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
}

int valueCount(GLenum pname) { return pname == GL_TEXTURE_GEN_MODE ? 1 : 4; }

template <typename T>
void texGenv(GLenum coord, GLenum pname, const T* params) {
  if (!params) return;
  float p[4] = {0, 0, 0, 0};
  for (int i = 0; i < valueCount(pname); ++i) p[i] = static_cast<float>(params[i]);
  texGen(coord, pname, p);
}

// glGetTexGen: the mode, or the plane as stored.
template <typename T>
void getTexGen(GLenum coord, GLenum pname, T* params) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const int c = coordIndex(coord);
  if (c < 0) return ctx->recordError(GL_INVALID_ENUM);
  const TexGenAttrib::Coord& g = ctx->texture.texgen[ctx->texture.activeUnit()].coord[c];
  const glm::vec4* plane = nullptr;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE:
      if (params) params[0] = static_cast<T>(g.mode);
      return;
    case GL_OBJECT_PLANE: plane = &g.objectPlane; break;
    case GL_EYE_PLANE: plane = &g.eyePlane; break;
    default: return ctx->recordError(GL_INVALID_ENUM);
  }
  if (params)
    for (int i = 0; i < 4; ++i) params[i] = static_cast<T>((*plane)[i]);  // integers: truncated, as Mesa
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glTexGeni(GLenum coord, GLenum pname, GLint param) {
  if (api::compiled(&glTexGeni, coord, pname, param)) return;
  const float p[4] = {static_cast<float>(param), 0, 0, 0};
  texGen(coord, pname, p);
}
GLAPI void APIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat param) {
  if (api::compiled(&glTexGenf, coord, pname, param)) return;
  const float p[4] = {param, 0, 0, 0};
  texGen(coord, pname, p);
}
GLAPI void APIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble param) {
  if (api::compiled(&glTexGend, coord, pname, param)) return;
  const float p[4] = {static_cast<float>(param), 0, 0, 0};
  texGen(coord, pname, p);
}
GLAPI void APIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint* params) {
  if (api::compiled(&glTexGeniv, coord, pname, api::copied(params, valueCount(pname)))) return;
  texGenv(coord, pname, params);
}
GLAPI void APIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat* params) {
  if (api::compiled(&glTexGenfv, coord, pname, api::copied(params, valueCount(pname)))) return;
  texGenv(coord, pname, params);
}
GLAPI void APIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble* params) {
  if (api::compiled(&glTexGendv, coord, pname, api::copied(params, valueCount(pname)))) return;
  texGenv(coord, pname, params);
}

GLAPI void APIENTRY glGetTexGeniv(GLenum coord, GLenum pname, GLint* params) {
  getTexGen(coord, pname, params);
}
GLAPI void APIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* params) {
  getTexGen(coord, pname, params);
}
GLAPI void APIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble* params) {
  getTexGen(coord, pname, params);
}

}  // extern "C"
