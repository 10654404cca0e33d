// Buffer objects (GL 2.1 §2.9): names, data, mapping, queries, the binding
// points, arrays and indices as offsets, glReadPixels into a pack buffer.
#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

class BufferObjectTest : public GLTest {};

GLint BufferParam(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetBufferParameteriv(target, pname, &v);
  return v;
}

TEST_F(BufferObjectTest, NamesBecomeObjectsWhenBound) {
  GLuint b[3] = {0, 0, 0};
  glGenBuffers(3, b);
  EXPECT_NO_GL_ERROR();
  EXPECT_NE(b[0], 0u);
  EXPECT_NE(b[0], b[1]);
  EXPECT_NE(b[1], b[2]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE);  // a name only, until bound
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_TRUE);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(glIsBuffer(0), GL_FALSE);
  glDeleteBuffers(3, b);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);  // deleting a bound buffer unbinds it
  EXPECT_NO_GL_ERROR();
  glGenBuffers(-1, b);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteBuffers(-1, b);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(BufferObjectTest, EveryBindingPoint) {
  GLuint b[4];
  glGenBuffers(4, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b[2]);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[3]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_ELEMENT_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[1]));
  EXPECT_EQ(GetInt(GL_PIXEL_PACK_BUFFER_BINDING), static_cast<GLint>(b[2]));
  EXPECT_EQ(GetInt(GL_PIXEL_UNPACK_BUFFER_BINDING), static_cast<GLint>(b[3]));
  glBindBuffer(GL_TEXTURE_2D, b[0]);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDeleteBuffers(4, b);
  EXPECT_EQ(GetInt(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_PIXEL_PACK_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);
}

// GL 2.1 (a compatibility context): any unused name may be bound, a deleted
// one too; it becomes a new object.
TEST_F(BufferObjectTest, BindingADeletedNameMakesANewObject) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glDeleteBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsBuffer(b), GL_TRUE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 0);
  glBindBuffer(GL_ARRAY_BUFFER, 4242);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsBuffer(4242), GL_TRUE);
}

TEST_F(BufferObjectTest, ParametersAndData) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_STATIC_DRAW);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  const unsigned char data[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glBufferData(GL_ARRAY_BUFFER, 8, data, GL_DYNAMIC_COPY);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 8);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_DYNAMIC_COPY);
  const unsigned char patch[3] = {70, 80, 90};
  glBufferSubData(GL_ARRAY_BUFFER, 4, 3, patch);
  unsigned char back[8] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, back);
  EXPECT_NO_GL_ERROR();
  const unsigned char expected[8] = {1, 2, 3, 4, 70, 80, 90, 8};
  EXPECT_EQ(std::memcmp(back, expected, 8), 0);
  glBufferData(GL_ARRAY_BUFFER, 16, nullptr, GL_STREAM_READ);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 16);
  GLint bad;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &bad);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDeleteBuffers(1, &b);
}

TEST_F(BufferObjectTest, DataErrors) {
  const unsigned char data[8] = {};
  glBufferData(GL_ARRAY_BUFFER, 8, data, GL_STATIC_DRAW);  // nothing bound
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLint v;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, -1, data, GL_STATIC_DRAW);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferData(GL_ARRAY_BUFFER, 8, data, GL_RGBA);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBufferData(GL_TEXTURE_2D, 8, data, GL_STATIC_DRAW);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBufferData(GL_ARRAY_BUFFER, 8, data, GL_STATIC_DRAW);
  EXPECT_NO_GL_ERROR();
  glBufferSubData(GL_ARRAY_BUFFER, -1, 2, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 0, -2, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBufferSubData(GL_ARRAY_BUFFER, 4, 5, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  unsigned char back[16];
  glGetBufferSubData(GL_ARRAY_BUFFER, 6, 3, back);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_RGBA, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDeleteBuffers(1, &b);
}

TEST_F(BufferObjectTest, MapAndUnmap) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  const unsigned char data[4] = {9, 8, 7, 6};
  glBufferData(GL_ARRAY_BUFFER, 4, data, GL_STATIC_DRAW);
  void* none = reinterpret_cast<void*>(0x1);
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &none);
  EXPECT_EQ(none, nullptr);
  unsigned char* p = static_cast<unsigned char*>(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE));
  ASSERT_NE(p, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(p[2], 7);
  p[2] = 77;
  void* q = nullptr;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
  EXPECT_EQ(q, p);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_TRUE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);  // mapped twice
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBufferSubData(GL_ARRAY_BUFFER, 0, 1, data);  // while mapped
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  unsigned char back[4];
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, back);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, back);
  EXPECT_EQ(back[2], 77);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_FALSE);  // not mapped
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_RGBA), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);  // nothing bound
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDeleteBuffers(1, &b);
}

// Pointers given with a buffer bound are offsets into it, and keep that
// buffer when the binding changes.
TEST_F(BufferObjectTest, ArrayPointersAreOffsets) {
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glVertexPointer(3, GL_FLOAT, 0, reinterpret_cast<void*>(16));
  glBindBuffer(GL_ARRAY_BUFFER, b[1]);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, reinterpret_cast<void*>(4));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glNormalPointer(GL_FLOAT, 0, nullptr);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[1]));
  EXPECT_EQ(GetInt(GL_NORMAL_ARRAY_BUFFER_BINDING), 0);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, reinterpret_cast<void*>(16));
  glDeleteBuffers(1, &b[0]);  // every binding of it reverts to 0
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[1]));
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, reinterpret_cast<void*>(16));
  glDeleteBuffers(1, &b[1]);
  EXPECT_NO_GL_ERROR();
}

// An array whose buffer was deleted keeps its offset as the pointer; a draw
// must not read client memory at that address.
TEST_F(BufferObjectTest, DrawAfterTheArrayBufferIsDeleted) {
  GLFX_SKIP_ON_MESA("Mesa reads client memory at the old offset (a crash)");
  const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, reinterpret_cast<void*>(16));
  glEnableClientState(GL_VERTEX_ARRAY);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDeleteBuffers(1, &b);
  glDrawArrays(GL_QUADS, 0, 4);
  glArrayElement(0);
  glPopClientAttrib();  // restores an array of the deleted buffer
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_NO_GL_ERROR();
}

// A quad from a vertex buffer with indices from an element buffer; indices
// past the end of the vertex buffer never read outside it.
TEST_F(BufferObjectTest, DrawFromBuffersAndIndicesPastTheEnd) {
  const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLuint idx[8] = {0, 0, 0, 1, 2, 3, 100000000, 7};
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 0);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, reinterpret_cast<void*>(3 * sizeof(GLuint)));
  EXPECT_NO_GL_ERROR();
  const unsigned char* px = pixels() + (32 * kWidth + 32) * 4;
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 255);
  EXPECT_EQ(px[2], 0);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, reinterpret_cast<void*>(5 * sizeof(GLuint)));
  glDrawArrays(GL_TRIANGLES, 2, 30000);  // far past the buffer's end
  glFinish();
  DrainErrors();
  glDeleteBuffers(2, b);
}

// A draw of 2^31 - 1 vertices from an 8-vertex buffer: never reads outside
// the buffer, draws what the real vertices make, and ends quickly.
TEST_F(BufferObjectTest, DrawFarPastTheEndOfABuffer) {
  GLFX_SKIP_ON_MESA("not run on Mesa: it would process all 2^31 vertices");
  const GLfloat quad[16] = {-1, -1, 1, -1, 1, 1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1};
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 1);
  for (GLenum mode : {GL_TRIANGLES, GL_QUADS, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUAD_STRIP, GL_POLYGON})
    glDrawArrays(mode, 4, 0x7fffffff);
  EXPECT_NO_GL_ERROR();
  const unsigned char* px = pixels() + (32 * kWidth + 32) * 4;
  EXPECT_EQ(px[1], 255);  // the quad made by the real vertices 4..7 is drawn
  glDeleteBuffers(1, &b);
}

TEST_F(BufferObjectTest, DrawingFromAMappedBufferIsAnError) {
  GLFX_SKIP_ON_MESA("Mesa draws from a mapped buffer without an error");
  const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(1, &b);
}

TEST_F(BufferObjectTest, ReadPixelsIntoAPixelPackBuffer) {
  glClearColor(1, 0, 0.5f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
  glBufferData(GL_PIXEL_PACK_BUFFER, 64, nullptr, GL_STREAM_READ);
  glReadPixels(1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(8));
  EXPECT_NO_GL_ERROR();
  unsigned char back[24] = {};
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 8, 16, back);
  EXPECT_EQ(back[0], 255);
  EXPECT_EQ(back[1], 0);
  EXPECT_EQ(back[2], 128);
  EXPECT_EQ(back[15], 255);
  glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(8));  // 64 bytes from 8
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &b);
}

TEST_F(BufferObjectTest, ClientAttribStackKeepsBindings) {
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b[1]);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPopClientAttrib();
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_PIXEL_PACK_BUFFER_BINDING), static_cast<GLint>(b[1]));
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(2, b);
}

}  // namespace
