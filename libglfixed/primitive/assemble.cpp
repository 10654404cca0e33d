// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include "primitive/assemble.h"

namespace glfixed::primitive {

namespace {

void triangles(uint32_t n, std::vector<Triangle>& out) {
  for (uint32_t i = 2; i < n; i += 3) out.push_back({i - 2, i - 1, i});
}

// Every path agrees on strips: the triangle's newest vertex goes last (or its
// oldest first), and odd triangles swap the other two to keep the winding.
void triangleStrip(uint32_t n, bool first, std::vector<Triangle>& out) {
  for (uint32_t i = 2; i < n; ++i) {
    const uint32_t odd = i & 1;
    if (first)
      out.push_back({i - 2, i + odd - 1, i - odd});
    else
      out.push_back({i + odd - 2, i - odd - 1, i});
  }
}

void triangleFan(uint32_t n, bool first, bool flat, DecomposePath path, std::vector<Triangle>& out) {
  // llvmpipe's linear path tries a 4-vertex smooth fan as a rectangle first,
  // whatever the provoking-vertex convention: (v0,v1,v2) (v0,v2,v3).
  if (path == DecomposePath::kLinear && !flat && n == 4) {
    out.push_back({0, 1, 2});
    out.push_back({0, 2, 3});
    return;
  }
  for (uint32_t i = 2; i < n; ++i) {
    if (first)
      out.push_back({i - 1, i, 0});
    else
      out.push_back({0, i - 1, i});
  }
}

// GL_POLYGON: a fan whose provoking vertex is vertex 0 (GL 2.1 table 2.12).
void polygon(uint32_t n, bool first, std::vector<Triangle>& out) {
  for (uint32_t i = 2; i < n; ++i) {
    if (first)
      out.push_back({0, i - 1, i});
    else
      out.push_back({i - 1, i, 0});
  }
}

// GL_QUADS ignore the provoking-vertex convention: vertex 4i+3 provokes.
void quads(uint32_t n, bool first, bool flat, DecomposePath path, std::vector<Triangle>& out) {
  for (uint32_t i = 3; i < n; i += 4) {
    if (first) {
      out.push_back({i, i - 3, i - 2});
      out.push_back({i, i - 2, i - 1});
    } else if (path == DecomposePath::kLinear && !flat) {
      out.push_back({i - 3, i - 2, i - 1});
      out.push_back({i - 3, i - 1, i});
    } else {
      out.push_back({i - 3, i - 2, i});
      out.push_back({i - 2, i - 1, i});
    }
  }
}

// GL_QUAD_STRIP quad k is (2k, 2k+1, 2k+3, 2k+2); vertex 2k+3 provokes. The
// pipeline emits the two halves in the opposite order.
void quadStrip(uint32_t n, bool first, DecomposePath path, std::vector<Triangle>& out) {
  for (uint32_t i = 3; i < n; i += 2) {
    Triangle a, b;
    if (first) {
      a = {i, i - 3, i - 2};
      b = {i, i - 1, i - 3};
    } else {
      a = {i - 3, i - 2, i};
      b = {i - 1, i - 3, i};
    }
    if (path == DecomposePath::kPipeline) {
      out.push_back(b);
      out.push_back(a);
    } else {
      out.push_back(a);
      out.push_back(b);
    }
  }
}

}  // namespace

uint32_t trimVertexCount(GLenum mode, uint32_t count) {
  uint32_t first = 3, step = 1;
  switch (mode) {
    case GL_POINTS:
      first = 1;
      step = 1;
      break;
    case GL_LINES:
      first = 2;
      step = 2;
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      first = 2;
      step = 1;
      break;
    case GL_TRIANGLES:
      first = 3;
      step = 3;
      break;
    case GL_QUADS:
      first = 4;
      step = 4;
      break;
    case GL_QUAD_STRIP:
      first = 4;
      step = 2;
      break;
    default:
      first = 3;
      step = 1;
      break;  // strips, fans, polygons
  }
  if (count < first) return 0;
  return count - (count - first) % step;
}

void splitIntoSegments(GLenum mode, uint32_t count, std::vector<Segment>& out, uint32_t maxSimple) {
  out.clear();
  count = trimVertexCount(mode, count);
  if (count == 0) return;
  // A draw that fits one simple segment is one, whatever its mode
  // (draw_split_tmp.h tests that first); only a longer fan or polygon is
  // split at the fan limit.
  if (count <= maxSimple) {
    out.push_back({0, count, false});
    return;
  }
  const bool fan = mode == GL_TRIANGLE_FAN || mode == GL_POLYGON;
  const uint32_t limit = fan ? kMaxFanSegment : maxSimple;
  uint32_t first = 3, step = 1;
  if (mode == GL_TRIANGLES) step = 3;
  if (mode == GL_QUADS) first = 4, step = 4;
  if (mode == GL_QUAD_STRIP) first = 4, step = 2;
  const uint32_t rollback = first - step;
  uint32_t segMax = trimVertexCount(mode, limit);
  if (mode == GL_TRIANGLE_STRIP && segMax < count && ((segMax - first) / step) % 2 == 0) segMax -= step;
  uint32_t segStart = 0;
  do {
    const uint32_t remaining = count - segStart;
    const bool later = segStart != 0;
    if (remaining > segMax) {
      out.push_back({segStart, segMax, fan && later});
      segStart += segMax - rollback;
    } else {
      out.push_back({segStart, remaining, fan && later});
      segStart += remaining;
    }
  } while (segStart < count);
}

void assembleTriangles(GLenum mode, uint32_t count, bool firstVertexConvention, bool flat, DecomposePath path,
                       std::vector<Triangle>& out) {
  out.clear();
  switch (mode) {
    case GL_TRIANGLES: triangles(count, out); break;
    case GL_TRIANGLE_STRIP: triangleStrip(count, firstVertexConvention, out); break;
    case GL_TRIANGLE_FAN: triangleFan(count, firstVertexConvention, flat, path, out); break;
    case GL_QUADS: quads(count, firstVertexConvention, flat, path, out); break;
    case GL_QUAD_STRIP: quadStrip(count, firstVertexConvention, path, out); break;
    case GL_POLYGON: polygon(count, firstVertexConvention, out); break;
    default: break;  // points and lines: not triangles
  }
}

}  // namespace glfixed::primitive
