// The lighting state's glGet* values and glEnable/glDisable capabilities
// (GL 2.1 tables 6.11-6.13, and GL_NORMALIZE / GL_RESCALE_NORMAL of table 6.5).
#include "vertex/lighting_queries.h"

#include "state/context.h"

namespace glfixed {

namespace {

int lightIndex(GLenum e) { return (e >= GL_LIGHT0 && e < GL_LIGHT0 + kMaxLights) ? int(e - GL_LIGHT0) : -1; }

void put(GLdouble* out, int* count, std::initializer_list<double> values) {
  int n = 0;
  for (double v : values) out[n++] = v;
  *count = n;
}

}  // namespace

bool getLightingState(Context& ctx, GLenum pname, GLdouble* out, int* count) {
  const LightingAttrib& l = ctx.lighting;
  if (int i = lightIndex(pname); i >= 0) {
    put(out, count, {double(l.light[i].enabled)});
    return true;
  }
  switch (pname) {
    case GL_LIGHTING: put(out, count, {double(l.lighting)}); return true;
    case GL_COLOR_MATERIAL: put(out, count, {double(l.colorMaterial)}); return true;
    case GL_COLOR_MATERIAL_FACE: put(out, count, {double(l.colorMaterialFace)}); return true;
    case GL_COLOR_MATERIAL_PARAMETER: put(out, count, {double(l.colorMaterialParameter)}); return true;
    case GL_LIGHT_MODEL_AMBIENT: {
      const glm::vec4& a = l.model.ambient;
      put(out, count, {a.r, a.g, a.b, a.a});
      return true;
    }
    case GL_LIGHT_MODEL_LOCAL_VIEWER: put(out, count, {double(l.model.localViewer)}); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: put(out, count, {double(l.model.twoSide)}); return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL: put(out, count, {double(l.model.colorControl)}); return true;
    case GL_SHADE_MODEL: put(out, count, {double(l.shadeModel)}); return true;
    case GL_MAX_LIGHTS: put(out, count, {double(kMaxLights)}); return true;
    case GL_NORMALIZE: put(out, count, {double(ctx.transform.normalize)}); return true;
    case GL_RESCALE_NORMAL: put(out, count, {double(ctx.transform.rescaleNormal)}); return true;
    default: return false;
  }
}

}  // namespace glfixed
