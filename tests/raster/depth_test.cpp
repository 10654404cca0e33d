// Depth: llvmpipe's float-to-unorm conversions and the depth test.
#include "raster/depth.h"

#include <gtest/gtest.h>

#include <cmath>

#include "raster/raster.h"
#include "raster/test_surface.h"

namespace glfixed::raster {
namespace {

using test::TestSurface;

TEST(DepthConversion, TwentyFourBitsRoundToNearestEven) {
  EXPECT_EQ(depthToUnorm(0.0f, 24), 0u);
  EXPECT_EQ(depthToUnorm(1.0f, 24), 0xffffffu);
  EXPECT_EQ(depthToUnorm(0.5f, 24), 0x800000u);  // 8388607.5 -> even (REFERENCE.md)
  EXPECT_EQ(depthToUnorm(2.0f, 24), 0xffffffu);  // clamped
  EXPECT_EQ(depthToUnorm(-1.0f, 24), 0u);
  EXPECT_EQ(depthToUnorm(NAN, 24), 0xffffffu);  // minps/maxps: NaN -> 1
}

TEST(DepthConversion, SixteenBitsUseTheMagicNumberConversion) {
  EXPECT_EQ(depthToUnorm(0.0f, 16), 0u);
  EXPECT_EQ(depthToUnorm(1.0f, 16), 0xffffu);
  EXPECT_EQ(depthToUnorm(0.5f, 16), 0x8000u);
  // z * (65535/65536) rounds to float before the + 128 rounds again, so this
  // z gives 0xa5f0 where rint(z * 65535) is 0xa5f1. A fused multiply-add
  // (fp contraction) would give 0xa5f1 too: this also guards the build flags.
  const float z = 0x1.4be24cp-1f;
  EXPECT_EQ(depthToUnorm(z, 16), 0xa5f0u);
  EXPECT_EQ(static_cast<uint32_t>(std::nearbyint(double(z) * 65535.0)), 0xa5f1u);
}

TEST(DepthTest, EveryFunction) {
  struct Case {
    GLenum func;
    bool less, equal, greater;
  };
  const Case cases[] = {{GL_NEVER, false, false, false},  {GL_LESS, true, false, false},
                        {GL_EQUAL, false, true, false},   {GL_LEQUAL, true, true, false},
                        {GL_GREATER, false, false, true}, {GL_NOTEQUAL, true, false, true},
                        {GL_GEQUAL, false, true, true},   {GL_ALWAYS, true, true, true}};
  for (const Case& c : cases) {
    EXPECT_EQ(depthPasses(c.func, 1, 2), c.less) << c.func;
    EXPECT_EQ(depthPasses(c.func, 2, 2), c.equal) << c.func;
    EXPECT_EQ(depthPasses(c.func, 3, 2), c.greater) << c.func;
  }
}

TEST(DepthTest, NearerTriangleWinsWithLessAndWritesDepth) {
  TestSurface s(8, 8);
  RasterState st = s.state();
  st.depthTest = true;
  st.depthFunc = GL_LESS;
  auto quad = [&](float z, float r, float g) {
    drawTriangle(st, s.fb, s.vertex(0, 0, z, r, g, 0), s.vertex(8, 0, z, r, g, 0), s.vertex(0, 8, z, r, g, 0),
                 nullptr);
    drawTriangle(st, s.fb, s.vertex(8, 0, z, r, g, 0), s.vertex(8, 8, z, r, g, 0), s.vertex(0, 8, z, r, g, 0),
                 nullptr);
  };
  quad(0.25f, 1, 0);
  quad(0.75f, 0, 1);  // behind: fails
  EXPECT_EQ(s.at(3, 3)[0], 255);
  EXPECT_EQ(s.at(3, 3)[1], 0);
  EXPECT_EQ(s.fb.depth.get(3, 3), depthToUnorm(0.25f, 24));
  // Without depth writes the buffer keeps its value.
  st.depthWrite = false;
  quad(0.1f, 0, 1);
  EXPECT_EQ(s.at(3, 3)[1], 255);
  EXPECT_EQ(s.fb.depth.get(3, 3), depthToUnorm(0.25f, 24));
}

TEST(DepthTest, SixteenBitBuffer) {
  TestSurface s(4, 4, 16);
  RasterState st = s.state();
  st.depthTest = true;
  st.depthFunc = GL_ALWAYS;
  drawTriangle(st, s.fb, s.vertex(0, 0, 0.5f), s.vertex(8, 0, 0.5f), s.vertex(0, 8, 0.5f), nullptr);
  EXPECT_EQ(s.fb.depth.get(0, 0), 0x8000u);
}

}  // namespace
}  // namespace glfixed::raster
