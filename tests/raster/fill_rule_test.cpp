// Coverage: llvmpipe's edge functions and fill rule (REFERENCE.md, "Coverage").
#include <gtest/gtest.h>

#include <random>

#include "raster/edge.h"
#include "raster/raster.h"
#include "raster/test_surface.h"

namespace glfixed::raster {
namespace {

using test::TestSurface;

// Draws and returns the set of covered pixels (GL window coordinates).
std::vector<bool> coverage(TestSurface& s, const WindowVertex& a, const WindowVertex& b,
                           const WindowVertex& c) {
  s.clear();
  drawTriangle(s.state(), s.fb, a, b, c, nullptr);
  std::vector<bool> out(size_t(s.width()) * s.height());
  for (int y = 0; y < s.height(); ++y)
    for (int x = 0; x < s.width(); ++x) out[size_t(y) * s.width() + x] = s.covered(x, y);
  return out;
}

TEST(FillRule, CentresOnLeftAndBottomEdgesAreCoveredRightAndTopAreNot) {
  TestSurface s(8, 8);
  // The square (0.5, 0.5)-(4.5, 4.5) in GL window coordinates: pixel centres
  // lie on all four edges.
  auto a = s.vertex(0.5f, 0.5f), b = s.vertex(4.5f, 0.5f), c = s.vertex(4.5f, 4.5f), d = s.vertex(0.5f, 4.5f);
  auto t1 = coverage(s, a, b, c);
  auto t2 = coverage(s, a, c, d);
  int n = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      bool in = t1[y * 8 + x] || t2[y * 8 + x];
      EXPECT_FALSE(t1[y * 8 + x] && t2[y * 8 + x]) << "pixel " << x << "," << y << " covered twice";
      EXPECT_EQ(in, x <= 3 && y <= 3) << "pixel " << x << "," << y;
      n += in;
    }
  EXPECT_EQ(n, 16);
}

TEST(FillRule, HorizontalBottomEdgeIncludedTopExcluded) {
  TestSurface s(8, 8);
  // A triangle with its horizontal bottom edge on row 2's centres (y = 2.5)
  // includes them; one with a horizontal top edge at y = 2.5 does not.
  auto up = coverage(s, s.vertex(0.5f, 2.5f), s.vertex(6.5f, 2.5f), s.vertex(3.5f, 6.5f));
  EXPECT_TRUE(up[2 * 8 + 3]);
  auto down = coverage(s, s.vertex(0.5f, 2.5f), s.vertex(3.5f, -1.5f), s.vertex(6.5f, 2.5f));
  EXPECT_FALSE(down[2 * 8 + 3]);
  EXPECT_TRUE(down[1 * 8 + 3]);
}

TEST(FillRule, OrientationDoesNotChangeCoverage) {
  TestSurface s(16, 16);
  auto a = s.vertex(1.25f, 2.5f), b = s.vertex(13.5f, 4.0f), c = s.vertex(6.5f, 14.75f);
  EXPECT_EQ(coverage(s, a, b, c), coverage(s, a, c, b));
  EXPECT_EQ(coverage(s, a, b, c), coverage(s, b, c, a));
}

TEST(FillRule, SharedEdgesAreCoveredExactlyOnce) {
  // Fans around a common centre (star-shaped polygons), with vertices on the
  // half-pixel grid (many centres exactly on edges) or anywhere: no pixel is
  // covered by two triangles of a fan.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  TestSurface s(32, 32);
  for (int iter = 0; iter < 400; ++iter) {
    const bool onGrid = iter % 2 == 0;
    auto snap = [&](float v) { return onGrid ? std::round(v * 2) / 2 : v; };
    const float cx = snap(8 + 16 * unit(rng)), cy = snap(8 + 16 * unit(rng));
    const int spokes = 4 + iter % 5;  // consecutive spokes less than 180 degrees apart
    std::vector<WindowVertex> ring;
    for (int i = 0; i < spokes; ++i) {
      float angle = (i + 0.1f + 0.8f * unit(rng)) * 6.2831853f / spokes;
      float r = 2 + 10 * unit(rng);
      ring.push_back(s.vertex(snap(cx + r * std::cos(angle)), snap(cy + r * std::sin(angle))));
    }
    std::vector<int> count(32 * 32, 0);
    for (int i = 0; i < spokes; ++i) {
      auto cov = coverage(s, s.vertex(cx, cy), ring[i], ring[(i + 1) % spokes]);
      for (size_t k = 0; k < cov.size(); ++k) count[k] += cov[k];
    }
    for (size_t k = 0; k < count.size(); ++k)
      ASSERT_LE(count[k], 1) << "iteration " << iter << " pixel " << k;
  }
}

TEST(FillRule, SpanClippingMatchesPerPixelTests) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> coord(-20 * 256, 60 * 256);
  for (int iter = 0; iter < 2000; ++iter) {
    FixedTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.x[i] = coord(rng);
      t.y[i] = coord(rng);
      if (iter % 3 == 0) t.x[i] &= ~255, t.y[i] &= ~255;  // vertices on pixel centres
    }
    if (fixedArea(t) <= 0) std::swap(t.x[0], t.x[1]), std::swap(t.y[0], t.y[1]);
    if (fixedArea(t) == 0) continue;
    Edge e[3] = {Edge::make(t, 0, true), Edge::make(t, 1, true), Edge::make(t, 2, true)};
    for (int py = -25; py < 65; ++py) {
      int64_t lo = -30, hi = 70;
      for (const Edge& edge : e) clipSpanToEdge(edge, py, lo, hi);
      for (int px = -30; px <= 70; ++px) {
        bool inside = e[0].inside(px, py) && e[1].inside(px, py) && e[2].inside(px, py);
        ASSERT_EQ(inside, px >= lo && px <= hi) << "iteration " << iter << " pixel " << px << "," << py;
      }
    }
  }
}

// A framebuffer object's rows are GL's (y up), where llvmpipe runs without
// its bottom_edge_rule (the top-left rule): the pixels a triangle covers there
// are the mirror image of those its mirror image covers with the rule in the
// y-down rows, so GL's bottom-left rule holds in both.
TEST(FillRule, TopLeftRuleInRowsUpMirrorsTheBottomEdgeRule) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int32_t> coord(-10, 40);
  std::uniform_int_distribution<int32_t> fraction(0, 255);
  for (int iter = 0; iter < 1000; ++iter) {
    FixedTriangle down;
    for (int i = 0; i < 3; ++i) {
      // Mostly on pixel centres, so that the rule decides many pixels.
      down.x[i] = coord(rng) * 256 + (iter % 2 ? 0 : fraction(rng));
      down.y[i] = coord(rng) * 256 + (iter % 3 ? 0 : fraction(rng));
    }
    if (iter % 4 == 0) down.y[1] = down.y[0];  // a horizontal edge
    if (fixedArea(down) < 0) std::swap(down.x[0], down.x[1]), std::swap(down.y[0], down.y[1]);
    if (fixedArea(down) == 0) continue;
    // y -> -y reverses the winding: swap two vertices to keep the area positive.
    FixedTriangle up = {{down.x[1], down.x[0], down.x[2]}, {-down.y[1], -down.y[0], -down.y[2]}};
    ASSERT_GT(fixedArea(up), 0);
    Edge d[3], u[3];
    for (int i = 0; i < 3; ++i) d[i] = Edge::make(down, i, true), u[i] = Edge::make(up, i, false);
    for (int py = -12; py <= 42; ++py)
      for (int px = -12; px <= 42; ++px) {
        const bool inDown = d[0].inside(px, py) && d[1].inside(px, py) && d[2].inside(px, py);
        const bool inUp = u[0].inside(px, -py) && u[1].inside(px, -py) && u[2].inside(px, -py);
        ASSERT_EQ(inDown, inUp) << "iteration " << iter << " pixel " << px << "," << py;
      }
  }
}

TEST(FillRule, SteppedSpansMatchDividedSpans) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int32_t> coord(-300 * 256, 300 * 256);
  for (int iter = 0; iter < 500; ++iter) {
    FixedTriangle t;
    for (int i = 0; i < 3; ++i) t.x[i] = coord(rng), t.y[i] = coord(rng);
    if (iter % 4 == 0) t.y[1] = t.y[0];  // a horizontal edge
    if (iter % 4 == 1) t.x[2] = t.x[1];  // a vertical edge
    if (fixedArea(t) < 0) std::swap(t.x[0], t.x[1]), std::swap(t.y[0], t.y[1]);
    if (fixedArea(t) == 0) continue;
    for (int i = 0; i < 3; ++i) {
      const Edge e = Edge::make(t, i, true);
      EdgeSpanStepper stepper(e, -310);
      for (int py = -310; py < 310; ++py) {
        int64_t lo1 = -400, hi1 = 400, lo2 = -400, hi2 = 400;
        clipSpanToEdge(e, py, lo1, hi1);
        stepper.clip(lo2, hi2);
        stepper.nextRow();
        ASSERT_EQ(lo1 <= hi1, lo2 <= hi2) << iter << " row " << py;
        if (lo1 <= hi1) {
          ASSERT_EQ(lo1, lo2) << iter << " row " << py;
          ASSERT_EQ(hi1, hi2) << iter << " row " << py;
        }
      }
    }
  }
}

TEST(FillRule, DegenerateTrianglesDrawNothing) {
  TestSurface s(8, 8);
  drawTriangle(s.state(), s.fb, s.vertex(1, 1), s.vertex(4, 4), s.vertex(7, 7), nullptr);
  EXPECT_EQ(s.coveredCount(), 0);
  // Distinct floats that snap to one line are degenerate too.
  drawTriangle(s.state(), s.fb, s.vertex(1, 1), s.vertex(4, 4.001f), s.vertex(7, 7), nullptr);
  EXPECT_EQ(s.coveredCount(), 0);
}

TEST(FillRule, ScissorLimitsTheWrittenPixels) {
  TestSurface s(16, 16);
  RasterState st = s.state();
  st.scissorX0 = 2;
  st.scissorY0 = 3;
  st.scissorX1 = 10;
  st.scissorY1 = 7;
  drawTriangle(st, s.fb, s.vertex(-5, -5), s.vertex(40, -5), s.vertex(-5, 40), nullptr);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(s.covered(x, y), x >= 2 && x < 10 && y >= 3 && y < 7);
}

}  // namespace
}  // namespace glfixed::raster
