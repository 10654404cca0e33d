#include "pipeline/immediate_mode.h"

#include <algorithm>

#include "pipeline/draw.h"
#include "primitive/merge.h"
#include "state/context.h"
#include "vertex/texcoord.h"

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

// After the first vertices of a batch are gone, the material snapshots no
// vertex uses any more are dropped too (a long glBegin/glEnd with glMaterial
// calls stays bounded); a batch that had several keeps at least two, so that
// it is still lit as one with per-vertex materials.
void dropUnusedMaterials(VertexBatch& b) {
  if (b.materials.size() <= 2 || b.size() == 0) return;
  const uint32_t first = std::min<uint32_t>(b.materialIndex.front(), static_cast<uint32_t>(b.materials.size() - 2));
  if (first == 0) return;
  b.materials.erase(b.materials.begin(), b.materials.begin() + first);
  for (uint32_t& i : b.materialIndex) i -= first;
}

// A primitive merged into the pending draw. With glMaterial inside either
// of them the material snapshots are concatenated, so that each vertex keeps
// its own (a batch with several snapshots is lit per vertex).
void appendMerged(VertexBatch& p, const VertexBatch& b) {
  const size_t first = p.size();
  if (p.materials.size() == 1 && b.materials.size() == 1) {
    p.appendVertices(b, 0, b.size());
    return;
  }
  const uint32_t offset = static_cast<uint32_t>(p.materials.size());
  p.materials.insert(p.materials.end(), b.materials.begin(), b.materials.end());
  p.appendVertices(b, 0, b.size());
  for (size_t i = first; i < p.size(); ++i) p.materialIndex[i] += offset;
}

// vbo_exec_wrap_buffers: Mesa draws everything buffered, the open
// primitive's first vertices as a draw of their own (not merged with the
// pending ones), and goes on with the vertices vbo_copy_vertices keeps
// (vbo_store.h). So the two pieces decide separately whether they need
// Mesa's draw pipeline (assemble.h).
void wrapBuffers(Context& ctx) {
  drawPending(ctx);
  VboStore& store = ctx.vboStore;
  VertexBatch& b = ctx.batch;
  if (ctx.insideBeginEnd && b.size() > 0) {
    const size_t count = b.size();
    const WrapSplit split = wrapSplit(b.mode, static_cast<uint32_t>(count));
    // The open primitive joins the last run when it has the same mode.
    const bool suppressed = store.primCount >= 2 && b.mode == store.runMode && store.runSuppressed();
    if (split.drawn > split.copied && !suppressed) {
      VertexBatch part;
      part.mode = b.mode;
      part.materials = b.materials;
      // A line loop's piece is a strip, without the first vertex's copy
      // once the loop has wrapped before.
      const size_t from = b.mode == GL_LINE_LOOP && store.openLoopWrapped ? 1 : 0;
      if (b.mode == GL_LINE_LOOP) part.mode = GL_LINE_STRIP;
      part.appendVertices(b, from, split.drawn);
      drawBatch(ctx, part);
    }
    if (b.mode == GL_LINE_LOOP && store.openLoopWrapped) {
      // vbo_copy_vertices on a later piece: it steps back to the first
      // vertex's copy but keeps the piece's shortened count, so the second
      // copy is the piece's second-to-last vertex, not its last (a Mesa
      // defect that decides which segment follows: kept, the pixels depend
      // on it).
      // With only the copy left, nothing is kept: the next vertex becomes
      // the one glEnd closes the loop with.
      if (count >= 3) {
        b.eraseVertices(count - 1, count);
        b.eraseVertices(1, count - 2);
      } else {
        b.eraseVertices(count == 2 ? 1 : 0, count);
      }
    } else if (split.keepFirst) {
      b.eraseVertices(1, count - 1);
    } else {
      b.eraseVertices(0, count - split.copied);
    }
    // The loop counts as wrapped (Mesa's begin marker 0) unless every vertex
    // was copied (vbo_exec_wrap_buffers keeps the marker then).
    if (b.mode == GL_LINE_LOOP && b.size() != count) store.openLoopWrapped = true;
    dropUnusedMaterials(b);
  }
  store.flushed(ctx.vbo.vertexFloats());
  if (ctx.insideBeginEnd) {
    store.vertexCount = static_cast<uint32_t>(b.size());
    store.primCount = 1;  // the open primitive goes on
  }
}

// An attribute becomes vertex data, or gets more components: the vertex
// format grows (vbo_exec_wrap_upgrade_vertex), which wraps the buffer first.
// Outside glBegin/glEnd, a new attribute after more than 8 vertices makes
// Mesa reset the whole format after the draw (its heuristic to keep
// attributes set between primitives out of the vertices), and the next
// glBegin drops the attribute left alone there: nothing is vertex data.
template <typename Grow>
void growVertexFormat(Context& ctx, bool newAttribute, Grow grow) {
  const bool reset = !ctx.insideBeginEnd && newAttribute && ctx.vboStore.vertexCount > 8;
  wrapBuffers(ctx);
  if (reset) {
    ctx.vbo = Context::VboFormat();
    return;
  }
  grow(ctx.vbo);
}

}  // namespace

void drawPending(Context& ctx) {
  if (ctx.pending.size() == 0) return;
  drawBatch(ctx, ctx.pending);
  ctx.pending.clearVertices();
}

void beginPrimitive(Context& ctx, GLenum mode) {
  ctx.batch.reset(mode, ctx.lighting.material);
  ctx.batch.setTexCoordUnits(vertex::texCoordInputUnits(ctx));  // texture coordinates (issue 14)
  ctx.batch.setHasFogCoord(vertex::fogCoordInput(ctx));         // fog
  ctx.batch.setHasSecondaryColor(!ctx.lighting.lighting && ctx.fog.colorSum);  // the colour sum
  ++ctx.vboStore.primCount;
  ctx.vboStore.openLoopWrapped = false;
}

void endPrimitive(Context& ctx) {
  VertexBatch& b = ctx.batch;
  VboStore& store = ctx.vboStore;
  if (b.mode == GL_LINE_LOOP && store.openLoopWrapped) {
    // _mesa_End: the rest of a wrapped loop is a strip from the vertex after
    // the first one's copy, closed by that copy appended at the end (one
    // more vertex in the buffer).
    store.openLoopWrapped = false;
    VertexBatch strip;
    strip.mode = GL_LINE_STRIP;
    strip.materials = b.materials;
    if (b.size() > 0) {
      strip.appendVertices(b, 1, b.size());
      strip.appendVertices(b, 0, 1);
      ++store.vertexCount;
    }
    std::swap(b, strip);
  }
  const uint32_t count = static_cast<uint32_t>(b.size());
  const GLenum mode = primitive::mesaConvertedMode(b.mode, count);
  // vbo_merge_draws looks at the previous primitive's whole vertex count,
  // an incomplete last primitive included.
  const bool merged = store.primCount >= 2 && primitive::mesaMergesPrimitives(store.lastMode, store.lastCount, mode);
  if (merged) {
    --store.primCount;
    store.lastCount += count;
    if (store.runDraws == 1) store.runFirstCount += count;  // merged into the run's first primitive
  } else {
    store.lastMode = mode;
    store.lastCount = count;
    if (store.primCount >= 2 && mode == store.runMode) {
      ++store.runDraws;
    } else {  // a new run
      store.runIndex = store.primCount >= 2 ? store.runIndex + 1 : 0;
      store.runMode = mode;
      store.runFirstCount = count;
      store.runDraws = 1;
    }
  }
  if (count > 0) ctx.vbo.verticesBuffered = true;
  if (count > 0 && store.runSuppressed()) {
    b.clearVertices();  // Mesa draws nothing of it (VboStore::runSuppressed)
  } else if (count > 0) {
    b.mode = mode;
    b.resizeVertices(wholePrimitives(mode, count));
    VertexBatch& p = ctx.pending;
    if (merged && p.size() > 0 && p.mode == mode) {
      appendMerged(p, b);
    } else {
      drawPending(ctx);
      std::swap(p, b);  // b's vectors are reset at the next glBegin
    }
  }
  if (store.primCount >= VboStore::kMaxPrimitives) {  // vbo_exec_vtx_flush, the format kept
    drawPending(ctx);
    store.flushed(ctx.vbo.vertexFloats());
  }
}

void vertexAdded(Context& ctx) {
  VboStore& store = ctx.vboStore;
  if (++store.vertexCount >= store.maxVertices(ctx.vbo.vertexFloats())) wrapBuffers(ctx);
}

void flushVertices(Context& ctx) {
  drawPending(ctx);
  ctx.vboStore.flushed(ctx.vbo.vertexFloats());
  ctx.vbo = Context::VboFormat();
}

void colorBecomesVertexData(Context& ctx, int size) {
  if (ctx.vbo.colorSize >= size) return;
  growVertexFormat(ctx, ctx.vbo.colorSize == 0, [size](Context::VboFormat& f) { f.colorSize = size; });
}
void normalBecomesVertexData(Context& ctx) {
  if (ctx.vbo.normalIsVertexData) return;
  growVertexFormat(ctx, true, [](Context::VboFormat& f) { f.normalIsVertexData = true; });
}
// glEdgeFlag is a vertex attribute of Mesa's vbo like glNormal
// (VBO_ATTRIB_EDGEFLAG): its first call inside glBegin/glEnd wraps the open
// primitive (scene lines_edge_flag_wraps).
void edgeFlagBecomesVertexData(Context& ctx) {
  if (ctx.vbo.edgeFlagIsVertexData) return;
  growVertexFormat(ctx, true, [](Context::VboFormat& f) { f.edgeFlagIsVertexData = true; });
}
void fogCoordBecomesVertexData(Context& ctx) {
  if (ctx.vbo.fogCoordIsVertexData) return;
  growVertexFormat(ctx, true, [](Context::VboFormat& f) { f.fogCoordIsVertexData = true; });
}
void secondaryColorBecomesVertexData(Context& ctx) {
  if (ctx.vbo.secondaryColorIsVertexData) return;
  growVertexFormat(ctx, true, [](Context::VboFormat& f) { f.secondaryColorIsVertexData = true; });
}
void positionGrows(Context& ctx, int size) {
  if (ctx.vbo.positionSize >= size) return;
  growVertexFormat(ctx, ctx.vbo.positionSize == 0, [size](Context::VboFormat& f) { f.positionSize = size; });
}

void materialBecomesVertexData(Context& ctx, uint32_t attributes) {
  const uint32_t added = attributes & ~ctx.vbo.materialAttributes;
  if (added == 0) return;
  // Colours 4 floats, shininess 1 (bits 4 and 9), colour indexes 3 (bits 10, 11).
  int floats = 0;
  for (uint32_t bit = 0; bit < 12; ++bit) {
    if (!(added & (1u << bit))) continue;
    floats += (bit == 4 || bit == 9) ? 1 : (bit >= 10 ? 3 : 4);
  }
  growVertexFormat(ctx, true, [added, floats](Context::VboFormat& f) {
    f.materialAttributes |= added;
    f.materialFloats += floats;
  });
}

}  // namespace glfixed::pipeline
