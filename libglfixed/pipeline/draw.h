// Draws a vertex batch: validate derived state, run the vertex stage on the
// whole batch, then primitive assembly, clipping and rasterization.
#pragma once

#include "pipeline/vertex_batch.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

void drawBatch(Context& ctx, const VertexBatch& batch);

}  // namespace glfixed::pipeline
