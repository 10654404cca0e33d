// drawPrimitives: assembly, clipping, culling, two-sided colour selection and
// the hand-over to the rasterizer, in the order Mesa's draw module and
// llvmpipe's setup do them.
// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cstring>
#include <vector>

#include "primitive/assemble.h"
#include "primitive/batch_context.h"
#include "primitive/clip.h"
#include "primitive/cull.h"
#include "primitive/primitive.h"
#include "primitive/viewport.h"
#include "raster/raster.h"
#include "state/lighting_attrib.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::primitive {

namespace {

// llvmpipe's triangle setup: snap, cull and face by the fixed-point area,
// pick front or back colours, put a clockwise triangle in counter-clockwise
// order keeping the provoking vertex in its slot, rasterize.
// `forcedFace` (polygon area): +1/-1 when the draw module's two-sided stage
// already chose the colours (they are then in the front slots), 0 otherwise.
void setupTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                   const ClipVertex& provoking, int forcedFace = 0) {
  const ClipVertex* v[3] = {&v0, &v1, &v2};
  raster::WindowVertex w[3];
  for (int i = 0; i < 3; ++i) {
    w[i].x = v[i]->window[0];
    w[i].y = v[i]->window[1];
    w[i].z = v[i]->window[2];
    w[i].oneOverW = v[i]->window[3];
  }
  raster::FixedTriangle fixed;
  const int sign = raster::snapTriangle(w[0], w[1], w[2], fixed);
  if (sign == 0) return;
  const bool front = b.face.isFront(sign);
  if (b.face.culls(front)) return;

  const int base = (b.twoSided && !front && forcedFace == 0) ? kBackAttribs : kFrontAttribs;
  for (int i = 0; i < 3; ++i) std::memcpy(w[i].varying, v[i]->attr + base, sizeof(float) * b.varyingCount);
  if (carriesMoreThanColours(b))  // texture coordinates (issue 14), fog
    for (int i = 0; i < 3; ++i) copyTexCoords(b, *v[i], w[i]);
  // Flat colours: the provoking vertex's (GL_FLAT), or Mesa's constant.
  const float* flat = nullptr;
  float flatValues[raster::kMaxVaryings];
  if (b.raster.flatGroups != 0) {
    const bool constantP = b.state.constantPrimary, constantS = b.state.constantSecondary;
    const float* provoked = provoking.attr + base;
    for (int k = 0; k < 4; ++k) flatValues[k] = constantP ? b.constantColours[k] : provoked[k];
    for (int k = 4; k < 8; ++k) flatValues[k] = constantS ? b.constantColours[k] : provoked[k];
    flat = flatValues;
  }

  // The stencil test's face (GL 2.0 §4.1.5) is the triangle's own.
  if (sign > 0) {
    raster::rasterCcwTriangle(b.raster, b.fb, fixed, w[0], w[1], w[2], flat, !front);
  } else if (b.state.firstVertexConvention) {
    raster::FixedTriangle r = {{fixed.x[0], fixed.x[2], fixed.x[1]}, {fixed.y[0], fixed.y[2], fixed.y[1]}};
    raster::rasterCcwTriangle(b.raster, b.fb, r, w[0], w[2], w[1], flat, !front);
  } else {
    raster::FixedTriangle r = {{fixed.x[1], fixed.x[0], fixed.x[2]}, {fixed.y[1], fixed.y[0], fixed.y[2]}};
    raster::rasterCcwTriangle(b.raster, b.fb, r, w[1], w[0], w[2], flat, !front);
  }
}

}  // namespace

void setupPipelineTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1,
                           const ClipVertex& v2, const ClipVertex& provoking, int face) {
  setupTriangle(b, v0, v1, v2, provoking, face);
}

// A triangle leaving the clipper: the draw module's cull stage (pipeline
// only), then llvmpipe's setup.
void emitTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                  const ClipVertex& provoking) {
  if (b.pipeline && drawModuleCulls(b.face, v0.window, v1.window, v2.window)) return;
  setupTriangle(b, v0, v1, v2, provoking);
}

namespace {

// The clipped polygon as a fan around its first vertex, which takes the
// provoking slot (draw_pipe_clip.c, emit_poly).
void emitClippedPolygon(const BatchContext& b, const ClippedPolygon& poly, const ClipVertex& provoking) {
  const ClipVertex& first = *poly.vertex[0];
  for (int i = 2; i < poly.count; ++i) {
    if (b.state.firstVertexConvention)
      emitTriangle(b, first, *poly.vertex[i - 1], *poly.vertex[i], provoking);
    else
      emitTriangle(b, *poly.vertex[i - 1], *poly.vertex[i], first, provoking);
  }
}

void loadVertices(const ShadedVertices& in, uint32_t n, const ViewportTransform& viewport,
                  const UserClipPlanes& user, std::vector<ClipVertex>& out, std::vector<uint32_t>& masks) {
  out.resize(n);
  masks.resize(n);
  const bool back = in.hasBack, secondary = in.hasSecondary;
  for (uint32_t i = 0; i < n; ++i) {
    ClipVertex& v = out[i];
    v.clip = in.clip[i];
    masks[i] = clipMask(v.clip, user);  // user clip planes: bits 6..13
    viewport.windowFromClip(v.clip, v.window);
    const glm::vec4& fp = in.primary[kFront][i];
    const glm::vec4 fs = secondary ? in.secondary[kFront][i] : glm::vec4(0);
    const glm::vec4& bp = back ? in.primary[kBack][i] : fp;
    const glm::vec4 bs = back && secondary ? in.secondary[kBack][i] : fs;
    for (int k = 0; k < 4; ++k) {
      v.attr[kFrontAttribs + k] = fp[k];
      v.attr[kFrontAttribs + 4 + k] = fs[k];
      v.attr[kBackAttribs + k] = bp[k];
      v.attr[kBackAttribs + 4 + k] = bs[k];
    }
    v.pointSize = in.hasPointSize ? in.pointSize[i] : 1.0f;  // points: per-vertex size
    // Texture coordinates (issue 14): after the colours, 4 per unit.
    for (uint32_t m = in.texCoordUnits; m != 0; m &= m - 1) {
      const int u = __builtin_ctz(m);
      std::memcpy(v.attr + kClipTexCoordAttribs + 4 * u, &in.texCoord[u][i][0], 4 * sizeof(float));
    }
    if (in.hasFog) v.attr[kClipFogAttrib] = in.fog[i];  // fog: last
  }
}

// An llvmpipe quirk (lp_setup_analysis.c, lp_setup_analyse_triangles, a
// workaround for Windows Aero): a non-indexed, unclipped, smooth GL_TRIANGLES
// draw of exactly 9 vertices whose last triangle has three equal window y
// draws nothing, unless the first six vertices form one particular
// axis-aligned rectangle, which llvmpipe then draws with its rectangle code
// (approximated here by the two triangles). Returns true when the draw is
// consumed. `v(i)`: the segment's vertex i.
template <typename VertexAt>
bool dropsNineVertexTriangles(const VertexAt& v, const BatchContext& b) {
  auto x = [&](int i) { return v(i).window[0]; };
  auto y = [&](int i) { return v(i).window[1]; };
  if (!(y(8) == y(7) && y(8) == y(6))) return false;
  if (x(0) == x(1) && x(0) == x(5) && x(2) == x(3) && x(2) == x(4) && y(0) == y(3) && y(0) == y(5) &&
      y(1) == y(2) && y(1) == y(4)) {
    emitTriangle(b, v(0), v(1), v(2), v(2));
    emitTriangle(b, v(3), v(4), v(5), v(5));
  }
  return true;
}

// One segment of the draw (assemble.h): decompose, clip, emit.
void drawSegment(BatchContext& b, GLenum mode, const Segment& seg, bool indexed,
                 const std::vector<ClipVertex>& clipVertices, const std::vector<uint32_t>& masks) {
  const PrimitiveState& state = b.state;
  auto global = [&](uint32_t local) { return (seg.hubReplaced && local == 0) ? 0u : seg.start + local; };
  uint32_t anyOutside = 0;
  for (uint32_t i = 0; i < seg.count; ++i) anyOutside |= masks[global(i)];
  b.pipeline = anyOutside != 0 || state.fetchedVertexOutside || b.polygon.active;
  const DecomposePath path =
      b.pipeline ? DecomposePath::kPipeline
                 : ((indexed || seg.hubReplaced) ? DecomposePath::kIndexed : DecomposePath::kLinear);
  if (path == DecomposePath::kLinear && mode == GL_TRIANGLES && !b.flatInputs && seg.count == 9 &&
      dropsNineVertexTriangles([&](int i) -> const ClipVertex& { return clipVertices[global(i)]; }, b))
    return;

  struct SiteTriangles {};
  std::vector<Triangle>& triangles = pipeline::threadScratch<std::vector<Triangle>, SiteTriangles>();
  assembleTriangles(mode, seg.count, state.firstVertexConvention, b.flatInputs, path, triangles);

  const int provokingSlot = primitive::provokingSlot(state.firstVertexConvention);
  const int attribCount = b.clipAttribCount;  // texture coordinates (issue 14): and theirs
  struct SitePolygon {};
  ClippedPolygon& polygon = pipeline::threadScratch<ClippedPolygon, SitePolygon>();
  // Polygon area: the draw module's polygon stages, with each triangle's
  // boundary edges (unfilled.cpp). GL 2.1 §3.6.4: edge flags apply to
  // independent triangles, quads and polygons only (Mesa applies them to
  // strips and fans too: MESA_FACTS.md "Polygons").
  if (b.polygon.active) {
    struct SiteEdgeBits {};
    std::vector<uint8_t>& edgeBits = pipeline::threadScratch<std::vector<uint8_t>, SiteEdgeBits>();
    const bool firstSegment = !seg.hubReplaced, lastSegment = seg.start + seg.count == b.vertexCount;
    assembleEdgeFlags(mode, seg.count, state.firstVertexConvention, firstSegment, lastSegment, edgeBits);
    const bool useFlags = b.edgeFlags && (mode == GL_TRIANGLES || mode == GL_QUADS || mode == GL_POLYGON);
    for (size_t i = 0; i < triangles.size(); ++i) {
      const Triangle& local = triangles[i];
      const uint32_t t[3] = {global(local[0]), global(local[1]), global(local[2])};
      unsigned edges = edgeBits[i];
      if (useFlags)
        for (int k = 0; k < 3; ++k)
          if (!b.edgeFlags[t[k]]) edges &= ~(1u << k);  // bit 3 (stipple reset) stays
      const ClipVertex* v[3] = {&clipVertices[t[0]], &clipVertices[t[1]], &clipVertices[t[2]]};
      const ClipVertex& provoking = clipVertices[t[provokingSlot]];
      const uint32_t m0 = masks[t[0]], m1 = masks[t[1]], m2 = masks[t[2]];
      if ((m0 | m1 | m2) == 0) {
        emitPolygonTriangle(b, *v[0], *v[1], *v[2], provoking, edges);
      } else if ((m0 & m1 & m2) == 0) {
        if (clipTriangle(*v[0], *v[1], *v[2], m0 | m1 | m2, attribCount, b.viewport, polygon,
                         state.userClipPlanes))
          emitPolygonClipped(b, polygon, v, edges, provoking);
      }
    }
    return;
  }
  for (const Triangle& local : triangles) {
    const uint32_t t[3] = {global(local[0]), global(local[1]), global(local[2])};
    const ClipVertex& v0 = clipVertices[t[0]];
    const ClipVertex& v1 = clipVertices[t[1]];
    const ClipVertex& v2 = clipVertices[t[2]];
    const ClipVertex& provoking = clipVertices[t[provokingSlot]];
    const uint32_t m0 = masks[t[0]], m1 = masks[t[1]], m2 = masks[t[2]];
    if ((m0 | m1 | m2) == 0) {
      emitTriangle(b, v0, v1, v2, provoking);
    } else if ((m0 & m1 & m2) == 0) {
      if (clipTriangle(v0, v1, v2, m0 | m1 | m2, attribCount, b.viewport, polygon, state.userClipPlanes))
        emitClippedPolygon(b, polygon, provoking);
    }
  }
}

}  // namespace

void drawPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, Framebuffer& fb) {
  const uint32_t n = trimVertexCount(state.mode, static_cast<uint32_t>(vertices.size()));
  if (n == 0 || !fb.bound()) return;
  const bool points = state.mode == GL_POINTS;
  const bool lines = state.mode == GL_LINES || state.mode == GL_LINE_STRIP || state.mode == GL_LINE_LOOP;
  if (!points && !lines && n < 3) return;

  BatchContext b{state,
                 fb,
                 ViewportTransform::make(state.viewportX, state.viewportY, state.viewportWidth,
                                         state.viewportHeight, state.depthNear, state.depthFar, fb.height(),
                                         state.flipViewportY),
                 FaceRule{state.cullFace, state.cullFaceMode, state.frontFace},
                 false,
                 std::clamp(state.raster.varyingCount, 4, 8),
                 vertices.hasBack,
                 {},
                 {},
                 false};
  // Culling both faces drops every polygon, never a line or a point (§3.5.1).
  if (!points && !lines && b.face.cullFace && b.face.cullFaceMode == GL_FRONT_AND_BACK) return;
  for (int k = 0; k < 4; ++k) {
    b.constantColours[k] = vertices.primary[kFront][0][k];
    b.constantColours[4 + k] = vertices.hasSecondary ? vertices.secondary[kFront][0][k] : 0.0f;
  }
  using Group = raster::RasterState;
  const bool secondary = b.varyingCount == 8;
  b.raster = state.raster;
  b.raster.firstVertexConvention = state.firstVertexConvention;
  b.raster.flatGroups = ((state.flat || state.constantPrimary) ? Group::kPrimaryGroup : 0u) |
                        ((state.flat || state.constantSecondary) ? Group::kSecondaryGroup : 0u);
  b.flatInputs = state.flat && (!state.constantPrimary || (secondary && !state.constantSecondary));
  // Texture coordinates (issue 14): the units the vertex stage made, carried
  // through the clipper after the colours.
  b.raster.texCoordUnits = vertices.texCoordUnits;
  if (vertices.texCoordUnits != 0) {
    const int units = 32 - __builtin_clz(vertices.texCoordUnits);
    b.clipAttribCount = kClipTexCoordAttribs + 4 * units;
    b.windowVaryingCount = raster::kTexCoordVarying + 4 * units;
  }
  // Fog: the fog distance, after every texture unit's slots.
  if (!vertices.hasFog) b.raster.fog = fragment::FogState();
  if (b.raster.fog.active()) {
    b.clipAttribCount = kMaxClipAttribs;
    b.windowVaryingCount = raster::kMaxVaryings;
  }

  // Polygon area: when polygon state makes Mesa run the draw module's
  // pipeline for polygons (batch_context.h, PolygonPipeline).
  if (!points && !lines) {
    PolygonPipeline& p = b.polygon;
    // st_atom_rasterizer.c: a culled face takes the other face's mode.
    p.fillFront = state.polygonModeFront;
    p.fillBack = state.polygonModeBack;
    if (state.cullFace && state.cullFaceMode != GL_BACK) p.fillFront = p.fillBack;
    if (state.cullFace && state.cullFaceMode != GL_FRONT) p.fillBack = p.fillFront;
    p.unfilled = p.fillFront != GL_FILL || p.fillBack != GL_FILL;
    p.offsetFill = state.offsetFill;
    p.offsetLine = state.offsetLine;
    p.offsetPoint = state.offsetPoint;
    p.offset = p.offsetFill || p.offsetLine || p.offsetPoint;
    // llvmpipe hands offset and two-sided colours to the draw module when
    // it needs the pipeline at all (lp_state_rasterizer.c), which for
    // polygons then runs when these are on (draw_pipe_validate.c).
    const bool handedOver = p.unfilled || state.polygonStipple || state.lineOrPointPipeline;
    p.active = p.unfilled || state.polygonStipple || (handedOver && (p.offset || b.twoSided));
    if (p.active) {
      const double mrd = fb.depth.bits() == 16 ? 1.0 / 65535.0 : 1.0 / 16777215.0;
      p.offsetScale = state.raster.offsetFactor;
      p.offsetUnits = static_cast<float>(double(state.raster.offsetUnits) * mrd * 2);
      b.raster.polygonOffset = false;  // the draw module offsets instead
    }
    b.edgeFlags = state.edgeFlags;
    b.vertexCount = n;
  }

  struct SiteClipVertices {};
  std::vector<ClipVertex>& clipVertices = pipeline::threadScratch<std::vector<ClipVertex>, SiteClipVertices>();
  struct SiteMasks {};
  std::vector<uint32_t>& masks = pipeline::threadScratch<std::vector<uint32_t>, SiteMasks>();
  struct SiteSegments {};
  std::vector<Segment>& segments = pipeline::threadScratch<std::vector<Segment>, SiteSegments>();
  loadVertices(vertices, n, b.viewport, state.userClipPlanes, clipVertices, masks);
  if (points) return drawPointBatch(b, n, clipVertices, masks);
  if (lines) return drawLineBatch(b, state.mode, n, clipVertices, masks);

  using Submission = PrimitiveState::Submission;
  const bool indexed =
      state.submission == Submission::kDrawElements || state.submission == Submission::kDisplayList;
  GLenum mode = state.mode;
  // (A display list converts in its vertex node, display_list.cpp: Mesa's
  // save module leaves the first primitive of a node unconverted.)
  if (state.submission == Submission::kBeginEnd && n == 3 &&
      (mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN))
    mode = GL_TRIANGLES;
  // An indexed batch is one of Mesa's segments (pipeline/array_draw.cpp
  // splits indexed draws).
  if (indexed)
    segments.assign(1, Segment{0, n, false});
  else
    splitIntoSegments(mode, n, segments);
  for (const Segment& seg : segments) drawSegment(b, mode, seg, indexed, clipVertices, masks);
  if (b.polygon.active) finishPolygonDraw(b);  // polygon area
}

}  // namespace glfixed::primitive
