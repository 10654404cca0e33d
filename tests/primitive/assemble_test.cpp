// Primitive assembly: llvmpipe's triangle order, splits and provoking vertices.
#include "primitive/assemble.h"

#include <gtest/gtest.h>

namespace glfixed::primitive {
namespace {

std::vector<Triangle> assemble(GLenum mode, uint32_t n, bool first, bool flat = false,
                               DecomposePath path = DecomposePath::kLinear) {
  std::vector<Triangle> t;
  assembleTriangles(mode, n, first, flat, path, t);
  return t;
}

using Tris = std::vector<Triangle>;

TEST(Assemble, Triangles) {
  EXPECT_EQ(assemble(GL_TRIANGLES, 6, false), (Tris{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(assemble(GL_TRIANGLES, 7, false).size(), 2u);  // incomplete last triangle dropped
}

TEST(Assemble, TriangleStripKeepsWindingAndProvokingVertex) {
  // Last-vertex convention: triangle i ends with vertex i+2.
  EXPECT_EQ(assemble(GL_TRIANGLE_STRIP, 5, false), (Tris{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}}));
  // First-vertex convention: triangle i starts with vertex i.
  EXPECT_EQ(assemble(GL_TRIANGLE_STRIP, 5, true), (Tris{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}}));
}

TEST(Assemble, TriangleFan) {
  EXPECT_EQ(assemble(GL_TRIANGLE_FAN, 5, false), (Tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  EXPECT_EQ(assemble(GL_TRIANGLE_FAN, 5, true), (Tris{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}));
  // A smooth 4-vertex fan on the linear path ignores the convention.
  EXPECT_EQ(assemble(GL_TRIANGLE_FAN, 4, true), (Tris{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(assemble(GL_TRIANGLE_FAN, 4, true, true), (Tris{{1, 2, 0}, {2, 3, 0}}));
  EXPECT_EQ(assemble(GL_TRIANGLE_FAN, 4, true, false, DecomposePath::kPipeline),
            (Tris{{1, 2, 0}, {2, 3, 0}}));
}

TEST(Assemble, PolygonIsAFanProvokedByVertexZero) {
  const Tris last = assemble(GL_POLYGON, 5, false);
  EXPECT_EQ(last, (Tris{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}));
  for (const Triangle& t : last) EXPECT_EQ(t[provokingSlot(false)], 0u);
  const Tris first = assemble(GL_POLYGON, 5, true);
  EXPECT_EQ(first, (Tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  for (const Triangle& t : first) EXPECT_EQ(t[provokingSlot(true)], 0u);
}

TEST(Assemble, QuadSplitsDependOnPathAndShading) {
  // Smooth, non-indexed, unclipped: (v0,v1,v2) (v0,v2,v3) (measured).
  EXPECT_EQ(assemble(GL_QUADS, 8, false), (Tris{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}));
  // Flat, indexed or clipped: (v0,v1,v3) (v1,v2,v3).
  const Tris other{{0, 1, 3}, {1, 2, 3}};
  EXPECT_EQ(assemble(GL_QUADS, 4, false, true), other);
  EXPECT_EQ(assemble(GL_QUADS, 4, false, false, DecomposePath::kIndexed), other);
  EXPECT_EQ(assemble(GL_QUADS, 4, false, false, DecomposePath::kPipeline), other);
  // First-vertex convention is ignored by quads: vertex 3 still provokes.
  for (DecomposePath p : {DecomposePath::kLinear, DecomposePath::kIndexed, DecomposePath::kPipeline}) {
    const Tris f = assemble(GL_QUADS, 4, true, false, p);
    EXPECT_EQ(f, (Tris{{3, 0, 1}, {3, 1, 2}}));
    for (const Triangle& t : f) EXPECT_EQ(t[provokingSlot(true)], 3u);
  }
  for (const Triangle& t : other) EXPECT_EQ(t[provokingSlot(false)], 3u);
}

TEST(Assemble, QuadStrip) {
  // Quad k is (2k, 2k+1, 2k+3, 2k+2); vertex 2k+3 provokes either way.
  const Tris last = assemble(GL_QUAD_STRIP, 6, false);
  EXPECT_EQ(last, (Tris{{0, 1, 3}, {2, 0, 3}, {2, 3, 5}, {4, 2, 5}}));
  const Tris first = assemble(GL_QUAD_STRIP, 6, true);
  EXPECT_EQ(first, (Tris{{3, 0, 1}, {3, 2, 0}, {5, 2, 3}, {5, 4, 2}}));
  for (const Triangle& t : first) EXPECT_EQ(t[provokingSlot(true)] % 2, 1u);
  // The pipeline emits the halves in the other order.
  EXPECT_EQ(assemble(GL_QUAD_STRIP, 4, false, false, DecomposePath::kPipeline), (Tris{{2, 0, 3}, {0, 1, 3}}));
  EXPECT_EQ(assemble(GL_QUAD_STRIP, 5, false).size(), 2u);  // odd vertex dropped
}

TEST(Assemble, PointsAndLinesMakeNoTriangles) {
  EXPECT_TRUE(assemble(GL_POINTS, 9, false).empty());
  EXPECT_TRUE(assemble(GL_LINES, 9, false).empty());
  EXPECT_TRUE(assemble(GL_LINE_LOOP, 9, false).empty());
}

TEST(Assemble, TrimsIncompletePrimitives) {
  EXPECT_EQ(trimVertexCount(GL_TRIANGLES, 8), 6u);
  EXPECT_EQ(trimVertexCount(GL_TRIANGLES, 2), 0u);
  EXPECT_EQ(trimVertexCount(GL_QUADS, 7), 4u);
  EXPECT_EQ(trimVertexCount(GL_QUAD_STRIP, 7), 6u);
  EXPECT_EQ(trimVertexCount(GL_QUAD_STRIP, 3), 0u);
  EXPECT_EQ(trimVertexCount(GL_TRIANGLE_STRIP, 7), 7u);
  EXPECT_EQ(trimVertexCount(GL_POLYGON, 2), 0u);
}

TEST(Segments, ShortPrimitivesAreOneSegment) {
  std::vector<Segment> s;
  splitIntoSegments(GL_QUADS, 4096, s);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].count, 4096u);
}

TEST(Segments, LongPrimitivesSplitLikeTheDrawModule) {
  std::vector<Segment> s;
  splitIntoSegments(GL_QUADS, 8400, s);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].start, 0u);
  EXPECT_EQ(s[1].start, 4096u);
  EXPECT_EQ(s[2].start, 8192u);
  EXPECT_EQ(s[2].count, 208u);
  // Strips overlap by two vertices and keep an even number of triangles.
  splitIntoSegments(GL_TRIANGLE_STRIP, 5001, s);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].count, 4096u);  // 4094 triangles
  EXPECT_EQ(s[1].start, 4094u);
  EXPECT_EQ(s[1].count, 907u);
  // Fans up to 4096 vertices are one segment (scene indexed_modes); longer
  // ones 1024 at a time, later segments swapping their first vertex for the hub.
  splitIntoSegments(GL_TRIANGLE_FAN, 4096, s);
  ASSERT_EQ(s.size(), 1u);
  splitIntoSegments(GL_TRIANGLE_FAN, 5000, s);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_TRUE(s[4].hubReplaced);
  EXPECT_EQ(s[4].start, 4088u);
  EXPECT_EQ(s[4].start + s[4].count, 5000u);
  // Indexed draws: 1024 indices a segment for every mode.
  splitIntoSegments(GL_TRIANGLES, 2000, s, kMaxIndexedSegment);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].start, 1023u);
  splitIntoSegments(GL_TRIANGLE_FAN, 2500, s, kMaxIndexedSegment);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_FALSE(s[0].hubReplaced);
  EXPECT_TRUE(s[1].hubReplaced);
  EXPECT_EQ(s[1].start, 1022u);
  EXPECT_EQ(s[2].start, 2044u);
  EXPECT_EQ(s[2].start + s[2].count, 2500u);
}

}  // namespace
}  // namespace glfixed::primitive
