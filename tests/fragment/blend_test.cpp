// Blending and the logic op in the block shader (fragment/blend.inc): each
// pixel against the scalar rule measured on llvmpipe (MESA_FACTS.md,
// "Blending"), on RGBA, BGRA and RGB buffers, with partial blocks and colour
// masks; and the AVX2 build against the generic one.
#include <gtest/gtest.h>

#include <random>

#include "fragment/blend_state.h"
#include "fragment/shade.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"
#include "raster/test_surface.h"

namespace glfixed::raster {
namespace {

using test::TestSurface;

const GLenum kFactors[15] = {GL_ZERO,
                             GL_ONE,
                             GL_SRC_COLOR,
                             GL_ONE_MINUS_SRC_COLOR,
                             GL_DST_COLOR,
                             GL_ONE_MINUS_DST_COLOR,
                             GL_SRC_ALPHA,
                             GL_ONE_MINUS_SRC_ALPHA,
                             GL_DST_ALPHA,
                             GL_ONE_MINUS_DST_ALPHA,
                             GL_CONSTANT_COLOR,
                             GL_ONE_MINUS_CONSTANT_COLOR,
                             GL_CONSTANT_ALPHA,
                             GL_ONE_MINUS_CONSTANT_ALPHA,
                             GL_SRC_ALPHA_SATURATE};
const GLenum kEquations[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

int mul8(int a, int b) {
  const int t = a * b;
  return (t + (t >> 8) + 128) >> 8;
}

int factor(GLenum f, int k, const int s[4], const int d[4], const int c[4]) {
  switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[k];
    case GL_ONE_MINUS_SRC_COLOR: return 255 - s[k];
    case GL_DST_COLOR: return d[k];
    case GL_ONE_MINUS_DST_COLOR: return 255 - d[k];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255 - d[3];
    case GL_CONSTANT_COLOR: return c[k];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 255 - c[k];
    case GL_CONSTANT_ALPHA: return c[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 255 - c[3];
    default: return k == 3 ? 255 : std::min(s[3], 255 - d[3]);  // GL_SRC_ALPHA_SATURATE
  }
}

int blendRef(const fragment::BlendState& b, int k, const int s[4], const int d[4]) {
  const GLenum e = k == 3 ? b.equationAlpha : b.equationRGB;
  if (e == GL_MIN) return std::min(s[k], d[k]);
  if (e == GL_MAX) return std::max(s[k], d[k]);
  const int c[4] = {b.constant[0], b.constant[1], b.constant[2], b.constant[3]};
  const int st = mul8(s[k], factor(k == 3 ? b.srcAlpha : b.srcRGB, k, s, d, c));
  const int dt = mul8(d[k], factor(k == 3 ? b.dstAlpha : b.dstRGB, k, s, d, c));
  if (e == GL_FUNC_SUBTRACT) return std::max(0, st - dt);
  if (e == GL_FUNC_REVERSE_SUBTRACT) return std::max(0, dt - st);
  return std::min(255, st + dt);
}

// A flat triangle of random colour over random destination bytes: every
// covered pixel is the rule applied to the flat colour's bytes and what
// was there; the others are unchanged.
TEST(Blend, EveryPixelFollowsTheRule) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-4, 36), unit(0, 1);
  for (int iter = 0; iter < 400; ++iter) {
    TestSurface s(33, 31, 0), plain(33, 31, 0);
    const PixelFormat format = iter % 3 == 0 ? PixelFormat::kBGRA : iter % 3 == 1 ? PixelFormat::kRGB
                                                                                  : PixelFormat::kRGBA;
    s.fb.color.setFormat(format);
    for (uint8_t& p : s.pixels) p = static_cast<uint8_t>(rng());
    const std::vector<uint8_t> before = s.pixels;
    RasterState st = s.state();
    const float color[4] = {unit(rng), unit(rng) * 1.4f - 0.2f, unit(rng), unit(rng)};
    st.blend = fragment::makeBlendState(true, kFactors[rng() % 15], kFactors[rng() % 14], kFactors[rng() % 15],
                                        kFactors[rng() % 14], kEquations[rng() % 5], kEquations[rng() % 5],
                                        color, iter % 5 == 0, GLenum(GL_CLEAR + rng() % 16));
    if (iter % 4 == 0) st.colorWrite[rng() % 4] = false;
    WindowVertex v[3];
    for (auto& x : v) {
      x = s.vertex(pos(rng), pos(rng));
      for (int k = 0; k < 4; ++k) x.varying[k] = unit(rng);
    }
    FixedTriangle f;
    const int sign = snapTriangle(v[0], v[1], v[2], f);
    if (sign == 0) continue;
    if (sign < 0) {
      std::swap(v[0], v[1]);
      snapTriangle(v[0], v[1], v[2], f);
    }
    PrimitiveSetup t;
    if (!setupTriangle(st, s.fb, f, v[0], v[1], v[2], v[2].varying, t)) continue;
    fragment::shadePrimitiveGeneric(t, fragment::makeShadeTarget(st, s.fb, t));
    // Which pixels are covered: the same triangle, unblended, on a cleared surface.
    RasterState stPlain = plain.state();
    PrimitiveSetup tp;
    ASSERT_TRUE(setupTriangle(stPlain, plain.fb, f, v[0], v[1], v[2], v[2].varying, tp));
    fragment::shadePrimitiveGeneric(tp, fragment::makeShadeTarget(stPlain, plain.fb, tp));
    const int src[4] = {colorToUnorm8(v[2].varying[0]), colorToUnorm8(v[2].varying[1]),
                        colorToUnorm8(v[2].varying[2]), colorToUnorm8(v[2].varying[3])};
    const ColorBuffer& cb = s.fb.color;
    const int off[4] = {cb.red, cb.green, cb.blue, cb.alpha};
    for (int y = 0; y < s.height(); ++y)
      for (int x = 0; x < s.width(); ++x) {
        const uint8_t* p = cb.pixel(x, y);
        const size_t at = size_t(p - s.pixels.data());
        int d[4];
        for (int k = 0; k < 4; ++k) d[k] = off[k] >= 0 ? before[at + off[k]] : 255;
        for (int k = 0; k < 4; ++k) {
          if (off[k] < 0) continue;
          int want = d[k];
          if (plain.covered(x, y) && st.colorWrite[k]) {
            if (st.blend.mode == fragment::BlendState::Mode::kBlend)
              want = blendRef(st.blend, k, src, d);
            else if (st.blend.mode == fragment::BlendState::Mode::kNone)
              want = src[k];
            else
              continue;  // the logic op: its own test (tests/api/blend_test.cpp)
          }
          ASSERT_EQ(p[off[k]], want) << "iteration " << iter << " pixel " << x << "," << y << " channel " << k;
        }
      }
  }
}

TEST(Blend, Avx2MatchesGeneric) {
  if (!fragment::haveAvx2Fma()) GTEST_SKIP() << "no AVX2/FMA on this CPU";
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> pos(-4, 44), unit(0, 1);
  for (int iter = 0; iter < 300; ++iter) {
    TestSurface a(40, 40, 24), b(40, 40, 24);
    if (iter % 3 == 1) a.fb.color.setFormat(PixelFormat::kRGB), b.fb.color.setFormat(PixelFormat::kRGB);
    for (size_t i = 0; i < a.pixels.size(); ++i) a.pixels[i] = b.pixels[i] = static_cast<uint8_t>(rng());
    RasterState st = a.state();
    const float color[4] = {unit(rng), unit(rng), unit(rng), unit(rng)};
    st.blend = fragment::makeBlendState(true, kFactors[rng() % 15], kFactors[rng() % 15], kFactors[rng() % 15],
                                        kFactors[rng() % 15], kEquations[rng() % 5], kEquations[rng() % 5],
                                        color, iter % 4 == 0, GLenum(GL_CLEAR + rng() % 16));
    if (iter % 5 == 0) st.colorWrite[rng() % 4] = false;
    for (int tri = 0; tri < 3; ++tri) {
      WindowVertex v[3];
      for (auto& x : v) {
        x = a.vertex(pos(rng), pos(rng));
        x.oneOverW = 0.2f + unit(rng);
        for (int k = 0; k < 4; ++k) x.varying[k] = unit(rng);
      }
      FixedTriangle f;
      const int sign = snapTriangle(v[0], v[1], v[2], f);
      if (sign == 0) continue;
      if (sign < 0) {
        std::swap(v[0], v[1]);
        snapTriangle(v[0], v[1], v[2], f);
      }
      PrimitiveSetup ta, tb;
      if (!setupTriangle(st, a.fb, f, v[0], v[1], v[2], nullptr, ta)) continue;
      setupTriangle(st, b.fb, f, v[0], v[1], v[2], nullptr, tb);
      fragment::shadePrimitiveGeneric(ta, fragment::makeShadeTarget(st, a.fb, ta));
      fragment::shadePrimitiveAvx2(tb, fragment::makeShadeTarget(st, b.fb, tb));
    }
    ASSERT_EQ(a.pixels, b.pixels) << "iteration " << iter;
  }
}

}  // namespace
}  // namespace glfixed::raster
