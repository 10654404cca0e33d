// Draws a vertex batch: validate derived state, run the vertex stage on the
// whole batch, then primitive assembly, clipping and rasterization.
#pragma once

#include "pipeline/vertex_batch.h"
#include "primitive/primitive.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// A glBegin/glEnd batch (the colour is vertex data as Context::vbo says).
void drawBatch(Context& ctx, const VertexBatch& batch);
// A batch of another submission: vertex arrays say themselves whether the
// colour is vertex data (a colour array is enabled). `fetchedVertexOutside`:
// see PrimitiveState.
void drawBatch(Context& ctx, const VertexBatch& batch, primitive::PrimitiveState::Submission submission,
               bool colorIsVertexData, bool fetchedVertexOutside = false);

// The rasterizer state glBitmap and glDrawPixels draw their quads with
// (pipeline/pixel_rect.cpp): the fragment operations of the context, the
// whole buffer (cut by an enabled scissor box) as the region.
raster::RasterState pixelRectRasterState(const Context& ctx);

// Whether some vertex of `batch` is outside the view volume once
// transformed (Mesa's clip test of the vertices it fetched).
bool anyVertexOutside(Context& ctx, const VertexBatch& batch);

}  // namespace glfixed::pipeline
