// Points (GL 2.1 §3.4): clipping and the hand-over to llvmpipe's point setup.
// Mesa's draw module drops a point whose centre is outside the view volume
// (draw_pipe_clip.c: a point is kept or dropped whole, never cut) and keeps
// one whose centre is inside even when its square reaches past the viewport
// (MESA_FACTS "Points"). Points are independent, so the draw module's
// segments (assemble.h) change nothing here.
#pragma GCC optimize("fp-contract=off")

#include <cstring>

#include "primitive/batch_context.h"
#include "raster/raster.h"

namespace glfixed::primitive {

void drawPointBatch(BatchContext& b, uint32_t n, const std::vector<ClipVertex>& vertices,
                    const std::vector<uint32_t>& masks) {
  for (uint32_t i = 0; i < n; ++i)
    if (masks[i] == 0) emitPoint(b, vertices[i]);
}

void emitPoint(const BatchContext& b, const ClipVertex& v) {
  const PrimitiveState& state = b.state;
  raster::WindowVertex w;
  w.x = v.window[0];
  w.y = v.window[1];
  w.z = v.window[2];
  w.oneOverW = v.window[3];
  // A point is always front-facing (§3.4: two-sided lighting gives points the front colours).
  std::memcpy(w.varying, v.attr + kFrontAttribs, sizeof(float) * b.varyingCount);
  if (carriesMoreThanColours(b)) copyTexCoords(b, v, w);  // texture coordinates (issue 14)
  const float* flat = nullptr;
  float flatValues[raster::kMaxVaryings];
  if (b.raster.flatGroups != 0) {
    for (int k = 0; k < 4; ++k) flatValues[k] = state.constantPrimary ? b.constantColours[k] : w.varying[k];
    for (int k = 4; k < 8; ++k) flatValues[k] = state.constantSecondary ? b.constantColours[k] : w.varying[k];
    flat = flatValues;
  }
  const float size = state.pointSizePerVertex ? v.pointSize : state.pointSize;
  if (state.pointSmooth) {
    // draw_pipe_aapoint.c: the radius is half the vertex's size, or, from
    // the state's size, 1 for sizes up to 2 (a NaN size gives NaN).
    const float radius = state.pointSizePerVertex ? 0.5f * size : (size <= 2.0f ? 1.0f : 0.5f * size);
    return raster::drawSmoothPoint(b.raster, b.fb, w, radius, flat);
  }
  raster::drawPoint(b.raster, b.fb, w, size, flat);
}

}  // namespace glfixed::primitive
