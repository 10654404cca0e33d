#include "vertex/vertex_stage.h"

#include <algorithm>

namespace glfixed::vertex {

namespace {
glm::vec4 clampColor(const glm::vec4& c) { return glm::clamp(c, glm::vec4(0.0f), glm::vec4(1.0f)); }
}  // namespace

void shadeBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out) {
  const size_t n = batch.size();
  out.clip.resize(n);
  for (size_t i = 0; i < n; ++i) out.clip[i] = state.clipFromObject * batch.position[i];

  out.hasBack = false;
  out.hasSecondary = false;
  if (state.lighting) {
    lightBatch(state, batch, out);
    return;
  }
  // Unlit: the current colour at each vertex, clamped (GL 2.1 §2.14.8).
  out.primary[kFront].resize(n);
  for (size_t i = 0; i < n; ++i) out.primary[kFront][i] = clampColor(batch.color[i]);
}

}  // namespace glfixed::vertex
