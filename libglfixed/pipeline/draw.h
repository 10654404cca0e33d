// Draws a vertex batch: validate derived state, run the vertex stage on the
// whole batch, then primitive assembly, clipping and rasterization.
#pragma once

#include "pipeline/vertex_batch.h"
#include "primitive/primitive.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// `submission`: how Mesa would receive the draw (primitive.h): display lists
// draw indexed, which splits quads otherwise.
void drawBatch(Context& ctx, const VertexBatch& batch,
               primitive::PrimitiveState::Submission submission = primitive::PrimitiveState::Submission::kBeginEnd);

}  // namespace glfixed::pipeline
