// Fog (GL 2.1 §3.10): glFog*, as Mesa's main/fog.c validates and stores it.
// The fragment stage applies it (fragment/fog.inc); the vertex stage makes
// the fog distance (vertex/vertex_stage.cpp).
#include "api/api.h"
#include "api/list_record.h"
#include "api/normalized.h"

using namespace glfixed;

namespace {

// NV_fog_distance (not in our gl.h).
constexpr GLenum kFogDistanceMode = 0x855A;   // GL_FOG_DISTANCE_MODE_NV
constexpr GLenum kEyeRadial = 0x855B;         // GL_EYE_RADIAL_NV
constexpr GLenum kEyePlaneAbsolute = 0x855C;  // GL_EYE_PLANE_ABSOLUTE_NV

// Mesa's _mesa_Fogfv: every pname takes params[0], GL_FOG_COLOR four values.
// An enum given as a float is truncated to an integer first.
void setFog(GLenum pname, const GLfloat* params) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  FogAttrib& fog = ctx->fog;
  const auto asEnum = [&] { return static_cast<GLenum>(static_cast<GLint>(params[0])); };
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum m = asEnum();
      if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) break;
      api::setState(*ctx, fog.mode, m, GL_FOG_BIT);
      return;
    }
    case GL_FOG_DENSITY:
      if (params[0] < 0.0f) {
        ctx->recordError(GL_INVALID_VALUE);
        return;
      }
      api::setState(*ctx, fog.density, params[0], GL_FOG_BIT);
      return;
    case GL_FOG_START: api::setState(*ctx, fog.start, params[0], GL_FOG_BIT); return;
    case GL_FOG_END: api::setState(*ctx, fog.end, params[0], GL_FOG_BIT); return;
    case GL_FOG_INDEX: api::setState(*ctx, fog.index, params[0], GL_FOG_BIT); return;
    case GL_FOG_COLOR:
      // Stored as given; glGet and the fragment stage clamp it (the buffers
      // are fixed-point: Mesa's Fog.Color is the clamped copy).
      api::setState(*ctx, fog.color, glm::vec4(params[0], params[1], params[2], params[3]), GL_FOG_BIT);
      return;
    case GL_FOG_COORD_SRC: {
      const GLenum s = asEnum();
      if (s != GL_FOG_COORD && s != GL_FRAGMENT_DEPTH) break;
      api::setState(*ctx, fog.coordSrc, s, GL_FOG_BIT);
      return;
    }
    case kFogDistanceMode: {
      const GLenum d = asEnum();
      if (d != kEyeRadial && d != GL_EYE_PLANE && d != kEyePlaneAbsolute) break;
      api::setState(*ctx, fog.distanceMode, d, GL_FOG_BIT);
      return;
    }
    default: break;
  }
  ctx->recordError(GL_INVALID_ENUM);  // a bad pname, or a bad enum value
}

// How many values glFogfv/glFogiv read for pname (for display lists).
int fogValueCount(GLenum pname) { return pname == GL_FOG_COLOR ? 4 : 1; }

}  // namespace

extern "C" {

GLAPI void APIENTRY glFogfv(GLenum pname, const GLfloat* params) {
  if (api::compiled(&glFogfv, pname, api::copied(params, params ? fogValueCount(pname) : 0))) return;
  if (params) setFog(pname, params);
}

// A scalar for every pname: GL_FOG_COLOR gets (param, 0, 0, 0), as in Mesa.
GLAPI void APIENTRY glFogf(GLenum pname, GLfloat param) {
  if (api::compiled(&glFogf, pname, param)) return;
  const GLfloat p[4] = {param, 0, 0, 0};
  setFog(pname, p);
}

// Integers: the colour is normalized (GL 2.1 table 2.9's signed rule), the
// others converted as they are.
GLAPI void APIENTRY glFogiv(GLenum pname, const GLint* params) {
  if (api::compiled(&glFogiv, pname, api::copied(params, params ? fogValueCount(pname) : 0))) return;
  if (!params) return;
  GLfloat p[4] = {static_cast<GLfloat>(params[0]), 0, 0, 0};
  if (pname == GL_FOG_COLOR)
    for (int i = 0; i < 4; ++i) p[i] = api::normalized(params[i]);
  setFog(pname, p);
}

GLAPI void APIENTRY glFogi(GLenum pname, GLint param) {
  if (api::compiled(&glFogi, pname, param)) return;
  const GLint p[4] = {param, 0, 0, 0};
  GLfloat f[4] = {static_cast<GLfloat>(param), 0, 0, 0};
  if (pname == GL_FOG_COLOR)
    for (int i = 0; i < 4; ++i) f[i] = api::normalized(p[i]);
  setFog(pname, f);
}

}  // extern "C"
