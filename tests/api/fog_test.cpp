// Fog (GL 2.1 §3.10): glFog*, GL_FOG, the fog coordinate (current, arrays,
// lists), their queries, errors and attribute groups, and a few fogged pixels
// that must be Mesa's (llvmpipe's exp2 approximation included).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include <limits>

#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

#ifndef GL_FOG_DISTANCE_MODE_NV
#define GL_FOG_DISTANCE_MODE_NV 0x855A
#define GL_EYE_RADIAL_NV 0x855B
#define GL_EYE_PLANE_ABSOLUTE_NV 0x855C
#endif

class FogTest : public GLTest {
 protected:
  // A black rectangle over the whole buffer in white fog; `fogCoord` is the
  // current fog coordinate (GL_FOG_COORD_SRC = GL_FOG_COORD). Returns the red
  // byte at the centre.
  int fogRed(GLenum mode, float density, float start, float end, float fogCoord) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    const GLfloat white[4] = {1, 1, 1, 1};
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, white);
    glFogi(GL_FOG_MODE, static_cast<GLint>(mode));
    glFogf(GL_FOG_DENSITY, density);
    glFogf(GL_FOG_START, start);
    glFogf(GL_FOG_END, end);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogCoordf(fogCoord);
    glColor3f(0, 0, 0);
    glRectf(-1, -1, 1, 1);
    return centreRed();
  }
  int centreRed() {
    glFinish();
    return pixels()[4 * (kWidth * (kHeight / 2) + kWidth / 2)];
  }
};

TEST_F(FogTest, Defaults) {
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_FALSE);
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_EXP);
  EXPECT_EQ(GetFloat(GL_FOG_DENSITY), 1.0f);
  EXPECT_EQ(GetFloat(GL_FOG_START), 0.0f);
  EXPECT_EQ(GetFloat(GL_FOG_END), 1.0f);
  EXPECT_EQ(GetFloat(GL_FOG_INDEX), 0.0f);
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{0, 0, 0, 0}));
  EXPECT_EQ(GetInt(GL_FOG_COORD_SRC), GL_FRAGMENT_DEPTH);
  EXPECT_EQ(GetInt(GL_FOG_DISTANCE_MODE_NV), GL_EYE_PLANE_ABSOLUTE_NV);
  EXPECT_EQ(GetInt(GL_FOG_HINT), GL_DONT_CARE);
  EXPECT_EQ(GetFloat(GL_CURRENT_FOG_COORD), 0.0f);
  EXPECT_EQ(glIsEnabled(GL_FOG_COORD_ARRAY), GL_FALSE);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_STRIDE), 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, EveryPnameIsStoredAndQueried) {
  for (GLenum m : {GL_LINEAR, GL_EXP2, GL_EXP}) {
    glFogi(GL_FOG_MODE, static_cast<GLint>(m));
    EXPECT_EQ(GetInt(GL_FOG_MODE), static_cast<GLint>(m));
  }
  glFogf(GL_FOG_MODE, static_cast<GLfloat>(GL_LINEAR));
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_LINEAR);
  glFogf(GL_FOG_DENSITY, 0.25f);
  EXPECT_EQ(GetFloat(GL_FOG_DENSITY), 0.25f);
  glFogi(GL_FOG_START, 3);
  EXPECT_EQ(GetFloat(GL_FOG_START), 3.0f);
  const GLfloat end = -7.5f;
  glFogfv(GL_FOG_END, &end);
  EXPECT_EQ(GetFloat(GL_FOG_END), -7.5f);
  const GLint index = 5;
  glFogiv(GL_FOG_INDEX, &index);
  EXPECT_EQ(GetFloat(GL_FOG_INDEX), 5.0f);
  const GLfloat c[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glFogfv(GL_FOG_COLOR, c);
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{0.25f, 0.5f, 0.75f, 1.0f}));
  const GLint ci[4] = {0x7fffffff, 0, 0x7fffffff, 0};
  glFogiv(GL_FOG_COLOR, ci);
  const auto got = GetFloats<4>(GL_FOG_COLOR);
  EXPECT_FLOAT_EQ(got[0], 1.0f);
  EXPECT_NEAR(got[1], 0.0f, 1e-6f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  EXPECT_EQ(GetInt(GL_FOG_COORD_SRC), GL_FOG_COORD);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);  // the GL 1.4 / EXT name
  EXPECT_EQ(GetInt(GL_FOG_COORD_SRC), GL_FRAGMENT_DEPTH);
  for (GLenum d : {GL_EYE_RADIAL_NV, GL_EYE_PLANE, GL_EYE_PLANE_ABSOLUTE_NV}) {
    glFogi(GL_FOG_DISTANCE_MODE_NV, static_cast<GLint>(d));
    EXPECT_EQ(GetInt(GL_FOG_DISTANCE_MODE_NV), static_cast<GLint>(d));
  }
  glEnable(GL_FOG);
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_TRUE);
  EXPECT_EQ(GetBool(GL_FOG), GL_TRUE);
  glDisable(GL_FOG);
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, ColourIsStoredAsGivenAndQueriedClamped) {
  const GLfloat c[4] = {2, -1, 0.5f, 3};
  glFogfv(GL_FOG_COLOR, c);
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{1, 0, 0.5f, 1}));
  glFogf(GL_FOG_COLOR, 0.5f);  // a scalar: (0.5, 0, 0, 0)
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{0.5f, 0, 0, 0}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, ErrorsChangeNothing) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogi(GL_FOG_MODE, GL_FOG);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_LINEAR);
  glFogf(GL_FOG_DENSITY, 0.5f);
  glFogf(GL_FOG_DENSITY, -0.25f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetFloat(GL_FOG_DENSITY), 0.5f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_FOG_COORD_SRC), GL_FRAGMENT_DEPTH);
  glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_FOG_DISTANCE_MODE_NV), GL_EYE_PLANE_ABSOLUTE_NV);
  glFogf(GL_FOG_HINT, 1.0f);  // not a glFog pname
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFogf(GL_DEPTH_TEST, 1.0f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_TRIANGLES);
  glFogf(GL_FOG_START, 4.0f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetFloat(GL_FOG_START), 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, FogBitAndEnableBitPushAndPop) {
  glPushAttrib(GL_FOG_BIT);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 9.0f);
  const GLfloat c[4] = {0.5f, 0.5f, 0.5f, 0.5f};
  glFogfv(GL_FOG_COLOR, c);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_FALSE);
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_EXP);
  EXPECT_EQ(GetFloat(GL_FOG_END), 1.0f);
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{0, 0, 0, 0}));
  // Mesa's glPopAttrib restores neither the fog coordinate source nor the
  // distance mode (main/attrib.c calls glFog for the others only).
  EXPECT_EQ(GetInt(GL_FOG_COORD_SRC), GL_FOG_COORD);
  EXPECT_EQ(GetInt(GL_FOG_DISTANCE_MODE_NV), GL_EYE_RADIAL_NV);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_FOG);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, ListsCompileFogAndFogCoordinates) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  const GLfloat c[4] = {0.25f, 0.5f, 1, 1};
  glFogfv(GL_FOG_COLOR, c);
  glBegin(GL_POINTS);
  glFogCoordf(3.5f);
  glVertex2f(0, 0);
  glEnd();
  glFogCoordf(7.0f);
  glEndList();
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_EXP);
  EXPECT_EQ(GetFloat(GL_CURRENT_FOG_COORD), 0.0f);
  glCallList(list);
  EXPECT_EQ(GetInt(GL_FOG_MODE), GL_LINEAR);
  EXPECT_EQ(GetFloats<4>(GL_FOG_COLOR), (std::array<GLfloat, 4>{0.25f, 0.5f, 1, 1}));
  EXPECT_EQ(GetFloat(GL_CURRENT_FOG_COORD), 7.0f);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FogTest, FogCoordinateArrayState) {
  static const GLdouble coords[4] = {1, 2, 3, 4};
  glFogCoordPointer(GL_DOUBLE, 16, coords);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_FOG_COORD_ARRAY), GL_TRUE);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_STRIDE), 16);
  EXPECT_EQ(GetInt(GL_FOG_COORD_ARRAY_BUFFER_BINDING), 0);
  void* p = nullptr;
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  EXPECT_EQ(p, static_cast<const void*>(coords));
  glFogCoordPointer(GL_INT, 0, coords);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFogCoordPointer(GL_FLOAT, -1, coords);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_FOG_COORD_ARRAY), GL_FALSE);
  // The EXT_fog_coord names.
  auto fogCoordfEXT = reinterpret_cast<void (*)(GLfloat)>(OSMesaGetProcAddress("glFogCoordfEXT"));
  ASSERT_NE(fogCoordfEXT, nullptr);
  fogCoordfEXT(2.5f);
  EXPECT_EQ(GetFloat(GL_CURRENT_FOG_COORD), 2.5f);
  EXPECT_NE(OSMesaGetProcAddress("glFogCoordPointerEXT"), nullptr);
  EXPECT_NO_GL_ERROR();
}

// Pixels: linear 0..20 at coordinate 5 (and -5: its absolute value) is
// f = 0.75; GL_EXP and GL_EXP2 through llvmpipe's exp2.
TEST_F(FogTest, FoggedPixelsAreMesas) {
  EXPECT_EQ(fogRed(GL_LINEAR, 1, 0, 20, 5), 64);
  EXPECT_EQ(fogRed(GL_LINEAR, 1, 0, 20, -5), 64);
  EXPECT_EQ(fogRed(GL_LINEAR, 1, 4, 4, 3.5f), 255);  // start == end: f = c - end, saturated
  EXPECT_EQ(fogRed(GL_LINEAR, 1, 4, 4, 4.5f), 128);
  EXPECT_EQ(fogRed(GL_EXP, 0.15f, 0, 1, 10), 198);
  EXPECT_EQ(fogRed(GL_EXP2, 0.3f, 0, 1, 2.5f), 110);
  EXPECT_EQ(fogRed(GL_EXP, 0.0f, 0, 1, 3), 0);  // density 0: no fog
  EXPECT_NO_GL_ERROR();
}

// GL_FRAGMENT_DEPTH: |z_eye| per fragment, the fog colour clamped.
TEST_F(FogTest, FragmentDepthAndClampedColour) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, 0, 100);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_FOG);
  const GLfloat bright[4] = {3, 3, 3, 1};
  glFogfv(GL_FOG_COLOR, bright);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 40);
  glColor3f(0, 0, 0);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, -10);
  glVertex3f(1, -1, -10);
  glVertex3f(1, 1, -10);
  glVertex3f(-1, 1, -10);
  glEnd();
  EXPECT_EQ(centreRed(), 64);                     // 1 * 0.25, not 3 * 0.25
  glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);  // signed z: f = (40 + 10) / 40, saturated
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, -10);
  glVertex3f(1, -1, -10);
  glVertex3f(1, 1, -10);
  glVertex3f(-1, 1, -10);
  glEnd();
  EXPECT_EQ(centreRed(), 0);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
