// Lighting entry points (GL 2.1 §2.14.2-§2.14.7, §6.1.3): glLight, glLightModel,
// glMaterial, glColorMaterial, glShadeModel and their queries. Each follows the
// one order of api/api.h; the value conversions and the errors are the ones
// Mesa 22.3 gives (measured with probes, see tests/vertex/light_api_test.cpp):
//   - glLightf/glLighti/glLightModelf/glLightModeli accept a vector pname and
//     set (param, 0, 0, 0), as Mesa does;
//   - integer colours convert as (2c + 1) / (2^32 - 2) (Mesa's INT_TO_FLOAT);
//   - glGetLightiv and glGetMaterialiv truncate toward zero (colours as
//     (GLint)(2147483647.0 * c)), except shininess and colour indexes, which round.
#include <cmath>
#include <cstdint>

#include "api/api.h"
#include "api/list_record.h"
#include "vertex/color_material.h"
#include "vertex/light_constants.h"
#include "vertex/lighting_matrix.h"

using namespace glfixed;

namespace {

constexpr float kMaxSpotExponent = 128.0f;
constexpr float kMaxShininess = 128.0f;

// Mesa's INT_TO_FLOAT: float arithmetic, then a double multiply.
inline float intToFloat(GLint i) {
  return static_cast<float>((2.0f * static_cast<float>(i) + 1.0f) * (1.0f / 4294967294.0));
}
// A double to GLint conversion with x86's result for values out of range.
inline GLint truncateToInt(double v) {
  if (!(v > -2147483649.0 && v < 2147483648.0)) return INT32_MIN;
  return static_cast<GLint>(v);
}
// Mesa's FLOAT_TO_INT for colours: (GLint)(2147483647.0 * c), truncated.
inline GLint colorToInt(float c) { return truncateToInt(2147483647.0 * static_cast<double>(c)); }
inline GLint roundToInt(float v) {
  const long r = std::lround(v);
  return (r < INT32_MIN || r > INT32_MAX) ? INT32_MIN : static_cast<GLint>(r);
}

int lightIndex(GLenum light) {
  return (light >= GL_LIGHT0 && light < GL_LIGHT0 + kMaxLights) ? int(light - GL_LIGHT0) : -1;
}

bool isColorPname(GLenum pname) { return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR; }

// ---- glLight ---------------------------------------------------------------

// How many values a glLight, glLightModel or glMaterial pname has: what a
// list copies from the caller's array.
size_t lightValueCount(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_POSITION:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE:
    case GL_LIGHT_MODEL_AMBIENT: return 4;
    case GL_SPOT_DIRECTION:
    case GL_COLOR_INDEXES: return 3;
    default: return 1;
  }
}

void lightfv(GLenum light, GLenum pname, const GLfloat* params) {
  if (api::compiled(&glLightfv, light, pname, api::copied(params, lightValueCount(pname)))) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const int i = lightIndex(light);
  if (i < 0) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  Light& l = ctx->lighting.light[i];
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR: {
      const glm::vec4 v4(params[0], params[1], params[2], params[3]);
      glm::vec4& c = pname == GL_AMBIENT ? l.ambient : pname == GL_DIFFUSE ? l.diffuse : l.specular;
      if (!api::setState(*ctx, c, v4, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    case GL_POSITION: {  // stored in eye coordinates (§2.14.2)
      const glm::vec4 v4(params[0], params[1], params[2], params[3]);
      const glm::vec4 p = vertex::transformPointLikeMesa(ctx->modelview.top(), v4);
      if (!api::setState(*ctx, l.eyePosition, p, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    case GL_SPOT_DIRECTION: {  // by the upper 3x3 of the modelview
      const glm::vec3 d = vertex::transformDirectionLikeMesa(ctx->modelview.top(),
                                                             glm::vec3(params[0], params[1], params[2]));
      if (!api::setState(*ctx, l.eyeSpotDirection, d, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    case GL_SPOT_EXPONENT:
      if (params[0] < 0.0f || params[0] > kMaxSpotExponent) {
        ctx->recordError(GL_INVALID_VALUE);
        return;
      }
      if (!api::setState(*ctx, l.spotExponent, params[0], GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    case GL_SPOT_CUTOFF:
      if ((params[0] < 0.0f || params[0] > 90.0f) && params[0] != 180.0f) {
        ctx->recordError(GL_INVALID_VALUE);
        return;
      }
      if (!api::setState(*ctx, l.spotCutoff, params[0], GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: {
      if (params[0] < 0.0f) {
        ctx->recordError(GL_INVALID_VALUE);
        return;
      }
      float& k = pname == GL_CONSTANT_ATTENUATION ? l.constantAttenuation
                 : pname == GL_LINEAR_ATTENUATION ? l.linearAttenuation
                                                  : l.quadraticAttenuation;
      if (!api::setState(*ctx, k, params[0], GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
  ctx->markDirty(kDirtyLighting);
}

void lightiv(GLenum light, GLenum pname, const GLint* params) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (isColorPname(pname)) {
    for (int j = 0; j < 4; ++j) f[j] = intToFloat(params[j]);
  } else if (pname == GL_POSITION) {
    for (int j = 0; j < 4; ++j) f[j] = static_cast<GLfloat>(params[j]);
  } else if (pname == GL_SPOT_DIRECTION) {
    for (int j = 0; j < 3; ++j) f[j] = static_cast<GLfloat>(params[j]);
  } else {
    f[0] = static_cast<GLfloat>(params[0]);  // scalars; a bad pname is caught by lightfv
  }
  lightfv(light, pname, f);
}

// The values glGetLight returns, or 0 values for a bad pname.
int lightValues(const Light& l, GLenum pname, GLfloat* out) {
  auto copy = [&](const float* v, int n) {
    for (int j = 0; j < n; ++j) out[j] = v[j];
    return n;
  };
  switch (pname) {
    case GL_AMBIENT: return copy(&l.ambient[0], 4);
    case GL_DIFFUSE: return copy(&l.diffuse[0], 4);
    case GL_SPECULAR: return copy(&l.specular[0], 4);
    case GL_POSITION: return copy(&l.eyePosition[0], 4);
    case GL_SPOT_DIRECTION: return copy(&l.eyeSpotDirection[0], 3);
    case GL_SPOT_EXPONENT: return copy(&l.spotExponent, 1);
    case GL_SPOT_CUTOFF: return copy(&l.spotCutoff, 1);
    case GL_CONSTANT_ATTENUATION: return copy(&l.constantAttenuation, 1);
    case GL_LINEAR_ATTENUATION: return copy(&l.linearAttenuation, 1);
    case GL_QUADRATIC_ATTENUATION: return copy(&l.quadraticAttenuation, 1);
    default: return 0;
  }
}

const Light* lightForQuery(Context* ctx, GLenum light, GLenum pname, GLfloat* values, int* count) {
  const int i = lightIndex(light);
  if (i < 0) {
    ctx->recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  const Light& l = ctx->lighting.light[i];
  *count = lightValues(l, pname, values);
  if (*count == 0) {
    ctx->recordError(GL_INVALID_ENUM);
    return nullptr;
  }
  return &l;
}

// ---- glLightModel ----------------------------------------------------------

void lightModelfv(GLenum pname, const GLfloat* params) {
  if (api::compiled(&glLightModelfv, pname, api::copied(params, lightValueCount(pname)))) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  LightModel& m = ctx->lighting.model;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: {
      const glm::vec4 a(params[0], params[1], params[2], params[3]);
      if (!api::setState(*ctx, m.ambient, a, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    case GL_LIGHT_MODEL_LOCAL_VIEWER:
    case GL_LIGHT_MODEL_TWO_SIDE: {
      bool& flag = pname == GL_LIGHT_MODEL_LOCAL_VIEWER ? m.localViewer : m.twoSide;
      const bool value = params[0] != 0.0f;
      if (!api::setState(*ctx, flag, value, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    case GL_LIGHT_MODEL_COLOR_CONTROL: {
      GLenum value;
      if (params[0] == static_cast<GLfloat>(GL_SINGLE_COLOR))
        value = GL_SINGLE_COLOR;
      else if (params[0] == static_cast<GLfloat>(GL_SEPARATE_SPECULAR_COLOR))
        value = GL_SEPARATE_SPECULAR_COLOR;
      else {
        ctx->recordError(GL_INVALID_ENUM);
        return;
      }
      if (!api::setState(*ctx, m.colorControl, value, GL_LIGHTING_BIT, kDirtyLighting)) return;
      break;
    }
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
  ctx->markDirty(kDirtyLighting);
}

void lightModeliv(GLenum pname, const GLint* params) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (pname == GL_LIGHT_MODEL_AMBIENT) {
    for (int j = 0; j < 4; ++j) f[j] = intToFloat(params[j]);
  } else {
    f[0] = static_cast<GLfloat>(params[0]);
  }
  lightModelfv(pname, f);
}

// ---- glMaterial ------------------------------------------------------------

// Allowed between glBegin and glEnd: then it changes the material of the
// vertices that follow (§2.14.3), through a new snapshot in the batch.
void materialfv(GLenum face, GLenum pname, const GLfloat* params) {
  // Between the list's glBegin and glEnd it changes the material per vertex.
  // Outside, as Mesa's save_Materialfv: a bad face or pname is a compiled
  // error; GL_COMPILE_AND_EXECUTE runs it before the vertices compiled so far
  // are fed back; and it is not compiled if it repeats the list's last values.
  const size_t count = lightValueCount(pname);
  if (pipeline::ListCompiler* list = api::listCompiler(currentContext()); list && !list->insideBeginEnd()) {
    const bool validFace = face == GL_FRONT || face == GL_BACK || face == GL_FRONT_AND_BACK;
    const bool validPname = pname == GL_EMISSION || pname == GL_AMBIENT || pname == GL_DIFFUSE ||
                            pname == GL_SPECULAR || pname == GL_SHININESS || pname == GL_COLOR_INDEXES ||
                            pname == GL_AMBIENT_AND_DIFFUSE;
    if (!validFace || !validPname) {
      list->recordError(*currentContext(), GL_INVALID_ENUM);
      return;
    }
    if (list->executes()) api::runUnrecorded(&glMaterialfv, face, pname, params);
    if (!list->materialRepeats(face, pname, params, int(count)))
      api::compiled(&glMaterialfv, face, pname, api::copied(params, count));
    return;
  }
  if (api::compiledVertexData([&](pipeline::ListCompiler& l) { l.material(face, pname, params, int(count)); },
                              &glMaterialfv, face, pname, api::copied(params, count)))
    return;
  Context* ctx = currentContext();
  if (!ctx) return;
  // Outside glBegin/glEnd the buffered vertices are drawn (they were lit with
  // the old material), but the vertex format is kept (a colour already
  // per-vertex data stays so) unless Mesa resets it (see below).
  // The faces to update; components that follow the colour are left alone
  // while GL_COLOR_MATERIAL is on (Mesa skips them silently).
  uint32_t faces;  // bit 0 front, bit 1 back
  switch (face) {
    case GL_FRONT: faces = 1; break;
    case GL_BACK: faces = 2; break;
    case GL_FRONT_AND_BACK: faces = 3; break;
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
  uint32_t bits;  // the MaterialBits pname names, front face
  switch (pname) {
    case GL_EMISSION: bits = vertex::kTrackEmission; break;
    case GL_AMBIENT: bits = vertex::kTrackAmbient; break;
    case GL_DIFFUSE: bits = vertex::kTrackDiffuse; break;
    case GL_SPECULAR: bits = vertex::kTrackSpecular; break;
    case GL_AMBIENT_AND_DIFFUSE: bits = vertex::kTrackAmbient | vertex::kTrackDiffuse; break;
    case GL_SHININESS:
      if (params[0] < 0.0f || params[0] > kMaxShininess) {
        ctx->recordError(GL_INVALID_VALUE);
        return;
      }
      bits = vertex::kMaterialShininess;
      break;
    case GL_COLOR_INDEXES: bits = 0; break;
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
  LightingAttrib& lighting = ctx->lighting;
  const uint32_t tracked = lighting.colorMaterial ? vertex::colorMaterialBits(lighting.colorMaterialFace,
                                                                              lighting.colorMaterialParameter)
                                                  : 0;
  // Read only as many values as pname has.
  glm::vec4 v4(params[0], 0, 0, 0);
  if (bits & ~vertex::kMaterialShininess) v4 = glm::vec4(params[0], params[1], params[2], params[3]);
  // Mesa's vbo takes each material component as a vertex attribute: one new
  // to its vertex format grows it (pipeline::materialBecomesVertexData),
  // which draws the buffered vertices first, with the old material.
  uint32_t attributes = 0;  // MaterialBit, both faces; colour indexes as bits 10, 11
  for (int f = 0; f < 2; ++f) {
    if (!(faces & (1u << f))) continue;
    attributes |= (bits & ~(tracked >> (f * vertex::kTrackBackShift))) << (f * vertex::kTrackBackShift);
    if (pname == GL_COLOR_INDEXES) attributes |= 1u << (10 + f);
  }
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::materialBecomesVertexData(*ctx, attributes);
  if (!ctx->insideBeginEnd) pipeline::drawPending(*ctx);
  bool changed = false;
  uint32_t setMask = 0;  // MaterialBit, both faces
  for (int f = 0; f < 2; ++f) {
    if (!(faces & (1u << f))) continue;
    Material& m = lighting.material[f];
    const uint32_t settable = bits & ~(tracked >> (f * vertex::kTrackBackShift));
    setMask |= settable << (f * vertex::kTrackBackShift);
    auto set = [&](uint32_t bit, glm::vec4& c) {
      if ((settable & bit) && c != v4) {
        c = v4;
        changed = true;
      }
    };
    set(vertex::kTrackEmission, m.emission);
    set(vertex::kTrackAmbient, m.ambient);
    set(vertex::kTrackDiffuse, m.diffuse);
    set(vertex::kTrackSpecular, m.specular);
    if (pname == GL_SHININESS && m.shininess != params[0]) {
      m.shininess = params[0];
      changed = true;
    }
    if (pname == GL_COLOR_INDEXES) {
      const glm::vec3 ci(params[0], params[1], params[2]);
      if (m.colorIndexes != ci) {
        m.colorIndexes = ci;
        changed = true;
      }
    }
  }
  if (changed) ctx->markChanged(GL_LIGHTING_BIT, kDirtyLighting);
  if (!ctx->insideBeginEnd) return;
  // Between glBegin and glEnd: the vertices from here on use the new material
  // (a new snapshot in the batch), and the components set are recorded, even
  // when the value is unchanged, because Mesa then reads them per vertex.
  // The first glMaterial of a batch always adds a snapshot, so that a batch
  // with glMaterial calls is one with more than one snapshot.
  VertexBatch& b = ctx->batch;
  if (b.materials.size() <= 1) {
    // (the pending draw may still be lit per vertex with the old mask)
    if (ctx->pending.size() == 0 || ctx->pending.materials.size() <= 1) lighting.beginEndMaterialMask = 0;
    b.materials.push_back(lighting.material);
  } else if (changed) {
    const bool lastReferenced = !b.materialIndex.empty() && b.materialIndex.back() == b.materials.size() - 1;
    if (lastReferenced)
      b.materials.push_back(lighting.material);
    else
      b.materials.back() = lighting.material;
  }
  lighting.beginEndMaterialMask |= setMask;
}

void materialiv(GLenum face, GLenum pname, const GLint* params) {
  GLfloat f[4] = {0, 0, 0, 0};
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE:
      for (int j = 0; j < 4; ++j) f[j] = intToFloat(params[j]);
      break;
    case GL_COLOR_INDEXES:
      for (int j = 0; j < 3; ++j) f[j] = static_cast<GLfloat>(params[j]);
      break;
    default: f[0] = static_cast<GLfloat>(params[0]);  // GL_SHININESS; bad pnames are caught by materialfv
  }
  materialfv(face, pname, f);
}

const Material* materialForQuery(Context* ctx, GLenum face) {
  switch (face) {
    case GL_FRONT: return &ctx->lighting.material[kFront];
    case GL_BACK: return &ctx->lighting.material[kBack];
    default: ctx->recordError(GL_INVALID_ENUM); return nullptr;
  }
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glLightfv(GLenum light, GLenum pname, const GLfloat* params) {
  if (!params) return;  // a null array is ignored, never read
  lightfv(light, pname, params);
}
GLAPI void APIENTRY glLightf(GLenum light, GLenum pname, GLfloat param) {
  const GLfloat f[4] = {param, 0, 0, 0};
  lightfv(light, pname, f);
}
GLAPI void APIENTRY glLightiv(GLenum light, GLenum pname, const GLint* params) {
  if (!params) return;  // a null array is ignored, never read
  lightiv(light, pname, params);
}
GLAPI void APIENTRY glLighti(GLenum light, GLenum pname, GLint param) {
  const GLint v[4] = {param, 0, 0, 0};
  lightiv(light, pname, v);
}

GLAPI void APIENTRY glGetLightfv(GLenum light, GLenum pname, GLfloat* params) {
  if (!params) return;  // a null array is ignored, never read
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  GLfloat v[4];
  int count = 0;
  if (!lightForQuery(ctx, light, pname, v, &count)) return;
  for (int j = 0; j < count; ++j) params[j] = v[j];
}

GLAPI void APIENTRY glGetLightiv(GLenum light, GLenum pname, GLint* params) {
  if (!params) return;  // a null array is ignored, never read
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  GLfloat v[4];
  int count = 0;
  if (!lightForQuery(ctx, light, pname, v, &count)) return;
  for (int j = 0; j < count; ++j) params[j] = isColorPname(pname) ? colorToInt(v[j]) : truncateToInt(v[j]);
}

GLAPI void APIENTRY glLightModelfv(GLenum pname, const GLfloat* params) {
  if (!params) return;  // a null array is ignored, never read
  lightModelfv(pname, params);
}
GLAPI void APIENTRY glLightModelf(GLenum pname, GLfloat param) {
  const GLfloat f[4] = {param, 0, 0, 0};
  lightModelfv(pname, f);
}
GLAPI void APIENTRY glLightModeliv(GLenum pname, const GLint* params) {
  if (!params) return;  // a null array is ignored, never read
  lightModeliv(pname, params);
}
GLAPI void APIENTRY glLightModeli(GLenum pname, GLint param) {
  const GLint v[4] = {param, 0, 0, 0};
  lightModeliv(pname, v);
}

GLAPI void APIENTRY glMaterialfv(GLenum face, GLenum pname, const GLfloat* params) {
  if (!params) return;  // a null array is ignored, never read
  materialfv(face, pname, params);
}
GLAPI void APIENTRY glMaterialf(GLenum face, GLenum pname, GLfloat param) {
  const GLfloat f[4] = {param, 0, 0, 0};
  materialfv(face, pname, f);
}
GLAPI void APIENTRY glMaterialiv(GLenum face, GLenum pname, const GLint* params) {
  if (!params) return;  // a null array is ignored, never read
  materialiv(face, pname, params);
}
GLAPI void APIENTRY glMateriali(GLenum face, GLenum pname, GLint param) {
  const GLint v[4] = {param, 0, 0, 0};
  materialiv(face, pname, v);
}

GLAPI void APIENTRY glGetMaterialfv(GLenum face, GLenum pname, GLfloat* params) {
  if (!params) return;  // a null array is ignored, never read
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const Material* m = materialForQuery(ctx, face);
  if (!m) return;
  auto copy = [&](const float* v, int n) {
    for (int j = 0; j < n; ++j) params[j] = v[j];
  };
  switch (pname) {
    case GL_AMBIENT: copy(&m->ambient[0], 4); break;
    case GL_DIFFUSE: copy(&m->diffuse[0], 4); break;
    case GL_SPECULAR: copy(&m->specular[0], 4); break;
    case GL_EMISSION: copy(&m->emission[0], 4); break;
    case GL_SHININESS: params[0] = m->shininess; break;
    case GL_COLOR_INDEXES: copy(&m->colorIndexes[0], 3); break;
    default: ctx->recordError(GL_INVALID_ENUM);
  }
}

GLAPI void APIENTRY glGetMaterialiv(GLenum face, GLenum pname, GLint* params) {
  if (!params) return;  // a null array is ignored, never read
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const Material* m = materialForQuery(ctx, face);
  if (!m) return;
  auto colors = [&](const glm::vec4& c) {
    for (int j = 0; j < 4; ++j) params[j] = colorToInt(c[j]);
  };
  switch (pname) {
    case GL_AMBIENT: colors(m->ambient); break;
    case GL_DIFFUSE: colors(m->diffuse); break;
    case GL_SPECULAR: colors(m->specular); break;
    case GL_EMISSION: colors(m->emission); break;
    case GL_SHININESS: params[0] = roundToInt(m->shininess); break;
    case GL_COLOR_INDEXES:
      for (int j = 0; j < 3; ++j) params[j] = roundToInt(m->colorIndexes[j]);
      break;
    default: ctx->recordError(GL_INVALID_ENUM);
  }
}

GLAPI void APIENTRY glColorMaterial(GLenum face, GLenum mode) {
  if (api::compiled(&glColorMaterial, face, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (vertex::colorMaterialBits(face, mode) == 0) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  LightingAttrib& l = ctx->lighting;
  if (l.colorMaterialFace == face && l.colorMaterialParameter == mode) return;
  api::beginStateChange(*ctx, GL_LIGHTING_BIT, kDirtyLighting);
  l.colorMaterialFace = face;
  l.colorMaterialParameter = mode;
  ctx->markDirty(kDirtyLighting);
  if (l.colorMaterial) trackColorMaterial(*ctx);  // the new components take the colour at once
}

GLAPI void APIENTRY glShadeModel(GLenum mode) {
  // Mesa's save_ShadeModel: in GL_COMPILE_AND_EXECUTE it runs first, before
  // the vertices compiled so far are fed back (scene list_compile_and_execute),
  // and a glShadeModel that repeats the list's previous one is not compiled,
  // so the vertices around it stay one node (scene list_merge).
  pipeline::ListCompiler* list = api::listCompiler(currentContext());
  if (list && !list->insideBeginEnd()) {
    if (list->executes()) api::runUnrecorded(&glShadeModel, mode);
    if (!list->shadeModelRepeats(mode)) api::compiled(&glShadeModel, mode);
    return;
  }
  if (api::compiled(&glShadeModel, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_FLAT && mode != GL_SMOOTH) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setState(*ctx, ctx->lighting.shadeModel, mode, GL_LIGHTING_BIT, kDirtyLighting);
}

}  // extern "C"
