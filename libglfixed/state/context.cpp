#include "state/context.h"

namespace glfixed {

namespace {
thread_local Context* tCurrent = nullptr;
}

Context* currentContext() { return tCurrent; }
void setCurrentContext(Context* ctx) { tCurrent = ctx; }

Context::Context(int depthBits, int stencilBits)
    : requestedDepthBits(depthBits), requestedStencilBits(stencilBits > 0 ? 8 : 0) {}

const vertex::VertexState& Context::validate() {
  if (dirty_ & (kDirtyModelview | kDirtyProjection)) {
    vertexState_.eyeFromObject = modelview.top();
    vertexState_.clipFromObject = projection.top() * modelview.top();
  }
  // Texture coordinates (issue 14): rebuilt at every draw (cheap while no
  // unit is enabled). Texgen that needs eye coordinates makes Mesa's whole
  // shader work in eye space (_NeedEyeCoords), lighting included.
  vertex::buildTexCoordState(*this, vertexState_.texCoord);
  if (vertexState_.texCoord.needEyeCoords != lightingConstants_.texgenNeedsEyeCoords) dirty_ |= kDirtyLighting;
  if (dirty_ & kDirtyLighting) {
    vertex::buildLightingConstants(lighting, transform, lightingConstants_);
    lightingConstants_.texgenNeedsEyeCoords = vertexState_.texCoord.needEyeCoords;
    if (lightingConstants_.texgenNeedsEyeCoords) lightingConstants_.lightsAllowObjectSpace = false;
  }
  vertexState_.lighting = lighting.lighting;
  vertexState_.lightingConstants = &lightingConstants_;
  vertexState_.lightingAttrib = &lighting;
  vertexState_.transformAttrib = &transform;
  // Points: what the vertex program's point-size code reads (vertex_stage.h).
  {
    const glm::vec3& a = point.distanceAttenuation;
    vertexState_.pointAttenuated = a.x != 1.0f || a.y != 0.0f || a.z != 0.0f;
    vertexState_.pointAttenuation = a;
    vertexState_.pointSizeClamp[0] = point.size;
    vertexState_.pointSizeClamp[1] = point.sizeMin >= 1.0f ? point.sizeMin : 1.0f;
    vertexState_.pointSizeClamp[2] = point.sizeMax <= 255.0f ? point.sizeMax : 255.0f;
  }
  // Fog: the vertex program's fog coordinate (vertex_stage.h).
  vertexState_.fog.enabled = fog.enabled;
  vertexState_.fog.fromFogCoord = fog.coordSrc == GL_FOG_COORD;
  vertexState_.fog.distanceMode = fog.distanceMode;
  vertexState_.fog.currentCoord = current.fogCoord;
  dirty_ = 0;
  return vertexState_;
}

}  // namespace glfixed
