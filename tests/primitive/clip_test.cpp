// Clipping in homogeneous space, one plane at a time.
#include "primitive/clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "primitive/viewport.h"

namespace glfixed::primitive {
namespace {

ClipVertex vertex(float x, float y, float z, float w, float attr = 0) {
  ClipVertex v;
  v.clip = glm::vec4(x, y, z, w);
  v.attr[0] = attr;
  return v;
}

const ViewportTransform kViewport = ViewportTransform::make(0, 0, 100, 100, 0, 1, 100);

TEST(ClipMask, OneBitPerPlane) {
  EXPECT_EQ(clipMask({0, 0, 0, 1}), 0u);
  EXPECT_EQ(clipMask({2, 0, 0, 1}), 1u << 0);   // x > w
  EXPECT_EQ(clipMask({-2, 0, 0, 1}), 1u << 1);  // x < -w
  EXPECT_EQ(clipMask({0, 2, 0, 1}), 1u << 2);
  EXPECT_EQ(clipMask({0, -2, 0, 1}), 1u << 3);
  EXPECT_EQ(clipMask({0, 0, -2, 1}), 1u << 4);  // near
  EXPECT_EQ(clipMask({0, 0, 2, 1}), 1u << 5);   // far
  EXPECT_EQ(clipMask({1, 1, 1, 1}), 0u);        // on the planes is inside
}

TEST(ClipMask, BehindTheEyeIsOutside) {
  EXPECT_NE(clipMask({0, 0, 0, -1}), 0u);
  EXPECT_NE(clipMask({0.5f, 0.5f, 0.5f, -0.1f}), 0u);
  EXPECT_EQ(clipMask({0, 0, 0, 0}), 0u);  // the one point no plane rejects
}

TEST(ClipMask, NanIsOutsideEveryPlaneItTakesPartIn) {
  EXPECT_EQ(clipMask({NAN, 0, 0, 1}), 0x3u);  // unordered comparisons: outside both x planes
  EXPECT_EQ(clipMask({0, 0, 0, NAN}), 0x3fu);
}

TEST(ClipDistance, OneFunctionPerPlane) {
  const glm::vec4 c(0.25f, -0.5f, 0.75f, 2.0f);
  EXPECT_EQ(distanceToRight(c), 1.75f);
  EXPECT_EQ(distanceToLeft(c), 2.25f);
  EXPECT_EQ(distanceToTop(c), 2.5f);
  EXPECT_EQ(distanceToBottom(c), 1.5f);
  EXPECT_EQ(distanceToNear(c), 2.75f);
  EXPECT_EQ(distanceToFar(c), 1.25f);
  for (int p = 0; p < 6; ++p) EXPECT_GE(distanceToPlane(p, c), 0.0f);
  EXPECT_TRUE(std::isnan(distanceToLeft({0, INFINITY, 0, 1})));  // inf * 0
}

// Clips against one plane; checks every output vertex is inside it and the
// attribute is the same linear function of the clip position as before.
void checkPlane(int plane) {
  std::mt19937 rng(plane + 1);
  std::uniform_real_distribution<float> u(-3, 3);
  for (int iter = 0; iter < 200; ++iter) {
    ClipVertex v[3];
    for (auto& x : v) {
      x = vertex(u(rng), u(rng), u(rng), std::fabs(u(rng)) + 0.5f);
      x.attr[0] = 0.5f * x.clip.x + 0.25f * x.clip.y - x.clip.z + 2 * x.clip.w;  // linear in clip space
    }
    ClippedPolygon poly;
    const bool any = clipTriangle(v[0], v[1], v[2], 1u << plane, 1, kViewport, poly);
    int outside = 0;
    for (auto& x : v) outside += distanceToPlane(plane, x.clip) < 0;
    if (outside == 3) {
      EXPECT_FALSE(any);
      continue;
    }
    ASSERT_TRUE(any);
    EXPECT_EQ(poly.count, outside == 0 ? 3 : (outside == 1 ? 4 : 3));
    for (int i = 0; i < poly.count; ++i) {
      const ClipVertex& c = *poly.vertex[i];
      EXPECT_GE(distanceToPlane(plane, c.clip), -1e-5f * std::fabs(c.clip.w) - 1e-5f);
      const float expected = 0.5f * c.clip.x + 0.25f * c.clip.y - c.clip.z + 2 * c.clip.w;
      EXPECT_NEAR(c.attr[0], expected, 1e-4f * (1 + std::fabs(expected)));
    }
  }
}

TEST(ClipTriangle, RightPlane) { checkPlane(0); }
TEST(ClipTriangle, LeftPlane) { checkPlane(1); }
TEST(ClipTriangle, TopPlane) { checkPlane(2); }
TEST(ClipTriangle, BottomPlane) { checkPlane(3); }
TEST(ClipTriangle, NearPlane) { checkPlane(4); }
TEST(ClipTriangle, FarPlane) { checkPlane(5); }

TEST(ClipTriangle, KeepsVertexOrderAndStartsAtTheFirstInsideVertex) {
  // v0 inside, v1 outside x > w, v2 inside: (v0, i01, i12, v2).
  ClipVertex v0 = vertex(0, 0, 0, 1), v1 = vertex(3, 0, 0, 1), v2 = vertex(0, 1, 0, 1);
  ClippedPolygon poly;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, 1u, 0, kViewport, poly));
  ASSERT_EQ(poly.count, 4);
  EXPECT_EQ(poly.vertex[0], &v0);
  EXPECT_FLOAT_EQ(poly.vertex[1]->clip.x, 1.0f);
  EXPECT_FLOAT_EQ(poly.vertex[1]->clip.y, 0.0f);
  EXPECT_FLOAT_EQ(poly.vertex[2]->clip.x, 1.0f);
  EXPECT_EQ(poly.vertex[3], &v2);
  // New vertices get window coordinates: x = w edge maps to the right edge.
  EXPECT_FLOAT_EQ(poly.vertex[1]->window[0], 100.0f);
}

TEST(ClipTriangle, GeometryBehindTheEye) {
  // A triangle with one vertex behind the eye (w < 0) is cut by the near
  // plane z = -w; what is left lies in front.
  ClipVertex v0 = vertex(0, 0, 0.5f, 1), v1 = vertex(0.5f, 0, 0.5f, 1), v2 = vertex(0, 0.5f, 2, -1);
  ClippedPolygon poly;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, clipMask(v0.clip) | clipMask(v1.clip) | clipMask(v2.clip), 0,
                           kViewport, poly));
  for (int i = 0; i < poly.count; ++i) {
    EXPECT_GT(poly.vertex[i]->clip.w, 0.0f);
    for (int p = 0; p < 6; ++p) EXPECT_GE(distanceToPlane(p, poly.vertex[i]->clip), -1e-6f) << i << " " << p;
  }
}

TEST(ClipTriangle, NanDropsTheTriangle) {
  ClipVertex v0 = vertex(0, 0, 0, 1), v1 = vertex(NAN, 0, 0, 1), v2 = vertex(0, 1, 0, 1);
  ClippedPolygon poly;
  EXPECT_FALSE(clipTriangle(v0, v1, v2, 0x3fu, 0, kViewport, poly));
}

TEST(ClipTriangle, AllPlanesAtOnce) {
  // A big triangle around the whole view volume: clipped to its square.
  ClipVertex v0 = vertex(-10, -10, 0, 1), v1 = vertex(10, -10, 0, 1), v2 = vertex(0, 10, 0, 1);
  ClippedPolygon poly;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, 0xfu, 0, kViewport, poly));
  EXPECT_GE(poly.count, 4);
  for (int i = 0; i < poly.count; ++i) {
    EXPECT_LE(std::fabs(poly.vertex[i]->clip.x), 1.0f + 1e-6f);
    EXPECT_LE(std::fabs(poly.vertex[i]->clip.y), 1.0f + 1e-6f);
  }
}

}  // namespace
// ---- user clip planes (planes 6..13) ----

UserClipPlanes planes(std::initializer_list<std::pair<int, glm::vec4>> list) {
  UserClipPlanes u;
  for (const auto& p : list) {
    u.enabled |= 1u << p.first;
    u.plane[p.first] = p.second;
  }
  return u;
}

TEST(UserClipPlanes, MaskBitsFollowTheFrustumBits) {
  const UserClipPlanes u = planes({{0, {1, 0, 0, 0}}, {5, {0, 1, 0, 0}}, {7, {0, 0, 0, -1}}});
  EXPECT_EQ(clipMask({0.5f, 0.5f, 0, 1}, u), 1u << 13);  // plane 7 keeps nothing with w > 0
  EXPECT_EQ(clipMask({-0.5f, 0.5f, 0, 1}, u), (1u << 6) | (1u << 13));
  EXPECT_EQ(clipMask({-0.5f, -0.5f, 0, 1}, u), (1u << 6) | (1u << 11) | (1u << 13));
  EXPECT_EQ(clipMask({2, 0.5f, 0, 1}, u), 1u | (1u << 13));
  EXPECT_EQ(clipMask({0, 0, 0, 1}, kNoUserClipPlanes), 0u);
  // A distance of exactly 0 is inside.
  EXPECT_EQ(clipMask({0, 0, 0, 0}, planes({{2, {1, 1, 1, 1}}})), 0u);
}

TEST(UserClipPlanes, NanIsOutside) {
  const UserClipPlanes u = planes({{3, {NAN, 0, 0, 0}}});
  EXPECT_EQ(clipMask({0, 0, 0, 1}, u), 1u << 9);
  EXPECT_TRUE(std::isnan(distanceToPlane(9, {0, 0, 0, 1}, u)));
}

// The mask's distance is llvmpipe's fused chain, the clipper's the unfused C
// dot product: here they differ in sign (probed on Mesa, scene
// clip_user_planes_all).
TEST(UserClipPlanes, MaskIsFusedClipperIsNot) {
  const float cz = 0.5f + std::ldexp(1.0f, -13) + std::ldexp(1.0f, -24);
  const float pz = 1.0f + std::ldexp(1.0f, -12);
  const float q = -(1.0f + std::ldexp(1.0f, -11) + std::ldexp(1.0f, -22)) / 2;
  const UserClipPlanes u = planes({{0, {2 * q, 0, pz, 0}}});
  const glm::vec4 c(0.5f, -0.5f, cz, 1);
  EXPECT_EQ(clipMask(c, u), 1u << 6);
  EXPECT_EQ(distanceToPlane(6, c, u), 0.0f);
}

TEST(UserClipPlanes, TriangleIsCutAfterTheFrustum) {
  const UserClipPlanes u = planes({{1, {-1, 0, 0, 0.25f}}});  // x <= 0.25
  ClipVertex v0 = vertex(-3, -0.5f, 0, 1, 0), v1 = vertex(0.75f, -0.5f, 0, 1, 1), v2 = vertex(0, 0.5f, 0, 1, 2);
  const uint32_t m = clipMask(v0.clip, u) | clipMask(v1.clip, u) | clipMask(v2.clip, u);
  EXPECT_EQ(m, (1u << 1) | (1u << 7));
  ClippedPolygon poly;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, m, 1, kViewport, poly, u));
  ASSERT_GE(poly.count, 4);
  for (int i = 0; i < poly.count; ++i) {
    EXPECT_GE(poly.vertex[i]->clip.x, -1.0f - 1e-6f) << i;
    EXPECT_LE(poly.vertex[i]->clip.x, 0.25f + 1e-6f) << i;
  }
  // Without the planes the same mask bits would read no user plane.
  EXPECT_EQ(distanceToPlane(7, v1.clip, kNoUserClipPlanes), 0.0f);
}

// Mesa's _mesa_transform_vector: the row vector times the matrix.
TEST(UserClipPlanes, TransformPlaneIsARowVectorProduct) {
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(1, 2, 3, 1);  // a translation
  EXPECT_EQ(transformPlane({1, 0, 0, 0}, m), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(transformPlane({0, 1, 1, 0}, m), glm::vec4(0, 1, 1, 5));
}

}  // namespace glfixed::primitive
