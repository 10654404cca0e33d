#include "pipeline/immediate_mode.h"

#include "pipeline/draw.h"
#include "primitive/merge.h"
#include "state/context.h"

namespace glfixed::pipeline {

namespace {

// Mesa drops the vertices of an incomplete last primitive before it merges.
size_t wholePrimitives(GLenum mode, size_t n) {
  switch (mode) {
    case GL_LINES: return n - n % 2;
    case GL_TRIANGLES: return n - n % 3;
    case GL_QUADS: return n - n % 4;
    default: return n;
  }
}

}  // namespace

void drawPending(Context& ctx) {
  if (ctx.pending.size() == 0) return;
  drawBatch(ctx, ctx.pending);
  ctx.pending.clearVertices();
}

void endPrimitive(Context& ctx) {
  VertexBatch& b = ctx.batch;
  if (b.size() == 0) return;
  ctx.vbo.verticesBuffered = true;
  b.mode = primitive::mesaConvertedMode(b.mode, static_cast<uint32_t>(b.size()));
  b.resizeVertices(wholePrimitives(b.mode, b.size()));
  // A batch with glMaterial inside is drawn at once: its per-vertex material
  // state (LightingAttrib::beginEndMaterialMask) belongs to it alone.
  const bool perVertexMaterial = b.materials.size() > 1;
  VertexBatch& p = ctx.pending;
  if (!perVertexMaterial && p.size() > 0 && p.materials.size() == 1 &&
      primitive::mesaMergesPrimitives(p.mode, static_cast<uint32_t>(p.size()), b.mode)) {
    p.appendVertices(b, 0, b.size());
    return;
  }
  drawPending(ctx);
  if (perVertexMaterial) {
    drawBatch(ctx, b);
    return;
  }
  std::swap(p, b);  // b's vectors are reset at the next glBegin
}

void flushVertices(Context& ctx) {
  drawPending(ctx);
  ctx.vbo = Context::VboFormat();
}

// Mesa's vbo grows its vertex format when an attribute first becomes vertex
// data between glBegin and glEnd (vbo_exec_wrap_upgrade_vertex): it draws the
// buffered vertices at once, the open primitive's whole primitives as a draw
// of their own (not merged with the pending ones), and keeps only the
// vertices of its incomplete last primitive. So the primitives before the
// glColor and those after it decide separately whether they need Mesa's draw
// pipeline (assemble.h). Modelled for GL_TRIANGLES and GL_QUADS, whose kept
// vertices are simply the incomplete last primitive.
void drawOpenPrimitivesSoFar(Context& ctx) {
  VertexBatch& b = ctx.batch;
  if (b.mode != GL_TRIANGLES && b.mode != GL_QUADS) return;
  if (b.materials.size() > 1) return;  // per-vertex material: drawn at glEnd
  const size_t whole = wholePrimitives(b.mode, b.size());
  if (whole == 0) return;
  VertexBatch part;
  part.mode = b.mode;
  part.materials = b.materials;
  part.appendVertices(b, 0, whole);
  drawBatch(ctx, part);
  b.eraseFirstVertices(whole);
}

namespace {
// An attribute becomes vertex data: the vertex format grows (see above).
void growVertexFormat(Context& ctx, bool& isVertexData) {
  if (isVertexData) return;
  drawPending(ctx);
  if (ctx.insideBeginEnd) drawOpenPrimitivesSoFar(ctx);
  isVertexData = true;
}
}  // namespace

void colorBecomesVertexData(Context& ctx) { growVertexFormat(ctx, ctx.vbo.colorIsVertexData); }
void normalBecomesVertexData(Context& ctx) { growVertexFormat(ctx, ctx.vbo.normalIsVertexData); }

}  // namespace glfixed::pipeline
