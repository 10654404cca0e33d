// Display lists (GL 2.1 §5.4): the list entry points, their queries and
// errors, what is compiled and what is executed at once, and client data
// captured at compile time. Run on Mesa too (mesa_api.*).
#include "api/gl_test_fixture.h"

namespace glfx_test {
namespace {

class DisplayListTest : public GLTest {
 protected:
  // The x translation of the modelview matrix: what the test lists change.
  static float TranslationX() {
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    return m[12];
  }
  // List `name` translates by `x`.
  static void DefineTranslation(GLuint name, float x) {
    glNewList(name, GL_COMPILE);
    glTranslatef(x, 0, 0);
    glEndList();
  }
  std::array<unsigned char, 4> Pixel(int x, int y) {
    const unsigned char* p = pixels() + (static_cast<size_t>(y) * kWidth + x) * 4;
    return {p[0], p[1], p[2], p[3]};
  }
  static void FullQuad() {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
};

TEST_F(DisplayListTest, QueriesOutsideAndInsideNewList) {
  EXPECT_GE(GetInt(GL_MAX_LIST_NESTING), 64);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
  EXPECT_EQ(GetInt(GL_LIST_MODE), 0);
  EXPECT_EQ(GetInt(GL_LIST_BASE), 0);
  glNewList(5, GL_COMPILE);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 5);  // glGet is executed at once, not compiled
  EXPECT_EQ(GetInt(GL_LIST_MODE), GL_COMPILE);
  glEndList();
  glNewList(6, GL_COMPILE_AND_EXECUTE);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 6);
  EXPECT_EQ(GetInt(GL_LIST_MODE), GL_COMPILE_AND_EXECUTE);
  glEndList();
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
  EXPECT_EQ(GetInt(GL_LIST_MODE), 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ListBaseIsCompiledAndQueried) {
  glListBase(7);
  EXPECT_EQ(GetInt(GL_LIST_BASE), 7);
  glNewList(1, GL_COMPILE);
  glListBase(9);
  glEndList();
  EXPECT_EQ(GetInt(GL_LIST_BASE), 7);  // compiled, not executed
  glCallList(1);
  EXPECT_EQ(GetInt(GL_LIST_BASE), 9);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, NewListErrors) {
  glNewList(0, GL_COMPILE);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glNewList(1, GL_COMPILE + 7);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
  glNewList(1, GL_COMPILE);
  glNewList(2, GL_COMPILE);  // while compiling
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 1);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glEndList();  // without glNewList
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glNewList(3, GL_COMPILE);  // between glBegin and glEnd
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
}

TEST_F(DisplayListTest, GenIsDeleteLists) {
  glGenLists(-1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(glGenLists(0), 0u);
  EXPECT_NO_GL_ERROR();
  DefineTranslation(2, 1);
  const GLuint first = glGenLists(3);
  ASSERT_NE(first, 0u);
  for (GLuint i = first; i < first + 3; ++i) {
    EXPECT_NE(i, 2u);                 // names already used are not handed out
    EXPECT_EQ(glIsList(i), GL_TRUE);  // glGenLists creates empty lists
  }
  EXPECT_EQ(glIsList(2), GL_TRUE);
  EXPECT_EQ(glIsList(first + 1000), GL_FALSE);
  EXPECT_EQ(glIsList(0), GL_FALSE);
  glDeleteLists(first, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(glIsList(first), GL_TRUE);
  glDeleteLists(first, 3);
  for (GLuint i = first; i < first + 3; ++i) EXPECT_EQ(glIsList(i), GL_FALSE);
  glDeleteLists(first, 0);  // nothing
  EXPECT_NO_GL_ERROR();
  // A deleted list is no longer called.
  glDeleteLists(2, 1);
  glCallList(2);
  EXPECT_EQ(TranslationX(), 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CompileDoesNotExecuteCompileAndExecuteDoes) {
  glNewList(1, GL_COMPILE);
  glTranslatef(2, 0, 0);
  EXPECT_EQ(TranslationX(), 0.0f);
  glEndList();
  EXPECT_EQ(TranslationX(), 0.0f);
  glCallList(1);
  EXPECT_EQ(TranslationX(), 2.0f);
  glLoadIdentity();
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  glTranslatef(3, 0, 0);
  EXPECT_EQ(TranslationX(), 3.0f);
  glEndList();
  glCallList(2);
  EXPECT_EQ(TranslationX(), 6.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, NewListReplacesTheListAtEndList) {
  DefineTranslation(1, 1);
  glNewList(1, GL_COMPILE);
  glTranslatef(10, 0, 0);
  glEndList();
  glCallList(1);
  EXPECT_EQ(TranslationX(), 10.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CallListOfMissingListIsIgnored) {
  glCallList(12345);
  EXPECT_NO_GL_ERROR();
  const GLuint names[2] = {12345, 12346};
  glCallLists(2, GL_UNSIGNED_INT, names);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(TranslationX(), 0.0f);
}

TEST_F(DisplayListTest, NestedCallsRunInsideTheCallingList) {
  DefineTranslation(1, 1);
  glNewList(2, GL_COMPILE);
  glTranslatef(10, 0, 0);
  glCallList(1);
  glCallList(1);
  glEndList();
  glCallList(2);
  EXPECT_EQ(TranslationX(), 12.0f);
  // A list called by name at execution: redefining the callee changes the caller.
  DefineTranslation(1, 100);
  glLoadIdentity();
  glCallList(2);
  EXPECT_EQ(TranslationX(), 210.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, NestingDeeperThanTheLimitIsIgnored) {
  // List i translates by 1 and calls list i + 1: 100 levels.
  for (GLuint i = 1; i <= 100; ++i) {
    glNewList(i, GL_COMPILE);
    glTranslatef(1, 0, 0);
    glCallList(i + 1);
    glEndList();
  }
  const GLint limit = GetInt(GL_MAX_LIST_NESTING);
  glCallList(1);
  EXPECT_EQ(TranslationX(), static_cast<float>(limit));
  EXPECT_NO_GL_ERROR();
  // A list that calls itself stops at the same depth.
  glNewList(200, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(200);
  glEndList();
  glLoadIdentity();
  glCallList(200);
  EXPECT_EQ(TranslationX(), static_cast<float>(limit));
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CallListsEveryType) {
  DefineTranslation(300, 300);
  DefineTranslation(44, 44);
  struct Case {
    GLenum type;
    std::vector<unsigned char> bytes;
    GLuint base;
  };
  auto bytesOf = [](const void* p, size_t n) {
    const unsigned char* b = static_cast<const unsigned char*>(p);
    return std::vector<unsigned char>(b, b + n);
  };
  const GLbyte b = -10;
  const GLubyte ub = 44;
  const GLshort s = -10;
  const GLushort us = 300;
  const GLint i = 300;
  const GLuint ui = 300;
  const GLfloat f = 300.0f;
  const Case cases[] = {
      {GL_BYTE, bytesOf(&b, 1), 310},  {GL_UNSIGNED_BYTE, bytesOf(&ub, 1), 0},
      {GL_SHORT, bytesOf(&s, 2), 310}, {GL_UNSIGNED_SHORT, bytesOf(&us, 2), 0},
      {GL_INT, bytesOf(&i, 4), 0},     {GL_UNSIGNED_INT, bytesOf(&ui, 4), 0},
      {GL_FLOAT, bytesOf(&f, 4), 0},   {GL_2_BYTES, {1, 44}, 0},
      {GL_3_BYTES, {0, 1, 44}, 0},     {GL_4_BYTES, {0, 0, 1, 44}, 0},
  };
  for (const Case& c : cases) {
    glLoadIdentity();
    glListBase(c.base);
    glCallLists(1, c.type, c.bytes.data());
    EXPECT_EQ(TranslationX(), c.type == GL_UNSIGNED_BYTE ? 44.0f : 300.0f) << "type 0x" << std::hex << c.type;
    EXPECT_NO_GL_ERROR();
  }
  glListBase(0);
}

TEST_F(DisplayListTest, CallListsWithBaseCallsEachName) {
  // Glyph-like: lists base+'a'.. translate by 1, 2, 4.
  const GLuint base = glGenLists(128);
  ASSERT_NE(base, 0u);
  DefineTranslation(base + 'a', 1);
  DefineTranslation(base + 'b', 2);
  DefineTranslation(base + 'c', 4);
  glListBase(base);
  const char* text = "abcca";
  glCallLists(5, GL_UNSIGNED_BYTE, text);
  EXPECT_EQ(TranslationX(), 12.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CallListsErrors) {
  const GLuint names[1] = {1};
  glCallLists(1, GL_DOUBLE, names);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glCallLists(-1, GL_UNSIGNED_INT, names);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCallLists(0, GL_UNSIGNED_INT, names);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CompiledCallListsUsesTheNamesAtCompileAndTheBaseAtExecution) {
  DefineTranslation(11, 1);
  DefineTranslation(12, 2);
  DefineTranslation(21, 10);
  GLubyte names[2] = {1, 1};
  glListBase(10);
  glNewList(1, GL_COMPILE);
  glCallLists(2, GL_UNSIGNED_BYTE, names);
  glEndList();
  names[1] = 2;  // the list keeps the names it was compiled with
  glCallList(1);
  EXPECT_EQ(TranslationX(), 2.0f);
  glLoadIdentity();
  glListBase(20);
  glCallList(1);
  EXPECT_EQ(TranslationX(), 20.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ErrorsOfCompiledCommandsAreRaisedAtExecution) {
  glNewList(1, GL_COMPILE);
  glDepthFunc(GL_LINE);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  // GL_COMPILE_AND_EXECUTE: raised at once as well.
  glNewList(3, GL_COMPILE_AND_EXECUTE);
  glCullFace(GL_LINE);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEndList();
  glCallList(3);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

TEST_F(DisplayListTest, BadBeginModeInAListIsAnErrorAtExecution) {
  glNewList(2, GL_COMPILE);
  glBegin(GL_POLYGON + 5);
  glEnd();
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(2);
  GLFX_SKIP_ON_MESA("a compiled glBegin with a bad mode raises no error when the list executes");
  EXPECT_EQ(DrainErrors(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST_F(DisplayListTest, StateCommandBetweenBeginAndEndOfAListIsAnErrorAtExecution) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glDepthFunc(GL_EQUAL);
  glEnd();
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(1);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_LESS);
}

TEST_F(DisplayListTest, CommandsExecutedAtOnceAreNotCompiled) {
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  EXPECT_EQ(GetInt(GL_UNPACK_ALIGNMENT), 2);
  const GLuint generated = glGenLists(1);
  EXPECT_NE(generated, 0u);
  EXPECT_EQ(glIsList(generated), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  glFlush();
  glFinish();
  GLubyte px[4] = {1, 2, 3, 4};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);  // read at once
  EXPECT_EQ(px[1], 0);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glCallList(1);
  EXPECT_EQ(GetInt(GL_UNPACK_ALIGNMENT), 4);  // glPixelStore was not in the list
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ClientDataIsCapturedAtCompileTime) {
  GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1};
  GLfloat diffuse[4] = {0.25f, 0.5f, 0.75f, 1};
  glNewList(1, GL_COMPILE);
  glLoadMatrixf(m);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glEndList();
  m[12] = 99;
  diffuse[0] = 0.9f;
  glCallList(1);
  EXPECT_EQ(TranslationX(), 5.0f);
  GLfloat d[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, d);
  EXPECT_EQ(d[0], 0.25f);
  EXPECT_EQ(d[2], 0.75f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ListDrawsOnlyWhenCalled) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE);
  glColor3f(1, 0, 0);
  FullQuad();
  glEndList();
  EXPECT_EQ(Pixel(32, 32)[0], 0);
  glColor3f(0, 0, 1);
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_COLOR)[2], 1.0f);  // the list's glColor was not executed
  glCallList(1);
  const auto p = Pixel(32, 32);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[2], 0);
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_COLOR)[0], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ColorBetweenBeginAndEndBecomesCurrentAfterTheCall) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(0, 1, 0);
  glNormal3f(0, 1, 0);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glColor3f(0, 0.5f, 1);
  glVertex2f(0, 1);
  glEnd();
  glEndList();
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_COLOR)[0], 1.0f);  // unchanged by compiling
  EXPECT_EQ(GetFloats<3>(GL_CURRENT_NORMAL)[2], 1.0f);
  glCallList(1);
  const auto c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_EQ(c[0], 0.0f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 1.0f);
  const auto n = GetFloats<3>(GL_CURRENT_NORMAL);
  EXPECT_EQ(n[1], 1.0f);
  EXPECT_EQ(n[2], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CompileAndExecuteDrawsWhileCompiling) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glColor3f(0, 1, 0);
  FullQuad();
  glEndList();
  EXPECT_EQ(Pixel(10, 10)[1], 255);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(Pixel(10, 10)[1], 0);
  glCallList(1);
  EXPECT_EQ(Pixel(10, 10)[1], 255);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ListCalledBetweenBeginAndEndAddsItsVertices) {
  // A list of bare glVertex calls (compiled as commands) continues the
  // primitive of the caller's glBegin.
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEndList();
  glColor3f(1, 1, 0);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glCallList(1);
  glEnd();
  EXPECT_NO_GL_ERROR();
  const auto p = Pixel(32, 32);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[1], 255);
}

TEST_F(DisplayListTest, MaterialBetweenBeginAndEndOfAList) {
  const GLfloat red[4] = {1, 0, 0, 1};
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  glEndList();
  GLfloat d[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
  EXPECT_NE(d[1], 0.0f);  // compiling changed nothing
  glCallList(1);
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
  EXPECT_EQ(d[0], 1.0f);
  EXPECT_EQ(d[1], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, ListCanEndInsideBeginEnd) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
}

TEST_F(DisplayListTest, CallListBetweenBeginAndEndOfAList) {
  // glCallList inside the list's own glBegin/glEnd: the rest of the
  // primitive is compiled as commands (Mesa's fallback); the replay draws it.
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(2, GL_COMPILE);
  glVertex2f(1, 1);
  glEndList();
  glNewList(1, GL_COMPILE);
  glColor3f(0, 1, 1);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glCallList(2);
  glVertex2f(-1, 1);
  glEnd();
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Pixel(32, 32)[1], 0);
  glCallList(1);
  EXPECT_NO_GL_ERROR();
  const auto p = Pixel(32, 32);
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(p[2], 255);
}

TEST_F(DisplayListTest, ListEndingInsideBeginEndLeavesThePrimitiveOpen) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE);
  glColor3f(1, 0, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(1);
  glVertex2f(-1, 3);  // completes the triangle the list began
  glEnd();
  EXPECT_NO_GL_ERROR();
  const auto p = Pixel(16, 16);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[2], 255);
}

TEST_F(DisplayListTest, ListCommandsBetweenBeginAndEnd) {
  DefineTranslation(1, 1);
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(glGenLists(1), 0u);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glIsList(1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glDeleteLists(1, 1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glIsList(1), GL_TRUE);
  glBegin(GL_TRIANGLES);
  glEndList();
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glListBase(3);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_LIST_BASE), 0);
  glBegin(GL_TRIANGLES);
  glCallList(1);  // allowed (§2.6.3), but the list's glTranslate is not
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(TranslationX(), 0.0f);
}

TEST_F(DisplayListTest, DeletedNamesAreGeneratedAgain) {
  const GLuint first = glGenLists(4);
  ASSERT_NE(first, 0u);
  glDeleteLists(first, 4);
  const GLuint again = glGenLists(4);
  EXPECT_NE(again, 0u);
  for (GLuint i = again; i < again + 4; ++i) EXPECT_EQ(glIsList(i), GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, CompileAndExecuteWithAColourThatGrowsTheFormatEndsCleanly) {
  // The glColor inside the second glBegin/glEnd pair grows the node's vertex
  // format: the node ends with that pair open, and is fed back at once.
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  for (int i = 0; i < 4; ++i) {
    if (i % 2 == 0) glColor3f(0.3f, 0.7f, 0.3f);
    glBegin(GL_QUAD_STRIP);
    if (i % 2 == 1) glColor3f(0.7f, 0.3f, 0.3f);
    glVertex2f(-1, -1);
    glVertex2f(-1, 1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glEnd();
  }
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_LIST_INDEX), 0);
  glCallList(1);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_COLOR)[0], 0.7f);
}

TEST_F(DisplayListTest, ContextsCreatedToShareListsShareThem) {
  DefineTranslation(7, 3);
  OSMesaContext sharing = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, ctx_);
  OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  ASSERT_NE(sharing, nullptr);
  ASSERT_NE(alone, nullptr);
  std::vector<unsigned char> buffer(kWidth * kHeight * 4);
  ASSERT_EQ(OSMesaMakeCurrent(sharing, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsList(7), GL_TRUE);
  glCallList(7);
  EXPECT_EQ(TranslationX(), 3.0f);
  DefineTranslation(8, 5);  // defined here, seen by the first context
  ASSERT_EQ(OSMesaMakeCurrent(alone, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsList(7), GL_FALSE);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsList(8), GL_TRUE);
  OSMesaDestroyContext(sharing);
  OSMesaDestroyContext(alone);
  EXPECT_EQ(glIsList(8), GL_TRUE);  // the lists outlive the context that made them
  EXPECT_NO_GL_ERROR();
}

TEST_F(DisplayListTest, HugeRangesDoNotHang) {
  DefineTranslation(5, 1);
  glDeleteLists(1, 0x7fffffff);  // every list from 1 on
  EXPECT_EQ(glIsList(5), GL_FALSE);
  glDeleteLists(0xfffffff0u, 1000);  // a range past the last name
  EXPECT_NO_GL_ERROR();
  GLFX_SKIP_ON_MESA("it would try to make 2^31 empty lists; libglfixed gives 0 above 2^20 names");
  EXPECT_EQ(glGenLists(0x7fffffff), 0u);
  EXPECT_NO_GL_ERROR();
}

// Mesa compiles glTexParameterf/i as glTexParameterfv of (param, 0, 0, 0), the
// integer converted to float, and runs that form in GL_COMPILE_AND_EXECUTE:
// the border colour can be set through the scalar calls in a list only.
TEST_F(DisplayListTest, ScalarTexParameterIsCompiledAsItsVectorForm) {
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
  EXPECT_NO_GL_ERROR();
  glEndList();
  GLfloat b[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b);
  EXPECT_EQ(b[0], 1.0f);  // 1 as a float, not 1 / (2^31 - 1)
  EXPECT_EQ(b[1], 0.0f);
  glNewList(2, GL_COMPILE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.25f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLfloat>(GL_NEAREST));
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(2);
  EXPECT_NO_GL_ERROR();
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b);
  EXPECT_EQ(b[0], 0.25f);
  GLint filter = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_NEAREST);
}

// A GL_COMPILE_AND_EXECUTE list that ends inside glBegin/glEnd leaves Mesa
// outside them: a glEnd next is GL_INVALID_OPERATION;
// glCallList of the same list leaves the primitive open for the vertices that
// follow it. (What Mesa draws of the unfinished primitive is not asserted:
// nothing at glFinish, the primitive after the erroneous glEnd.)
TEST_F(DisplayListTest, EndListInsideBeginEndOfCompileAndExecute) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEndList();
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(1);
  glEnd();
  EXPECT_NO_GL_ERROR();
  glFinish();
  EXPECT_EQ(Pixel(kWidth / 2, kHeight / 2)[0], 255);
}

}  // namespace
}  // namespace glfx_test
