// glPopAttrib(GL_LIGHTING_BIT) restores the material (GL 2.1 table 6.11),
// for drawing as for glGetMaterial. Mesa 22.3 keeps a glMaterial made inside
// the push once something was drawn before it, in glGetMaterial and in the
// pixels (MESA_FACTS.md, "Attribute stack"; found by fuzz_command_layer).
#include <array>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using AttribMaterialTest = GLTest;

const GLfloat kPushed[4] = {0.25f, 0.5f, 0.75f, 1.0f};
const GLfloat kInside[4] = {0.9f, 0.1f, 0.2f, 0.3f};

// A lit triangle over the centre.
void DrawLitTriangle() {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glNormal3f(0.2f, 0.3f, 0.9f);
  glVertex2f(-0.9f, -0.9f);
  glNormal3f(0.5f, -0.3f, 0.7f);
  glVertex2f(0.9f, -0.9f);
  glNormal3f(-0.2f, 0.1f, 0.9f);
  glVertex2f(0.0f, 0.9f);
  glEnd();
}

TEST_F(AttribMaterialTest, PopAttribRestoresAMaterialSetInsideThePush) {
  GLFX_SKIP_ON_MESA("glPopAttrib does not undo a glMaterial made since the push");
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_SPECULAR, kPushed);
  auto centre = [this] {
    DrawLitTriangle();
    const unsigned char* p = pixels() + (24 * kWidth + 32) * 4;
    return std::array<unsigned char, 4>{p[0], p[1], p[2], p[3]};
  };
  const std::array<unsigned char, 4> expected = centre();
  for (GLbitfield mask : {GLbitfield(GL_LIGHTING_BIT), GLbitfield(GL_ALL_ATTRIB_BITS)}) {
    SCOPED_TRACE(::testing::Message() << "mask 0x" << std::hex << mask);
    glPushAttrib(mask);
    glMaterialfv(GL_FRONT, GL_SPECULAR, kInside);
    glPopAttrib();
    GLfloat v[4] = {-1, -1, -1, -1};
    glGetMaterialfv(GL_FRONT, GL_SPECULAR, v);
    ASSERT_NO_GL_ERROR();
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(v[i], kPushed[i]);
    EXPECT_EQ(centre(), expected);
  }
}

}  // namespace
}  // namespace glfx_test
