// TEMPORARY scaffolding while the lighting and raster stages are written in
// parallel: weak definitions that their real (strong) ones replace at link time.
// This file is deleted before the core issue is closed.
#include "primitive/primitive.h"
#include "raster/raster.h"
#include "state/context.h"
#include "vertex/color_material.h"
#include "vertex/lighting_queries.h"
#include "vertex/vertex_stage.h"

namespace glfixed {
__attribute__((weak)) void trackColorMaterial(Context&) {}
__attribute__((weak)) bool getLightingState(Context&, GLenum, GLdouble*, int*) { return false; }
__attribute__((weak)) bool setLightingCapability(Context&, GLenum, bool) { return false; }
namespace vertex {
__attribute__((weak)) void buildLightingConstants(const LightingAttrib&, const TransformAttrib&, LightingConstants&) {}
__attribute__((weak)) void lightBatch(const VertexState&, const VertexBatch& b, ShadedVertices& out) {
  out.primary[kFront].assign(b.size(), glm::vec4(1));
}
}  // namespace vertex
namespace primitive {
__attribute__((weak)) void drawPrimitives(const PrimitiveState&, const ShadedVertices&, Framebuffer&) {}
}  // namespace primitive
}  // namespace glfixed
