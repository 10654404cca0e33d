// pipeline/array_draw: reading index lists where they lie, and the index
// bounds Mesa knows for a draw (which decide how it is split: scenes
// indexed_triangles, indexed_modes).
#include "pipeline/array_draw.h"

#include <gtest/gtest.h>

#include <cstring>

#include "state/context.h"

namespace glfixed::pipeline {
namespace {

IndexList list(const void* data, GLenum type, uint32_t count) {
  IndexList l;
  l.data = static_cast<const uint8_t*>(data);
  l.type = type;
  l.count = count;
  return l;
}

TEST(IndexList, ReadsEachIndexType) {
  const uint8_t b[3] = {7, 255, 0};
  const uint16_t s[3] = {65535, 1, 300};
  const uint32_t i[3] = {0xffffffffu, 70000, 2};
  EXPECT_EQ(list(b, GL_UNSIGNED_BYTE, 3).at(1), 255u);
  EXPECT_EQ(list(s, GL_UNSIGNED_SHORT, 3).at(0), 65535u);
  EXPECT_EQ(list(s, GL_UNSIGNED_SHORT, 3).at(2), 300u);
  EXPECT_EQ(list(i, GL_UNSIGNED_INT, 3).at(0), 0xffffffffu);
  EXPECT_EQ(list(i, GL_UNSIGNED_INT, 3).at(1), 70000u);
}

ArraySources positions(size_t limit) {
  static const float p[8] = {};
  ArraySources src;
  src.vertex = true;
  src.vertexView.base = reinterpret_cast<const uint8_t*>(p);
  src.vertexView.size = 2;
  src.vertexView.stride = 8;
  src.vertexView.limit = limit;
  return src;
}

TEST(ElementBounds, ComputedOverEveryListWhenAnArrayIsInClientMemory) {
  Context ctx(24);
  const uint32_t a[3] = {5, 9, 6}, b[2] = {2, 4};
  const IndexList lists[2] = {list(a, GL_UNSIGNED_INT, 3), list(b, GL_UNSIGNED_INT, 2)};
  const IndexBounds bounds = elementBounds(ctx, positions(SIZE_MAX), lists, 2);
  ASSERT_TRUE(bounds.valid);
  EXPECT_EQ(bounds.min, 2u);
  EXPECT_EQ(bounds.max, 9u);
}

TEST(ElementBounds, UnknownWhenTheArraysAreInBufferObjects) {
  Context ctx(24);
  const uint32_t a[3] = {5, 9, 6};
  const IndexList l = list(a, GL_UNSIGNED_INT, 3);
  EXPECT_FALSE(elementBounds(ctx, positions(64), &l, 1).valid);
  // A client colour array counts only when the vertex shader reads it.
  ArraySources src = positions(64);
  src.color = true;
  src.colorView = src.vertexView;
  src.colorView.limit = SIZE_MAX;
  EXPECT_TRUE(elementBounds(ctx, src, &l, 1).valid);
  ctx.lighting.lighting = true;
  EXPECT_FALSE(elementBounds(ctx, src, &l, 1).valid);
}

TEST(ElementBounds, UnknownForAnEmptyList) {
  Context ctx(24);
  const IndexList l = list(nullptr, GL_UNSIGNED_INT, 0);
  EXPECT_FALSE(elementBounds(ctx, positions(SIZE_MAX), &l, 1).valid);
}

}  // namespace
}  // namespace glfixed::pipeline
