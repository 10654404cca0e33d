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

// Line clipping as draw_pipe_clip.c does it (do_clip_line): for each plane
// some end is outside, t0/t1 grow to the largest fraction cut off at each
// end; the line is dropped once t0 + t1 >= 1. Returns false when nothing is
// left; else `out0`/`out1` point at the ends (the inputs or `made`).
// Planes 6.. are the user clip planes of `user`.
bool clipLine(const ClipVertex& v0, const ClipVertex& v1, uint32_t planes, int attribCount,
              const ViewportTransform& viewport, ClipVertex made[2], const ClipVertex** out0,
              const ClipVertex** out1, const UserClipPlanes& user = kNoUserClipPlanes);

}  // namespace glfixed::primitive
