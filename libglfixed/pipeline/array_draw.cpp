#include "pipeline/array_draw.h"

#include <algorithm>

#include "pipeline/draw.h"
#include "primitive/assemble.h"
#include "state/context.h"

namespace glfixed::pipeline {

namespace {

using Submission = primitive::PrimitiveState::Submission;

// How many of Mesa's draw segments (primitive/assemble.h) one chunk holds: a
// chunk is fetched, shaded and drawn before the next is read, so a draw of
// millions of vertices never holds more than this many at once.
constexpr size_t kSegmentsPerChunk = 4;

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

}  // namespace

void drawArrays(Context& ctx, const ArraySources& src, GLenum mode, uint32_t first, uint32_t count) {
  if (!src.vertex) return;  // no vertex array: nothing is drawn (GL 2.1 §2.8)
  count = countWithinBuffer(src.vertexView, first, count);
  if (count == 0) return;
  static thread_local VertexBatch batch;
  // Mesa's draw module splits a long draw into segments and decides for each
  // alone whether it needs clipping (assemble.h). A chunk of whole segments,
  // drawn as a batch of its own, splits into the same segments again: every
  // segment of a non-fan mode starts at a multiple of its step (strips keep
  // their parity) and the chunk's own split reproduces them. Fans and
  // polygons share vertex 0 across segments: they are drawn whole.
  static thread_local std::vector<primitive::Segment> segments;
  const bool fan = mode == GL_TRIANGLE_FAN || mode == GL_POLYGON;
  primitive::splitIntoSegments(mode, count, segments);
  if (fan || segments.size() <= kSegmentsPerChunk) {
    batch.reset(mode, ctx.lighting.material);
    appendRange(src, ctx, first, count, batch);
    drawBatch(ctx, batch, Submission::kDrawArrays, src.color);
    return;
  }
  for (size_t s = 0; s < segments.size(); s += kSegmentsPerChunk) {
    const size_t last = std::min(segments.size(), s + kSegmentsPerChunk) - 1;
    const uint32_t start = segments[s].start;
    const uint32_t end = segments[last].start + segments[last].count;
    batch.reset(mode, ctx.lighting.material);
    appendRange(src, ctx, first + start, end - start, batch);
    drawBatch(ctx, batch, Submission::kDrawArrays, src.color);
  }
}

void drawElements(Context& ctx, const ArraySources& src, GLenum mode, const std::vector<uint32_t>& indices) {
  if (!src.vertex || indices.empty()) return;
  static thread_local VertexBatch batch;
  batch.reset(mode, ctx.lighting.material);
  appendIndexed(src, ctx, indices.data(), indices.size(), batch);
  drawBatch(ctx, batch, Submission::kDrawElements, src.color);
}

}  // namespace glfixed::pipeline
