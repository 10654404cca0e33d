// The polygon rasterization state of GL 2.1 §3.6: glPolygonMode,
// glPolygonOffset, glPolygonStipple/glGetPolygonStipple (with the pixel
// store), glEdgeFlag, their enables, queries and errors.
#include <cmath>
#include <limits>

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

}  // namespace
