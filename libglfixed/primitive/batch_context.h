// Internal to the primitive stage: what every primitive of one draw shares on
// its way from assembly to the rasterizer, and the hand-over points of each
// primitive class. drawPrimitives (draw_primitives.cpp) loads the vertices
// and routes the batch by mode: triangles stay there, lines go to lines.cpp,
// points to points.cpp. Polygon modes GL_LINE and GL_POINT (§3.6.4) hand
// their edges and vertices to emitLine and emitPoint.
#pragma once

#include <cstdint>
#include <cstring>
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

// Polygon area: what Mesa's draw module does to polygons when polygon state
// makes it run its pipeline for them (llvmpipe_create_rasterizer_state,
// draw_pipe_validate.c): an unfilled mode or polygon stipple. The pipeline
// then takes over culling (float determinant), two-sided colours (the same
// determinant) and polygon offset (per vertex, draw_pipe_offset.c) from
// llvmpipe's setup, and its unfilled stage turns triangles into edges or
// points (draw_pipe_unfilled.c). unfilled.cpp.
struct PolygonPipeline {
  bool active = false;    // every triangle of the draw goes through these stages
  bool unfilled = false;  // a face is GL_LINE or GL_POINT (the cull stage then always runs)
  GLenum fillFront = GL_FILL, fillBack = GL_FILL;  // after st's simplification for culling
  bool offset = false;                             // an offset enable is on: the offset stage runs
  bool offsetFill = false, offsetLine = false, offsetPoint = false;
  float offsetScale = 0, offsetUnits = 0;  // units already scaled by the depth buffer
  // The offset stage picks its mode from the first triangle it sees and keeps
  // it for the draw (draw_pipe_offset.c, offset_first_tri): -1 not yet.
  mutable int offsetOn = -1;
  // The stipple stage binds its fragment shader at the first filled
  // triangle and keeps it until the pipeline flushes, so the lines and
  // points of GL_LINE and GL_POINT faces after it are stippled too
  // (draw_pipe_pstipple.c; mesa_diff polymode runs).
  mutable bool stippleBound = false;
};

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
  // Polygon area: the polygon stages above, and each vertex's edge flag
  // (null: all true).
  PolygonPipeline polygon = {};
  const uint8_t* edgeFlags = nullptr;
  uint32_t vertexCount = 0;  // of the whole draw (its last segment ends there)
  // Lines (lines.cpp): where the draw module's stipple stage stands along the
  // lines drawn so far: each line adds its length in pixels rounded up
  // (draw_pipe_stipple.c, an unsigned `counter`; scene lines_stipple).
  mutable uint32_t lineStippleCounter = 0;
  // Texture coordinates (issue 14): the attributes the clipper interpolates
  // (colours, then 4 per unit up to the highest in raster.texCoordUnits), and
  // the window varyings that carry them (colours, then kTexCoordVarying + 4 u).
  int clipAttribCount = kClipAttribCount;
  int windowVaryingCount = 8;
};

// Texture coordinates (issue 14): ClipVertex attributes -> window varyings
// for the units in b.raster.texCoordUnits, and the fog distance.
inline bool carriesMoreThanColours(const BatchContext& b) {
  return b.raster.texCoordUnits != 0 || b.raster.fog.active();
}
inline void copyTexCoords(const BatchContext& b, const ClipVertex& v, raster::WindowVertex& w) {
  for (uint32_t m = b.raster.texCoordUnits; m != 0; m &= m - 1) {
    const int u = __builtin_ctz(m);
    std::memcpy(w.varying + raster::kTexCoordVarying + 4 * u, v.attr + kClipTexCoordAttribs + 4 * u,
                4 * sizeof(float));
  }
  if (b.raster.fog.active()) w.varying[raster::kFogVarying] = v.attr[kClipFogAttrib];
}

// A triangle leaving the clipper: the draw module's cull stage (pipeline
// only), then llvmpipe's triangle setup.
void emitTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                  const ClipVertex& provoking);

// Polygon area (unfilled.cpp). The edge flags of each triangle of `mode` as
// the draw module's decomposition sets them (draw_decompose_tmp.h): bit k
// for edge k, from vertex k to vertex k + 1 of the triangle as assembled on
// the pipeline path, bit 3 where the line stipple restarts; a polygon split
// into segments hides the split edges.
void assembleEdgeFlags(GLenum mode, uint32_t count, bool firstVertexConvention, bool firstSegment,
                       bool lastSegment, std::vector<uint8_t>& out);
// A triangle through the polygon stages (PolygonPipeline), unclipped:
// `edges` bit k says edge k is a boundary edge with its edge flag set.
void emitPolygonTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1,
                         const ClipVertex& v2, const ClipVertex& provoking, unsigned edges);
// The same for what the clipper left of triangle `original` (its three
// vertices) with edges `edges`: frustum clip edges are hidden, others keep
// the flag of the edge they lie on (draw_pipe_clip.c).
void emitPolygonClipped(const BatchContext& b, const ClippedPolygon& poly,
                        const ClipVertex* const original[3], unsigned edges, const ClipVertex& provoking);
// The end of a draw: what the polygon stages still hold is drawn.
void finishPolygonDraw(const BatchContext& b);
// llvmpipe's triangle setup for a triangle from the pipeline (draw_primitives.cpp):
// face +1/-1 forces the colours of that face (the draw module's two-sided
// stage chose them), 0 lets llvmpipe's setup choose.
void setupPipelineTriangle(const BatchContext& b, const ClipVertex& v0, const ClipVertex& v1,
                           const ClipVertex& v2, const ClipVertex& provoking, int face);

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
