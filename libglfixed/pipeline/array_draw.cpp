#include "pipeline/array_draw.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "pipeline/draw.h"
#include "primitive/assemble.h"
#include "state/context.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::pipeline {

namespace {

using Submission = primitive::PrimitiveState::Submission;

// How many of Mesa's draw segments (primitive/assemble.h) one chunk of a
// glDrawArrays holds: a chunk is fetched, shaded and drawn before the next is
// read, so a draw of millions of vertices never holds more than this many at
// once.
constexpr size_t kSegmentsPerChunk = 4;

// Mesa's vsplit (draw_pt_vsplit_tmp.h, vsplit_primitive) draws an indexed
// draw whole, fetching every vertex of its index range, when the range is
// known, no wider than the draw, and the draw is at most the llvm middle
// end's 4096 vertices (16-bit indices from 0, used as they are) or the
// 1024-index segment (any other).
constexpr uint32_t kMaxWholeShortDraw = 4096;
constexpr uint32_t kMaxWholeDraw = primitive::kMaxIndexedSegment;

// Points and lines are chunked by this many vertices (see drawLines).
constexpr uint32_t kLineChunk = 4096;

// Elements past the end of a vertex array in a buffer object all read as the
// same point, so every primitive made only of them is degenerate and draws
// nothing. A draw far past the end is cut a little after it: the first
// past-end elements are kept (with the last real ones they make real
// primitives, and they take part in their segment's clipping decision), a
// multiple of 12 from `first` keeps every mode's primitives whole, and the
// segments dropped would have drawn nothing.
uint32_t countWithinBuffer(const ArrayView& v, uint32_t first, uint32_t count) {
  if (v.limit == SIZE_MAX) return count;
  const size_t need = static_cast<size_t>(v.size) * componentBytes(v.type);
  const size_t available = v.limit >= need ? (v.limit - need) / v.stride + 1 : 0;
  const size_t fromFirst = available > first ? available - first : 0;
  const size_t kept = (fromFirst + 4 + 11) / 12 * 12;
  return static_cast<uint32_t>(std::min<size_t>(count, kept));
}

bool isPointsOrLines(GLenum mode) {
  return mode == GL_POINTS || mode == GL_LINES || mode == GL_LINE_LOOP || mode == GL_LINE_STRIP;
}

// Appends the elements at draw positions [from, to) to `batch`; `elementAt`
// maps a position of the draw to its array element.
template <typename ElementAt>
void appendPositions(const ArraySources& src, const Context& ctx, const ElementAt& elementAt, size_t from,
                     size_t to, VertexBatch& batch) {
  struct SiteElements {};
  std::vector<uint32_t>& elements = threadScratch<std::vector<uint32_t>, SiteElements>();
  elements.clear();
  for (size_t k = from; k < to; ++k) elements.push_back(elementAt(k));
  appendIndexed(src, ctx, elements.data(), elements.size(), batch);
}

// Mesa's segments of a draw of `count` vertices, each drawn as a batch of its
// own: a batch of one segment is drawn as that segment again (primitive/
// draw_primitives.cpp). A segment whose first vertex is replaced by the
// draw's first (fans and polygons after their first segment) is drawn
// indexed, as Mesa draws it.
template <typename ElementAt>
void drawSegments(Context& ctx, const ArraySources& src, GLenum mode,
                  const std::vector<primitive::Segment>& segments, const ElementAt& elementAt,
                  Submission submission) {
  struct SiteBatch {};
  VertexBatch& batch = threadScratch<VertexBatch, SiteBatch>();
  for (const primitive::Segment& seg : segments) {
    batch.reset(mode, ctx.lighting.material);
    if (seg.hubReplaced) {
      appendPositions(src, ctx, elementAt, 0, 1, batch);
      appendPositions(src, ctx, elementAt, seg.start + 1, seg.start + seg.count, batch);
    } else {
      appendPositions(src, ctx, elementAt, seg.start, seg.start + seg.count, batch);
    }
    drawBatch(ctx, batch, seg.hubReplaced ? Submission::kDrawElements : submission, src.color, false,
              src.secondaryColor);
  }
}

// Points and lines are drawn in chunks that keep the same primitives in the
// same order (in GL_SELECT and GL_FEEDBACK each point and line is reported
// alone: Mesa never writes a line reset token): strips overlap by one vertex,
// a loop becomes strips and its closing line, and the line stipple pattern
// carries on from chunk to chunk.
template <typename ElementAt>
void drawPointsOrLines(Context& ctx, const ArraySources& src, GLenum mode, uint32_t count,
                       const ElementAt& elementAt, Submission submission) {
  count = primitive::trimVertexCount(mode, count);
  if (count == 0) return;
  struct SiteBatch {};
  VertexBatch& batch = threadScratch<VertexBatch, SiteBatch>();
  const bool strip = mode == GL_LINE_STRIP || mode == GL_LINE_LOOP;
  const GLenum chunkMode = count <= kLineChunk ? mode : (mode == GL_LINE_LOOP ? GL_LINE_STRIP : mode);
  for (uint32_t start = 0;;) {
    const uint32_t end = std::min(count, start + kLineChunk);
    batch.reset(chunkMode, ctx.lighting.material);
    appendPositions(src, ctx, elementAt, start, end, batch);
    const bool last = end == count;
    if (last && chunkMode != mode) appendPositions(src, ctx, elementAt, 0, 1, batch);  // the closing line
    // Lines: a strip's later chunks carry on its stipple pattern (Mesa's
    // vsplit flags them DRAW_SPLIT_BEFORE).
    ctx.lineStipple.continues = strip && start != 0;
    drawBatch(ctx, batch, submission, src.color, false, src.secondaryColor);
    ctx.lineStipple.continues = false;
    if (last) return;
    start = strip ? end - 1 : end;
  }
}

bool isClientMemory(const ArrayView& v) { return v.limit == SIZE_MAX; }

// vsplit_primitive's conditions (see kMaxWholeDraw).
bool drawnWhole(const IndexList& list, uint32_t count, const IndexBounds& b) {
  if (!b.valid || b.max < b.min) return false;
  // The list must end before the last index of its buffer.
  if (list.bufferIndices != SIZE_MAX && list.firstInBuffer + count >= list.bufferIndices) return false;
  const bool asTheyAre = b.min == 0 && list.type == GL_UNSIGNED_SHORT;
  if (count > (asTheyAre ? kMaxWholeShortDraw : kMaxWholeDraw)) return false;
  return b.max - b.min <= count - 1;
}

}  // namespace

uint32_t IndexList::at(size_t i) const {
  switch (type) {
    case GL_UNSIGNED_BYTE: return data[i];
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, data + 2 * i, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, data + 4 * i, 4);
      return v;
    }
  }
}

IndexBounds elementBounds(const Context& ctx, const ArraySources& src, const IndexList* lists, size_t count) {
  // The fixed-function vertex shader reads the position, the colour unless
  // lighting without colour material, and the normal when lighting.
  const bool lit = ctx.lighting.lighting;
  const bool readsClientArray =
      (src.vertex && isClientMemory(src.vertexView)) ||
      (src.color && (!lit || ctx.lighting.colorMaterial) && isClientMemory(src.colorView)) ||
      (src.normal && lit && isClientMemory(src.normalView));
  IndexBounds b;
  if (!readsClientArray) return b;
  b.min = UINT32_MAX;
  for (size_t d = 0; d < count; ++d)
    for (uint32_t i = 0; i < lists[d].count; ++i) {
      const uint32_t e = lists[d].element(i);
      b.min = std::min(b.min, e);
      b.max = std::max(b.max, e);
      b.valid = true;
    }
  return b;
}

void drawArrays(Context& ctx, const ArraySources& src, GLenum mode, uint32_t first, uint32_t count) {
  if (!src.vertex) return;  // no vertex array: nothing is drawn (GL 2.1 §2.8)
  count = countWithinBuffer(src.vertexView, first, count);
  if (count == 0) return;
  auto elementAt = [first](size_t k) { return first + static_cast<uint32_t>(k); };
  if (isPointsOrLines(mode))
    return drawPointsOrLines(ctx, src, mode, count, elementAt, Submission::kDrawArrays);
  struct SiteSegments {};
  std::vector<primitive::Segment>& segments = threadScratch<std::vector<primitive::Segment>, SiteSegments>();
  primitive::splitIntoSegments(mode, count, segments);
  if (mode == GL_TRIANGLE_FAN || mode == GL_POLYGON)
    return drawSegments(ctx, src, mode, segments, elementAt, Submission::kDrawArrays);
  // Every segment of the other modes starts at a multiple of its step (strips
  // keep their parity), so a chunk of whole segments drawn as a batch of its
  // own splits into the same segments again.
  struct SiteBatch {};
  VertexBatch& batch = threadScratch<VertexBatch, SiteBatch>();
  for (size_t s = 0; s < segments.size(); s += kSegmentsPerChunk) {
    const size_t last = std::min(segments.size(), s + kSegmentsPerChunk) - 1;
    const uint32_t start = segments[s].start;
    const uint32_t end = segments[last].start + segments[last].count;
    batch.reset(mode, ctx.lighting.material);
    appendRange(src, ctx, first + start, end - start, batch);
    drawBatch(ctx, batch, Submission::kDrawArrays, src.color, false, src.secondaryColor);
  }
}

void drawElements(Context& ctx, const ArraySources& src, GLenum mode, const IndexList& indices,
                  const IndexBounds& bounds) {
  if (!src.vertex || indices.count == 0) return;
  auto elementAt = [&indices](size_t k) { return indices.element(k); };
  if (isPointsOrLines(mode))
    return drawPointsOrLines(ctx, src, mode, indices.count, elementAt, Submission::kDrawElements);
  const uint32_t count = primitive::trimVertexCount(mode, indices.count);
  if (count == 0) return;
  if (drawnWhole(indices, count, bounds)) {
    // Mesa fetches and clip-tests every vertex of the range, used or not: one
    // outside sends the whole draw through its pipeline.
    struct SiteBatch {};
    struct SiteRange {};
    VertexBatch& batch = threadScratch<VertexBatch, SiteBatch>();
    VertexBatch& range = threadScratch<VertexBatch, SiteRange>();
    batch.reset(mode, ctx.lighting.material);
    appendPositions(src, ctx, elementAt, 0, count, batch);
    range.reset(mode, ctx.lighting.material);
    appendRange(src, ctx, bounds.min, bounds.max - bounds.min + 1, range);
    drawBatch(ctx, batch, Submission::kDrawElements, src.color, anyVertexOutside(ctx, range), src.secondaryColor);
    return;
  }
  // Otherwise segments of at most 1024 indices, each fetching only the
  // vertices it uses (vsplit's vertex cache) and clip-tested alone.
  struct SiteSegments {};
  std::vector<primitive::Segment>& segments = threadScratch<std::vector<primitive::Segment>, SiteSegments>();
  primitive::splitIntoSegments(mode, count, segments, primitive::kMaxIndexedSegment);
  drawSegments(ctx, src, mode, segments, elementAt, Submission::kDrawElements);
}

}  // namespace glfixed::pipeline
