// pipeline/array_fetch: element reads, the conversions of table 2.9 as
// llvmpipe's vertex fetch does them, strides, and reads past a buffer's end.
#include "pipeline/array_fetch.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "state/context.h"

namespace glfixed::pipeline {
namespace {

ArrayView view(const void* base, GLint size, GLenum type, size_t stride, bool normalized,
               size_t limit = SIZE_MAX) {
  ArrayView v;
  v.base = static_cast<const uint8_t*>(base);
  v.size = size;
  v.type = type;
  v.stride = stride;
  v.normalized = normalized;
  v.limit = limit;
  return v;
}

TEST(ArrayFetch, SignedNormalizedIsScaledByTheLargestValueAndClamped) {
  const int8_t b[4] = {127, -127, -128, 0};
  const glm::vec4 r = view(b, 4, GL_BYTE, 4, true).read(0, glm::vec4(9));
  EXPECT_EQ(r.x, 1.0f);
  EXPECT_EQ(r.y, -1.0f);
  EXPECT_EQ(r.z, -1.0f);  // -128 clamps to -1
  EXPECT_EQ(r.w, 0.0f);
  const int16_t s[3] = {32767, -16384, 1};
  const glm::vec4 q = view(s, 3, GL_SHORT, 6, true).read(0, glm::vec4(0, 0, 0, 7));
  EXPECT_EQ(q.x, 1.0f);
  EXPECT_EQ(q.y, -16384.0f * static_cast<float>(1.0 / 32767.0));
  EXPECT_EQ(q.w, 7.0f);  // not in the array: the fill value
}

TEST(ArrayFetch, UnsignedNormalizedReachesOne) {
  const uint8_t ub[4] = {255, 0, 51, 128};
  const glm::vec4 r = view(ub, 4, GL_UNSIGNED_BYTE, 4, true).read(0, glm::vec4(0));
  EXPECT_EQ(r.x, 1.0f);
  EXPECT_EQ(r.y, 0.0f);
  EXPECT_NEAR(r.z, 0.2f, 1e-7);
  EXPECT_NEAR(r.w, 128.0f / 255.0f, 1e-7);
  const uint32_t ui[1] = {0xffffffffu};
  EXPECT_EQ(view(ui, 1, GL_UNSIGNED_INT, 4, true).read(0, glm::vec4(0)).x, 1.0f);
}

TEST(ArrayFetch, IntegersAreNotNormalizedForPositions) {
  const int32_t i[3] = {-5, 70000, 3};
  const glm::vec4 r = view(i, 3, GL_INT, 12, false).read(0, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(r, glm::vec4(-5, 70000, 3, 1));
  const double d[2] = {0.1, -2.5};
  const glm::vec4 q = view(d, 2, GL_DOUBLE, 16, false).read(0, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(q, glm::vec4(static_cast<float>(0.1), -2.5f, 0, 1));
}

TEST(ArrayFetch, StrideSelectsTheElement) {
  struct Vertex {
    float p[2];
    uint8_t pad[4];
  } v[3] = {{{1, 2}, {}}, {{3, 4}, {}}, {{5, 6}, {}}};
  const ArrayView a = view(v, 2, GL_FLOAT, sizeof(Vertex), false);
  EXPECT_EQ(a.read(2, glm::vec4(0, 0, 0, 1)), glm::vec4(5, 6, 0, 1));
}

TEST(ArrayFetch, PastTheEndOfABufferReadsZeros) {
  const float f[6] = {1, 2, 3, 4, 5, 6};
  // A buffer of 5 floats: element 0 whole, element 1 only partly inside.
  const ArrayView a = view(f, 3, GL_FLOAT, 12, false, 5 * sizeof(float));
  EXPECT_EQ(a.read(0, glm::vec4(0, 0, 0, 1)), glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(a.read(1, glm::vec4(0, 0, 0, 1)), glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(a.elementBytes(1), nullptr);
  EXPECT_EQ(a.read(4000000000u, glm::vec4(0, 0, 0, 1)), glm::vec4(0, 0, 0, 1));
}

TEST(ArrayFetch, DisabledArraysTakeTheCurrentValues) {
  Context ctx(24);
  const float pos[6] = {1, 2, 3, 4, 5, 6};
  ctx.vertexArray.vertex.enabled = true;
  ctx.vertexArray.vertex.size = 3;
  ctx.vertexArray.vertex.pointer = pos;
  ctx.current.color = glm::vec4(0.25f, 0.5f, 0.75f, 1);
  ctx.current.normal = glm::vec3(0, 1, 0);
  ArraySources src;
  ASSERT_EQ(resolveArrays(ctx, src), static_cast<GLenum>(GL_NO_ERROR));
  VertexBatch batch;
  const uint32_t idx[3] = {1, 0, 1};
  appendIndexed(src, ctx, idx, 3, batch);
  ASSERT_EQ(batch.size(), 3u);
  EXPECT_EQ(batch.position[0], glm::vec4(4, 5, 6, 1));
  EXPECT_EQ(batch.position[1], glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(batch.color[2], ctx.current.color);
  EXPECT_EQ(batch.normal[2], ctx.current.normal);
  EXPECT_EQ(batch.materialIndex[2], 0u);
}

TEST(ArrayFetch, AMappedBufferCannotBeSourced) {
  Context ctx(24);
  GLuint name;
  ctx.buffers.generate(1, &name);
  BufferObject* b = ctx.buffers.bind(name);
  b->data.resize(64);
  b->mapped = true;
  ctx.vertexArray.vertex.enabled = true;
  ctx.vertexArray.vertex.bufferBinding = name;
  ArraySources src;
  EXPECT_EQ(resolveArrays(ctx, src), static_cast<GLenum>(GL_INVALID_OPERATION));
  b->mapped = false;
  EXPECT_EQ(resolveArrays(ctx, src), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(src.vertexView.limit, 64u);
}

}  // namespace
}  // namespace glfixed::pipeline
