// The lighting constants (light_constants.h): what Mesa's light.c and
// prog_statevars.c hand to the fixed-function vertex program, computed the same
// way on the CPU, once per state change.
#include "vertex/light_constants.h"

#include <atomic>
#include <cmath>

#include "vertex/lighting_math.h"

namespace glfixed::vertex {

uint32_t colorMaterialBits(GLenum face, GLenum mode) {
  uint32_t front = 0;
  switch (mode) {
    case GL_EMISSION: front = kTrackEmission; break;
    case GL_AMBIENT: front = kTrackAmbient; break;
    case GL_DIFFUSE: front = kTrackDiffuse; break;
    case GL_SPECULAR: front = kTrackSpecular; break;
    case GL_AMBIENT_AND_DIFFUSE: front = kTrackAmbient | kTrackDiffuse; break;
    default: return 0;
  }
  switch (face) {
    case GL_FRONT: return front;
    case GL_BACK: return front << kTrackBackShift;
    case GL_FRONT_AND_BACK: return front | (front << kTrackBackShift);
    default: return 0;
  }
}

namespace {

// _CosCutoff of light.c: cosf of the cutoff in radians (the product in double,
// narrowed to float for cosf), never below 0.
float spotCosCutoff(float cutoffDegrees) {
  const float radians = static_cast<float>(cutoffDegrees * M_PI / 180.0);
  const float c = std::cos(radians);
  return c < 0 ? 0.0f : c;
}

}  // namespace

void buildLightingConstants(const LightingAttrib& lighting, const TransformAttrib& transform,
                            LightingConstants& out) {
  out.twoSide = lighting.model.twoSide;
  out.separateSpecular = lighting.model.colorControl == GL_SEPARATE_SPECULAR_COLOR;
  out.localViewer = lighting.model.localViewer;
  out.modelAmbient = lighting.model.ambient;
  out.normalize = transform.normalize;
  out.rescaleNormal = transform.rescaleNormal;
  out.colorMaterial = lighting.colorMaterial
                          ? colorMaterialBits(lighting.colorMaterialFace, lighting.colorMaterialParameter)
                          : 0;

  bool needEyeCoords = out.localViewer || out.separateSpecular;
  out.lightCount = 0;
  for (int i = 0; i < kMaxLights; ++i) {
    const Light& l = lighting.light[i];
    if (!l.enabled) continue;
    LightConstants& c = out.lights[out.lightCount++];
    c = LightConstants{};
    c.index = i;
    c.positional = l.eyePosition.w != 0.0f;
    c.spot = l.spotCutoff != 180.0f;
    c.attenuated =
        l.constantAttenuation != 1.0f || l.linearAttenuation != 0.0f || l.quadraticAttenuation != 0.0f;
    c.attenuation = glm::vec3(l.constantAttenuation, l.linearAttenuation, l.quadraticAttenuation);
    c.ambient = glm::vec3(l.ambient);
    c.diffuse = glm::vec3(l.diffuse);
    c.specular = glm::vec3(l.specular);
    if (c.positional || c.spot) needEyeCoords = true;

    const glm::vec3 eye(l.eyePosition);
    if (c.positional) {
      const float wInv = 1.0f / l.eyePosition.w;
      c.position = glm::vec3(eye.x * wInv, eye.y * wInv, eye.z * wInv);
    } else {
      c.eyeDirection = eye;
      c.direction = lp::normalizeLikeMesa(eye);
      c.halfVector = lp::normalizeLikeMesa(c.direction + glm::vec3(0, 0, 1));
    }
    if (c.spot) {
      c.spotDirection = lp::normalizeLikeMesa(lp::normalizeLikeMesa(l.eyeSpotDirection));
      c.spotCosCutoff = spotCosCutoff(l.spotCutoff);
      c.spotExponent = l.spotExponent;
      if (!c.positional) {
        // The shader's per-vertex spot term, constant for a directional light:
        // dot(-VP, spot direction) > cos(cutoff) ? |dot|^exponent : 0.
        const float d = lp::dot3(-c.direction, c.spotDirection);
        c.directionalSpotFactor = c.spotCosCutoff < d ? lp::pow(std::fabs(d), c.spotExponent) : 0.0f;
      }
    }
  }
  out.lightsAllowObjectSpace = !needEyeCoords;
  // Unique across every LightingConstants, so that a cache keyed by it never
  // mistakes a new context's constants for a destroyed one's at the same address.
  static std::atomic<uint64_t> generations{0};
  out.generation = ++generations;
}

void buildLightingSpace(const LightingConstants& k, const glm::mat4& modelview, LightingSpace& out) {
  const ModelviewAnalysis mv = analyseModelview(modelview);
  out.objectSpace = k.lightsAllowObjectSpace && mv.lengthPreserving;
  out.normalRescale = out.objectSpace ? 1.0f : mv.normalRescale;
  // The shader multiplies the normal by the rows of the inverse transpose:
  // row i is column i of the inverse.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.normalFromObject[i][j] = mv.inverse[i][j];
  if (!out.objectSpace) {
    for (int i = 0; i < k.lightCount; ++i) {
      out.lights[i].direction = k.lights[i].direction;
      out.lights[i].halfVector = k.lights[i].halfVector;
    }
    return;
  }
  // Object space (compute_light_positions): light positions through the
  // inverse modelview, the viewer's z direction through the modelview's rows.
  const glm::vec3 eyeZ = transformNormalLikeMesa(modelview, glm::vec3(0, 0, 1));
  for (int i = 0; i < k.lightCount; ++i) {
    const glm::vec3 p(transformPointLikeMesa(mv.inverse, glm::vec4(k.lights[i].eyeDirection, 0.0f)));
    const glm::vec3 vp = lp::normalizeLikeMesa(p);
    out.lights[i].direction = vp;
    out.lights[i].halfVector = lp::normalizeLikeMesa(vp + eyeZ);
  }
}

}  // namespace glfixed::vertex
