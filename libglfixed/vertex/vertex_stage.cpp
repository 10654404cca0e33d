#include "vertex/vertex_stage.h"

#include <cmath>

#include "state/context.h"
#include "vertex/lighting_math.h"

namespace glfixed::vertex {

namespace {

// clip = MVP * position as Mesa's vertex program evaluates it: a multiply and
// three multiply-adds down the columns, each rounded, in this order
// (ffvertex_prog.c; glm's operator* pairs the terms differently, which moves
// depth and, at ties, coverage).
inline glm::vec4 transformPosition(const glm::mat4& m, const glm::vec4& p) {
  glm::vec4 r = m[0] * p.x;
  r = m[1] * p.y + r;
  r = m[2] * p.z + r;
  return m[3] * p.w + r;
}

// Lighting has computed the whole eye position (a positional light or a
// local viewer: lighting.cpp); the program's later uses reuse it.
bool lightingMadeEyePosition(const VertexState& state) {
  if (!state.lighting || !state.lightingConstants) return false;
  const LightingConstants& k = *state.lightingConstants;
  bool eyePosition = k.localViewer;
  for (int l = 0; l < k.lightCount; ++l) eyePosition |= k.lights[l].positional;
  return eyePosition;
}

// The eye z as the program has it: lighting's eye position summed column by
// column, or a DP4 with the modelview's third row (NIR sums it from w down).
inline float eyeZ(const glm::mat4& m, const glm::vec4& p, bool eyePosition) {
  return eyePosition ? ((p.x * m[0][2] + p.y * m[1][2]) + p.z * m[2][2]) + p.w * m[3][2]
                     : ((p.w * m[3][2] + p.z * m[2][2]) + p.y * m[1][2]) + p.x * m[0][2];
}

// Fog (build_fog, measured with ST_DEBUG=nir): GL_FOG_COORD gives
// |coordinate|; GL_FRAGMENT_DEPTH gives |z_eye| (GL_EYE_PLANE_ABSOLUTE_NV,
// the default), z_eye (GL_EYE_PLANE, signed) or the length of the eye
// position (GL_EYE_RADIAL_NV: the eye position column by column, then
// sqrt((z z + y y) + x x), unfused, an exact square root).
void computeFog(const VertexState& state, const VertexBatch& batch, ShadedVertices& out) {
  const size_t n = batch.size();
  const FogVertexState& fog = state.fog;
  out.fog.resize(n);
  if (fog.fromFogCoord) {
    const bool perVertex = batch.hasFogCoord && batch.fogCoord.size() == n;
    for (size_t i = 0; i < n; ++i) out.fog[i] = std::fabs(perVertex ? batch.fogCoord[i] : fog.currentCoord);
    return;
  }
  const glm::mat4& m = state.eyeFromObject;
  if (fog.distanceMode == 0x855B) {  // GL_EYE_RADIAL_NV
    for (size_t i = 0; i < n; ++i) {
      const glm::vec4& p = batch.position[i];
      const glm::vec3 e =
          ((glm::vec3(m[0]) * p.x + glm::vec3(m[1]) * p.y) + glm::vec3(m[2]) * p.z) + glm::vec3(m[3]) * p.w;
      out.fog[i] = std::sqrt((e.z * e.z + e.y * e.y) + e.x * e.x);
    }
    return;
  }
  const bool eyePosition = lightingMadeEyePosition(state);
  const bool absolute = fog.distanceMode != GL_EYE_PLANE;
  for (size_t i = 0; i < n; ++i) {
    const float z = eyeZ(m, batch.position[i], eyePosition);
    out.fog[i] = absolute ? std::fabs(z) : z;
  }
}

}  // namespace

bool fogCoordInput(const Context& ctx) { return ctx.fog.enabled && ctx.fog.coordSrc == GL_FOG_COORD; }

// ffvertex_prog.c, build_atten_pointsize, as llvmpipe runs it: the eye z is a
// DP4 with the modelview's third row (NIR sums it from w down, unfused), the
// distance is |z_eye|, the factor a + d (b + d c) is two unfused MADs, RSQ
// takes |factor| (an ARB program's RSQ does) and is 1 / sqrt; then
// MAX(size, min) and MIN(., max) as x86 maxps/minps: a NaN operand gives the
// second one (measured: a NaN attenuation draws a size-min point).
float attenuatedPointSize(const VertexState& state, const glm::vec4& p) {
  const glm::mat4& m = state.eyeFromObject;
  // When lighting has computed the whole eye position, the program reuses
  // its z, summed column by column.
  const float zEye = eyeZ(m, p, lightingMadeEyePosition(state));
  const float d = std::fabs(zEye);
  const glm::vec3& a = state.pointAttenuation;
  float factor = d * a.z + a.y;
  factor = d * factor + a.x;
  const float size = lp::rsq(std::fabs(factor)) * state.pointSizeClamp[0];
  const float atLeast = size > state.pointSizeClamp[1] ? size : state.pointSizeClamp[1];
  return atLeast < state.pointSizeClamp[2] ? atLeast : state.pointSizeClamp[2];
}

void shadeBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out) {
  const size_t n = batch.size();
  out.clip.resize(n);
  for (size_t i = 0; i < n; ++i) out.clip[i] = transformPosition(state.clipFromObject, batch.position[i]);

  out.hasBack = false;
  out.hasSecondary = false;
  // Points: per-vertex sizes under distance attenuation.
  out.hasPointSize = state.pointAttenuated;
  if (state.pointAttenuated) {
    out.pointSize.resize(n);
    for (size_t i = 0; i < n; ++i) out.pointSize[i] = attenuatedPointSize(state, batch.position[i]);
  }
  // Texture coordinates (issue 14): only for the units the shader outputs.
  out.texCoordUnits = 0;
  if (state.texCoord.units != 0) computeTexCoords(state.texCoord, state.eyeFromObject, batch, out);
  out.hasFog = state.fog.enabled;  // fog: each vertex's fog distance
  if (out.hasFog) computeFog(state, batch, out);
  if (state.lighting) {
    lightBatch(state, batch, out);
    return;
  }
  // Unlit: the current colour at each vertex, clamped as llvmpipe clamps
  // (GL 2.1 §2.14.8; NaN becomes 1).
  out.primary[kFront].resize(n);
  for (size_t i = 0; i < n; ++i) out.primary[kFront][i] = lp::clampColor(batch.color[i]);
}

}  // namespace glfixed::vertex
