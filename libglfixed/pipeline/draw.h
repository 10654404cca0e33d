// Draws a vertex batch: validate derived state, run the vertex stage on the
// whole batch, then primitive assembly, clipping and rasterization.
#pragma once

#include "fragment/texture_stage.h"
#include "pipeline/vertex_batch.h"
#include "state/attrib_groups.h"
#include "texture/texture_objects.h"
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
               bool colorIsVertexData, bool fetchedVertexOutside = false, bool secondaryIsVertexData = false);

// The rasterizer state glBitmap and glDrawPixels draw their quads with
// (pipeline/pixel_rect.cpp): the fragment operations of the context, the
// whole buffer (cut by an enabled scissor box) as the region.
raster::RasterState pixelRectRasterState(const Context& ctx);

// Texturing (GL 2.1 §3.8.15): the units that texture, each with the first
// of its enabled targets whose texture is complete; `current` gives each
// unit's constant coordinates (TextureStage::Unit::currentCoord).
bool anyTextureEnabled(const TextureAttrib& texture);
void buildTextureStage(const TextureAttrib& texture, const texture::TextureObjects& objects,
                       const glm::vec4 (&current)[kMaxTextureUnits], fragment::TextureStage& stage);

// The colour sum without lighting (GL 2.1 §3.9, GL_COLOR_SUM): Mesa's
// fixed-function fragment shader adds the current secondary colour, read as
// a constant clamped to [0, 1] (STATE_CURRENT_ATTRIB_MAYBE_VP_CLAMPED), its
// alpha not added; on a float buffer the sum is not clamped.
glm::vec4 clampedCurrentSecondaryColor(const Context& ctx);
void addCurrentSecondaryColor(const Context& ctx, ShadedVertices& shaded);

// Whether some vertex of `batch` is outside the view volume once
// transformed (Mesa's clip test of the vertices it fetched).
bool anyVertexOutside(Context& ctx, const VertexBatch& batch);

}  // namespace glfixed::pipeline
