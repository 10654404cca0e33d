// Hit records (state/render_mode.h): the words Mesa writes, measured with
// reference/feedback/select_pick.c ("depth values", "overflow").
#include "state/render_mode.h"

#include <gtest/gtest.h>

namespace glfixed {
namespace {

TEST(HitRecord, DepthScaledAsMesaScalesIt) {
  GLuint words[32] = {};
  SelectState s;
  s.buffer = words;
  s.bufferSize = 32;
  s.bufferGiven = true;
  s.nameStackDepth = 2;
  s.nameStack[0] = 7;
  s.nameStack[1] = 9;
  const float pairs[][2] = {{0.5f, 0.5f}, {0.25f, 0.75f}, {0.0f, 1.0f}};
  for (const auto& p : pairs) {
    s.updateHitFlag(p[0]);
    s.updateHitFlag(p[1]);
    s.writeHitRecord();
  }
  EXPECT_EQ(s.hits, 3u);
  EXPECT_FALSE(s.hitFlag);
  const GLuint expected[] = {2, 2147483648u, 2147483648u, 7, 9,   //
                             2, 1073741824u, 3221225472u, 7, 9,   //
                             2, 0u,          0u,          7, 9};  // z = 1.0 wraps to 0 in Mesa
  for (int i = 0; i < 15; ++i) EXPECT_EQ(words[i], expected[i]) << "word " << i;
}

TEST(HitRecord, OverflowWritesWhatFitsAndCountsTheRest) {
  GLuint words[8];
  for (GLuint& w : words) w = 0xdeadbeefu;
  SelectState s;
  s.buffer = words;
  s.bufferSize = 6;
  s.nameStackDepth = 3;
  s.updateHitFlag(0.5f);
  s.writeHitRecord();
  EXPECT_EQ(s.bufferCount, 6u);
  s.updateHitFlag(0.5f);
  s.writeHitRecord();
  EXPECT_EQ(s.bufferCount, 12u);  // > bufferSize: glRenderMode returns -1
  EXPECT_EQ(words[5], 0u);
  EXPECT_EQ(words[6], 0xdeadbeefu);
}

}  // namespace
}  // namespace glfixed
