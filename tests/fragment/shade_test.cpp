// The two builds of the block shader (generic x86-64, AVX2 and FMA) must give
// the same bits.
#include "fragment/shade.h"

#include <gtest/gtest.h>

#include <random>

#include "raster/primitive_setup.h"
#include "raster/raster.h"
#include "raster/test_surface.h"

namespace glfixed::raster {
namespace {

using test::TestSurface;

void shadeAll(const RasterState& st, TestSurface& s, const FixedTriangle& f, const WindowVertex* v,
              const float* flat, bool avx2, bool lateDepth = false) {
  PrimitiveSetup t;
  if (!setupTriangle(st, s.fb, f, v[0], v[1], v[2], flat, t)) return;
  fragment::ShadeTarget target = fragment::makeShadeTarget(st, s.fb, t);
  target.lateDepth = target.lateDepth || lateDepth;  // the alpha test sets it
  if (avx2)
    fragment::shadePrimitiveAvx2(t, target);
  else
    fragment::shadePrimitiveGeneric(t, target);
}

// Three vertices in and around a 40x40 surface, z in [0, 1].
void randomVertices(std::mt19937& rng, WindowVertex v[3]) {
  std::uniform_real_distribution<float> pos(-4, 44), unit(0, 1);
  for (int i = 0; i < 3; ++i) {
    WindowVertex& x = v[i];
    x.x = pos(rng);
    x.y = pos(rng);
    x.z = unit(rng);
    x.oneOverW = 0.2f + unit(rng);
    for (float& c : x.varying) c = unit(rng);
  }
}

TEST(Shade, Avx2MatchesGeneric) {
  if (!fragment::haveAvx2Fma()) GTEST_SKIP() << "no AVX2/FMA on this CPU";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> pos(-4, 44), unit(0, 1);
  const GLenum funcs[] = {GL_LESS,   GL_LEQUAL,   GL_EQUAL,  GL_GREATER,
                          GL_GEQUAL, GL_NOTEQUAL, GL_ALWAYS, GL_NEVER};
  for (int iter = 0; iter < 600; ++iter) {
    const int depthBits = iter % 3 == 0 ? 16 : 24;
    TestSurface a(40, 40, depthBits), b(40, 40, depthBits);
    RasterState st = a.state();
    st.depthTest = iter % 4 != 0;
    st.depthFunc = funcs[iter % 8];
    st.depthWrite = iter % 5 != 0;
    st.varyingCount = iter % 2 ? 8 : 4;
    if (iter % 7 == 0) st.colorWrite[iter % 4] = false;
    if (iter % 11 == 0) a.fb.color.setFormat(PixelFormat::kBGRA), b.fb.color.setFormat(PixelFormat::kBGRA);
    st.alphaTest = fragment::makeAlphaTest(iter % 3 == 2, funcs[(iter / 3) % 8], unit(rng));
    // Fog (fog.inc: the exp2 polynomial's fused operations) on the fog varying.
    const GLenum fogModes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
    st.fog = fragment::makeFogState(iter % 5 >= 2, fogModes[iter % 3], 2.5f, 0.2f, 0.8f,
                                    glm::vec4(0.3f, 0.6f, 0.9f, 1));
    for (int tri = 0; tri < 4; ++tri) {
      WindowVertex v[3];
      for (auto& x : v) {
        x.x = pos(rng);
        x.y = pos(rng);
        x.z = unit(rng) * 1.2f - 0.1f;
        x.oneOverW = 0.2f + unit(rng);
        for (float& c : x.varying) c = unit(rng);
      }
      FixedTriangle f;
      int sign = snapTriangle(v[0], v[1], v[2], f);
      if (sign == 0) continue;
      if (sign < 0) {
        std::swap(v[0], v[1]);
        snapTriangle(v[0], v[1], v[2], f);
      }
      const float* flat = iter % 3 == 1 ? v[2].varying : nullptr;
      shadeAll(st, a, f, v, flat, false, iter % 6 == 5);
      shadeAll(st, b, f, v, flat, true, iter % 6 == 5);
    }
    ASSERT_EQ(a.pixels, b.pixels) << "iteration " << iter;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) ASSERT_EQ(a.fb.depth.get(x, y), b.fb.depth.get(x, y)) << iter;
  }
}

// Where nothing discards, the depth test after the colour (lateDepth) gives
// what the test before it gives, colour write masks and no colour included.
TEST(Shade, LateDepthTestMatchesEarly) {
  std::mt19937 rng(9);
  const GLenum funcs[] = {GL_LESS,   GL_LEQUAL,   GL_EQUAL,  GL_GREATER,
                          GL_GEQUAL, GL_NOTEQUAL, GL_ALWAYS, GL_NEVER};
  size_t drawn = 0;
  for (int iter = 0; iter < 200; ++iter) {
    const int depthBits = iter % 3 == 0 ? 16 : 24;
    TestSurface a(40, 40, depthBits), b(40, 40, depthBits);
    RasterState st = a.state();
    st.depthTest = true;
    st.depthFunc = funcs[iter % 8];
    st.depthWrite = iter % 5 != 0;
    if (iter % 7 == 0) st.colorWrite[iter % 4] = false;
    if (iter % 13 == 0)
      for (bool& w : st.colorWrite) w = false;
    for (int tri = 0; tri < 4; ++tri) {
      WindowVertex v[3];
      randomVertices(rng, v);
      FixedTriangle f;
      const int sign = snapTriangle(v[0], v[1], v[2], f);
      if (sign == 0) continue;
      if (sign < 0) {
        std::swap(v[0], v[1]);
        snapTriangle(v[0], v[1], v[2], f);
      }
      shadeAll(st, a, f, v, nullptr, false, false);
      shadeAll(st, b, f, v, nullptr, false, true);
    }
    ASSERT_EQ(a.pixels, b.pixels) << "iteration " << iter;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) ASSERT_EQ(a.fb.depth.get(x, y), b.fb.depth.get(x, y)) << iter;
    for (auto p : a.pixels) drawn += p != 0;
  }
  EXPECT_GT(drawn, 0u);  // the triangles drew something
}

// Lines: the line set-up's quadrilaterals, and triangles carrying a smooth
// line's coverage (flat and smooth colours).
TEST(Shade, Avx2MatchesGenericForLines) {
  if (!fragment::haveAvx2Fma()) GTEST_SKIP() << "no AVX2/FMA on this CPU";
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> pos(-4, 44), unit(0, 1);
  for (int iter = 0; iter < 400; ++iter) {
    TestSurface a(40, 40), b(40, 40);
    RasterState st = a.state();
    st.varyingCount = iter % 2 ? 8 : 4;
    const bool flatColours = iter % 3 == 1;
    for (int prim = 0; prim < 4; ++prim) {
      WindowVertex v[3];
      randomVertices(rng, v);
      const float* flat = flatColours ? v[1].varying : nullptr;
      PrimitiveSetup t;
      bool drawn;
      if (iter % 2 == 0) {
        LineStyle style;
        style.width = 1.0f + 6.0f * unit(rng);
        drawn = setupLine(st, a.fb, style, v[0], v[1], flat, t);
      } else {
        FixedTriangle f;
        const int sign = snapTriangle(v[0], v[1], v[2], f);
        if (sign < 0) {
          std::swap(v[0], v[1]);
          snapTriangle(v[0], v[1], v[2], f);
        }
        drawn = sign != 0 && setupTriangle(st, a.fb, f, v[0], v[1], v[2], flat, t);
        if (drawn) {
          const PlaneSetup ps(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
          t.w = ps.plane(v[0].oneOverW, v[1].oneOverW, v[2].oneOverW);
          t.lineCoverage = true;
          t.coverageHalfWidth = 1.0f + 2.0f * unit(rng);
          t.coverageHalfLength = 10.0f * unit(rng);
          t.coverageAlongScale = iter % 4 == 1 ? unit(rng) : 1.0f;
          t.coverageX = ps.plane(-t.coverageHalfWidth * v[0].oneOverW, t.coverageHalfWidth * v[1].oneOverW,
                                 0.5f * v[2].oneOverW);
          t.coverageZ = ps.plane(t.coverageHalfLength * v[0].oneOverW, -t.coverageHalfLength * v[1].oneOverW,
                                 2.0f * v[2].oneOverW);
        }
      }
      if (!drawn) continue;
      fragment::shadePrimitiveGeneric(t, fragment::makeShadeTarget(st, a.fb, t));
      fragment::shadePrimitiveAvx2(t, fragment::makeShadeTarget(st, b.fb, t));
    }
    ASSERT_EQ(a.pixels, b.pixels) << "iteration " << iter;
  }
}

// Smooth points: triangles carrying the aapoint shader's (s, t) planes, its
// discard and alpha factor, with and without a depth test.
TEST(Shade, Avx2MatchesGenericForSmoothPoints) {
  if (!fragment::haveAvx2Fma()) GTEST_SKIP() << "no AVX2/FMA on this CPU";
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> pos(-4, 44), unit(0, 1);
  for (int iter = 0; iter < 300; ++iter) {
    TestSurface a(40, 40), b(40, 40);
    RasterState st = a.state();
    st.depthTest = iter % 2 == 0;
    for (int prim = 0; prim < 4; ++prim) {
      WindowVertex v[3];
      randomVertices(rng, v);
      FixedTriangle f;
      const int sign = snapTriangle(v[0], v[1], v[2], f);
      if (sign < 0) {
        std::swap(v[0], v[1]);
        snapTriangle(v[0], v[1], v[2], f);
      }
      const float* flat = iter % 3 == 1 ? v[1].varying : nullptr;
      PrimitiveSetup t;
      if (sign == 0 || !setupTriangle(st, a.fb, f, v[0], v[1], v[2], flat, t)) continue;
      const PlaneSetup ps(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
      t.w = ps.plane(v[0].oneOverW, v[1].oneOverW, v[2].oneOverW);
      t.aaPoint = true;
      t.aaS = ps.plane(-1.2f * v[0].oneOverW, 1.1f * v[1].oneOverW, 0.3f * v[2].oneOverW);
      t.aaT = ps.plane(-0.9f * v[0].oneOverW, -1.0f * v[1].oneOverW, 1.3f * v[2].oneOverW);
      t.aaK = 0.5f * unit(rng);
      fragment::shadePrimitiveGeneric(t, fragment::makeShadeTarget(st, a.fb, t));
      fragment::shadePrimitiveAvx2(t, fragment::makeShadeTarget(st, b.fb, t));
    }
    ASSERT_EQ(a.pixels, b.pixels) << "iteration " << iter;
  }
}

}  // namespace
}  // namespace glfixed::raster
