// Internal to the primitive stage: what every primitive of one draw shares on
// its way from assembly to the rasterizer, and the hand-over points of each
// primitive class. drawPrimitives (draw_primitives.cpp) loads the vertices
// and routes the batch by mode: triangles stay there, lines go to lines.cpp,
// points to points.cpp. Polygon modes GL_LINE and GL_POINT (§3.6.4) hand
// their edges and vertices to emitLine and emitPoint.
#pragma once

#include <cstdint>
#include <vector>

#include "primitive/clip.h"
#include "primitive/cull.h"
#include "primitive/primitive.h"
#include "primitive/viewport.h"
#include "raster/raster.h"

namespace glfixed::primitive {

// Attribute layout inside ClipVertex::attr.
constexpr int kFrontAttribs = 0;  // primary RGBA, secondary RGBA
constexpr int kBackAttribs = 8;
constexpr int kClipAttribCount = kBackAttribs + 8;

struct BatchContext {
  const PrimitiveState& state;
  Framebuffer& fb;
  ViewportTransform viewport;
  FaceRule face;
  bool pipeline;  // Mesa runs its draw pipeline for the current segment (assemble.h)
  int varyingCount;
  bool twoSided;
  float constantColours[8];    // primary, secondary of vertex 0 (see PrimitiveState::constantPrimary)
  raster::RasterState raster;  // state.raster with flatGroups set for this draw
  // llvmpipe's "uses constant interpolation": GL_FLAT with a colour the
  // fragment shader really reads as an input. It changes quad splits.
  bool flatInputs;
  // Lines (lines.cpp): where the draw module's stipple stage stands along the
  // lines drawn so far: each line adds its length in pixels rounded up
  // (draw_pipe_stipple.c, an unsigned `counter`; scene lines_stipple).
  mutable uint32_t lineStippleCounter = 0;
};

// A triangle leaving the clipper: the draw module's cull stage (pipeline
// only), then llvmpipe's triangle setup.
void emitTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                  const ClipVertex& provoking);

// GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP (lines.cpp): `n` loaded vertices
// with their clip masks.
void drawLineBatch(BatchContext& b, GLenum mode, uint32_t n, const std::vector<ClipVertex>& vertices,
                   const std::vector<uint32_t>& masks);
// GL_POINTS (points.cpp).
void drawPointBatch(BatchContext& b, uint32_t n, const std::vector<ClipVertex>& vertices,
                    const std::vector<uint32_t>& masks);

// One clipped line segment in window space, to llvmpipe's line setup;
// `provoking` gives its flat colour.
void emitLine(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& provoking);
// Restarts the line stipple pattern (the draw module's
// DRAW_PIPE_RESET_STIPPLE): at each GL_LINES line, at the first line of a
// strip or loop, at each polygon's first edge.
inline void resetLineStipple(const BatchContext& b) { b.lineStippleCounter = 0; }
// One point whose centre survived clipping, to llvmpipe's point setup.
void emitPoint(const BatchContext& b, const ClipVertex& v);

}  // namespace glfixed::primitive
