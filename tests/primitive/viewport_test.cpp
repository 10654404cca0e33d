#include "primitive/viewport.h"

#include <gtest/gtest.h>

namespace glfixed::primitive {
namespace {

TEST(Viewport, ScaleAndTranslateWithYFlipped) {
  ViewportTransform v = ViewportTransform::make(10, 20, 200, 100, 0.25, 0.75, 300);
  EXPECT_EQ(v.scale[0], 100.0f);
  EXPECT_EQ(v.translate[0], 110.0f);
  EXPECT_EQ(v.scale[1], -50.0f);
  EXPECT_EQ(v.translate[1], 300.0f - 70.0f);  // y measured down from the top
  EXPECT_EQ(v.scale[2], 0.25f);
  EXPECT_EQ(v.translate[2], 0.5f);
}

TEST(Viewport, MapsTheNdcCube) {
  ViewportTransform v = ViewportTransform::make(0, 0, 64, 32, 0, 1, 32);
  float w[4];
  v.windowFromClip({-2, -2, -2, 2}, w);  // NDC (-1, -1, -1): bottom left, near
  EXPECT_EQ(w[0], 0.0f);
  EXPECT_EQ(w[1], 32.0f);  // the bottom row is y = 32 from the top
  EXPECT_EQ(w[2], 0.0f);
  EXPECT_EQ(w[3], 0.5f);
  v.windowFromClipUnfused({1, 1, 1, 1}, w);
  EXPECT_EQ(w[0], 64.0f);
  EXPECT_EQ(w[1], 0.0f);
  EXPECT_EQ(w[2], 1.0f);
}

TEST(Viewport, DepthRangeIsClampedAndMayBeReversed) {
  ViewportTransform v = ViewportTransform::make(0, 0, 4, 4, 1.5, -2, 4);
  float w[4];
  v.windowFromClip({0, 0, -1, 1}, w);
  EXPECT_EQ(w[2], 1.0f);
  v.windowFromClip({0, 0, 1, 1}, w);
  EXPECT_EQ(w[2], 0.0f);
}

TEST(Viewport, FusedAndUnfusedDifferOnlyInRounding) {
  ViewportTransform v = ViewportTransform::make(0, 0, 37, 29, 0, 1, 29);
  float a[4], b[4];
  v.windowFromClip({0.123f, -0.456f, 0.789f, 1.3f}, a);
  v.windowFromClipUnfused({0.123f, -0.456f, 0.789f, 1.3f}, b);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], 1e-5f);
}

}  // namespace
}  // namespace glfixed::primitive
