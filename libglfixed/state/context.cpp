#include "state/context.h"

namespace glfixed {

namespace {
thread_local Context* tCurrent = nullptr;
}

Context* currentContext() { return tCurrent; }
void setCurrentContext(Context* ctx) { tCurrent = ctx; }

Context::Context(int depthBits) : requestedDepthBits(depthBits) {}

const vertex::VertexState& Context::validate() {
  if (dirty_ & (kDirtyModelview | kDirtyProjection)) {
    vertexState_.eyeFromObject = modelview.top();
    vertexState_.clipFromObject = projection.top() * modelview.top();
  }
  if (dirty_ & kDirtyLighting) vertex::buildLightingConstants(lighting, transform, lightingConstants_);
  vertexState_.lighting = lighting.lighting;
  vertexState_.lightingConstants = &lightingConstants_;
  vertexState_.lightingAttrib = &lighting;
  vertexState_.transformAttrib = &transform;
  dirty_ = 0;
  return vertexState_;
}

}  // namespace glfixed
