// ARB_draw_elements_base_vertex (GL 3.2 §2.8.2): the base vertex is added to
// every index, also a negative one, from client memory and from buffers, and
// in display lists the elements are read when the list compiles. Runs on
// Mesa too: every expectation holds there.
#include "api/gl_test_fixture.h"

namespace glfx_test {
namespace {

using BaseVertexTest = GLTest;

// Four quads side by side: quad q covers x in [-1 + q/2, -1 + (q+1)/2), each
// its own colour: red, green, blue, white.
struct Quads {
  GLfloat xy[16 * 2];
  GLubyte rgb[16 * 3];
  Quads() {
    const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int q = 0; q < 4; ++q) {
      const GLfloat x0 = -1 + q * 0.5f, x1 = x0 + 0.5f;
      const GLfloat corners[4][2] = {{x0, -1}, {x1, -1}, {x1, 1}, {x0, 1}};
      for (int c = 0; c < 4; ++c) {
        xy[(q * 4 + c) * 2] = corners[c][0];
        xy[(q * 4 + c) * 2 + 1] = corners[c][1];
        for (int k = 0; k < 3; ++k) rgb[(q * 4 + c) * 3 + k] = colours[q][k];
      }
    }
  }
};

// Which quads are drawn: a bit per quad, read at each quad's centre row.
int DrawnQuads(const unsigned char* p) {
  int bits = 0;
  for (int q = 0; q < 4; ++q) {
    const unsigned char* px = p + (32 * kWidth + q * 16 + 8) * 4;
    if (px[0] || px[1] || px[2]) bits |= 1 << q;
  }
  return bits;
}

void Arrays(const Quads& quads, bool inBuffer) {
  static GLuint buffer = 0;
  if (inBuffer) {
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof(quads.xy) + sizeof(quads.rgb), nullptr, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(quads.xy), quads.xy);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof(quads.xy), sizeof(quads.rgb), quads.rgb);
    glVertexPointer(2, GL_FLOAT, 0, nullptr);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, reinterpret_cast<const void*>(sizeof(quads.xy)));
  } else {
    glVertexPointer(2, GL_FLOAT, 0, quads.xy);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, quads.rgb);
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
}

const GLushort kQuad0[6] = {0, 1, 2, 0, 2, 3};
const GLushort kQuad3[6] = {12, 13, 14, 12, 14, 15};

TEST_F(BaseVertexTest, AddsTheBaseVertexToEveryIndex) {
  const Quads quads;
  for (bool inBuffer : {false, true}) {
    Arrays(quads, inBuffer);
    glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, kQuad0, 8);
    ASSERT_NO_GL_ERROR();
    EXPECT_EQ(DrawnQuads(pixels()), 1 << 2) << "in a buffer: " << inBuffer;
    EXPECT_EQ(pixels()[(32 * kWidth + 40) * 4 + 2], 255);  // blue
    // A negative base vertex with larger indices.
    glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, kQuad3, -8);
    EXPECT_EQ(DrawnQuads(pixels()), (1 << 1) | (1 << 2));
    glDrawRangeElementsBaseVertex(GL_TRIANGLES, 12, 15, 6, GL_UNSIGNED_SHORT, kQuad3, -12);
    EXPECT_EQ(DrawnQuads(pixels()), 7);
    ASSERT_NO_GL_ERROR();
  }
}

TEST_F(BaseVertexTest, IndicesInAnElementBuffer) {
  const Quads quads;
  Arrays(quads, true);
  GLuint elements = 0;
  glGenBuffers(1, &elements);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elements);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(kQuad3), kQuad3, GL_STATIC_DRAW);
  glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, nullptr, -4);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(DrawnQuads(pixels()), 1 << 2);
  const GLsizei counts[2] = {6, 6};
  const void* offsets[2] = {nullptr, nullptr};
  const GLint bases[2] = {-12, -8};
  glClear(GL_COLOR_BUFFER_BIT);
  glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, offsets, 2, bases);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(DrawnQuads(pixels()), 3);
}

TEST_F(BaseVertexTest, ListsCompileTheVerticesRead) {
  Quads quads;
  Arrays(quads, false);
  glNewList(1, GL_COMPILE);
  glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, kQuad0, 4);
  const GLsizei counts[1] = {6};
  const void* lists[1] = {kQuad3};
  const GLint bases[1] = {0};
  glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, lists, 1, bases);
  glEndList();
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(DrawnQuads(pixels()), 0);
  // Moving quad 1 away after the compile changes nothing the list draws.
  for (int c = 4; c < 8; ++c) quads.xy[c * 2 + 1] += 5;
  glCallList(1);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(DrawnQuads(pixels()), (1 << 1) | (1 << 3));
}

TEST_F(BaseVertexTest, ErrorsAreThoseOfTheDrawsWithout) {
  const Quads quads;
  Arrays(quads, false);
  glDrawElementsBaseVertex(0x77, 6, GL_UNSIGNED_SHORT, kQuad0, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawElementsBaseVertex(GL_TRIANGLES, -1, GL_UNSIGNED_SHORT, kQuad0, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_SHORT, kQuad0, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawRangeElementsBaseVertex(GL_TRIANGLES, 3, 2, 6, GL_UNSIGNED_SHORT, kQuad0, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBegin(GL_TRIANGLES);
  glDrawElementsBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, kQuad0, 0);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(DrawnQuads(pixels()), 0);
}

}  // namespace
}  // namespace glfx_test
