// Vertex array objects (ARB_vertex_array_object; GL 3.0 §2.10): names, what
// an object holds, the errors, display lists, the client attribute stack and
// drawing. Every expectation was measured on Mesa 22.3 (the test runs on it
// too; reference/MESA_FACTS.md, "Vertex array objects").
#include "api/gl_test_fixture.h"

#ifndef GL_VERTEX_ARRAY_BINDING
#define GL_VERTEX_ARRAY_BINDING 0x85B5
#endif

namespace glfx_test {
namespace {

using VertexArrayObjectTest = GLTest;

TEST_F(VertexArrayObjectTest, NamesBecomeVertexArraysWhenBound) {
  GLuint v[3] = {0, 0, 0};
  glGenVertexArrays(3, v);
  ASSERT_NO_GL_ERROR();
  EXPECT_NE(v[0], 0u);
  EXPECT_NE(v[0], v[1]);
  EXPECT_NE(v[1], v[2]);
  EXPECT_EQ(glIsVertexArray(v[0]), GL_FALSE);  // generated, not bound yet
  EXPECT_EQ(glIsVertexArray(0), GL_FALSE);
  glBindVertexArray(v[0]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsVertexArray(v[0]), GL_TRUE);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), static_cast<GLint>(v[0]));
  // A name glGenVertexArrays never gave.
  glBindVertexArray(v[2] + 100);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), static_cast<GLint>(v[0]));
  // Deleting the bound object binds 0; its name is no longer bindable.
  glDeleteVertexArrays(1, &v[0]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), 0);
  EXPECT_EQ(glIsVertexArray(v[0]), GL_FALSE);
  glBindVertexArray(v[0]);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // A generated name never bound is deleted quietly too; 0 and unknown names are ignored.
  const GLuint ignored[3] = {0, v[1], v[2] + 100};
  glDeleteVertexArrays(3, ignored);
  EXPECT_NO_GL_ERROR();
  glBindVertexArray(v[1]);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindVertexArray(v[2]);
  EXPECT_NO_GL_ERROR();
  glBindVertexArray(0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(VertexArrayObjectTest, NegativeCountsAndBeginEndAreErrors) {
  GLuint v[2] = {0, 0};
  glGenVertexArrays(-1, v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteVertexArrays(-1, v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGenVertexArrays(1, v);
  glBegin(GL_TRIANGLES);
  glBindVertexArray(v[0]);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), 0);
  glBegin(GL_TRIANGLES);
  glGenVertexArrays(1, &v[1]);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glIsVertexArray(v[0]);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glDeleteVertexArrays(1, v);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindVertexArray(v[0]);  // still there
  EXPECT_NO_GL_ERROR();
}

// GL 3.0 §5.4: the commands run while a list compiles and are not compiled.
TEST_F(VertexArrayObjectTest, RunsAtOnceInsideDisplayLists) {
  GLuint v = 0;
  glGenVertexArrays(1, &v);
  glNewList(1, GL_COMPILE);
  glBindVertexArray(v);
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), static_cast<GLint>(v));
  glBindVertexArray(0);
  glCallList(1);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), 0);
}

TEST_F(VertexArrayObjectTest, HoldsTheArraysAndTheElementBufferOnly) {
  GLuint v = 0, b[2] = {0, 0};
  glGenVertexArrays(1, &v);
  glGenBuffers(2, b);
  glVertexPointer(2, GL_SHORT, 8, reinterpret_cast<const void*>(16));
  glEnableClientState(GL_COLOR_ARRAY);
  glBindVertexArray(v);
  // A new object has the initial array state.
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_FALSE);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glVertexPointer(3, GL_FLOAT, 0, reinterpret_cast<const void*>(4));
  glEnableClientState(GL_NORMAL_ARRAY);
  glClientActiveTexture(GL_TEXTURE2);
  ASSERT_NO_GL_ERROR();
  glBindVertexArray(0);
  // The default object is as it was; the array buffer binding and the client
  // active texture are context state.
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_STRIDE), 8);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
  EXPECT_EQ(GetInt(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE2);
  GLvoid* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, reinterpret_cast<GLvoid*>(16));
  glBindVertexArray(v);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_ELEMENT_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[1]));
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_TRUE);
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, reinterpret_cast<GLvoid*>(4));
  EXPECT_NO_GL_ERROR();
}

// GL 3.0 §2.10: a named object takes no client memory (Mesa refuses it in a
// compatibility context too); a null pointer and the default object are fine.
TEST_F(VertexArrayObjectTest, RefusesClientPointersInANamedObject) {
  static const GLfloat kVerts[6] = {0};
  GLuint v = 0;
  glGenVertexArrays(1, &v);
  glBindVertexArray(v);
  glVertexPointer(3, GL_FLOAT, 0, kVerts);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // Mesa stores the refused pointer anyway, as it does one with a negative
  // stride; GL 2.1 §2.5: a command in error changes nothing.
  if (!kTestingAgainstMesa) EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 4);
  // The check comes before the size's and the type's (Mesa's order).
  glVertexPointer(5, GL_UNSIGNED_BYTE, 0, kVerts);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glVertexPointer(2, GL_FLOAT, -1, kVerts);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glColorPointer(3, GL_FLOAT, 0, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 3);
  glBindVertexArray(0);
  glVertexPointer(3, GL_FLOAT, 0, kVerts);
  EXPECT_NO_GL_ERROR();
}

TEST_F(VertexArrayObjectTest, ClientAttribStackSavesTheBindingAndTheState) {
  GLuint v[3] = {0, 0, 0}, b = 0;
  glGenVertexArrays(3, v);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBindVertexArray(v[0]);
  glVertexPointer(3, GL_FLOAT, 0, reinterpret_cast<const void*>(16));
  glEnableClientState(GL_VERTEX_ARRAY);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glVertexPointer(4, GL_FLOAT, 0, reinterpret_cast<const void*>(48));
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindVertexArray(v[1]);
  glVertexPointer(2, GL_FLOAT, 0, reinterpret_cast<const void*>(32));
  glPopClientAttrib();
  ASSERT_NO_GL_ERROR();
  // The saved object is bound again, with the saved state; the other keeps its own.
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), static_cast<GLint>(v[0]));
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glBindVertexArray(v[1]);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 2);
  // The saved object deleted before the pop: the whole group stays as it is,
  // the array buffer binding and the client active texture included, with
  // no error.
  glBindVertexArray(v[2]);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glBindVertexArray(v[1]);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glClientActiveTexture(GL_TEXTURE3);
  glDeleteVertexArrays(1, &v[2]);
  glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), static_cast<GLint>(v[1]));
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE3);
  // Popping to the default object.
  glBindVertexArray(0);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glBindVertexArray(v[1]);
  glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BINDING), 0);
}

// Each object draws its own buffers, colours and element list.
TEST_F(VertexArrayObjectTest, DrawsFromTheBoundObject) {
  // Left and right halves, red and green, each from its own buffer.
  const GLfloat left[] = {-1, -1, 1, 0, 0, 0, -1, 1, 0, 0, 0, 1, 1, 0, 0, -1, 1, 1, 0, 0};
  const GLfloat right[] = {0, -1, 0, 1, 0, 1, -1, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 0};
  const GLubyte quad[] = {0, 1, 2, 0, 2, 3};
  GLuint v[2] = {0, 0}, b[3] = {0, 0, 0};
  glGenVertexArrays(2, v);
  glGenBuffers(3, b);
  const GLfloat* data[2] = {left, right};
  for (int i = 0; i < 2; ++i) {
    glBindVertexArray(v[i]);
    glBindBuffer(GL_ARRAY_BUFFER, b[i]);
    glBufferData(GL_ARRAY_BUFFER, sizeof(left), data[i], GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 5 * sizeof(GLfloat), nullptr);
    glColorPointer(3, GL_FLOAT, 5 * sizeof(GLfloat), reinterpret_cast<const void*>(2 * sizeof(GLfloat)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[2]);
  }
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(quad), quad, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindVertexArray(v[0]);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, nullptr);
  glBindVertexArray(0);  // no arrays enabled in the default object: nothing drawn
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ASSERT_NO_GL_ERROR();
  const unsigned char* p = pixels();
  auto at = [p](int x, int y) { return p + (y * kWidth + x) * 4; };
  EXPECT_EQ(at(10, 32)[0], 255);
  EXPECT_EQ(at(50, 32)[2], 255);  // still the clear colour
  glBindVertexArray(v[1]);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, nullptr);
  ASSERT_NO_GL_ERROR();
  p = pixels();
  EXPECT_EQ(at(10, 32)[0], 255);
  EXPECT_EQ(at(50, 32)[1], 255);
  EXPECT_EQ(at(50, 32)[2], 0);
}

// Objects are not shared with the share group (GL 3.0 appendix D).
TEST_F(VertexArrayObjectTest, NotSharedBetweenContexts) {
  GLuint v = 0;
  glGenVertexArrays(1, &v);
  glBindVertexArray(v);
  OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, ctx_);
  ASSERT_NE(shared, nullptr);
  std::vector<unsigned char> buffer(kWidth * kHeight * 4);
  ASSERT_EQ(OSMesaMakeCurrent(shared, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsVertexArray(v), GL_FALSE);
  glBindVertexArray(v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  OSMesaDestroyContext(shared);
  EXPECT_EQ(glIsVertexArray(v), GL_TRUE);
}

}  // namespace
}  // namespace glfx_test
