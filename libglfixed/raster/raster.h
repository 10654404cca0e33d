// The triangle rasterizer: window-space triangles in, fragments out, with
// llvmpipe's coverage rules, depth test and perspective-correct colours.
#pragma once

#include <GL/gl.h>

#include "fragment/alpha_test_state.h"
#include "fragment/blend_state.h"
#include "fragment/fog_state.h"

#include "fragment/depth_image_state.h"
#include "fragment/stencil_state.h"
#include "framebuffer/framebuffer.h"
#include "raster/edge.h"

namespace glfixed::fragment {
struct TextureStage;  // fragment/texture_stage.h
}  // namespace glfixed::fragment

namespace glfixed::raster {

// The varyings of a window vertex: primary RGBA (0..3), secondary RGBA
// (4..7, the separate specular colour), then s, t, r, q of texture unit u at
// kTexCoordVarying + 4 u.
constexpr int kTexCoordVarying = 8;
constexpr int kMaxTexCoordUnits = 8;
// Fog (GL 2.1 §3.10): the vertex program's fog distance, last.
constexpr int kFogVarying = kTexCoordVarying + 4 * kMaxTexCoordUnits;
constexpr int kMaxVaryings = kFogVarying + 1;

// A vertex in window coordinates AS LLVMPIPE SEES THEM: Mesa renders an OSMesa
// buffer (or a window) upside down (gallium's y = 0 is the top row) and flips
// it when it hands the image back. So `y` is measured DOWN from the top edge
// of such a framebuffer: yDown = framebufferHeight - yGL. A framebuffer
// object is rendered as GL has it: there `y` is GL's (Framebuffer::rowsUp).
// Keeping llvmpipe's orientation matters because snapping and float rounding
// happen there (see primitive/viewport.h for how x, y, z are computed).
struct WindowVertex {
  float x = 0, y = 0, z = 0;  // x, y down from the top, z in [0,1] after glDepthRange
  float oneOverW = 1;         // 1 / w_clip, for perspective-correct interpolation
  float varying[kMaxVaryings] = {};
};

// A rectangle of pixels in GL window coordinates (y up), [x0, x1) x [y0, y1).
struct WindowRegion {
  int x0 = 0, y0 = 0, x1 = 1 << 30, y1 = 1 << 30;
};

struct RasterState {
  bool depthTest = false;
  GLenum depthFunc = GL_LESS;
  bool depthWrite = true;
  bool depthClamp = false;  // ARB_depth_clamp: depth in [depthClampMin, depthClampMax]
  float depthClampMin = 0, depthClampMax = 1;
  bool colorWrite[4] = {true, true, true, true};
  // The stencil test (both faces) and which winding faces front
  // (glFrontFace): a triangle's set-up gives its facing (PrimitiveSetup).
  fragment::StencilState stencil;
  // As llvmpipe has it (front_ccw): GL's glFrontFace, the other one when
  // drawing into a framebuffer object, whose y is not flipped (Mesa's
  // st_atom_rasterizer.c), so that GL's front stays front.
  GLenum frontFace = GL_CCW;
  // llvmpipe's bottom_edge_rule: on for a window-system buffer (y down), off
  // for a framebuffer object (the top-left rule in its y-up rows); on for the
  // state tracker's own quads (bitmaps, pixel rectangles) everywhere.
  bool bottomEdgeRule = true;
  int varyingCount = 4;  // 4: primary colour; 8: primary + secondary, summed per fragment
  // Bit u: the vertices carry unit u's texture coordinates (varyings
  // kTexCoordVarying + 4 u ...), interpolated perspective-correct, never flat.
  uint32_t texCoordUnits = 0;
  // The draw's texturing (null or no unit: none), which the fragment stage
  // applies; owned by the draw.
  const fragment::TextureStage* textures = nullptr;
  // The alpha test (GL 2.1 §4.1.4; func GL_ALWAYS when disabled).
  fragment::AlphaTestState alphaTest;
  bool clampFragmentColor = false;  // on float colour buffers too (OSMesaColorClamp)
  // Only pixels in [scissorX0, scissorX1) x [scissorY0, scissorY1) are written,
  // in GL window coordinates (y up): the viewport intersected with the buffer.
  int scissorX0 = 0, scissorY0 = 0, scissorX1 = 0, scissorY1 = 0;
  // glProvokingVertex(GL_FIRST_VERTEX_CONVENTION): drawTriangle reorders a
  // clockwise triangle as (v0, v2, v1) instead of (v1, v0, v2), as llvmpipe
  // does to keep the provoking vertex in its slot. The order changes float
  // rounding of the interpolated attributes.
  bool firstVertexConvention = false;
  // Which colours take the triangle's `flatVaryings` at every fragment
  // instead of being interpolated: bit 0 the primary colour (varyings 0..3),
  // bit 1 the secondary (4..7). GL_FLAT makes both flat; a colour Mesa reads
  // as a constant (PrimitiveState::constantPrimary) makes only that one.
  unsigned flatGroups = kPrimaryGroup | kSecondaryGroup;
  static constexpr unsigned kPrimaryGroup = 1, kSecondaryGroup = 2;
  // Polygon area: polygon offset (GL 2.1 §3.6.5) as llvmpipe's own triangle
  // setup applies it (lp_state_setup.c, lp_do_offset_tri): one offset a
  // triangle, from its unsnapped window positions, added to the interpolated
  // z of every fragment. `polygonOffset` is on when Mesa hands the offset to
  // llvmpipe's setup (draw.cpp says when); the factor and units are
  // glPolygonOffset's, the units scaled here by the depth buffer's precision.
  bool polygonOffset = false;
  float offsetFactor = 0, offsetUnits = 0;
  // Polygon stipple (GL 2.1 §3.6.2): 32 rows of 32 bits, row 0 the bottom
  // row, bit 31 the leftmost pixel; null when disabled. Only triangle setup
  // reads it (llvmpipe stipples filled polygons only).
  const uint32_t* polygonStipple = nullptr;
  // Stipple lines and points too (Mesa's stipple shader left bound after a
  // filled polygon: primitive/batch_context.h, PolygonPipeline).
  bool stippleEveryPrimitive = false;
  // Points and lines (raster/point.cpp, line.cpp): llvmpipe draws them
  // wherever they fall in its draw region, the framebuffer cut by the scissor
  // box when there is one, not in the viewport (a wide point or line spills
  // past the viewport edge); always further cut to the buffer.
  WindowRegion pointLineRegion;
  // Point sprites (GL 2.0 §3.3.1; raster/point.cpp): GL_POINT_SPRITE makes
  // llvmpipe draw points as quads of the snapped size (not legacy points);
  // the units of spriteCoordReplace (bit u: GL_COORD_REPLACE) get the sprite
  // coordinates, with GL_POINT_SPRITE_COORD_ORIGIN.
  bool pointSprite = false;
  uint32_t spriteCoordReplace = 0;
  // In llvmpipe's rows: GL's origin, the other one into a framebuffer object.
  GLenum spriteCoordOrigin = GL_UPPER_LEFT;
  // Blending or the logic op before the colour write (fragment/blend.inc).
  fragment::BlendState blend;
  // Fog (fragment/fog.inc): active when GL_FOG is on; then the vertices
  // carry the fog distance in varying kFogVarying, interpolated
  // perspective-correct like the texture coordinates, never flat.
  fragment::FogState fog;

  // glDrawPixels(GL_DEPTH_COMPONENT): fragments take their depth from the
  // image at unit 0's texture coordinates (fragment/depth_image.inc).
  fragment::DepthImageState depthImage;

  // The active GL_SAMPLES_PASSED query's counter (null: none): the fragments
  // that pass every test are added to it (state/query_objects.h).
  uint64_t* samplesPassed = nullptr;
};

// The llvmpipe rows [first, last] of GL rows [y0, y1) of `fb`, cut to the buffer.
struct LlvmpipeRows {
  int64_t first = 0, last = -1;
};
inline LlvmpipeRows llvmpipeRows(const Framebuffer& fb, int64_t y0, int64_t y1) {
  const int64_t h = fb.height();
  y0 = y0 < 0 ? 0 : y0;
  y1 = y1 > h ? h : y1;
  if (fb.rowsUp()) return {y0, y1 - 1};
  return {h - y1, h - 1 - y0};
}

// Snaps the three vertices to llvmpipe's 1/256 grid (fixed_point.h) and
// returns the sign of the fixed-point area: +1 counter-clockwise in GL window
// space, -1 clockwise, 0 degenerate (llvmpipe never draws it). Culling and
// two-sided colour selection use this sign.
int snapTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, FixedTriangle& out);

// Rasterizes a triangle whose snapped area is positive, with the vertices in
// the order llvmpipe's setup sees them. `flatVaryings` non-null: the colours
// in state.flatGroups take these values at every fragment.
// `backFacing`: the triangle faces back (the stencil test's back state).
void rasterCcwTriangle(const RasterState& state, Framebuffer& fb, const FixedTriangle& fixed,
                       const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                       const float* flatVaryings, bool backFacing = false);

// Snap, then draw whichever way the triangle faces (no culling): a clockwise
// triangle is reordered as llvmpipe does (see firstVertexConvention).
// `flatVaryings` non-null means every fragment takes those values (the
// provoking vertex's colour, chosen by primitive assembly), for the colours
// in state.flatGroups (both by default).
void drawTriangle(const RasterState& state, Framebuffer& fb, const WindowVertex& v0, const WindowVertex& v1,
                  const WindowVertex& v2, const float* flatVaryings);

// Points (raster/point.cpp). The width in pixels llvmpipe gives a non-smooth point of `size`: rounded,
// .5 down, at least 1, at most 255; a NaN size is 1.
int pointWidthInPixels(float size);
// A non-smooth, non-sprite point at `v` (llvmpipe's window space) of `size`;
// `flatVaryings` as for drawTriangle.
void drawPoint(const RasterState& state, Framebuffer& fb, const WindowVertex& v, float size,
               const float* flatVaryings);
// A GL_POINT_SMOOTH point of `radius` (Mesa's draw module makes it a quad of
// two triangles with a coverage shader: raster/point.cpp).
void drawSmoothPoint(const RasterState& state, Framebuffer& fb, const WindowVertex& v, float radius,
                     const float* flatVaryings);
// How llvmpipe's line set-up draws a line (lp_setup_line.c): `width` as the
// rasterizer state has it (glLineWidth clamped to Mesa's range); aliased
// lines round it, rectangular ones (GL_LINE_SMOOTH) use it as it is.
struct LineStyle {
  float width = 1;
  bool rectangular = false;
};

// One line segment from v1 to v2 in llvmpipe's window space (raster/line.cpp).
// `flatVaryings` as for drawTriangle.
void drawLine(const RasterState& state, Framebuffer& fb, const LineStyle& style, const WindowVertex& v1,
              const WindowVertex& v2, const float* flatVaryings);

// One GL_LINE_SMOOTH line from v0 to v1 as the draw module's aaline stage
// draws it (raster/line.cpp): two triangles whose alpha carries coverage.
void drawSmoothLine(const RasterState& state, Framebuffer& fb, float width, const WindowVertex& v0,
                    const WindowVertex& v1, const float* flatVaryings);

// Float colour to 8 bits as llvmpipe's colour output does it: clamp to [0,1]
// (NaN gives 0), then rint(v * 255) in single precision.
inline uint8_t colorToUnorm8(float v) {
  v = v > 0.0f ? v : 0.0f;  // NaN -> 0
  v = v < 1.0f ? v : 1.0f;
  return static_cast<uint8_t>(roundToInt32(v * 255.0f));
}

}  // namespace glfixed::raster
