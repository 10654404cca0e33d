// Every float operation here must round exactly as Mesa's draw module does:
// forbid contracting a * b + c into a fused multiply-add.
#pragma GCC optimize("fp-contract=off")

#include "primitive/unrasterized.h"

#include <cmath>
#include <vector>

#include "primitive/assemble.h"
#include "primitive/clip_line.h"
#include "primitive/cull.h"
#include "primitive/viewport.h"
#include "state/lighting_attrib.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::primitive {

namespace {

constexpr int kColorAttribCount = 8;  // front and back primary colours
constexpr int kAttribCount = kSinkTexCoord + 4;  // and unit 0's texture coordinates

struct Batch {
  const PrimitiveState& state;
  PrimitiveSink& sink;
  ViewportTransform viewport;
  FaceRule face;
  bool twoSided;
};

void loadVertices(const ShadedVertices& in, uint32_t n, const ViewportTransform& viewport,
                  const UserClipPlanes& user, std::vector<ClipVertex>& out, std::vector<uint32_t>& masks) {
  out.resize(n);
  masks.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    ClipVertex& v = out[i];
    v.clip = in.clip[i];
    masks[i] = clipMask(v.clip, user);  // user clip planes: bits 6..13
    viewport.windowFromClip(v.clip, v.window);
    const glm::vec4& front = in.primary[kFront][i];
    const glm::vec4& back = in.hasBack ? in.primary[kBack][i] : front;
    for (int k = 0; k < 4; ++k) {
      v.attr[kSinkFrontColor + k] = front[k];
      v.attr[kSinkBackColor + k] = back[k];
    }
    // Texture coordinates (issue 14): unit 0's, when the vertex stage made them.
    const glm::vec4 t = (in.texCoordUnits & 1u) ? in.texCoord[0][i] : glm::vec4(0, 0, 0, 1);
    for (int k = 0; k < 4; ++k) v.attr[kSinkTexCoord + k] = t[k];
  }
}

// After the clipper: the draw module's cull stage, then its two-sided colour
// choice, by the sign of the same float determinant (llvmpipe's rows, cull.h).
void emitTriangle(const Batch& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2) {
  if (drawModuleCulls(b.face, v0.window, v1.window, v2.window)) return;
  int color = kSinkFrontColor;
  if (b.twoSided) {
    const float det = (v0.window[0] - v2.window[0]) * (v1.window[1] - v2.window[1]) -
                      (v0.window[1] - v2.window[1]) * (v1.window[0] - v2.window[0]);
    if (det != 0.0f && !b.face.isFront(det < 0.0f ? 1 : -1)) color = kSinkBackColor;
  }
  b.sink.triangle(v0, v1, v2, color);
}

// The clipped polygon as the clipper emits it (draw_pipe_clip.c, emit_poly):
// a fan around its first vertex; under GL_FLAT the first vertex is first
// given the provoking vertex's colours.
void emitClippedPolygon(const Batch& b, const ClippedPolygon& poly, const ClipVertex& provoking) {
  ClipVertex firstCopy;
  const ClipVertex* first = poly.vertex[0];
  if (b.state.flat && first != &provoking) {
    firstCopy = *first;
    for (int k = 0; k < kColorAttribCount; ++k) firstCopy.attr[k] = provoking.attr[k];
    first = &firstCopy;
  }
  for (int i = 2; i < poly.count; ++i) {
    if (b.state.firstVertexConvention)
      emitTriangle(b, *first, *poly.vertex[i - 1], *poly.vertex[i]);
    else
      emitTriangle(b, *poly.vertex[i - 1], *poly.vertex[i], *first);
  }
}

void drawTriangles(const Batch& b, GLenum mode, uint32_t n, const std::vector<ClipVertex>& v,
                   const std::vector<uint32_t>& masks) {
  struct SiteTriangles {};
  std::vector<Triangle>& triangles = pipeline::threadScratch<std::vector<Triangle>, SiteTriangles>();
  struct SitePolygon {};
  ClippedPolygon& polygon = pipeline::threadScratch<ClippedPolygon, SitePolygon>();
  assembleTriangles(mode, n, b.state.firstVertexConvention, b.state.flat, DecomposePath::kPipeline,
                    triangles);
  const int provokingSlot = primitive::provokingSlot(b.state.firstVertexConvention);
  for (const Triangle& t : triangles) {
    const uint32_t m0 = masks[t[0]], m1 = masks[t[1]], m2 = masks[t[2]];
    if ((m0 | m1 | m2) == 0) {
      emitTriangle(b, v[t[0]], v[t[1]], v[t[2]]);
    } else if ((m0 & m1 & m2) == 0) {
      if (clipTriangle(v[t[0]], v[t[1]], v[t[2]], m0 | m1 | m2, kAttribCount, b.viewport, polygon,
                       b.state.userClipPlanes))
        emitClippedPolygon(b, polygon, v[t[provokingSlot]]);
    }
  }
}

void emitLine(const Batch& b, const ClipVertex& v0, const ClipVertex& v1, uint32_t m0, uint32_t m1) {
  if ((m0 | m1) == 0) {
    b.sink.line(v0, v1);
    return;
  }
  if ((m0 & m1) != 0) return;
  ClipVertex made[2];
  const ClipVertex *e0, *e1;
  // GL_FLAT: a clipped end takes the provoking vertex's colours.
  const ClipVertex& provoking = b.state.firstVertexConvention ? v0 : v1;
  if (!clipLine(v0, v1, m0, m1, m0 | m1, kAttribCount, b.viewport, b.state.flat, provoking, made, &e0, &e1,
                b.state.userClipPlanes))
    return;
  b.sink.line(*e0, *e1);
}

void drawLines(const Batch& b, GLenum mode, uint32_t n, const std::vector<ClipVertex>& v,
               const std::vector<uint32_t>& masks) {
  auto line = [&](uint32_t i, uint32_t j) { emitLine(b, v[i], v[j], masks[i], masks[j]); };
  switch (mode) {
    case GL_LINES:
      for (uint32_t i = 1; i < n; i += 2) line(i - 1, i);
      break;
    case GL_LINE_STRIP:
      for (uint32_t i = 1; i < n; ++i) line(i - 1, i);
      break;
    default:  // GL_LINE_LOOP: the closing segment last
      for (uint32_t i = 1; i < n; ++i) line(i - 1, i);
      if (n >= 2) line(n - 1, 0);
      break;
  }
}

}  // namespace

void drawUnrasterized(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                      PrimitiveSink& sink) {
  const uint32_t n = trimVertexCount(state.mode, static_cast<uint32_t>(vertices.size()));
  if (n == 0) return;
  Batch b{state, sink,
          ViewportTransform::make(state.viewportX, state.viewportY, state.viewportWidth, state.viewportHeight,
                                  state.depthNear, state.depthFar, framebufferHeight, state.flipViewportY),
          FaceRule{state.cullFace, state.cullFaceMode, state.frontFace}, vertices.hasBack};

  struct SiteClipVertices {};
  std::vector<ClipVertex>& clipVertices = pipeline::threadScratch<std::vector<ClipVertex>, SiteClipVertices>();
  struct SiteMasks {};
  std::vector<uint32_t>& masks = pipeline::threadScratch<std::vector<uint32_t>, SiteMasks>();
  loadVertices(vertices, n, b.viewport, state.userClipPlanes, clipVertices, masks);

  GLenum mode = state.mode;
  using Submission = PrimitiveState::Submission;
  if ((state.submission == Submission::kBeginEnd || state.submission == Submission::kDisplayList) && n == 3 &&
      (mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN))
    mode = GL_TRIANGLES;
  switch (mode) {
    case GL_POINTS:
      for (uint32_t i = 0; i < n; ++i)
        if (masks[i] == 0) sink.point(clipVertices[i]);
      break;
    case GL_LINES:
    case GL_LINE_STRIP:
    case GL_LINE_LOOP: drawLines(b, mode, n, clipVertices, masks); break;
    default: drawTriangles(b, mode, n, clipVertices, masks); break;
  }
}

}  // namespace glfixed::primitive
