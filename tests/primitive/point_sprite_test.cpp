// Point sprite coordinates (primitive/point_sprite.h): the planes give s from
// 0 to 1 across the sprite's square and t from 0 to 1 down it for
// GL_UPPER_LEFT, up it for GL_LOWER_LEFT (GL 2.0 §3.3.1, in llvmpipe's
// y-down window space), r = 0, q = 1; pre-multiplied by 1/w when perspective.
#include "primitive/point_sprite.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glfixed::primitive {
namespace {

float at(const SpritePlane& p, float x, float y) { return p.a0 + x * p.dadx + y * p.dady; }

TEST(PointSprite, CoordinatesRunAcrossTheSquare) {
  const float x = 20.5f, y = 10.5f, size = 8.0f;  // the square covers [16.5, 24.5] x [6.5, 14.5]
  const SpriteCoordPlanes p = spriteCoordPlanes(x, y, size, GL_UPPER_LEFT, 1.0f, false);
  // Window positions are pixel centres: llvmpipe's planes are in terms of
  // x - 0.5, so the left edge (x - size / 2) is at s = 0.
  EXPECT_FLOAT_EQ(at(p.s, x - size / 2 - 0.5f, 0), 0.0f);
  EXPECT_FLOAT_EQ(at(p.s, x - 0.5f, 0), 0.5f);
  EXPECT_FLOAT_EQ(at(p.s, x + size / 2 - 0.5f, 0), 1.0f);
  EXPECT_FLOAT_EQ(at(p.t, 0, y - size / 2 - 0.5f), 0.0f);  // top: t = 0
  EXPECT_FLOAT_EQ(at(p.t, 0, y + size / 2 - 0.5f), 1.0f);
  EXPECT_EQ(p.s.dady, 0.0f);
  EXPECT_EQ(p.t.dadx, 0.0f);
  EXPECT_EQ(at(p.r, 3, 4), 0.0f);
  EXPECT_EQ(at(p.q, 3, 4), 1.0f);
}

TEST(PointSprite, LowerLeftOriginRunsUp) {
  const SpriteCoordPlanes p = spriteCoordPlanes(20.5f, 10.5f, 8.0f, GL_LOWER_LEFT, 1.0f, false);
  EXPECT_FLOAT_EQ(at(p.t, 0, 10.5f - 4 - 0.5f), 1.0f);  // top: t = 1
  EXPECT_FLOAT_EQ(at(p.t, 0, 10.5f + 4 - 0.5f), 0.0f);
}

TEST(PointSprite, PerspectivePremultipliesByOneOverW) {
  const float w0 = 0.25f;
  const SpriteCoordPlanes a = spriteCoordPlanes(20.5f, 10.5f, 8.0f, GL_UPPER_LEFT, 1.0f, false);
  const SpriteCoordPlanes b = spriteCoordPlanes(20.5f, 10.5f, 8.0f, GL_UPPER_LEFT, w0, true);
  EXPECT_EQ(b.s.dadx, a.s.dadx * w0);
  EXPECT_EQ(b.s.a0, a.s.a0 * w0);
  EXPECT_EQ(b.t.dady, a.t.dady * w0);
  EXPECT_EQ(b.q.a0, w0);
}

TEST(PointSprite, WidthIsTheSnappedSizeAtLeastOnePixel) {
  EXPECT_EQ(spriteFixedWidth(8.0f), 8 * 256);
  EXPECT_EQ(spriteFixedWidth(2.5f), 640);  // not rounded to whole pixels
  EXPECT_EQ(spriteFixedWidth(0.25f), 256);
  EXPECT_EQ(spriteFixedWidth(1000.0f), 255 * 256);
  EXPECT_EQ(spriteFixedWidth(std::nanf("")), 256);
}

}  // namespace
}  // namespace glfixed::primitive
