// Lines (GL 2.1 §3.5): assembly, clipping and the hand-over to llvmpipe's
// line set-up, in the order Mesa's draw module and llvmpipe draw them:
//   - GL_LINES (2i, 2i+1); GL_LINE_STRIP (i, i+1); GL_LINE_LOOP the strip,
//     then its closing line (n-1, 0) last (lp_setup_vbuf.c; the draw
//     pipeline's decomposition is the same);
//   - the flat colour is the line's second vertex's, or its first's under
//     GL_FIRST_VERTEX_CONVENTION (lp_setup_line.c; the loop's closing line
//     takes vertex 0's);
//   - a line with an end outside the view volume is clipped (clip_line.h),
//     then goes on as any other.
// Every float operation here must round exactly as llvmpipe's does.
#pragma GCC optimize("fp-contract=off")

#include <cmath>
#include <cstdint>
#include <cstring>

#include "primitive/batch_context.h"
#include "primitive/clip_line.h"

namespace glfixed::primitive {

namespace {

// `restart`: the line restarts the stipple pattern, if it reaches the
// stipple stage (a line clipped away does not).
void clipAndEmit(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, uint32_t m0, uint32_t m1,
                 bool restart) {
  const ClipVertex& provoking = b.state.firstVertexConvention ? v0 : v1;
  if ((m0 & m1) != 0) return;  // wholly outside one plane
  if ((m0 | m1) == 0) {
    if (restart) resetLineStipple(b);
    return emitLine(b, v0, v1, provoking);
  }
  ClipVertex made[2];
  const ClipVertex *e0, *e1;
  // Under GL_FLAT the clipper copies the provoking colours into a moved end
  // (copy_flat); emitLine takes them from `provoking` anyway.
  if (!clipLine(v0, v1, m0, m1, m0 | m1, b.clipAttribCount, b.viewport, b.state.flat, provoking, made, &e0,
                &e1, b.state.userClipPlanes))  // clip planes and scissor: the user planes too
    return;
  if (restart) resetLineStipple(b);
  emitLine(b, *e0, *e1, provoking);
}

}  // namespace

void drawLineBatch(BatchContext& b, GLenum mode, uint32_t n, const std::vector<ClipVertex>& v,
                   const std::vector<uint32_t>& masks) {
  // The stipple counter lives on from draw to draw, as in Mesa's draw module.
  uint32_t* const carried = b.state.lineStippleCounter;
  if (carried) b.lineStippleCounter = *carried;
  const bool first = !b.state.lineStippleContinues;
  auto line = [&](uint32_t i, uint32_t j, bool restart) {
    clipAndEmit(b, v[i], v[j], masks[i], masks[j], restart);
  };
  switch (mode) {
    case GL_LINES:
      for (uint32_t i = 1; i < n; i += 2) line(i - 1, i, true);
      break;
    case GL_LINE_STRIP:
      for (uint32_t i = 1; i < n; ++i) line(i - 1, i, first && i == 1);
      break;
    default:  // GL_LINE_LOOP
      for (uint32_t i = 1; i < n; ++i) line(i - 1, i, first && i == 1);
      if (n >= 2) line(n - 1, 0, false);
      break;
  }
  if (carried) *carried = b.lineStippleCounter;
}

namespace {

// draw_pipe_stipple.c, stipple_test: bit (counter / factor) mod 16 of the
// pattern, in unsigned 32-bit arithmetic.
inline bool stippleBit(uint32_t counter, int factor, uint16_t pattern) {
  const uint32_t b = (counter / static_cast<uint32_t>(factor)) & 0xf;
  return ((1u << b) & pattern) != 0;
}

// screen_interp: every attribute, the window position and 1/w included,
// linear in window space.
void screenInterpolate(const raster::WindowVertex& a, const raster::WindowVertex& b, float t, int varyings,
                       raster::WindowVertex& out) {
  out.x = a.x + t * (b.x - a.x);
  out.y = a.y + t * (b.y - a.y);
  out.z = a.z + t * (b.z - a.z);
  out.oneOverW = a.oneOverW + t * (b.oneOverW - a.oneOverW);
  for (int k = 0; k < varyings; ++k) out.varying[k] = a.varying[k] + t * (b.varying[k] - a.varying[k]);
}

// The draw module's stipple stage (draw_pipe_stipple.c): the line is cut
// into the pieces whose pixels the pattern keeps, each drawn as a line of its
// own. Its length is counted in pixels along the major axis (Euclidean for
// rectangular lines); the counter carries on to the next line by the length
// rounded up.
template <typename DrawPiece>
void stippleLine(const BatchContext& b, const raster::WindowVertex& v0, const raster::WindowVertex& v1,
                 bool rectangular, const DrawPiece& drawPiece) {
  float length;
  if (rectangular) {
    const float dx = v1.x - v0.x, dy = v1.y - v0.y;
    length = std::sqrt(dx * dx + dy * dy);
  } else {
    const float dx = v0.x > v1.x ? v0.x - v1.x : v1.x - v0.x;
    const float dy = v0.y > v1.y ? v0.y - v1.y : v1.y - v0.y;
    length = dx > dy ? dx : dy;
  }
  // (Clipped lines are never longer than the viewport's diagonal; the bound
  // only keeps a line of bad input from running for ever.)
  const int intLength = length < 1e7f ? static_cast<int>(std::ceil(length)) : 0;
  const int factor = b.state.lineStippleFactor;
  const uint16_t pattern = b.state.lineStipplePattern;
  const uint32_t counter = b.lineStippleCounter;
  auto piece = [&](float t0, float t1) {
    raster::WindowVertex p0, p1;
    // Texture coordinates (issue 14): interpolated with the colours.
    const int varyings = carriesMoreThanColours(b) ? b.windowVaryingCount : b.varyingCount;
    if (t0 > 0.0) screenInterpolate(v0, v1, t0, varyings, p0);
    if (t1 < 1.0) screenInterpolate(v0, v1, t1, varyings, p1);
    drawPiece(t0 > 0.0 ? p0 : v0, t1 < 1.0 ? p1 : v1);
  };
  float start = 0;
  bool on = false;
  for (int i = 0; i < intLength; ++i) {
    const bool bit = stippleBit(counter + static_cast<uint32_t>(i), factor, pattern);
    if (bit == on) continue;
    if (on)
      piece(start / length, static_cast<float>(i) / length);
    else
      start = static_cast<float>(i);
    on = bit;
  }
  if (on && start < length) piece(start / length, 1.0f);
  b.lineStippleCounter += static_cast<uint32_t>(intLength);
}

}  // namespace

void emitLine(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1,
              const ClipVertex& provoking) {
  raster::WindowVertex w[2];
  const ClipVertex* v[2] = {&v0, &v1};
  for (int i = 0; i < 2; ++i) {
    w[i].x = v[i]->window[0];
    w[i].y = v[i]->window[1];
    w[i].z = v[i]->window[2];
    w[i].oneOverW = v[i]->window[3];
    // Lines are always front-facing (lp_setup_line.c): front colours.
    std::memcpy(w[i].varying, v[i]->attr + kFrontAttribs, sizeof(float) * b.varyingCount);
    if (carriesMoreThanColours(b)) copyTexCoords(b, *v[i], w[i]);  // texture coordinates (issue 14), fog
  }
  // Flat colours: the provoking vertex's (GL_FLAT), or Mesa's constant.
  const float* flat = nullptr;
  float flatValues[raster::kMaxVaryings];
  if (b.raster.flatGroups != 0) {
    const float* provoked = provoking.attr + kFrontAttribs;
    for (int k = 0; k < 4; ++k) flatValues[k] = b.state.constantPrimary ? b.constantColours[k] : provoked[k];
    for (int k = 4; k < 8; ++k)
      flatValues[k] = b.state.constantSecondary ? b.constantColours[k] : provoked[k];
    flat = flatValues;
  }
  raster::LineStyle style;
  style.width = b.state.lineWidth;
  style.rectangular = b.state.lineSmooth;
  auto draw = [&](const raster::WindowVertex& a, const raster::WindowVertex& c) {
    if (style.rectangular)
      raster::drawSmoothLine(b.raster, b.fb, style.width, a, c, flat);
    else
      raster::drawLine(b.raster, b.fb, style, a, c, flat);
  };
  if (b.state.lineStipple)
    stippleLine(b, w[0], w[1], style.rectangular, draw);
  else
    draw(w[0], w[1]);
}

}  // namespace glfixed::primitive
