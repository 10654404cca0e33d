#include "pipeline/draw.h"

#include <algorithm>

#include "primitive/primitive.h"
#include "state/context.h"
#include "vertex/vertex_stage.h"

namespace glfixed::pipeline {

namespace {

primitive::PrimitiveState primitiveState(const Context& ctx, GLenum mode, bool separateSpecular) {
  primitive::PrimitiveState s;
  s.mode = mode;
  s.flat = ctx.lighting.shadeModel == GL_FLAT;
  s.firstVertexConvention = ctx.lighting.provokingVertex == GL_FIRST_VERTEX_CONVENTION;
  s.cullFace = ctx.polygon.cullFace;
  s.cullFaceMode = ctx.polygon.cullFaceMode;
  s.frontFace = ctx.polygon.frontFace;
  s.viewportX = ctx.viewport.x;
  s.viewportY = ctx.viewport.y;
  s.viewportWidth = ctx.viewport.width;
  s.viewportHeight = ctx.viewport.height;
  s.depthNear = ctx.viewport.depthNear;
  s.depthFar = ctx.viewport.depthFar;

  raster::RasterState& r = s.raster;
  // Without a depth buffer the depth test always passes (GL 2.1 §4.1.6).
  r.depthTest = ctx.depth.test && ctx.framebuffer.depth.bits() > 0;
  r.depthFunc = ctx.depth.func;
  r.depthWrite = ctx.depth.writeMask;
  for (int i = 0; i < 4; ++i) r.colorWrite[i] = ctx.colorBuffer.writeMask[i];
  r.varyingCount = separateSpecular ? 8 : 4;
  r.scissorX0 = std::max(0, ctx.viewport.x);
  r.scissorY0 = std::max(0, ctx.viewport.y);
  r.scissorX1 = std::min(ctx.framebuffer.width(), ctx.viewport.x + ctx.viewport.width);
  r.scissorY1 = std::min(ctx.framebuffer.height(), ctx.viewport.y + ctx.viewport.height);
  return s;
}

}  // namespace

void drawBatch(Context& ctx, const VertexBatch& batch, primitive::PrimitiveState::Submission submission) {
  if (!ctx.framebuffer.bound() || batch.size() == 0) return;
  const vertex::VertexState& vs = ctx.validate();
  static thread_local ShadedVertices shaded;  // reused: no allocation per batch
  vertex::shadeBatch(vs, batch, shaded);
  primitive::PrimitiveState ps = primitiveState(ctx, batch.mode, shaded.hasSecondary);
  ps.constantPrimary = !vs.lighting && !ctx.vbo.colorIsVertexData;
  ps.submission = submission;
  primitive::drawPrimitives(ps, shaded, ctx.framebuffer);
}

}  // namespace glfixed::pipeline
