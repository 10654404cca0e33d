// glBitmap's cache across OSMesaMakeCurrent (Mesa's st_cb_bitmap.c keeps
// small bitmaps and draws them later): another context made current draws
// the old context's cached bitmaps into the old buffer first
// (_mesa_make_current flushes it); the same context bound to a new buffer
// keeps them and draws them into the new one. Measured on Mesa 22.3; the
// test runs on both.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

constexpr int kSize = 32;
const GLubyte kSolid[8] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};

class BitmapMakeCurrentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    first_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    second_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    ASSERT_TRUE(first_ && second_);
    ASSERT_TRUE(OSMesaMakeCurrent(first_, a_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    glColor3f(1, 0, 0);
    glRasterPos2f(0, 0);  // the centre of the buffer
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(8, 8, 0, 0, 0, 0, kSolid);
  }
  void TearDown() override {
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    if (first_) OSMesaDestroyContext(first_);
    if (second_) OSMesaDestroyContext(second_);
  }
  static int redAtCentre(const std::vector<GLubyte>& buffer) { return buffer[4 * (20 * kSize + 20)]; }

  OSMesaContext first_ = nullptr, second_ = nullptr;
  std::vector<GLubyte> a_ = std::vector<GLubyte>(kSize * kSize * 4, 0);
  std::vector<GLubyte> b_ = std::vector<GLubyte>(kSize * kSize * 4, 0);
};

TEST_F(BitmapMakeCurrentTest, AnotherContextDrawsTheCachedBitmapsIntoTheOldBuffer) {
  ASSERT_TRUE(OSMesaMakeCurrent(second_, b_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  EXPECT_EQ(redAtCentre(a_), 255);
  glFinish();
  EXPECT_EQ(redAtCentre(b_), 0);
}

TEST_F(BitmapMakeCurrentTest, TheSameContextOnANewBufferKeepsThem) {
  ASSERT_TRUE(OSMesaMakeCurrent(first_, b_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  EXPECT_EQ(redAtCentre(a_), 0);
  glFinish();
  EXPECT_EQ(redAtCentre(a_), 0);
  EXPECT_EQ(redAtCentre(b_), 255);
}

TEST_F(BitmapMakeCurrentTest, ReleasingTheContextDrawsThem) {
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  EXPECT_EQ(redAtCentre(a_), 255);
}

}  // namespace
}  // namespace glfx_test
