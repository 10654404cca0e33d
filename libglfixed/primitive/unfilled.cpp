// Polygon area: the draw module's polygon stages, in the order its pipeline
// runs them (draw_pipe_validate.c): cull (which also computes the
// determinant), two-sided colours, polygon offset, flat shading, unfilled;
// then llvmpipe's triangle setup for filled triangles, or the line and point
// hand-overs for GL_LINE and GL_POINT faces (GL 2.1 §3.6.4).
// Every float operation here must round exactly as Mesa's does: forbid
// contracting a * b + c into a fused multiply-add.
#pragma GCC optimize("fp-contract=off")

#include <algorithm>
#include <cmath>
#include <cstring>

#include "primitive/batch_context.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::primitive {

namespace {

constexpr unsigned kEdge0 = 1, kEdge1 = 2, kEdge2 = 4, kAllEdges = 7;
// DRAW_PIPE_RESET_STIPPLE: the line stipple restarts at this triangle's edges.
constexpr unsigned kResetStipple = 8;

// draw_pipe_cull.c: det = (v0 - v2) x (v1 - v2) in llvmpipe's window
// space; det < 0 is counter-clockwise in GL's window space.
float determinant(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2) {
  const float ex = v0.window[0] - v2.window[0];
  const float ey = v0.window[1] - v2.window[1];
  const float fx = v1.window[0] - v2.window[0];
  const float fy = v1.window[1] - v2.window[1];
  return ex * fy - ey * fx;
}

// draw_pipe_offset.c, do_offset_tri: the offset of one triangle, from the
// determinant the cull stage computed (units already scaled).
float drawModuleOffset(const PolygonPipeline& p, float det, const ClipVertex& v0, const ClipVertex& v1,
                       const ClipVertex& v2, bool on) {
  const float invDet = 1.0f / det;
  const float ex = v0.window[0] - v2.window[0], ey = v0.window[1] - v2.window[1];
  const float ez = v0.window[2] - v2.window[2];
  const float fx = v1.window[0] - v2.window[0], fy = v1.window[1] - v2.window[1];
  const float fz = v1.window[2] - v2.window[2];
  const float a = ey * fz - ez * fy;
  const float b = ez * fx - ex * fz;
  const float dzdx = std::fabs(a * invDet), dzdy = std::fabs(b * invDet);
  const float maxSlope = dzdx > dzdy ? dzdx : dzdy;  // MAX2: NaN gives dzdy
  const float mult = maxSlope * (on ? p.offsetScale : 0.0f);
  return (on ? p.offsetUnits : 0.0f) + mult;
}

float saturate(float z) { return z < 0.0f ? 0.0f : (z > 1.0f ? 1.0f : z); }  // NaN stays

GLenum fillMode(const BatchContext& b, bool front) {
  return front ? b.polygon.fillFront : b.polygon.fillBack;
}

void emitUnfilled(const BatchContext& b, ClipVertex (&w)[3], const ClipVertex& prov, GLenum mode,
                  unsigned edges);

// Polygon stipple: the lines or points of the run the vbuf stage holds when
// the first filled triangle binds the stipple shader are drawn with it, so
// until then each run waits here (draw_pipe_pstipple.c, draw_pipe_vbuf.c:
// a change between points, lines and triangles renders the held run).
struct DeferredUnfilled {
  ClipVertex w[3];
  ClipVertex prov;
  GLenum mode;
  unsigned edges;
};
std::vector<DeferredUnfilled>& deferredUnfilled() {
  struct Site {};
  return pipeline::threadScratch<std::vector<DeferredUnfilled>, Site>();
}

void emitDeferred(const BatchContext& b, bool stippled) {
  std::vector<DeferredUnfilled>& deferred = deferredUnfilled();
  if (deferred.empty()) return;
  BatchContext withStipple = b;
  withStipple.raster.stippleEveryPrimitive = stippled;
  for (DeferredUnfilled& d : deferred) emitUnfilled(withStipple, d.w, d.prov, d.mode, d.edges);
  b.lineStippleCounter = withStipple.lineStippleCounter;
  deferred.clear();
}

void deferUnfilled(const BatchContext& b, ClipVertex (&w)[3], const ClipVertex& prov, GLenum mode,
                   unsigned edges) {
  std::vector<DeferredUnfilled>& deferred = deferredUnfilled();
  if (!deferred.empty() && deferred.back().mode != mode) emitDeferred(b, false);
  deferred.push_back({{w[0], w[1], w[2]}, prov, mode, edges});
}

}  // namespace

void assembleEdgeFlags(GLenum mode, uint32_t count, bool first, bool firstSegment, bool lastSegment,
                       std::vector<uint8_t>& out) {
  out.clear();
  const unsigned r = kResetStipple;
  switch (mode) {
    case GL_TRIANGLES:
      for (uint32_t i = 2; i < count; i += 3) out.push_back(kAllEdges | r);
      break;
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 2; i < count; ++i) out.push_back(kAllEdges | r);
      break;
    case GL_QUADS:  // (0,1,3) (1,2,3), or (3,0,1) (3,1,2): the diagonal hidden
      for (uint32_t i = 3; i < count; i += 4) {
        out.push_back(r | (first ? kEdge0 | kEdge1 : kEdge0 | kEdge2));
        out.push_back(first ? kEdge1 | kEdge2 : kEdge0 | kEdge1);
      }
      break;
    case GL_QUAD_STRIP:  // the pipeline's halves: (2k+2, 2k, 2k+3) (2k, 2k+1, 2k+3)
      for (uint32_t i = 3; i < count; i += 2) {
        out.push_back(r | (first ? kEdge0 | kEdge1 : kEdge0 | kEdge2));
        out.push_back(first ? kEdge1 | kEdge2 : kEdge0 | kEdge1);
      }
      break;
    case GL_POLYGON: {  // a fan: (i-1, i, 0), or (0, i-1, i)
      const unsigned next = first ? kEdge1 : kEdge0;
      const unsigned opening = first ? kEdge0 : kEdge2, closing = first ? kEdge2 : kEdge1;
      for (uint32_t i = 2; i < count; ++i) {
        unsigned e = next;
        if (i == 2) e |= r;
        if (i == 2 && firstSegment) e |= opening;
        if (i + 1 == count && lastSegment) e |= closing;
        out.push_back(static_cast<uint8_t>(e));
      }
      break;
    }
    default: break;
  }
}

void emitPolygonTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1,
                         const ClipVertex& v2, const ClipVertex& provoking, unsigned edges) {
  const PolygonPipeline& p = b.polygon;
  const bool frontCcw = b.state.frontFace == GL_CCW;
  const float det = determinant(v0, v1, v2);
  // The cull stage runs when the determinant is needed or culling is on; a
  // zero determinant counts as back-facing there.
  if (p.unfilled || p.offset || b.twoSided || b.face.cullFace) {
    if (b.face.cullFace) {
      const bool front = det != 0.0f && ((det < 0.0f) == frontCcw);
      if (b.face.culls(front)) return;
    }
  }
  ClipVertex w[3] = {v0, v1, v2};
  ClipVertex prov = provoking;
  // Two-sided colours: the back ones where det says back (draw_pipe_twoside.c),
  // copied over the front ones, which is what later stages read.
  int face = 0;
  if (b.twoSided) {
    const bool back = frontCcw ? det > 0.0f : det < 0.0f;
    face = back ? -1 : 1;
    if (back) {
      for (ClipVertex* v : {&w[0], &w[1], &w[2], &prov})
        std::memcpy(v->attr + kFrontAttribs, v->attr + kBackAttribs, sizeof(float) * 8);
    }
  }
  // Polygon offset, decided by the first triangle's face mode.
  if (p.offset) {
    if (p.offsetOn < 0) {
      const bool front = (det < 0.0f) == frontCcw;
      const GLenum mode = p.fillFront != p.fillBack ? fillMode(b, front) : p.fillFront;
      p.offsetOn = mode == GL_FILL ? p.offsetFill : (mode == GL_LINE ? p.offsetLine : p.offsetPoint);
    }
    // Off, the stage still runs with a zero factor and units: it clamps z to
    // [0, 1] (which moves vertices the clipper left a little outside), and
    // an infinite slope times 0 is NaN.
    const float offset = drawModuleOffset(p, det, v0, v1, v2, p.offsetOn != 0);
    for (ClipVertex& v : w) v.window[2] = saturate(v.window[2] + offset);
  }
  // Unfilled: det >= 0 is clockwise in GL's window space.
  const bool cw = det >= 0.0f;
  const GLenum mode = fillMode(b, cw != frontCcw);
  if (mode == GL_FILL) {
    if (b.state.polygonStipple && !p.stippleBound) {
      p.stippleBound = true;
      emitDeferred(b, true);  // the vbuf stage renders them after the bind
    }
    return setupPipelineTriangle(b, w[0], w[1], w[2], prov, face);
  }
  if (b.state.polygonStipple && !p.stippleBound) return deferUnfilled(b, w, prov, mode, edges);
  if (p.stippleBound && !b.raster.stippleEveryPrimitive) {
    BatchContext stippled = b;  // rare: lines and points under the stipple shader
    stippled.raster.stippleEveryPrimitive = true;
    emitUnfilled(stippled, w, prov, mode, edges);
    b.lineStippleCounter = stippled.lineStippleCounter;  // the line stipple carries on
    return;
  }
  emitUnfilled(b, w, prov, mode, edges);
}

namespace {

void emitUnfilled(const BatchContext& b, ClipVertex (&w)[3], const ClipVertex& prov, GLenum mode,
                  unsigned edges) {
  // GL_FLAT: the flat-shade stage gave every vertex the provoking colour; the
  // line and point set-ups take it from the `provoking` argument.
  if (mode == GL_LINE) {
    if (edges & kResetStipple) resetLineStipple(b);
    if (edges & kEdge2) emitLine(b, w[2], w[0], prov);
    if (edges & kEdge0) emitLine(b, w[0], w[1], prov);
    if (edges & kEdge1) emitLine(b, w[1], w[2], prov);
  } else {
    if (b.state.flat)  // the flat-shade stage: every vertex takes the provoking colours
      for (ClipVertex& v : w)
        std::memcpy(v.attr + kFrontAttribs, prov.attr + kFrontAttribs, sizeof(float) * 8);
    if (edges & kEdge0) emitPoint(b, w[0]);
    if (edges & kEdge1) emitPoint(b, w[1]);
    if (edges & kEdge2) emitPoint(b, w[2]);
  }
}

}  // namespace

namespace {

// True when a and b, both made by the clipper, lie on one plane of the view
// volume: the edge between them runs along that plane (relative tolerance:
// the clipper's interpolation leaves a few ulps).
bool onSameFrustumPlane(const ClipVertex& a, const ClipVertex& b) {
  auto scale = [](const glm::vec4& c) {
    return std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + std::fabs(c.w);
  };
  const float ea = 1e-5f * scale(a.clip), eb = 1e-5f * scale(b.clip);
  for (int plane = 0; plane < 6; ++plane)
    if (std::fabs(distanceToPlane(plane, a.clip)) <= ea && std::fabs(distanceToPlane(plane, b.clip)) <= eb)
      return true;
  return false;
}

// Which edge j of the original triangle (v_j to v_j+1) the points a and b
// lie on, by the residual of each against the edge's line in clip space;
// -1 when on none (an edge along a user clip plane).
int originalEdgeOf(const ClipVertex& a, const ClipVertex& b, const ClipVertex* const original[3]) {
  int best = -1;
  double bestResidual = 1e-8;
  for (int j = 0; j < 3; ++j) {
    const glm::dvec4 p0(original[j]->clip), d = glm::dvec4(original[(j + 1) % 3]->clip) - p0;
    const double dd = glm::dot(d, d);
    if (!(dd > 0)) continue;
    double residual = 0;
    for (const ClipVertex* v : {&a, &b}) {
      const glm::dvec4 r = glm::dvec4(v->clip) - p0;
      const glm::dvec4 off = r - d * (glm::dot(r, d) / dd);
      residual += glm::dot(off, off) / dd;
    }
    if (residual < bestResidual) {
      bestResidual = residual;
      best = j;
    }
  }
  return best;
}

}  // namespace

void finishPolygonDraw(const BatchContext& b) { emitDeferred(b, b.polygon.stippleBound); }

void emitPolygonClipped(const BatchContext& b, const ClippedPolygon& poly,
                        const ClipVertex* const original[3], unsigned edges, const ClipVertex& provoking) {
  const int n = poly.count;
  // Whether polygon edge k (vertex k to k + 1) is drawn: the clipper hides
  // the edges it makes along the view volume, keeps the flag of the
  // triangle edge a piece lies on, and shows edges along user clip planes.
  bool drawn[kMaxClippedVertices + 1];
  auto originalIndex = [&](const ClipVertex* v) {
    for (int j = 0; j < 3; ++j)
      if (v == original[j]) return j;
    return -1;
  };
  for (int k = 0; k < n; ++k) {
    const ClipVertex* a = poly.vertex[k];
    const ClipVertex* c = poly.vertex[(k + 1) % n];
    const int ia = originalIndex(a), ic = originalIndex(c);
    int edge;
    if (ia >= 0)
      edge = ia;
    else if (ic >= 0)
      edge = (ic + 2) % 3;
    else if (onSameFrustumPlane(*a, *c))
      edge = -2;
    else
      edge = originalEdgeOf(*a, *c, original);
    drawn[k] = edge == -1 || (edge >= 0 && (edges >> edge) & 1);
  }
  // emit_poly: a fan around vertex 0 with the polygon's edges flagged.
  const bool first = b.state.firstVertexConvention;
  for (int i = 2; i < n; ++i) {
    unsigned e = i == 2 ? kResetStipple : 0u;
    if (first) {  // (0, i-1, i): edge 0 is 0 -> 1 (first only), 1 is i-1 -> i, 2 is i -> 0 (last only)
      if (i == 2 && drawn[0]) e |= kEdge0;
      if (drawn[i - 1]) e |= kEdge1;
      if (i == n - 1 && drawn[n - 1]) e |= kEdge2;
      emitPolygonTriangle(b, *poly.vertex[0], *poly.vertex[i - 1], *poly.vertex[i], provoking, e);
    } else {  // (i-1, i, 0): edge 0 is i-1 -> i, 1 is i -> 0 (last only), 2 is 0 -> 1 (first only)
      if (drawn[i - 1]) e |= kEdge0;
      if (i == n - 1 && drawn[n - 1]) e |= kEdge1;
      if (i == 2 && drawn[0]) e |= kEdge2;
      emitPolygonTriangle(b, *poly.vertex[i - 1], *poly.vertex[i], *poly.vertex[0], provoking, e);
    }
  }
}

}  // namespace glfixed::primitive
