// GL_SELECT and GL_FEEDBACK (GL 2.1 §5.2, §5.3): primitives are assembled,
// clipped, culled and mapped to window coordinates, then handed to a sink
// instead of the rasterizer. Done as Mesa does it: the state tracker runs a
// private instance of the draw module whose last stage is the selection or
// feedback stage (st_cb_feedback.c), so every draw goes through the draw
// pipeline:
//   - triangles are decomposed as the pipeline decomposes them
//     (assemble.h, DecomposePath::kPipeline), whatever the draw;
//   - a clipped triangle reaches the sink as the fan of triangles the clipper
//     emits (clip.h), never as one polygon;
//   - with culling on, the draw module's float determinant culls (cull.h);
//   - GL_FLAT changes no vertex's colour, except that a clipped polygon's
//     first vertex takes the provoking vertex's colour;
//   - lines are clipped as points on a segment, each clipped end interpolated
//     from the end outside; points are dropped when outside any plane.
#pragma once

#include <GL/gl.h>

#include "pipeline/vertex_batch.h"
#include "primitive/clip.h"
#include "primitive/primitive.h"

namespace glfixed::primitive {

// Attribute layout inside ClipVertex::attr for the sinks.
constexpr int kSinkFrontColor = 0;
constexpr int kSinkBackColor = 4;
// Texture coordinates (issue 14): unit 0's s, t, r, q, interpolated by the
// clipper like the colours (GL_FEEDBACK reports them).
constexpr int kSinkTexCoord = kClipTexCoordAttribs;

// Receives the primitives in order. A vertex's window position is x, y
// measured down from the top of the framebuffer, z, and 1/w (viewport.h).
// `color` is the first of the four colour attributes to use (front or back).
class PrimitiveSink {
 public:
  virtual ~PrimitiveSink() = default;
  virtual void point(const ClipVertex& v) = 0;
  virtual void line(const ClipVertex& v0, const ClipVertex& v1) = 0;
  virtual void triangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, int color) = 0;
};

void drawUnrasterized(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                      PrimitiveSink& sink);

// Lines are clipped as when they are drawn (clip_line.h).

}  // namespace glfixed::primitive
