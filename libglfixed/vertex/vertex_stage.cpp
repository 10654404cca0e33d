#include "vertex/vertex_stage.h"

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

}  // namespace

void shadeBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out) {
  const size_t n = batch.size();
  out.clip.resize(n);
  for (size_t i = 0; i < n; ++i) out.clip[i] = transformPosition(state.clipFromObject, batch.position[i]);

  out.hasBack = false;
  out.hasSecondary = false;
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
