// The pixel map lookups (state/pixel_maps.h, GL 2.1 §3.6.5): index maps
// masked by their size, colour maps rounded as glReadPixels and glTexImage
// look them up; the stencil lookup that glDrawPixels(GL_STENCIL_INDEX) and
// glCopyPixels(GL_STENCIL) use with GL_MAP_STENCIL.
#include "state/pixel_maps.h"

#include <gtest/gtest.h>

namespace glfixed {
namespace {

TEST(PixelMaps, StartWithOneZeroEntry) {
  const PixelMaps maps;
  for (const PixelMap& m : maps.map) {
    EXPECT_EQ(m.size, 1);
    EXPECT_EQ(m.values[0], 0.0f);
  }
  EXPECT_EQ(maps.mapStencil(200), 0);
}

TEST(PixelMaps, IndicesAreMaskedBySizeMinusOne) {
  PixelMaps maps;
  PixelMap& s = maps[GL_PIXEL_MAP_S_TO_S];
  s.size = 4;
  s.values = {};
  for (int i = 0; i < 4; ++i) s.values[size_t(i)] = static_cast<float>(10 + i);
  EXPECT_EQ(maps.mapStencil(0), 10);
  EXPECT_EQ(maps.mapStencil(3), 13);
  EXPECT_EQ(maps.mapStencil(6), 12);
  EXPECT_EQ(maps.mapStencil(-1), 13);  // two's complement, as Mesa masks unsigned values
}

TEST(PixelMaps, ColourLookupRoundsToTheNearestEntryAfterClamping) {
  PixelMap m;
  m.size = 3;
  m.values[0] = 0.2f;
  m.values[1] = 0.5f;
  m.values[2] = 0.8f;
  EXPECT_EQ(m.atColor(-1.0f), 0.2f);
  EXPECT_EQ(m.atColor(0.2f), 0.2f);   // 0.4 -> 0
  EXPECT_EQ(m.atColor(0.3f), 0.5f);   // 0.6 -> 1
  EXPECT_EQ(m.atColor(0.8f), 0.8f);   // 1.6 -> 2
  EXPECT_EQ(m.atColor(7.0f), 0.8f);
}

}  // namespace
}  // namespace glfixed
