// The two sinks of primitive/unrasterized.h: GL_SELECT updates the hit
// (GL 2.1 §5.2), GL_FEEDBACK writes tokens and vertices (§5.3).
#pragma once

#include <glm/glm.hpp>

#include "pipeline/vertex_batch.h"
#include "primitive/primitive.h"
#include "state/render_mode.h"

namespace glfixed::primitive {

// Every primitive that survives clipping and culling widens the hit's z range
// by each of its vertices' window z.
void selectPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                      SelectState& select);

// Writes each primitive as Mesa's feedback stage does: GL_POLYGON_TOKEN 3 per
// triangle, GL_LINE_TOKEN per line (Mesa never writes GL_LINE_RESET_TOKEN),
// GL_POINT_TOKEN per point; each vertex as x, y (GL window y, up), z, w, the
// colour and `texCoord` as the type asks (table 5.1).
void feedbackPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                        const glm::vec4& texCoord, FeedbackState& feedback);

}  // namespace glfixed::primitive
