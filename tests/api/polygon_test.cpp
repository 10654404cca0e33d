// The polygon rasterization state of GL 2.1 §3.6: glPolygonMode,
// glPolygonOffset, glPolygonStipple/glGetPolygonStipple (with the pixel
// store), glEdgeFlag, their enables, queries and errors.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

class PolygonTest : public GLTest {};

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

TEST_F(PolygonTest, Defaults) {
  const std::array<GLint, 2> mode = GetInts<2>(GL_POLYGON_MODE);
  EXPECT_EQ(mode[0], GL_FILL);
  EXPECT_EQ(mode[1], GL_FILL);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), 0.0f);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), 0.0f);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_LINE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_POINT), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_STIPPLE), GL_FALSE);
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, PolygonModePerFace) {
  glPolygonMode(GL_FRONT, GL_LINE);
  std::array<GLint, 2> mode = GetInts<2>(GL_POLYGON_MODE);
  EXPECT_EQ(mode[0], GL_LINE);
  EXPECT_EQ(mode[1], GL_FILL);
  glPolygonMode(GL_BACK, GL_POINT);
  mode = GetInts<2>(GL_POLYGON_MODE);
  EXPECT_EQ(mode[0], GL_LINE);
  EXPECT_EQ(mode[1], GL_POINT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  mode = GetInts<2>(GL_POLYGON_MODE);
  EXPECT_EQ(mode[0], GL_FILL);
  EXPECT_EQ(mode[1], GL_FILL);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, PolygonModeErrors) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glPolygonMode(GL_LEFT, GL_POINT);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glPolygonMode(GL_FRONT, GL_TRIANGLES);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glPolygonMode(GL_FRONT, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  const std::array<GLint, 2> mode = GetInts<2>(GL_POLYGON_MODE);  // unchanged
  EXPECT_EQ(mode[0], GL_LINE);
  EXPECT_EQ(mode[1], GL_LINE);
  glBegin(GL_TRIANGLES);
  glPolygonMode(GL_FRONT, GL_FILL);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInts<2>(GL_POLYGON_MODE)[0], GL_LINE);
}

TEST_F(PolygonTest, PolygonOffsetStoresAnyValue) {
  glPolygonOffset(-2.5f, 7.0f);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), -2.5f);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), 7.0f);
  glPolygonOffset(kInf, -kInf);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), kInf);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), -kInf);
  glPolygonOffset(kNaN, 1e30f);
  EXPECT_TRUE(std::isnan(GetFloat(GL_POLYGON_OFFSET_FACTOR)));
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), 1e30f);
  EXPECT_NO_GL_ERROR();
  glBegin(GL_TRIANGLES);
  glPolygonOffset(1, 1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), 1e30f);
}

TEST_F(PolygonTest, EnablesAndPolygonBit) {
  glEnable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glEnable(GL_POLYGON_OFFSET_POINT);
  glEnable(GL_POLYGON_STIPPLE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_TRUE);
  EXPECT_EQ(GetBool(GL_POLYGON_OFFSET_LINE), GL_TRUE);
  EXPECT_EQ(GetBool(GL_POLYGON_OFFSET_POINT), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_STIPPLE), GL_TRUE);
  glPushAttrib(GL_POLYGON_BIT);
  glPolygonMode(GL_FRONT, GL_POINT);
  glPolygonOffset(3, 4);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_POLYGON_STIPPLE);
  glPopAttrib();
  EXPECT_EQ(GetInts<2>(GL_POLYGON_MODE)[0], GL_FILL);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), 0.0f);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), 0.0f);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_STIPPLE), GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, PolygonStateInDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPolygonMode(GL_BACK, GL_LINE);
  glPolygonOffset(1.5f, -2.0f);
  glEndList();
  EXPECT_EQ(GetInts<2>(GL_POLYGON_MODE)[1], GL_FILL);  // compiled, not run
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), 0.0f);
  glCallList(list);
  EXPECT_EQ(GetInts<2>(GL_POLYGON_MODE)[1], GL_LINE);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_FACTOR), 1.5f);
  EXPECT_EQ(GetFloat(GL_POLYGON_OFFSET_UNITS), -2.0f);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, EdgeFlag) {
  glEdgeFlag(GL_FALSE);
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_FALSE);
  const GLboolean t = GL_TRUE;
  glEdgeFlagv(&t);
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_TRUE);
  glBegin(GL_TRIANGLES);  // allowed between glBegin and glEnd
  glEdgeFlag(GL_FALSE);
  glEnd();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_FALSE);
  glPushAttrib(GL_CURRENT_BIT);
  glEdgeFlag(GL_TRUE);
  glPopAttrib();
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_FALSE);
}

// ---- glPolygonStipple / glGetPolygonStipple (GL 2.1 §3.6.2, §6.1.6) ----------

std::array<GLubyte, 128> TestPattern() {
  std::array<GLubyte, 128> p;
  for (int i = 0; i < 128; ++i) p[i] = static_cast<GLubyte>(i * 37 + 11);
  return p;
}

TEST_F(PolygonTest, StippleDefaultIsAllOnes) {
  std::array<GLubyte, 128> out;
  out.fill(0);
  glGetPolygonStipple(out.data());
  for (GLubyte b : out) EXPECT_EQ(b, 0xff);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, StippleRoundTrip) {
  const std::array<GLubyte, 128> in = TestPattern();
  glPolygonStipple(in.data());
  std::array<GLubyte, 128> out;
  out.fill(0);
  glGetPolygonStipple(out.data());
  EXPECT_EQ(out, in);
  EXPECT_NO_GL_ERROR();
}

// §3.6.4: the pattern is read as a 32x32 bitmap through the unpack state.
TEST_F(PolygonTest, StippleReadsThroughTheUnpackState) {
  const std::array<GLubyte, 128> want = TestPattern();
  // Row length 40 pixels (5 bytes, 8 with alignment 8), 3 rows and 8 pixels skipped.
  std::vector<GLubyte> src(8 * 40, 0xEE);
  for (int row = 0; row < 32; ++row)
    for (int k = 0; k < 4; ++k) src[(3 + row) * 8 + 1 + k] = want[row * 4 + k];
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 8);
  glPolygonStipple(src.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  std::array<GLubyte, 128> out;
  out.fill(0);
  glGetPolygonStipple(out.data());
  EXPECT_EQ(out, want);
  EXPECT_NO_GL_ERROR();
}

// A skip of 3 pixels: each row's bits start 3 bits into its first byte.
TEST_F(PolygonTest, StippleSkipPixelsWithinAByte) {
  const std::array<GLubyte, 128> want = TestPattern();
  std::vector<GLubyte> src(32 * 8, 0);
  for (int row = 0; row < 32; ++row) {
    uint64_t bits = 0;
    for (int k = 0; k < 4; ++k) bits = (bits << 8) | want[row * 4 + k];
    bits <<= 64 - 32 - 3;  // 3 leading bits skipped
    for (int k = 0; k < 8; ++k) src[row * 8 + k] = static_cast<GLubyte>(bits >> (56 - 8 * k));
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPolygonStipple(src.data());
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  std::array<GLubyte, 128> out;
  glGetPolygonStipple(out.data());
  EXPECT_EQ(out, want);
  EXPECT_NO_GL_ERROR();
}

// §4.3.2 through §6.1.6: glGetPolygonStipple writes through the pack state.
TEST_F(PolygonTest, GetStippleWritesThroughThePackState) {
  const std::array<GLubyte, 128> in = TestPattern();
  glPolygonStipple(in.data());
  std::vector<GLubyte> dst(6 * 40, 0xEE);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_ROW_LENGTH, 40);  // 5 bytes, 6 with alignment 2
  glPixelStorei(GL_PACK_SKIP_ROWS, 2);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 16);
  glGetPolygonStipple(dst.data());
  for (int row = 0; row < 34; ++row)
    for (int k = 0; k < 6; ++k) {
      const bool inside = row >= 2 && k >= 2 && k < 6;
      const GLubyte expect = inside ? in[(row - 2) * 4 + (k - 2)] : 0xEE;
      EXPECT_EQ(dst[row * 6 + k], expect) << "row " << row << " byte " << k;
    }
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, StippleFromAndToPixelBuffers) {
  const std::array<GLubyte, 128> in = TestPattern();
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers[0]);
  std::vector<GLubyte> data(16 + 128, 0);
  std::copy(in.begin(), in.end(), data.begin() + 16);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, static_cast<GLsizeiptr>(data.size()), data.data(), GL_STATIC_DRAW);
  glPolygonStipple(reinterpret_cast<const GLubyte*>(16));  // an offset into the buffer
  EXPECT_NO_GL_ERROR();
  glPolygonStipple(reinterpret_cast<const GLubyte*>(17));  // one byte too far
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers[1]);
  glBufferData(GL_PIXEL_PACK_BUFFER, 130, nullptr, GL_STATIC_READ);
  glGetPolygonStipple(reinterpret_cast<GLubyte*>(2));
  EXPECT_NO_GL_ERROR();
  glGetPolygonStipple(reinterpret_cast<GLubyte*>(3));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  std::array<GLubyte, 128> out;
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 2, 128, out.data());
  EXPECT_EQ(out, in);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(2, buffers);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, StippleInsideBeginEndIsAnError) {
  const std::array<GLubyte, 128> in = TestPattern();
  glBegin(GL_TRIANGLES);
  glPolygonStipple(in.data());
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  std::array<GLubyte, 128> out;
  glBegin(GL_TRIANGLES);
  glGetPolygonStipple(out.data());
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetPolygonStipple(out.data());
  for (GLubyte b : out) EXPECT_EQ(b, 0xff);
}

// GL 2.1 says nothing of a null pointer; Mesa ignores it (probed), and so does
// libglfixed: no error, the pattern unchanged, no crash.
TEST_F(PolygonTest, NullStipplePointersAreIgnored) {
  glPolygonStipple(nullptr);
  glGetPolygonStipple(nullptr);
  EXPECT_NO_GL_ERROR();
  std::array<GLubyte, 128> out;
  glGetPolygonStipple(out.data());
  for (GLubyte b : out) EXPECT_EQ(b, 0xff);
}

// §5.4: a list keeps the pattern as unpacked at compile time.
TEST_F(PolygonTest, StippleInAListIsUnpackedAtCompileTime) {
  std::array<GLubyte, 128> in = TestPattern();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPolygonStipple(in.data());
  glEndList();
  const std::array<GLubyte, 128> want = in;
  in.fill(0);  // the client memory changes after the compile
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 5);
  glCallList(list);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  std::array<GLubyte, 128> out;
  glGetPolygonStipple(out.data());
  EXPECT_EQ(out, want);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PolygonTest, StippleIsInThePolygonStippleBit) {
  std::array<GLubyte, 128> in = TestPattern();
  glPushAttrib(GL_POLYGON_STIPPLE_BIT);
  glPolygonStipple(in.data());
  glPopAttrib();
  std::array<GLubyte, 128> out;
  glGetPolygonStipple(out.data());
  for (GLubyte b : out) EXPECT_EQ(b, 0xff);
  EXPECT_NO_GL_ERROR();
}

// Bad input: huge and NaN offsets draw without an error and without a crash.
TEST_F(PolygonTest, NonFiniteOffsetsDraw) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  for (float f : {kNaN, kInf, -kInf, 1e38f, -1e38f})
    for (float u : {kNaN, kInf, -kInf, 3e38f, -3e38f, 0.0f}) {
      glPolygonOffset(f, u);
      glBegin(GL_TRIANGLES);
      glVertex3f(-0.5f, -0.5f, 0.1f);
      glVertex3f(0.5f, -0.5f, -0.3f);
      glVertex3f(0.0f, 0.5f, 0.2f);
      glEnd();
      glEnable(GL_POLYGON_STIPPLE);  // the draw module's offset on the second pass
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      glBegin(GL_QUADS);
      glVertex3f(-0.5f, -0.5f, 0.1f);
      glVertex3f(0.5f, -0.5f, -0.3f);
      glVertex3f(0.5f, 0.5f, 0.2f);
      glVertex3f(-0.5f, 0.5f, 0.2f);
      glEnd();
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
      glDisable(GL_POLYGON_STIPPLE);
    }
  glFinish();
  EXPECT_NO_GL_ERROR();
}

}  // namespace
