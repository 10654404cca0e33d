// The command layer (vertex arrays and buffer objects, evaluators, selection
// and feedback, the attribute stacks) driven as a careless or hostile program
// drives it: sizes, offsets, counts and strides at the ends of their types,
// NaN and infinities, stacks pushed past their depth. Nothing may crash or
// read outside a buffer (the sanitizer build checks the library's reads); the
// GL error is the one GL 2.1 gives, measured on Mesa 22.3.6 where the
// specification leaves it open. Where Mesa itself crashes, hangs or departs
// from GL 2.1, the check is skipped on Mesa and says why.
#include <dlfcn.h>

#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using BadInputCommandLayerTest = GLTest;

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

void* Offset(uintptr_t bytes) { return reinterpret_cast<void*>(bytes); }

// The library under test was built with AddressSanitizer, whose operator new
// ends the program where an allocation fails instead of throwing.
bool UnderAddressSanitizer() { return dlsym(RTLD_DEFAULT, "__asan_init") != nullptr; }

GLint BufferParameter(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetBufferParameteriv(target, pname, &v);
  return v;
}

// A buffer of `bytes` bytes bound to `target`, filled with `data`.
GLuint MakeBuffer(GLenum target, GLsizeiptr bytes, const void* data) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(target, b);
  glBufferData(target, bytes, data, GL_STATIC_DRAW);
  return b;
}

const GLfloat kTriangle[6] = {-1, -1, 1, -1, 0, 1};

// ---- buffer objects (GL 2.1 §2.9) ------------------------------------------

TEST_F(BadInputCommandLayerTest, BufferDataNegativeSizeIsInvalidValueAndKeepsTheStore) {
  MakeBuffer(GL_ARRAY_BUFFER, 16, nullptr);
  glBufferData(GL_ARRAY_BUFFER, -1, nullptr, GL_STATIC_DRAW);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(BufferParameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 16);
  glBufferData(GL_ARRAY_BUFFER, 16, nullptr, 0x1234);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// A store that cannot be allocated: GL_OUT_OF_MEMORY, and the object is left
// with an empty store (Mesa: GL_BUFFER_SIZE 0).
TEST_F(BadInputCommandLayerTest, BufferDataTooLargeIsOutOfMemory) {
  MakeBuffer(GL_ARRAY_BUFFER, 16, nullptr);
  for (GLsizeiptr size : {GLsizeiptr(PTRDIFF_MAX), GLsizeiptr(1) << 40}) {
    glBufferData(GL_ARRAY_BUFFER, size, nullptr, GL_STATIC_DRAW);
    EXPECT_GL_ERROR(GL_OUT_OF_MEMORY) << size;
    EXPECT_EQ(BufferParameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 0) << size;
  }
  // The object still works.
  glBufferData(GL_ARRAY_BUFFER, 8, nullptr, GL_STATIC_DRAW);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferParameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 8);
}

TEST_F(BadInputCommandLayerTest, SubDataOutOfRangeIsInvalidValue) {
  const unsigned char bytes[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  MakeBuffer(GL_ARRAY_BUFFER, 16, bytes);
  unsigned char out[32] = {};
  glBufferSubData(GL_ARRAY_BUFFER, 8, 9, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, -1, 4, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 0, -1, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 17, 0, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 16, 0, bytes);  // the end itself, empty: fine
  EXPECT_NO_GL_ERROR();
  glGetBufferSubData(GL_ARRAY_BUFFER, 8, 9, out);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, -4, out);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(out[0], 0);  // nothing was written by the refused calls
  glGetBufferSubData(GL_ARRAY_BUFFER, 12, 4, out);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(out[0], 13);
  EXPECT_EQ(out[3], 16);
}

// offset + size overflows: Mesa's range check wraps and it copies (crash).
TEST_F(BadInputCommandLayerTest, SubDataWhoseEndOverflowsIsInvalidValue) {
  GLFX_SKIP_ON_MESA("offset + size wraps in Mesa's range check, which then copies outside the store");
  unsigned char bytes[16] = {};
  MakeBuffer(GL_ARRAY_BUFFER, 16, bytes);
  glBufferSubData(GL_ARRAY_BUFFER, PTRDIFF_MAX, PTRDIFF_MAX, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 8, PTRDIFF_MAX, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetBufferSubData(GL_ARRAY_BUFFER, PTRDIFF_MAX, 2, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 2, PTRDIFF_MAX, bytes);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(BadInputCommandLayerTest, NullDataPointersAreIgnored) {
  GLFX_SKIP_ON_MESA(
      "Mesa copies into a null glGetBufferSubData pointer and reads a null glDeleteBuffers list");
  MakeBuffer(GL_ARRAY_BUFFER, 16, nullptr);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 16, nullptr);
  glDeleteBuffers(1, nullptr);
  glGenBuffers(1, nullptr);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BadInputCommandLayerTest, NegativeCountsOfNamesAreInvalidValue) {
  GLuint b[2] = {0, 0};
  glGenBuffers(-1, b);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteBuffers(-1, b);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(BadInputCommandLayerTest, MapTwiceAndSubDataOfAMappedBufferAreInvalidOperation) {
  unsigned char bytes[16] = {};
  MakeBuffer(GL_ARRAY_BUFFER, 16, bytes);
  void* p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
  EXPECT_NE(p, nullptr);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // A new store ends the mapping (§2.9); unmapping then is an error.
  glBufferData(GL_ARRAY_BUFFER, 16, nullptr, GL_STATIC_DRAW);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferParameter(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_FALSE);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_FALSE);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

// Deleting a mapped buffer that is bound and sourced by the vertex array:
// no error, every binding reverts to 0 (§2.9), the name is free.
TEST_F(BadInputCommandLayerTest, DeletingAMappedBoundBufferUnbindsIt) {
  GLuint b = MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  ASSERT_NE(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), nullptr);
  glDeleteBuffers(1, &b);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(glIsBuffer(b), GL_FALSE);
}

// After its buffer is deleted, an array's pointer is the old offset, now a
// client address (8 here). Drawing from it reads address 8 on Mesa (a crash);
// libglfixed reads nothing there and draws no error.
TEST_F(BadInputCommandLayerTest, DrawingFromAnArrayWhoseBufferWasDeletedDoesNotCrash) {
  GLFX_SKIP_ON_MESA("Mesa reads the deleted buffer's offset as a client pointer (address 8) and crashes");
  const GLfloat data[8] = {9, 9, -1, -1, 1, -1, 0, 1};
  GLuint b = MakeBuffer(GL_ARRAY_BUFFER, sizeof data, data);
  glVertexPointer(2, GL_FLOAT, 0, Offset(8));
  glEnableClientState(GL_VERTEX_ARRAY);
  glDeleteBuffers(1, &b);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, Offset(8));  // the query still answers the offset given
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glArrayElement(1);
  EXPECT_NO_GL_ERROR();
  // The same after glPopClientAttrib brings back an array of a deleted buffer.
  b = MakeBuffer(GL_ARRAY_BUFFER, sizeof data, data);
  glVertexPointer(2, GL_FLOAT, 0, Offset(8));
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDeleteBuffers(1, &b);
  glPopClientAttrib();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_NO_GL_ERROR();
  // A new pointer is a client pointer again, and draws.
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glVertexPointer(2, GL_FLOAT, 0, kTriangle);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(pixels()[(32 * kWidth + 32) * 4], 255);
}

// GL 2.1 §2.9: an array in a mapped buffer may not be drawn from. Mesa 22
// checks this only in debug builds.
TEST_F(BadInputCommandLayerTest, DrawingFromAMappedBufferIsInvalidOperation) {
  GLFX_SKIP_ON_MESA("Mesa draws from a mapped buffer without an error");
  MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  ASSERT_NE(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  const GLuint indices[3] = {0, 1, 2};
  MakeBuffer(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  ASSERT_NE(glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

// ---- array draws (GL 2.1 §2.8) ---------------------------------------------

TEST_F(BadInputCommandLayerTest, DrawArgumentsOutOfRangeAreErrors) {
  glVertexPointer(2, GL_FLOAT, 0, kTriangle);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawArrays(0x20, 0, 3);  // (GL_POLYGON + 1 is an adjacency mode on Mesa)
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_INT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawRangeElements(GL_TRIANGLES, 5, 2, 3, GL_UNSIGNED_INT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  const GLint first[2] = {0, 0};
  const GLsizei count[2] = {3, -3};
  glMultiDrawArrays(GL_TRIANGLES, first, count, 2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

// Counts, firsts and strides far past a small buffer's end: the draw reads
// nothing outside the store (the sanitizer build checks) and is no error.
TEST_F(BadInputCommandLayerTest, ArrayDrawsPastTheEndOfABufferStayInside) {
  MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 3, 300);
  glDrawArrays(GL_TRIANGLES, INT_MAX, 3);
  glDrawArrays(GL_TRIANGLE_STRIP, INT_MAX - 1, 3);
  glArrayElement(INT_MAX);
  EXPECT_NO_GL_ERROR();
  // The offset near the top of the address space (-8 as a pointer).
  glVertexPointer(2, GL_FLOAT, 0, Offset(UINTPTR_MAX - 7));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glVertexPointer(2, GL_FLOAT, 16, Offset(4));
  glDrawArrays(GL_TRIANGLES, 0, 30);
  EXPECT_NO_GL_ERROR();
}

// A fan or polygon is fetched whole: one of INT_MAX vertices needs some
// 100 GB, and is GL_OUT_OF_MEMORY where that cannot be had (never an
// exception out of glDrawArrays). Mesa draws it in bounded memory, in
// minutes.
TEST_F(BadInputCommandLayerTest, FanOfIntMaxVerticesIsOutOfMemoryOrDrawn) {
  GLFX_SKIP_ON_MESA("Mesa draws the 2^31 vertices, which takes minutes");
  if (UnderAddressSanitizer()) GTEST_SKIP() << "the sanitizer's operator new aborts instead of throwing";
  MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLE_FAN, 0, INT_MAX);
  const GLenum error = glGetError();
  EXPECT_TRUE(error == GL_OUT_OF_MEMORY || error == GL_NO_ERROR) << error;
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 3);  // the next draw draws
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(pixels()[(32 * kWidth + 32) * 4], 255);
}

// A stride of INT_MAX: element i is i * INT_MAX bytes on, far past the store.
// Mesa limits strides to GL_MAX_VERTEX_ATTRIB_STRIDE (a GL 4.4 rule).
TEST_F(BadInputCommandLayerTest, HugeStridesReadNothingOutsideTheBuffer) {
  GLFX_SKIP_ON_MESA("Mesa refuses a stride above GL_MAX_VERTEX_ATTRIB_STRIDE (2048), a GL 4.4 rule");
  MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, INT_MAX, nullptr);
  EXPECT_NO_GL_ERROR();
  glEnableClientState(GL_VERTEX_ARRAY);
  glColorPointer(4, GL_UNSIGNED_BYTE, INT_MAX, Offset(4));
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 300);
  glDrawArrays(GL_TRIANGLES, INT_MAX - 3, 3);
  glArrayElement(INT_MAX);
  const GLuint indices[3] = {0, 0xFFFFFFFFu, 0x80000000u};
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, indices);
  EXPECT_NO_GL_ERROR();
}

// Element indices: count past the end of the element buffer, an offset past
// its end or at -4, indices naming elements far past the vertex buffer. (A
// count of 2^20, not INT_MAX: Mesa takes 40 s a call over INT_MAX indices.)
TEST_F(BadInputCommandLayerTest, ElementDrawsPastTheEndOfTheirBuffersStayInside) {
  MakeBuffer(GL_ARRAY_BUFFER, sizeof kTriangle, kTriangle);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  const GLuint indices[3] = {0, 0x7FFFFFFFu, 0xFFFFFFFFu};
  MakeBuffer(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  glDrawElements(GL_TRIANGLES, 300, GL_UNSIGNED_INT, nullptr);
  glDrawElements(GL_TRIANGLES, 1 << 20, GL_UNSIGNED_BYTE, nullptr);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, Offset(1000));
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, Offset(UINTPTR_MAX - 3));
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, Offset(11));  // one byte short of the last index
  glDrawRangeElements(GL_TRIANGLES, 0, 2, 1 << 20, GL_UNSIGNED_INT, nullptr);
  const GLsizei counts[2] = {3, 1 << 20};
  const void* offsets[2] = {nullptr, Offset(8)};
  glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets, 2);
  EXPECT_NO_GL_ERROR();
}

// NaN and infinite coordinates and colours in the arrays draw no error and
// write no pixel outside the window (the fixture's buffer is exactly the
// window: the sanitizer build would see a write past it).
TEST_F(BadInputCommandLayerTest, NonFiniteArrayValuesDrawWithoutError) {
  const GLfloat v[] = {kNaN, 0,     1,    1,     0,     kNaN,   kInf,  -kInf, 0,
                       1,    -kInf, kInf, 1e38f, 1e38f, -1e38f, 1e38f, 0,     0};
  const GLfloat c[] = {kNaN, 1, 1, 1, kInf, 0, 0, 1, -kInf, 1, kNaN, 1, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1};
  glVertexPointer(3, GL_FLOAT, 0, v);
  glColorPointer(4, GL_FLOAT, 0, c);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  for (GLenum mode :
       {GL_POINTS, GL_LINES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_POLYGON})
    glDrawArrays(mode, 0, 6);
  const GLubyte indices[6] = {5, 4, 3, 2, 1, 0};
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BadInputCommandLayerTest, InterleavedArraysBadFormatAndStride) {
  const GLfloat data[8] = {};
  glInterleavedArrays(0x1234, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glInterleavedArrays(GL_V2F, -1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glInterleavedArrays(0x1234, -1, data);  // Mesa looks at the stride first
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);  // nothing was set
}

// glInterleavedArrays with a buffer bound and offset 0, the common use: the
// arrays' offsets are sums on a null pointer (which must not be pointer
// arithmetic on null), and every format draws inside the buffer.
TEST_F(BadInputCommandLayerTest, InterleavedArraysAtOffsetZeroOfASmallBuffer) {
  const GLfloat data[6] = {-1, -1, 1, -1, 0, 1};
  MakeBuffer(GL_ARRAY_BUFFER, sizeof data, data);
  for (GLenum format : {GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F, GL_C4F_N3F_V3F,
                        GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F, GL_T2F_N3F_V3F,
                        GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F}) {
    glInterleavedArrays(format, 0, nullptr);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glInterleavedArrays(format, 2048, nullptr);  // Mesa's largest stride
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  EXPECT_NO_GL_ERROR();
}

// ---- evaluators (GL 2.1 §5.1) ----------------------------------------------

std::vector<GLfloat> ControlPoints(int n) {
  std::vector<GLfloat> p(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) p[static_cast<size_t>(i)] = static_cast<GLfloat>(i % 7) * 0.1f - 0.3f;
  return p;
}

// The largest maps: 30 x 30 points of GL_MAP2_VERTEX_4, read from an array of
// exactly that size (nothing past it is read), and one order more is refused.
TEST_F(BadInputCommandLayerTest, Map2OfTheMaximumOrder) {
  EXPECT_EQ(GetInt(GL_MAX_EVAL_ORDER), 30);
  const std::vector<GLfloat> pts = ControlPoints(30 * 30 * 4);
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 30, 0, 1, 120, 30, pts.data());
  EXPECT_NO_GL_ERROR();
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 31, 0, 1, 124, 30, pts.data());
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 30, 0, 1, 120, 0, pts.data());
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  GLint order[2] = {0, 0};
  glGetMapiv(GL_MAP2_VERTEX_4, GL_ORDER, order);
  EXPECT_EQ(order[0], 30);
  EXPECT_EQ(order[1], 30);
  glEnable(GL_MAP2_VERTEX_4);
  glMapGrid2f(40, 0, 1, 40, 0, 1);
  glEvalMesh2(GL_FILL, 0, 40, 0, 40);
  glEvalMesh2(GL_LINE, 0, 40, 0, 40);
  EXPECT_NO_GL_ERROR();
}

// A stride is read only as far as the order reaches: order 1 with a stride of
// INT_MAX reads one point; a stride below the map's size is refused.
TEST_F(BadInputCommandLayerTest, MapStrides) {
  const GLfloat one[3] = {0.5f, 0.25f, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, INT_MAX, 1, one);
  EXPECT_NO_GL_ERROR();
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, INT_MAX, 1, 0, 1, INT_MAX, 1, one);
  EXPECT_NO_GL_ERROR();
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, -3, 2, one);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, INT_MIN, 2, one);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, INT_MAX, one);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, INT_MIN, one);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  GLfloat coeff[3] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, coeff);
  EXPECT_EQ(coeff[0], 0.5f);
}

// The domain check is u1 == u2 (§5.1): NaN passes it, so does (-inf, inf);
// (inf, inf) does not. Evaluating such a map draws no error, and an integer
// query of an infinite domain is 0 on Mesa (lroundf of inf).
TEST_F(BadInputCommandLayerTest, NonFiniteDomains) {
  const std::vector<GLfloat> pts = ControlPoints(6);
  glMap1f(GL_MAP1_VERTEX_3, kNaN, 1, 3, 2, pts.data());
  EXPECT_NO_GL_ERROR();
  glMap1f(GL_MAP1_VERTEX_3, kNaN, kNaN, 3, 2, pts.data());
  EXPECT_NO_GL_ERROR();
  glMap1f(GL_MAP1_VERTEX_3, kInf, kInf, 3, 2, pts.data());
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_3, -kInf, kInf, 3, 2, pts.data());
  EXPECT_NO_GL_ERROR();
  GLfloat domain[2] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_DOMAIN, domain);
  EXPECT_EQ(domain[0], -kInf);
  EXPECT_EQ(domain[1], kInf);
  GLint idomain[2] = {7, 7};
  glGetMapiv(GL_MAP1_VERTEX_3, GL_DOMAIN, idomain);
  EXPECT_EQ(idomain[0], 0);
  EXPECT_EQ(idomain[1], 0);
  const GLdouble huge[6] = {0, 0, 0, 1e300, 1, 1};
  glMap1d(GL_MAP1_VERTEX_3, 1e300, -1e300, 3, 2, huge);  // rounds to ±inf in float
  EXPECT_NO_GL_ERROR();
  GLint icoeff[6] = {};
  glGetMapiv(GL_MAP1_VERTEX_3, GL_COEFF, icoeff);
  EXPECT_EQ(icoeff[3], 0);
  EXPECT_EQ(icoeff[4], 1);
  glEnable(GL_MAP1_VERTEX_3);
  glMap1f(GL_MAP1_VERTEX_3, kNaN, 1, 3, 2, pts.data());
  glMapGrid1f(4, 0, 1);
  glEvalMesh1(GL_LINE, 0, 4);
  glBegin(GL_LINE_STRIP);
  glEvalCoord1f(kNaN);
  glEvalCoord1f(kInf);
  glEvalCoord1f(-kInf);
  glEvalPoint1(INT_MAX);
  glEnd();
  glEnable(GL_MAP2_VERTEX_3);
  const std::vector<GLfloat> pts2 = ControlPoints(12);
  glMap2f(GL_MAP2_VERTEX_3, -kInf, kInf, 3, 2, kNaN, 0, 6, 2, pts2.data());
  EXPECT_NO_GL_ERROR();
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(2, 0, 1, 2, 0, 1);
  glEvalMesh2(GL_FILL, 0, 2, 0, 2);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BadInputCommandLayerTest, MapGridSegmentCounts) {
  glMapGrid1f(0, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid1f(INT_MIN, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid2f(INT_MAX, 0, 1, -1, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid2d(-1, 0, 1, 5, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  // Huge counts and non-finite grid domains are fine, and are what the
  // queries return (the integer query of a NaN is 0 on Mesa).
  glMapGrid1f(INT_MAX, kNaN, kInf);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), INT_MAX);
  EXPECT_EQ(GetInt(GL_MAP1_GRID_DOMAIN), 0);
  const std::array<GLfloat, 2> domain = GetFloats<2>(GL_MAP1_GRID_DOMAIN);
  EXPECT_TRUE(std::isnan(domain[0]));
  EXPECT_EQ(domain[1], kInf);
  glEnable(GL_MAP1_VERTEX_3);
  const std::vector<GLfloat> pts = ControlPoints(6);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts.data());
  glEvalMesh1(GL_LINE, 0, 10);
  glEvalPoint1(INT_MAX);
  glEvalPoint1(INT_MIN);
  glEnable(GL_MAP2_VERTEX_3);
  const std::vector<GLfloat> pts2 = ControlPoints(12);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, pts2.data());
  glMapGrid2f(INT_MAX, kNaN, kInf, INT_MAX, -kInf, kNaN);
  glEvalMesh2(GL_FILL, 0, 2, 0, 2);
  glEvalMesh2(GL_LINE, 0, 2, 0, 2);
  glEvalPoint2(INT_MAX, INT_MIN);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BadInputCommandLayerTest, EvalMeshBadModesAndEmptyRanges) {
  glEnable(GL_MAP1_VERTEX_3);
  const std::vector<GLfloat> pts = ControlPoints(6);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts.data());
  glEvalMesh1(0x1234, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh1(GL_FILL, 0, 1);  // not a mode of glEvalMesh1
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh2(0x1234, 0, 1, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh1(GL_POINT, 5, -5);
  glEvalMesh2(GL_FILL, 2, 0, 2, 0);
  glEvalMesh1(GL_LINE, INT_MIN, INT_MIN);
  EXPECT_NO_GL_ERROR();
}

// A mesh whose last index is INT_MAX: Mesa's int loop counter overflows there
// and never ends; libglfixed draws the one row and column and returns.
TEST_F(BadInputCommandLayerTest, EvalMeshEndingAtIntMaxEnds) {
  GLFX_SKIP_ON_MESA("Mesa's glEvalMesh loop counter overflows at INT_MAX and the loop never ends");
  glEnable(GL_MAP2_VERTEX_3);
  const std::vector<GLfloat> pts = ControlPoints(12);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, pts.data());
  glMapGrid2f(4, 0, 1, 4, 0, 1);
  for (GLenum mode : {GL_POINT, GL_LINE, GL_FILL}) glEvalMesh2(mode, INT_MAX, INT_MAX, INT_MAX - 1, INT_MAX);
  glEnable(GL_MAP1_VERTEX_3);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts.data());
  glMapGrid1f(4, 0, 1);
  glEvalMesh1(GL_LINE, INT_MAX - 1, INT_MAX);
  EXPECT_NO_GL_ERROR();
}

// A mesh of 2^20 points in one glBegin/glEnd: the vertices go through the
// bounded immediate-mode store (Mesa's 512 KiB buffer, then a draw), never
// all at once. (Mesa takes about 1.2 s a million points.)
TEST_F(BadInputCommandLayerTest, LargeEvalMeshIsDrawnInPieces) {
  glEnable(GL_MAP2_VERTEX_3);
  const std::vector<GLfloat> pts = ControlPoints(12);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, pts.data());
  glMapGrid2f(1024, 0, 1, 1024, 0, 1);
  glEvalMesh2(GL_POINT, 0, 1023, 0, 1023);
  EXPECT_NO_GL_ERROR();
}

// ---- selection and feedback (GL 2.1 §5.2, §5.3) ----------------------------

void DrawTriangle(GLfloat z = 0) {
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, z);
  glVertex3f(1, -1, z);
  glVertex3f(0, 1, z);
  glEnd();
}

// A one-word selection buffer: the hit records overflow, glRenderMode
// answers -1, and only the word that fits is written.
TEST_F(BadInputCommandLayerTest, TinySelectionBufferOverflows) {
  GLuint sel[4] = {77, 77, 77, 77};
  glSelectBuffer(1, sel);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(5);
  DrawTriangle();
  glPushName(6);
  DrawTriangle();
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(sel[0], 1u);
  EXPECT_EQ(sel[1], 77u);
  glSelectBuffer(-1, sel);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(BadInputCommandLayerTest, NameStackLimits) {
  GLuint sel[256] = {};
  glSelectBuffer(256, sel);
  glRenderMode(GL_SELECT);
  glSelectBuffer(256, sel);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glInitNames();
  EXPECT_EQ(GetInt(GL_MAX_NAME_STACK_DEPTH), 64);
  for (int i = 0; i < 64; ++i) glPushName(static_cast<GLuint>(i));
  EXPECT_NO_GL_ERROR();
  glPushName(64);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 64);
  DrawTriangle();
  for (int i = 0; i < 64; ++i) glPopName();
  EXPECT_NO_GL_ERROR();
  glPopName();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  glLoadName(3);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(sel[0], 64u);  // the record of the full stack
  EXPECT_EQ(sel[3 + 63], 63u);
}

// glRenderMode between glBegin and glEnd is refused; the primitive goes on
// in the mode it began in.
TEST_F(BadInputCommandLayerTest, RenderModeChangeMidDrawIsRefused) {
  GLuint sel[16] = {};
  glSelectBuffer(16, sel);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glRenderMode(GL_SELECT);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glRenderMode(GL_RENDER);
  glPushName(2);
  glVertex2f(1, -1);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_SELECT);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(sel[0], 1u);  // one name: the refused glPushName pushed nothing
  EXPECT_EQ(sel[3], 1u);
  glRenderMode(0x1234);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// Triangles whose z is NaN or infinite are no hit on Mesa (clipped away).
TEST_F(BadInputCommandLayerTest, NonFiniteDepthsInSelection) {
  GLuint sel[4] = {77, 77, 77, 77};
  glSelectBuffer(4, sel);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(9);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, kNaN);
  glVertex3f(1, 0, kInf);
  glVertex3f(0, 1, -kInf);
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(sel[0], 77u);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BadInputCommandLayerTest, TinyFeedbackBufferOverflows) {
  GLfloat fb[8];
  for (GLfloat& f : fb) f = -7;
  glFeedbackBuffer(2, 0x1234, fb);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFeedbackBuffer(-1, GL_2D, fb);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFeedbackBuffer(4, GL_2D, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFeedbackBuffer(2, GL_2D, fb);
  EXPECT_NO_GL_ERROR();
  glRenderMode(GL_FEEDBACK);
  DrawTriangle();
  glPassThrough(kNaN);
  glPassThrough(kInf);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  EXPECT_EQ(fb[0], static_cast<GLfloat>(GL_POLYGON_TOKEN));
  EXPECT_EQ(fb[1], 3.0f);
  EXPECT_EQ(fb[2], -7.0f);  // nothing past the two words given
  // Pass-through tokens carry NaN and infinities as they are.
  glFeedbackBuffer(4, GL_2D, fb);
  glRenderMode(GL_FEEDBACK);
  glPassThrough(kNaN);
  glPassThrough(-kInf);
  EXPECT_EQ(glRenderMode(GL_RENDER), 4);
  EXPECT_EQ(fb[0], static_cast<GLfloat>(GL_PASS_THROUGH_TOKEN));
  EXPECT_TRUE(std::isnan(fb[1]));
  EXPECT_EQ(fb[3], -kInf);
  EXPECT_NO_GL_ERROR();
}

// Feedback of every type with vertices at NaN, infinity and w = 0: no error,
// nothing written past the buffer.
TEST_F(BadInputCommandLayerTest, NonFiniteVerticesInFeedback) {
  for (GLenum type : {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE}) {
    std::vector<GLfloat> fb(20, -7.0f);
    glFeedbackBuffer(19, type, fb.data());
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex4f(kNaN, 0, 0, 1);
    glVertex4f(0, 0, 0, 0);
    glVertex4f(kInf, 0, 0, 1);
    glVertex4f(0, 0, kNaN, kNaN);
    glColor4f(kNaN, kInf, -kInf, 1);
    glVertex3f(0, 0, 0);
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, kNaN);
    glVertex3f(1e38f, 0, 0);
    glVertex4f(0, 1, 0, 1e-38f);
    glEnd();
    glRenderMode(GL_RENDER);
    EXPECT_EQ(fb[19], -7.0f) << type;
    EXPECT_NO_GL_ERROR();
  }
}

// ---- the attribute stacks (GL 2.1 §6.1.14) ---------------------------------

TEST_F(BadInputCommandLayerTest, AttribStackDepthLimits) {
  EXPECT_EQ(GetInt(GL_MAX_ATTRIB_STACK_DEPTH), 16);
  for (int i = 0; i < 16; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_NO_GL_ERROR();
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 16);
  for (int i = 0; i < 16; ++i) glPopAttrib();
  EXPECT_NO_GL_ERROR();
  glPopAttrib();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  glPushAttrib(0);
  glPopAttrib();
  glPushAttrib(0xFFFFFFFFu);  // bits of no group are ignored
  glPopAttrib();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);
}

TEST_F(BadInputCommandLayerTest, ClientAttribStackDepthLimits) {
  EXPECT_EQ(GetInt(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH), 16);
  for (int i = 0; i < 16; ++i) glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  EXPECT_NO_GL_ERROR();
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 16);
  for (int i = 0; i < 16; ++i) glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
  glPopClientAttrib();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  glPushClientAttrib(0xFFFFFFFFu);
  glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
}

// Between glBegin and glEnd both pushes are refused and push nothing.
TEST_F(BadInputCommandLayerTest, AttribPushesInsideBeginEndAreRefused) {
  glBegin(GL_TRIANGLES);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
}

// NaN and infinities pushed and popped come back as they were.
TEST_F(BadInputCommandLayerTest, NonFiniteStateSurvivesPushAndPop) {
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glColor4f(kNaN, kInf, -kInf, 0.5f);
  glPointSize(kNaN);
  glLineWidth(kInf);
  glFogf(GL_FOG_DENSITY, kNaN);
  glAlphaFunc(GL_LESS, kNaN);
  glPolygonOffset(kNaN, kInf);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glColor4f(0, 0, 0, 0);
  glPopAttrib();
  const std::array<GLfloat, 4> c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_EQ(GetInt(GL_CURRENT_COLOR), INT_MIN);  // a NaN colour as an integer, on Mesa
  EXPECT_TRUE(std::isnan(c[0]));
  EXPECT_EQ(c[1], kInf);
  EXPECT_EQ(c[2], -kInf);
  glPopAttrib();
  DrainErrors();  // (the point size and line width may be refused)
  DrawTriangle();
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
