// How a display list's vertex node merges its glBegin/glEnd primitives into
// draws, by Mesa 22.3's rules (vbo_save_api.c merge_prims and the index
// buffer of compile_vertex_list). The pixel consequences are checked against
// Mesa by the list_* reference scenes; lines and points, which draw no pixels
// yet, only here.
#include <gtest/gtest.h>

#include "pipeline/display_list.h"

namespace glfixed::pipeline {
namespace {

ListPrimitive prim(GLenum mode, uint32_t first, uint32_t count) {
  ListPrimitive p;
  p.mode = mode;
  p.first = first;
  p.count = count;
  p.end = true;
  return p;
}

TEST(DisplayListMerge, QuadsAndTrianglesMergeAsInImmediateMode) {
  const auto merged =
      mergeLikeImmediateMode({prim(GL_QUADS, 0, 4), prim(GL_QUADS, 4, 4), prim(GL_TRIANGLES, 8, 3)});
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].count, 8u);
  EXPECT_EQ(merged[1].mode, static_cast<GLenum>(GL_TRIANGLES));
}

TEST(DisplayListMerge, FirstPrimitiveIsNotConverted) {
  const auto merged = mergeLikeImmediateMode({prim(GL_TRIANGLE_FAN, 0, 3), prim(GL_TRIANGLE_FAN, 3, 3)});
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].mode, static_cast<GLenum>(GL_TRIANGLE_FAN));  // kept
  EXPECT_EQ(merged[1].mode, static_cast<GLenum>(GL_TRIANGLES));     // converted
  // ... and a fan after triangles joins them.
  const auto joined = mergeLikeImmediateMode({prim(GL_TRIANGLES, 0, 3), prim(GL_TRIANGLE_FAN, 3, 3)});
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].count, 6u);
}

TEST(DisplayListMerge, TriangleStripsJoinWithDegenerateTriangles) {
  // 4 + 5 vertices: 2 triangles, even, so two joining indices.
  auto draws = mergeIntoDraws({prim(GL_TRIANGLE_STRIP, 0, 4), prim(GL_TRIANGLE_STRIP, 4, 5)});
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 3, 4, 4, 5, 6, 7, 8}));
  // 5 + 4: 3 triangles, odd, so one more index keeps the winding.
  draws = mergeIntoDraws({prim(GL_TRIANGLE_STRIP, 0, 5), prim(GL_TRIANGLE_STRIP, 5, 4)});
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 4, 5, 5, 5, 6, 7, 8}));
}

TEST(DisplayListMerge, FansQuadStripsPolygonsAndLoopsNeverJoin) {
  for (GLenum mode : {GL_TRIANGLE_FAN, GL_QUAD_STRIP, GL_POLYGON, GL_LINE_LOOP}) {
    const auto draws = mergeIntoDraws({prim(mode, 0, 4), prim(mode, 4, 4)});
    EXPECT_EQ(draws.size(), 2u) << mode;
  }
}

TEST(DisplayListMerge, LineStripsBecomeLinesWhenTheyJoin) {
  const auto draws = mergeIntoDraws({prim(GL_LINE_STRIP, 0, 3), prim(GL_LINE_STRIP, 3, 2)});
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].mode, static_cast<GLenum>(GL_LINES));
  EXPECT_EQ(draws[0].indices, (std::vector<uint32_t>{0, 1, 1, 2, 3, 4}));
  // A lone line strip stays one.
  const auto alone = mergeIntoDraws({prim(GL_LINE_STRIP, 0, 3), prim(GL_QUADS, 3, 4)});
  ASSERT_EQ(alone.size(), 2u);
  EXPECT_EQ(alone[0].mode, static_cast<GLenum>(GL_LINE_STRIP));
}

TEST(DisplayListMerge, ShortPrimitivesArePaddedWithTheirLastVertex) {
  const auto draws = mergeIntoDraws({prim(GL_TRIANGLES, 0, 2)});
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].indices, (std::vector<uint32_t>{0, 1, 1}));
}

TEST(DisplayListMerge, EmptyPrimitivesAreDropped) {
  EXPECT_TRUE(mergeIntoDraws({prim(GL_QUADS, 0, 0)}).empty());
}

}  // namespace
}  // namespace glfixed::pipeline
