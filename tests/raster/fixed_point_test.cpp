#include "raster/fixed_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace glfixed::raster {
namespace {

TEST(FixedPoint, PixelCentresLandOnTheIntegerGrid) {
  EXPECT_EQ(snapToFixed(0.5f), 0);
  EXPECT_EQ(snapToFixed(1.5f), 256);
  EXPECT_EQ(snapToFixed(10.5f), 10 * 256);
  EXPECT_EQ(snapToFixed(0.0f), -128);
  EXPECT_EQ(snapToFixed(-3.5f), -4 * 256);
}

TEST(FixedPoint, RoundsToNearestEvenAt1Over512) {
  // (x - 0.5) * 256 = 0.5 exactly: ties to even, 0.
  EXPECT_EQ(snapToFixed(0.5f + 1.0f / 512), 0);
  // 1.5 -> 2, 2.5 -> 2, -0.5 -> 0, -1.5 -> -2.
  EXPECT_EQ(snapToFixed(0.5f + 3.0f / 512), 2);
  EXPECT_EQ(snapToFixed(0.5f + 5.0f / 512), 2);
  EXPECT_EQ(snapToFixed(0.5f - 1.0f / 512), 0);
  EXPECT_EQ(snapToFixed(0.5f - 3.0f / 512), -2);
  // Just off a tie rounds to the nearer value.
  EXPECT_EQ(snapToFixed(std::nextafter(0.5f + 1.0f / 512, 1.0f)), 1);
}

TEST(FixedPoint, SubtractsTheHalfPixelInSinglePrecision) {
  // x = 2^-9 + 2^-27. Exactly, (x - 0.5) * 256 = -127.5 + 2^-19, which rounds
  // to -127. llvmpipe subtracts in float first: x - 0.5f loses the 2^-27 (a
  // quarter ulp of the result), leaving a tie at -127.5, which goes to -128.
  const float x = std::ldexp(1.0f, -9) + std::ldexp(1.0f, -27);
  EXPECT_EQ(snapToFixed(x), -128);
}

TEST(FixedPoint, NanAndHugeValuesGiveIntegerIndefinite) {
  EXPECT_EQ(snapToFixed(std::numeric_limits<float>::quiet_NaN()), INT32_MIN);
  EXPECT_EQ(snapToFixed(1e30f), INT32_MIN);
  EXPECT_EQ(snapToFixed(-1e30f), INT32_MIN);
}

}  // namespace
}  // namespace glfixed::raster
