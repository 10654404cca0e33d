// Vertex arrays (GL 2.1 §2.8) and the client attribute stack (§6.1.14):
// defaults, state queries, every error, and a few draws read back.
#include <dlfcn.h>

#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

class ArrayTest : public GLTest {};

void* GetPointer(GLenum pname) {
  void* p = reinterpret_cast<void*>(0x1);
  glGetPointerv(pname, &p);
  return p;
}

// Table 6.6-6.8 defaults.
TEST_F(ArrayTest, Defaults) {
  for (GLenum cap : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY,
                     GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_TEXTURE_COORD_ARRAY}) {
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
    EXPECT_EQ(GetInt(cap), 0) << cap;
  }
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_STRIDE), 0);
  EXPECT_EQ(GetInt(GL_NORMAL_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 4);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_SECONDARY_COLOR_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_SECONDARY_COLOR_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_EDGE_FLAG_ARRAY_STRIDE), 0);
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE0);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
  EXPECT_GE(GetInt(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH), 16);
  EXPECT_GE(GetInt(GL_MAX_TEXTURE_COORDS), 2);
  EXPECT_GT(GetInt(GL_MAX_ELEMENTS_VERTICES), 0);
  EXPECT_GT(GetInt(GL_MAX_ELEMENTS_INDICES), 0);
  for (GLenum p : {GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER,
                   GL_SECONDARY_COLOR_ARRAY_POINTER, GL_FOG_COORD_ARRAY_POINTER, GL_INDEX_ARRAY_POINTER,
                   GL_EDGE_FLAG_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_POINTER})
    EXPECT_EQ(GetPointer(p), nullptr) << p;
  EXPECT_NO_GL_ERROR();
}

TEST_F(ArrayTest, PointersAreStoredAndQueried) {
  static GLfloat data[64];
  glVertexPointer(3, GL_SHORT, 12, data);
  glNormalPointer(GL_BYTE, 8, data + 1);
  glColorPointer(3, GL_UNSIGNED_BYTE, 4, data + 2);
  glSecondaryColorPointer(3, GL_UNSIGNED_SHORT, 16, data + 3);
  glFogCoordPointer(GL_DOUBLE, 24, data + 4);
  glIndexPointer(GL_SHORT, 6, data + 5);
  glEdgeFlagPointer(2, data + 6);
  glTexCoordPointer(2, GL_INT, 20, data + 7);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_STRIDE), 12);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), data);
  EXPECT_EQ(GetInt(GL_NORMAL_ARRAY_TYPE), GL_BYTE);
  EXPECT_EQ(GetInt(GL_NORMAL_ARRAY_STRIDE), 8);
  EXPECT_EQ(GetPointer(GL_NORMAL_ARRAY_POINTER), data + 1);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_STRIDE), 4);
  EXPECT_EQ(GetPointer(GL_COLOR_ARRAY_POINTER), data + 2);
  EXPECT_EQ(GetInt(GL_SECONDARY_COLOR_ARRAY_TYPE), GL_UNSIGNED_SHORT);
  EXPECT_EQ(GetInt(GL_SECONDARY_COLOR_ARRAY_STRIDE), 16);
  EXPECT_EQ(GetPointer(GL_SECONDARY_COLOR_ARRAY_POINTER), data + 3);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_STRIDE), 24);
  EXPECT_EQ(GetPointer(GL_FOG_COORD_ARRAY_POINTER), data + 4);
  EXPECT_EQ(GetInt(GL_INDEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(GetInt(GL_INDEX_ARRAY_STRIDE), 6);
  EXPECT_EQ(GetPointer(GL_INDEX_ARRAY_POINTER), data + 5);
  EXPECT_EQ(GetInt(GL_EDGE_FLAG_ARRAY_STRIDE), 2);
  EXPECT_EQ(GetPointer(GL_EDGE_FLAG_ARRAY_POINTER), data + 6);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_TYPE), GL_INT);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_STRIDE), 20);
  EXPECT_EQ(GetPointer(GL_TEXTURE_COORD_ARRAY_POINTER), data + 7);
  EXPECT_NO_GL_ERROR();
}

// Every size and type GL 2.1 allows is accepted.
TEST_F(ArrayTest, EveryLegalSizeAndType) {
  static GLfloat data[16];
  for (GLint size : {2, 3, 4})
    for (GLenum type : {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}) {
      glVertexPointer(size, type, 0, data);
      EXPECT_NO_GL_ERROR() << size << " " << type;
      EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), size);
    }
  for (GLenum type : {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}) {
    glNormalPointer(type, 0, data);
    EXPECT_NO_GL_ERROR() << type;
  }
  for (GLint size : {3, 4})
    for (GLenum type : {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
                        GL_FLOAT, GL_DOUBLE}) {
      glColorPointer(size, type, 0, data);
      EXPECT_NO_GL_ERROR() << size << " " << type;
      if (size == 3) {
        glSecondaryColorPointer(size, type, 0, data);
        EXPECT_NO_GL_ERROR() << type;
      }
    }
  for (GLenum type : {GL_FLOAT, GL_DOUBLE}) {
    glFogCoordPointer(type, 0, data);
    EXPECT_NO_GL_ERROR();
  }
  for (GLenum type : {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}) {
    glIndexPointer(type, 0, data);
    EXPECT_NO_GL_ERROR() << type;
  }
  for (GLint size : {1, 2, 3, 4})
    for (GLenum type : {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}) {
      glTexCoordPointer(size, type, 0, data);
      EXPECT_NO_GL_ERROR();
    }
}

TEST_F(ArrayTest, BadSizeTypeOrStrideIsAnErrorAndChangesNothing) {
  static GLfloat data[16];
  glVertexPointer(3, GL_FLOAT, 0, data);
  glVertexPointer(1, GL_FLOAT, 0, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glVertexPointer(5, GL_FLOAT, 0, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glVertexPointer(3, GL_BYTE, 0, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), data);
  glVertexPointer(3, GL_FLOAT, -4, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);

  glNormalPointer(GL_UNSIGNED_BYTE, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glNormalPointer(GL_FLOAT, -1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glColorPointer(2, GL_FLOAT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glColorPointer(4, GL_BITMAP, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glColorPointer(4, GL_FLOAT, -1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glSecondaryColorPointer(2, GL_FLOAT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glSecondaryColorPointer(3, GL_BITMAP, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFogCoordPointer(GL_INT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFogCoordPointer(GL_FLOAT, -1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glIndexPointer(GL_BYTE, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glIndexPointer(GL_INT, -1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glEdgeFlagPointer(-1, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexCoordPointer(0, GL_FLOAT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexCoordPointer(5, GL_FLOAT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexCoordPointer(2, GL_BYTE, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexCoordPointer(2, GL_FLOAT, -8, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

// GL 2.1 §2.5: a command that records an error has no other effect.
TEST_F(ArrayTest, NegativeStrideChangesNothing) {
  GLFX_SKIP_ON_MESA("Mesa records GL_INVALID_VALUE but stores the pointer");
  static GLfloat data[4];
  glVertexPointer(3, GL_FLOAT, 0, data);
  glVertexPointer(2, GL_FLOAT, -4, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), data);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
}

TEST_F(ArrayTest, SecondaryColorSizeFourIsAnError) {
  GLFX_SKIP_ON_MESA("Mesa accepts size 4 (GL 3.x and later allow it)");
  static GLfloat data[4];
  glSecondaryColorPointer(4, GL_FLOAT, 0, data);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(ArrayTest, EnableAndDisableClientState) {
  for (GLenum cap : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY,
                     GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_TEXTURE_COORD_ARRAY}) {
    glEnableClientState(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << cap;
    EXPECT_EQ(GetBool(cap), GL_TRUE) << cap;
    glDisableClientState(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
  }
  EXPECT_NO_GL_ERROR();
  glEnableClientState(GL_LIGHTING);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDisableClientState(GL_DEPTH_TEST);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// The texture coordinate array state is per unit, chosen by glClientActiveTexture.
TEST_F(ArrayTest, ClientActiveTextureSelectsTheTexCoordArray) {
  static GLfloat data[8];
  glClientActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE1);
  glTexCoordPointer(2, GL_SHORT, 4, data);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_TRUE);
  glClientActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_FALSE);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  EXPECT_EQ(GetPointer(GL_TEXTURE_COORD_ARRAY_POINTER), nullptr);
  glClientActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(GetPointer(GL_TEXTURE_COORD_ARRAY_POINTER), data);
  EXPECT_NO_GL_ERROR();
  glClientActiveTexture(GL_TEXTURE0 + GetInt(GL_MAX_TEXTURE_COORDS));
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glClientActiveTexture(GL_TEXTURE0 - 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE1);
}

TEST_F(ArrayTest, GetPointervBadNameIsAnError) {
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_SIZE, &p);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// GL 2.1 §2.8, table 2.5: one interleaved format sets every array.
TEST_F(ArrayTest, InterleavedArraysSetsEveryArray) {
  static GLfloat block[64];
  glEnableClientState(GL_INDEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glInterleavedArrays(GL_C4F_N3F_V3F, 0, block);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_EDGE_FLAG_ARRAY), GL_FALSE);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 4);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_STRIDE), 40);
  EXPECT_EQ(GetInt(GL_NORMAL_ARRAY_STRIDE), 40);
  EXPECT_EQ(GetPointer(GL_COLOR_ARRAY_POINTER), block);
  EXPECT_EQ(GetPointer(GL_NORMAL_ARRAY_POINTER), block + 4);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), block + 7);

  glInterleavedArrays(GL_T2F_C4UB_V3F, 32, block);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_TRUE);
  EXPECT_EQ(GetInt(GL_TEXTURE_COORD_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_STRIDE), 32);
  EXPECT_EQ(GetPointer(GL_COLOR_ARRAY_POINTER), block + 2);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), block + 3);

  glInterleavedArrays(GL_T4F_C4F_N3F_V4F, 0, block);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_STRIDE), 60);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), block + 11);
  EXPECT_NO_GL_ERROR();

  glInterleavedArrays(GL_RGBA, 0, block);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glInterleavedArrays(GL_V3F, -4, block);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(ArrayTest, PushPopClientAttribRestoresEachGroup) {
  static GLfloat data[8];
  glVertexPointer(2, GL_FLOAT, 8, data);
  glEnableClientState(GL_VERTEX_ARRAY);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 1);
  glVertexPointer(4, GL_SHORT, 0, data + 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 2);
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetPointer(GL_VERTEX_ARRAY_POINTER), data);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(GetInt(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE0);
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 2);

  // Only the groups pushed are restored.
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glVertexPointer(3, GL_INT, 0, data);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPopClientAttrib();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 2);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glVertexPointer(4, GL_INT, 0, data);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPopClientAttrib();
  EXPECT_EQ(GetInt(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ArrayTest, ClientAttribStackOverflowAndUnderflow) {
  glPopClientAttrib();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  const int max = GetInt(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH);
  for (int i = 0; i < max; ++i) glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), max);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), max);
  for (int i = 0; i < max; ++i) glPopClientAttrib();
  EXPECT_NO_GL_ERROR();
  glPopClientAttrib();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
}

TEST_F(ArrayTest, DrawErrors) {
  static GLfloat v[12];
  static GLushort idx[3] = {0, 1, 2};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawArrays(0x1F, 0, 3);  // GL_POLYGON + 1 is GL_LINES_ADJACENCY on Mesa
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_SHORT, idx);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawElements(0x1F, 3, GL_UNSIGNED_SHORT, idx);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, idx);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawElements(GL_TRIANGLES, 3, GL_SHORT, idx);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawRangeElements(GL_TRIANGLES, 2, 1, 3, GL_UNSIGNED_SHORT, idx);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawRangeElements(GL_TRIANGLES, 0, 2, -1, GL_UNSIGNED_SHORT, idx);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_INT, idx);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLint first[2] = {0, 0};
  GLsizei count[2] = {3, -1};
  glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMultiDrawArrays(GL_TRIANGLES, first, count, 2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  const void* lists[2] = {idx, idx};
  glMultiDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_SHORT, lists, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMultiDrawElements(GL_TRIANGLES, count, GL_FLOAT, lists, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_TRIANGLES);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_NO_GL_ERROR();
}

// A full-window red quad through each draw path fills the window.
class ArrayDrawTest : public ArrayTest {
 protected:
  void SetUp() override {
    ArrayTest::SetUp();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, kQuad);
  }
  bool centreIs(int r, int g, int b) {
    const unsigned char* p = pixels() + (kHeight / 2 * kWidth + kWidth / 2) * 4;
    return p[0] == r && p[1] == g && p[2] == b;
  }
  static constexpr GLfloat kQuad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
};

TEST_F(ArrayDrawTest, DrawArraysUsesTheCurrentColourWithoutAColourArray) {
  glColor3f(0, 1, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(centreIs(0, 255, 0));
}

TEST_F(ArrayDrawTest, ColourArrayOfUnsignedBytes) {
  static const GLubyte colors[16] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  static const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(centreIs(255, 0, 0));
}

// GL 2.1 §2.8 leaves the current values of enabled arrays indeterminate
// after glDrawArrays; Mesa leaves them unchanged, and later immediate-mode
// draws see that.
TEST_F(ArrayDrawTest, DrawArraysLeavesTheCurrentColourAndNormal) {
  static const GLfloat colors[16] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0.5f, 0.5f, 0.5f, 0.5f};
  static const GLfloat normals[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.6f, 0.8f, 0};
  glColor4f(0.25f, 0.75f, 0.125f, 1);
  glNormal3f(0.5f, 0.5f, 0.5f);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, colors);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, 0, normals);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_NO_GL_ERROR();
  auto c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_FLOAT_EQ(c[0], 0.25f);
  EXPECT_FLOAT_EQ(c[1], 0.75f);
  EXPECT_FLOAT_EQ(c[2], 0.125f);
  auto n = GetFloats<3>(GL_CURRENT_NORMAL);
  EXPECT_FLOAT_EQ(n[0], 0.5f);
  EXPECT_FLOAT_EQ(n[2], 0.5f);
}

TEST_F(ArrayDrawTest, NoVertexArrayDrawsNothing) {
  glDisableClientState(GL_VERTEX_ARRAY);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(centreIs(0, 0, 0));
}

// Inside glBegin/glEnd an element is the glColor and glVertex calls it stands
// for: the current colour becomes the last element's.
TEST_F(ArrayDrawTest, ArrayElementSetsTheCurrentColour) {
  static const GLfloat colors[16] = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0.5f, 0.25f, 1, 1};
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, colors);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) glArrayElement(i);
  glEnd();
  EXPECT_NO_GL_ERROR();
  auto c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_FLOAT_EQ(c[0], 0.5f);
  EXPECT_FLOAT_EQ(c[1], 0.25f);
  EXPECT_FLOAT_EQ(c[2], 1.0f);
}

// The other arrays too: each sets its current value (GL 2.1 §2.8).
TEST_F(ArrayDrawTest, ArrayElementSetsEveryCurrentValue) {
  static const GLubyte secondary[6] = {0, 0, 0, 255, 0, 51};
  static const GLdouble fog[2] = {0, 2.5};
  static const GLshort index[2] = {0, 7};
  static const GLboolean edge[2] = {GL_TRUE, GL_FALSE};
  static const GLfloat tex[6] = {0, 0, 0, 0.25f, 0.5f, 0.75f};
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, secondary);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glFogCoordPointer(GL_DOUBLE, 0, fog);
  glEnableClientState(GL_INDEX_ARRAY);
  glIndexPointer(GL_SHORT, 0, index);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glEdgeFlagPointer(0, edge);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);  // unit 0: GL_CURRENT_TEXTURE_COORDS reads the active unit's
  glTexCoordPointer(3, GL_FLOAT, 0, tex);
  glDisableClientState(GL_VERTEX_ARRAY);
  glArrayElement(1);  // outside glBegin/glEnd: sets the current values only
  EXPECT_NO_GL_ERROR();
  auto sc = GetFloats<3>(GL_CURRENT_SECONDARY_COLOR);
  EXPECT_FLOAT_EQ(sc[0], 1.0f);
  EXPECT_FLOAT_EQ(sc[1], 0.0f);
  EXPECT_FLOAT_EQ(sc[2], 0.2f);
  EXPECT_FLOAT_EQ(GetFloat(GL_CURRENT_FOG_COORD), 2.5f);
  EXPECT_FLOAT_EQ(GetFloat(GL_CURRENT_INDEX), 7.0f);
  EXPECT_EQ(GetBool(GL_EDGE_FLAG), GL_FALSE);
  auto t = GetFloats<4>(GL_CURRENT_TEXTURE_COORDS);
  EXPECT_FLOAT_EQ(t[0], 0.25f);
  EXPECT_FLOAT_EQ(t[1], 0.5f);
  EXPECT_FLOAT_EQ(t[2], 0.75f);
  EXPECT_FLOAT_EQ(t[3], 1.0f);
}

TEST_F(ArrayDrawTest, MultiDrawArraysDrawsEachRange) {
  static const GLfloat halves[16] = {-1, -1, 0, -1, 0, 1, -1, 1, 0, -1, 1, -1, 1, 1, 0, 1};
  glVertexPointer(2, GL_FLOAT, 0, halves);
  glColor3f(1, 0, 1);
  const GLint first[2] = {0, 4};
  const GLsizei count[2] = {4, 4};
  glMultiDrawArrays(GL_QUADS, first, count, 2);
  EXPECT_NO_GL_ERROR();
  const unsigned char* p = pixels();
  EXPECT_EQ(p[(32 * kWidth + 16) * 4 + 0], 255);
  EXPECT_EQ(p[(32 * kWidth + 48) * 4 + 0], 255);
  EXPECT_EQ(p[(32 * kWidth + 48) * 4 + 1], 0);
}

TEST(ArrayAliases, ExtensionNamesAreExported) {
  for (const char* name :
       {"glBindBufferARB", "glGenBuffersARB", "glBufferDataARB", "glBufferSubDataARB", "glDeleteBuffersARB",
        "glIsBufferARB", "glMapBufferARB", "glUnmapBufferARB", "glGetBufferParameterivARB",
        "glGetBufferPointervARB", "glGetBufferSubDataARB", "glDrawRangeElementsEXT", "glMultiDrawArraysEXT",
        "glMultiDrawElementsEXT", "glClientActiveTextureARB"}) {
    EXPECT_NE(dlsym(RTLD_DEFAULT, name), nullptr) << name;
    EXPECT_NE(reinterpret_cast<void*>(OSMesaGetProcAddress(name)), nullptr) << name;
  }
}

// EXT_vertex_array's way: glEnable and glDisable of an array's name set its
// client state, as Mesa's compatibility contexts do (also from a display
// list); glPopAttrib(GL_ENABLE_BIT) does not restore it.
TEST_F(ArrayTest, EnableOfAnArrayIsItsClientState) {
  const GLenum arrays[] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY,
                           GL_EDGE_FLAG_ARRAY};
  for (GLenum a : arrays) {
    glEnable(a);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(glIsEnabled(a), GL_TRUE) << a;
    glDisable(a);
    EXPECT_EQ(glIsEnabled(a), GL_FALSE) << a;
  }
  glNewList(1, GL_COMPILE);
  glEnable(GL_VERTEX_ARRAY);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  glCallList(1);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_NORMAL_ARRAY);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

}  // namespace

// EXT_vertex_array_bgra: the colour arrays take the size GL_BGRA, of
// unsigned bytes stored blue, green, red, alpha (Mesa 22.3, measured).
TEST_F(ArrayTest, BgraColorArrays) {
  static const GLubyte bgra[4 * 4] = {10, 20, 30, 40, 10, 20, 30, 40, 10, 20, 30, 40, 10, 20, 30, 40};
  glColorPointer(GL_BGRA, GL_FLOAT, 0, bgra);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glColorPointer(GL_BGRA, GL_BYTE, 0, bgra);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glColorPointer(GL_BGRA, 0x1234, 0, bgra);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glVertexPointer(GL_BGRA, GL_FLOAT, 0, bgra);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexCoordPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, bgra);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 4);  // nothing changed
  glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, bgra);
  glSecondaryColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, bgra);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), GL_BGRA);
  EXPECT_EQ(GetInt(GL_SECONDARY_COLOR_ARRAY_SIZE), GL_BGRA);

  static const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  auto pixel = [] {
    std::array<int, 4> p{};
    GLubyte b[4] = {};
    glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
    for (int i = 0; i < 4; ++i) p[i] = b[i];
    return p;
  };
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(pixel(), (std::array<int, 4>{30, 20, 10, 40}));
  // glInterleavedArrays sets plain sizes again.
  glInterleavedArrays(GL_C4UB_V2F, 0, nullptr);
  EXPECT_EQ(GetInt(GL_COLOR_ARRAY_SIZE), 4);
  EXPECT_NO_GL_ERROR();
}

// glArrayElement reads a GL_BGRA colour array in the same order
// (EXT_vertex_array_bgra); Mesa 22.3 passes its bytes on unswapped.
TEST_F(ArrayTest, BgraColorArrayElement) {
  GLFX_SKIP_ON_MESA("glArrayElement takes a GL_BGRA colour array's bytes as red, green, blue, alpha");
  static const GLubyte bgra[4 * 4] = {10, 20, 30, 40, 10, 20, 30, 40, 10, 20, 30, 40, 10, 20, 30, 40};
  static const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, bgra);
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glBegin(GL_QUADS);
  for (GLint i = 0; i < 4; ++i) glArrayElement(i);
  glEnd();
  GLubyte b[4] = {};
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
  EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{30, 20, 10, 40}));
}
