// Primitive assembly, clipping, culling and the viewport transform: turns the
// shaded vertices of one batch into window-space triangles for the rasterizer.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "framebuffer/framebuffer.h"
#include "pipeline/vertex_batch.h"
#include "primitive/clip.h"
#include "raster/raster.h"

namespace glfixed::primitive {

struct PrimitiveState {
  GLenum mode = GL_TRIANGLES;
  bool flat = false;                   // GL_FLAT: the provoking vertex's colour
  bool firstVertexConvention = false;  // glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)
  bool cullFace = false;
  GLenum cullFaceMode = GL_BACK;
  GLenum frontFace = GL_CCW;  // as llvmpipe has it (raster::RasterState::frontFace)
  // Viewport (GL 2.1 §2.11.1).
  int viewportX = 0, viewportY = 0, viewportWidth = 0, viewportHeight = 0;
  // The viewport transform flips y (viewport.h): a window-system buffer, not
  // a framebuffer object (Framebuffer::rowsUp); st_draw_quad's pixel
  // rectangles flip always (their quad is placed for it).
  bool flipViewportY = true;
  double depthNear = 0, depthFar = 1;
  // How the batch was submitted. Mesa treats the ways differently: an indexed
  // draw splits quads otherwise (assemble.h), and glBegin/glEnd turns a
  // 3-vertex strip or fan into GL_TRIANGLES (vbo_exec.c,
  // vbo_try_prim_conversion), which moves a fan's first-vertex provoking
  // vertex. Display lists convert every primitive of a vertex node but its
  // first (pipeline/display_list.cpp, scene list_provoking_first).
  enum class Submission { kBeginEnd, kDrawArrays, kDrawElements, kDisplayList };
  Submission submission = Submission::kBeginEnd;
  // A colour that is not a per-vertex attribute of the draw in Mesa's terms
  // (lighting off, and the colour not part of the vertex data: no colour
  // array, or under glBegin/glEnd not in the vbo vertex format) is read by
  // Mesa's fixed-function fragment shader as a constant, the current colour,
  // clamped (ff_fragment_shader.cpp, STATE_CURRENT_ATTRIB_MAYBE_VP_CLAMPED):
  // never interpolated, and it does not make GL_FLAT a "flat input" (so
  // quads split as when smooth, assemble.h). Every vertex then carries that
  // colour; vertex 0's is used. Measured with glColor before glBegin.
  bool constantPrimary = false;
  // Mesa fetched and tested a vertex with this draw that no primitive of it
  // uses, and it is outside the view volume: the draw runs the draw
  // module's pipeline as if one of its own were (an indexed draw drawn whole
  // fetches its whole index range: pipeline/array_draw.cpp).
  bool fetchedVertexOutside = false;
  bool constantSecondary = false;
  // Polygon area (GL 2.1 §3.6.4-§3.6.6; pipeline/draw.cpp fills them):
  // the modes per face, the offset enables (the factor and units are in
  // `raster`), the stipple enable (the pattern too), whether line or point
  // state (smooth points or lines, line stipple) makes llvmpipe hand offset
  // and two-sided colours to the draw module, and each vertex's edge flag
  // (null: all true).
  GLenum polygonModeFront = GL_FILL, polygonModeBack = GL_FILL;
  bool offsetFill = false, offsetLine = false, offsetPoint = false;
  bool polygonStipple = false;
  bool lineOrPointPipeline = false;
  const uint8_t* edgeFlags = nullptr;
  // Lines (GL 2.1 §3.5; primitive/lines.cpp), as Mesa's state tracker hands
  // them to llvmpipe (st_atom_rasterizer.c): the width clamped to [1, 255]
  // (NaN gives 1); stipple only when enabled with a pattern other than
  // 0xffff; GL_LINE_SMOOTH makes rectangular, antialiased lines.
  float lineWidth = 1;
  bool lineSmooth = false;
  bool lineStipple = false;
  int lineStippleFactor = 1;  // [1, 256]
  uint16_t lineStipplePattern = 0xffff;
  uint32_t* lineStippleCounter = nullptr;  // kept from draw to draw (Context::lineStipple)
  bool lineStippleContinues = false;       // the batch goes on with the previous one's strip
  // Clip planes and scissor: the enabled user clip planes (§2.12) in clip
  // space, the eye-space planes times the inverse projection (clip.h).
  UserClipPlanes userClipPlanes;
  raster::RasterState raster;  // depth test, scissor to the viewport, ...
  // Points (GL 2.1 §3.4; primitive/points.cpp). pointSize: glPointSize
  // clamped to [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX] as the state tracker
  // does it (Mesa's CLAMP: a NaN minimum wins); pointSizePerVertex: distance
  // attenuation is on and each vertex carries its size (ClipVertex).
  // pointSmooth: GL_POINT_SMOOTH, drawn by the draw module's aapoint stage.
  // Where points may fall: raster::RasterState::pointLineRegion.
  float pointSize = 1;
  bool pointSizePerVertex = false;
  bool pointSmooth = false;
};

// Draws every primitive of `vertices` (in the order GL_<mode> defines).
void drawPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, Framebuffer& fb);

}  // namespace glfixed::primitive
