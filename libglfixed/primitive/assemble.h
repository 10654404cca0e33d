// Primitive assembly: which triangles a GL_<mode> batch makes, with their
// vertices in the order llvmpipe hands them to its triangle setup. The order
// matters: it decides the provoking vertex, the split of a quad (visible under
// smooth shading) and the float rounding of every interpolated value.
//
// llvmpipe always takes the flat colour from the triangle's LAST vertex, or its
// FIRST under glProvokingVertex(GL_FIRST_VERTEX_CONVENTION), so each triple is
// ordered to put the provoking vertex there (provokingSlot()).
//
// Mesa decomposes in one of three places, which disagree about quads:
//   kLinear:   non-indexed draws (glBegin/glEnd, glDrawArrays) that need no
//              clipping: llvmpipe's lp_setup_vbuf.c, lp_setup_draw_arrays;
//   kIndexed:  indexed draws (glDrawElements, display lists) that need no
//              clipping: lp_setup_vbuf.c, lp_setup_draw_elements;
//   kPipeline: any draw with a vertex outside the view volume: the draw
//              module's pipeline (draw_decompose_tmp.h), which then clips.
// Quads (v0,v1,v2,v3), last-vertex convention:
//   kLinear, smooth:               (v0,v1,v2) (v0,v2,v3)
//   kLinear flat, kIndexed, kPipeline: (v0,v1,v3) (v1,v2,v3)
//   first-vertex convention, all:  (v3,v0,v1) (v3,v1,v2)  (quads ignore it)
// A 4-vertex smooth GL_TRIANGLE_FAN on the linear path is (v0,v1,v2)
// (v0,v2,v3) under either convention.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <vector>

namespace glfixed::primitive {

enum class DecomposePath { kLinear, kIndexed, kPipeline };

using Triangle = std::array<uint32_t, 3>;

// Appends the triangles of `count` vertices drawn as `mode` to `out`
// (cleared first). Points and lines give none. `flat`: GL_FLAT shading
// (llvmpipe's "constant interpolation" changes the linear quad split).
void assembleTriangles(GLenum mode, uint32_t count, bool firstVertexConvention, bool flat, DecomposePath path,
                       std::vector<Triangle>& out);

// The vertices a batch really uses: Mesa's draw module trims an incomplete
// last primitive before running the vertex shader (draw_pt_util.c), so a
// dropped vertex never counts as "outside the view volume".
uint32_t trimVertexCount(GLenum mode, uint32_t count);

// Mesa's draw module runs a long non-indexed primitive in segments
// (draw_pt_vsplit.c, draw_split_tmp.h), and decides per segment whether to
// run its pipeline. Triangles, strips, quads and quad strips: at most 4096
// vertices a segment, strips overlapping by 2 vertices and keeping an even
// number of triangles a segment. Fans and polygons of more than 4096: at most
// 1024 a segment, and every segment after the first is drawn indexed, with
// its first vertex replaced by vertex 0 (the hub); up to 4096 they are one
// segment (scene indexed_modes). An indexed draw is split the same way with at most
// 1024 indices a segment for every mode (vsplit's segment size), unless it
// is drawn whole (pipeline/array_draw.cpp).
constexpr uint32_t kMaxSimpleSegment = 4096;
constexpr uint32_t kMaxFanSegment = 1024;
constexpr uint32_t kMaxIndexedSegment = 1024;
struct Segment {
  uint32_t start = 0, count = 0;
  bool hubReplaced = false;  // vertex list (0, start+1, ..., start+count-1), indexed
};
// `maxSimple`: the segment limit of the modes that are not fans or polygons.
void splitIntoSegments(GLenum mode, uint32_t count, std::vector<Segment>& out,
                       uint32_t maxSimple = kMaxSimpleSegment);

// The slot of each triple that holds the provoking vertex.
inline int provokingSlot(bool firstVertexConvention) { return firstVertexConvention ? 0 : 2; }

}  // namespace glfixed::primitive
