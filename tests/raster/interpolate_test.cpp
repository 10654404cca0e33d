// Attribute planes and per-fragment colour (REFERENCE.md, "Colour").
#include "raster/interpolate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "raster/raster.h"
#include "raster/test_surface.h"

namespace glfixed::raster {
namespace {

using test::TestSurface;

TEST(Planes, ConstantAttributeStaysExact) {
  PlaneSetup ps(1.25f, 3.5f, 17.0f, 2.0f, 9.75f, 30.5f);
  Plane p = ps.plane(0.3f, 0.3f, 0.3f);
  EXPECT_EQ(p.dadx, 0.0f);
  EXPECT_EQ(p.dady, 0.0f);
  EXPECT_EQ(p.at(5, 9), 0.3f);
}

TEST(Planes, ReproducesVertexValuesAtTheirPositions) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 64);
  for (int i = 0; i < 100; ++i) {
    float x[3], y[3], a[3];
    for (int k = 0; k < 3; ++k) x[k] = u(rng), y[k] = u(rng), a[k] = u(rng) / 64;
    PlaneSetup ps(x[0], y[0], x[1], y[1], x[2], y[2]);
    Plane p = ps.plane(a[0], a[1], a[2]);
    // pixel (px, py) samples (px + 0.5, py + 0.5)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.at(x[k] - 0.5f, y[k] - 0.5f), a[k], 2e-3);
  }
}

TEST(Planes, SetupIsNotContracted) {
  // Computed step by step with every product rounded; a build that fuses
  // a * b - c * d into an FMA gets other bits for this triangle.
  PlaneSetup ps(0.1f, 0.7f, 13.3f, 2.9f, 5.3f, 11.1f);
  volatile float dx01 = 0.1f - 13.3f, dy01 = 0.7f - 2.9f, dx20 = 5.3f - 0.1f, dy20 = 11.1f - 0.7f;
  volatile float e = dx01 * dy20, f = dy01 * dx20;
  volatile float ooa = 1.0f / (e - f);
  volatile float dy20o = dy20 * ooa, dy01o = dy01 * ooa;
  volatile float da01 = 0.3f - 0.9f, da20 = 0.55f - 0.3f;
  volatile float t1 = da01 * dy20o, t2 = da20 * dy01o;
  volatile float dadx = t1 - t2;
  EXPECT_EQ(ps.plane(0.3f, 0.9f, 0.55f).dadx, dadx);
}

TEST(Colour, ConversionIsRintOf255Times) {
  EXPECT_EQ(colorToUnorm8(0.3f), 76);  // 76.5 in float: ties to even (REFERENCE.md)
  EXPECT_EQ(colorToUnorm8(1.0f), 255);
  EXPECT_EQ(colorToUnorm8(2.0f), 255);
  EXPECT_EQ(colorToUnorm8(-1.0f), 0);
  EXPECT_EQ(colorToUnorm8(NAN), 0);
  EXPECT_EQ(colorToUnorm8(0.5f), 128);  // 127.5 -> 128
}

TEST(Colour, FlatTakesTheGivenValues) {
  TestSurface s(8, 8);
  const float flat[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  drawTriangle(s.state(), s.fb, s.vertex(0, 0, 0.5f, 1, 0, 0), s.vertex(8, 0, 0.5f, 0, 1, 0),
               s.vertex(0, 8, 0.5f, 0, 0, 1), flat);
  const uint8_t* p = s.at(1, 1);
  EXPECT_EQ(p[0], colorToUnorm8(0.2f));
  EXPECT_EQ(p[1], colorToUnorm8(0.4f));
  EXPECT_EQ(p[2], colorToUnorm8(0.6f));
  EXPECT_EQ(p[3], colorToUnorm8(0.8f));
}

TEST(Colour, SmoothIsPerspectiveCorrect) {
  // A vertical strip from x = 0 (1/w = 1) to x = 16 (1/w = 1/4), red 0 -> 1:
  // perspective-correct red at screen fraction s is s/w1 / ((1-s)/w0 + s/w1).
  TestSurface s(16, 4);
  auto v = [&](float x, float y, float oow, float r) {
    WindowVertex w = s.vertex(x, y, 0.5f, r, 0, 0, 1);
    w.oneOverW = oow;
    return w;
  };
  drawTriangle(s.state(), s.fb, v(0, 0, 1, 0), v(16, 0, 0.25f, 1), v(16, 4, 0.25f, 1), nullptr);
  drawTriangle(s.state(), s.fb, v(0, 0, 1, 0), v(16, 4, 0.25f, 1), v(0, 4, 1, 0), nullptr);
  for (int x = 0; x < 16; ++x) {
    double sfrac = (x + 0.5) / 16;
    double red = sfrac * 0.25 / ((1 - sfrac) * 1 + sfrac * 0.25);
    EXPECT_NEAR(s.at(x, 1)[0], red * 255, 1.0) << x;
  }
}

TEST(Colour, SecondaryColourIsAddedAndClamped) {
  TestSurface s(8, 8);
  RasterState st = s.state();
  st.varyingCount = 8;
  auto v = [&](float x, float y) {
    WindowVertex w = s.vertex(x, y, 0.5f, 0.5f, 0.75f, 0.1f, 0.4f);
    w.varying[4] = 0.25f;
    w.varying[5] = 0.5f;
    w.varying[6] = 0.0f;
    w.varying[7] = 0.9f;  // secondary alpha is not added
    return w;
  };
  drawTriangle(st, s.fb, v(0, 0), v(8, 0), v(0, 8), nullptr);
  const uint8_t* p = s.at(1, 1);
  EXPECT_EQ(p[0], colorToUnorm8(0.75f));
  EXPECT_EQ(p[1], 255);
  EXPECT_NEAR(p[2], 0.1 * 255, 1);
  EXPECT_NEAR(p[3], 0.4 * 255, 1);
}

TEST(Colour, WriteMaskKeepsMaskedChannels) {
  TestSurface s(4, 4);
  RasterState st = s.state();
  st.colorWrite[1] = false;
  st.colorWrite[3] = false;
  const float flat[4] = {1, 1, 1, 1};
  drawTriangle(st, s.fb, s.vertex(0, 0), s.vertex(8, 0), s.vertex(0, 8), flat);
  const uint8_t* p = s.at(0, 0);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[1], 0);
  EXPECT_EQ(p[2], 255);
  EXPECT_EQ(p[3], 0);
}

}  // namespace
}  // namespace glfixed::raster
