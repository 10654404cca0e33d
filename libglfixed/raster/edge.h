// Edge functions of a snapped triangle and llvmpipe's fill rule
// (lp_setup_tri.c, do_triangle_ccw; lp_rast_tri.c).
//
// Coordinates are llvmpipe's: fixed point with 8 fractional bits, pixel
// centres on the integer grid (see fixed_point.h), y pointing DOWN for a
// window-system buffer (row 0 is the top of the OSMesa buffer, which Mesa
// renders upside down and flips on read-back), UP for a framebuffer object
// (Framebuffer::rowsUp). A set-up triangle has a positive llvmpipe area
// (fixedArea() > 0): counter-clockwise in GL window space when y is down,
// clockwise when y is up.
#pragma once

#include <cstdint>

#include "raster/fixed_point.h"

namespace glfixed::raster {

// Three snapped vertices.
struct FixedTriangle {
  int32_t x[3] = {}, y[3] = {};
};

// llvmpipe's area: (x0-x1)(y2-y0) - (x2-x0)(y0-y1), exact in 64 bits.
// Positive: clockwise as seen in llvmpipe's space (counter-clockwise in GL
// window coordinates when y is down). Zero-area triangles are never drawn.
inline int64_t fixedArea(const FixedTriangle& t) {
  int64_t dx01 = int64_t(t.x[0]) - t.x[1], dy01 = int64_t(t.y[0]) - t.y[1];
  int64_t dx20 = int64_t(t.x[2]) - t.x[0], dy20 = int64_t(t.y[2]) - t.y[0];
  return dx01 * dy20 - dx20 * dy01;
}

// The edge from vertex i to vertex i+1 (mod 3), as llvmpipe sets it up:
// E(px, py) = dcdx * (x_i - 256 px) - dcdy * (y_i - 256 py) + bias, and pixel
// (px, py) is inside when E > 0 for all three edges. `bias` (1 or 0) is the
// fill rule: a centre exactly on an edge is inside only for a "left" edge
// (dcdx < 0) or a horizontal edge at GL's bottom: with llvmpipe's
// bottom_edge_rule (y down) one with dcdy < 0, without it (a framebuffer
// object, y up: the top-left rule in llvmpipe's rows) one with dcdy > 0
// (lp_setup_tri.c; st_atom_rasterizer.c sets the rule for Y_0_TOP only).
struct Edge {
  int64_t dcdx = 0, dcdy = 0;  // y_i - y_{i+1}, x_i - x_{i+1}
  int64_t c = 0;               // E at pixel (0, 0), fill-rule bias included

  static Edge make(const FixedTriangle& t, int i, bool bottomEdgeRule) {
    return make(t.x, t.y, 3, i, bottomEdgeRule);
  }
  // The edge from vertex i to vertex i+1 (mod n) of a convex polygon of n
  // snapped vertices (a line's or a point's quadrilateral has 4), with the
  // same fill rule.
  static Edge make(const int32_t* x, const int32_t* y, int n, int i, bool bottomEdgeRule) {
    int j = (i + 1) % n;
    Edge e;
    e.dcdx = int64_t(y[i]) - y[j];
    e.dcdy = int64_t(x[i]) - x[j];
    e.c = e.dcdx * x[i] - e.dcdy * y[i];
    if (e.dcdx < 0 || (e.dcdx == 0 && (bottomEdgeRule ? e.dcdy < 0 : e.dcdy > 0))) e.c += 1;
    return e;
  }
  // E at pixel (px, py).
  int64_t at(int px, int py) const { return c - dcdx * kFixedOne * px + dcdy * kFixedOne * py; }
  bool inside(int px, int py) const { return at(px, py) > 0; }
};

// floor(a / b) for b > 0.
inline int64_t floorDiv(int64_t a, int64_t b) {
  int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

// Narrows [lo, hi] on row py to the pixels inside `e` (exact integer
// arithmetic, equal to testing every pixel).
inline void clipSpanToEdge(const Edge& e, int py, int64_t& lo, int64_t& hi) {
  int64_t a = e.c + e.dcdy * kFixedOne * py;  // E at px = 0
  int64_t d = e.dcdx * kFixedOne;             // E decreases by d per pixel step
  if (d == 0) {
    if (a <= 0) hi = lo - 1;
  } else if (d > 0) {  // a - d px > 0  <=>  px <= floor((a - 1) / d)
    int64_t m = floorDiv(a - 1, d);
    if (m < hi) hi = m;
  } else {  // a + |d| px > 0  <=>  px >= floor(-a / |d|) + 1
    int64_t m = floorDiv(-a, -d) + 1;
    if (m > lo) lo = m;
  }
}

// The same bound for consecutive rows without dividing: for an edge with
// d != 0 the bound is floor(N / D) with N growing by a constant per row, so a
// quotient and remainder are stepped (exact, like a DDA).
class EdgeSpanStepper {
 public:
  EdgeSpanStepper() = default;
  EdgeSpanStepper(const Edge& e, int py) {
    const int64_t a = e.c + e.dcdy * kFixedOne * py;
    const int64_t d = e.dcdx * kFixedOne;
    const int64_t s = e.dcdy * kFixedOne;  // a grows by s per row
    if (d == 0) {
      kind_ = kConstant;
      a_ = a;
      step_ = s;
    } else {
      kind_ = d > 0 ? kUpper : kLower;
      // kUpper: hi = floor((a - 1) / d); kLower: lo = floor(-a / -d) + 1.
      const int64_t n = d > 0 ? a - 1 : -a;
      div_ = d > 0 ? d : -d;
      const int64_t stepN = d > 0 ? s : -s;
      q_ = floorDiv(n, div_);
      r_ = n - q_ * div_;
      stepQ_ = floorDiv(stepN, div_);
      stepR_ = stepN - stepQ_ * div_;
    }
  }
  // Narrows [lo, hi] for the current row.
  void clip(int64_t& lo, int64_t& hi) const {
    if (kind_ == kConstant) {
      if (a_ <= 0) hi = lo - 1;
    } else if (kind_ == kUpper) {
      if (q_ < hi) hi = q_;
    } else {
      if (q_ + 1 > lo) lo = q_ + 1;
    }
  }
  void nextRow() {
    if (kind_ == kConstant) {
      a_ += step_;
      return;
    }
    q_ += stepQ_;
    r_ += stepR_;
    if (r_ >= div_) r_ -= div_, q_ += 1;
  }

 private:
  enum Kind { kConstant, kUpper, kLower } kind_ = kConstant;
  int64_t a_ = 0, step_ = 0;  // kConstant
  int64_t q_ = 0, r_ = 0, div_ = 1, stepQ_ = 0, stepR_ = 0;
};

}  // namespace glfixed::raster
