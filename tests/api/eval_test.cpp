// Evaluators (GL 2.1 §5.1): the initial maps and grids (table 6.39), glMap1/
// glMap2 read back with glGetMap (GL_COEFF, GL_ORDER, GL_DOMAIN), the enables,
// every error of §5.1, glEvalCoord leaving the current values alone, and a
// few pixels of glEvalMesh2 and glEvalCoord2 inside glBegin/glEnd.
#include <functional>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using EvalTest = GLTest;

const GLenum kMap1Targets[] = {GL_MAP1_COLOR_4,         GL_MAP1_INDEX,           GL_MAP1_NORMAL,
                               GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
                               GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3,        GL_MAP1_VERTEX_4};
const GLenum kMap2Targets[] = {GL_MAP2_COLOR_4,         GL_MAP2_INDEX,           GL_MAP2_NORMAL,
                               GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
                               GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3,        GL_MAP2_VERTEX_4};
// Table 5.1: values per control point, in the order above.
const int kComponents[] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
// Table 6.39: the single initial control point of each map.
const float kInitial[9][4] = {{1, 1, 1, 1}, {1},          {0, 0, 1}, {0},         {0, 0},
                              {0, 0, 0},    {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0, 1}};

std::vector<GLfloat> GetMapF(GLenum target, GLenum query, int n) {
  std::vector<GLfloat> v(64, -777.0f);
  glGetMapfv(target, query, v.data());
  v.resize(n);
  return v;
}

TEST_F(EvalTest, InitialState) {
  EXPECT_GE(GetInt(GL_MAX_EVAL_ORDER), 8);
  EXPECT_EQ(glIsEnabled(GL_AUTO_NORMAL), GL_FALSE);
  EXPECT_EQ(GetBool(GL_AUTO_NORMAL), GL_FALSE);
  for (int i = 0; i < 9; ++i) {
    for (GLenum t : {kMap1Targets[i], kMap2Targets[i]}) {
      SCOPED_TRACE(::testing::Message() << "target 0x" << std::hex << t);
      const bool twoD = t >= GL_MAP2_COLOR_4;
      EXPECT_EQ(glIsEnabled(t), GL_FALSE);
      EXPECT_EQ(GetInt(t), 0);
      std::vector<GLfloat> order = GetMapF(t, GL_ORDER, twoD ? 2 : 1);
      for (GLfloat o : order) EXPECT_EQ(o, 1.0f);
      std::vector<GLfloat> domain = GetMapF(t, GL_DOMAIN, twoD ? 4 : 2);
      EXPECT_EQ(domain[0], 0.0f);
      EXPECT_EQ(domain[1], 1.0f);
      if (twoD) {
        EXPECT_EQ(domain[2], 0.0f);
        EXPECT_EQ(domain[3], 1.0f);
      }
      std::vector<GLfloat> coeff = GetMapF(t, GL_COEFF, kComponents[i] + 1);
      for (int c = 0; c < kComponents[i]; ++c) EXPECT_EQ(coeff[c], kInitial[i][c]) << "component " << c;
      EXPECT_EQ(coeff[kComponents[i]], -777.0f) << "more values than the map has";
    }
  }
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 1);
  std::array<GLfloat, 2> d1 = GetFloats<2>(GL_MAP1_GRID_DOMAIN);
  EXPECT_EQ(d1[0], 0.0f);
  EXPECT_EQ(d1[1], 1.0f);
  std::array<GLint, 2> s2 = GetInts<2>(GL_MAP2_GRID_SEGMENTS);
  EXPECT_EQ(s2[0], 1);
  EXPECT_EQ(s2[1], 1);
  std::array<GLfloat, 4> d2 = GetFloats<4>(GL_MAP2_GRID_DOMAIN);
  EXPECT_EQ(d2[0], 0.0f);
  EXPECT_EQ(d2[1], 1.0f);
  EXPECT_EQ(d2[2], 0.0f);
  EXPECT_EQ(d2[3], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, EnableEveryMapAndAutoNormal) {
  std::vector<GLenum> caps(std::begin(kMap1Targets), std::end(kMap1Targets));
  caps.insert(caps.end(), std::begin(kMap2Targets), std::end(kMap2Targets));
  caps.push_back(GL_AUTO_NORMAL);
  for (GLenum cap : caps) {
    SCOPED_TRACE(::testing::Message() << "cap 0x" << std::hex << cap);
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE);
    EXPECT_EQ(GetBool(cap), GL_TRUE);
    EXPECT_EQ(GetInt(cap), 1);
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
    EXPECT_NO_GL_ERROR();
  }
}

TEST_F(EvalTest, Map1StoresPointsWithStride) {
  // order 3, stride 5 (two unused values after each point), VERTEX_3
  const GLfloat pts[15] = {1, 2, 3, -9, -9, 4, 5, 6, -9, -9, 7, 8, 9, -9, -9};
  glMap1f(GL_MAP1_VERTEX_3, -1.0f, 3.0f, 5, 3, pts);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_3, GL_ORDER, 1)[0], 3.0f);
  std::vector<GLfloat> domain = GetMapF(GL_MAP1_VERTEX_3, GL_DOMAIN, 2);
  EXPECT_EQ(domain[0], -1.0f);
  EXPECT_EQ(domain[1], 3.0f);
  std::vector<GLfloat> coeff = GetMapF(GL_MAP1_VERTEX_3, GL_COEFF, 10);
  const GLfloat expected[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(coeff[i], expected[i]) << i;
  EXPECT_EQ(coeff[9], -777.0f);
  // glGetMapdv and glGetMapiv read the same map.
  GLdouble dv[9];
  glGetMapdv(GL_MAP1_VERTEX_3, GL_COEFF, dv);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(dv[i], expected[i]);
  GLint order = -1;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 3);
  // The other maps are untouched.
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_4, GL_ORDER, 1)[0], 1.0f);
  EXPECT_EQ(GetMapF(GL_MAP2_VERTEX_3, GL_ORDER, 2)[0], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, Map1dRoundsToFloatAndGetMapivRounds) {
  const GLdouble pts[8] = {0.1, 1.5, -2.5, 2.6, 0.7, -0.2, 3.49, 100.25};
  glMap1d(GL_MAP1_COLOR_4, 0.3, 2.5, 4, 2, pts);
  ASSERT_NO_GL_ERROR();
  std::vector<GLfloat> f = GetMapF(GL_MAP1_COLOR_4, GL_COEFF, 8);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(f[i], static_cast<GLfloat>(pts[i])) << i;
  GLdouble d[8];
  glGetMapdv(GL_MAP1_COLOR_4, GL_COEFF, d);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(d[i], static_cast<GLdouble>(static_cast<GLfloat>(pts[i]))) << i;
  GLdouble dom[2];
  glGetMapdv(GL_MAP1_COLOR_4, GL_DOMAIN, dom);
  EXPECT_EQ(dom[0], static_cast<GLdouble>(0.3f));
  EXPECT_EQ(dom[1], 2.5);
  GLint i[8];
  glGetMapiv(GL_MAP1_COLOR_4, GL_COEFF, i);
  const GLint rounded[8] = {0, 2, -3, 3, 1, 0, 3, 100};  // to the nearest, halves away from 0
  for (int k = 0; k < 8; ++k) EXPECT_EQ(i[k], rounded[k]) << k;
  GLint idom[2];
  glGetMapiv(GL_MAP1_COLOR_4, GL_DOMAIN, idom);
  EXPECT_EQ(idom[0], 0);
  EXPECT_EQ(idom[1], 3);
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, Map2StoresPointsUMajor) {
  // uorder 2, vorder 3, TEXTURE_COORD_2; points laid out v-major in memory
  // (vstride 2*2... ustride 2, vstride 4) to check the strides are followed.
  GLfloat mem[2 * 3 * 2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) {
      mem[i * 2 + j * 4 + 0] = 10.0f * i + j;
      mem[i * 2 + j * 4 + 1] = -(10.0f * i + j);
    }
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 2.0f, 2, 2, -1.0f, 1.0f, 4, 3, mem);
  ASSERT_NO_GL_ERROR();
  std::vector<GLfloat> order = GetMapF(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, 2);
  EXPECT_EQ(order[0], 2.0f);
  EXPECT_EQ(order[1], 3.0f);
  std::vector<GLfloat> domain = GetMapF(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN, 4);
  EXPECT_EQ(domain[0], 0.0f);
  EXPECT_EQ(domain[1], 2.0f);
  EXPECT_EQ(domain[2], -1.0f);
  EXPECT_EQ(domain[3], 1.0f);
  std::vector<GLfloat> coeff = GetMapF(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, 13);
  // GL_COEFF: point (i, j) at (i * vorder + j) * k.
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(coeff[(i * 3 + j) * 2 + 0], 10.0f * i + j) << i << "," << j;
      EXPECT_EQ(coeff[(i * 3 + j) * 2 + 1], -(10.0f * i + j)) << i << "," << j;
    }
  EXPECT_EQ(coeff[12], -777.0f);
  GLint iorder[2];
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, iorder);
  EXPECT_EQ(iorder[0], 2);
  EXPECT_EQ(iorder[1], 3);
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, MapGridState) {
  glMapGrid1f(7, 0.25f, -3.0f);
  glMapGrid2d(3, 1.5, 2.5, 9, -1.0, 4.0);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 7);
  std::array<GLfloat, 2> d1 = GetFloats<2>(GL_MAP1_GRID_DOMAIN);
  EXPECT_EQ(d1[0], 0.25f);
  EXPECT_EQ(d1[1], -3.0f);
  std::array<GLint, 2> s2 = GetInts<2>(GL_MAP2_GRID_SEGMENTS);
  EXPECT_EQ(s2[0], 3);
  EXPECT_EQ(s2[1], 9);
  std::array<GLdouble, 4> d2 = GetDoubles<4>(GL_MAP2_GRID_DOMAIN);
  EXPECT_EQ(d2[0], 1.5);
  EXPECT_EQ(d2[1], 2.5);
  EXPECT_EQ(d2[2], -1.0);
  EXPECT_EQ(d2[3], 4.0);
  EXPECT_NO_GL_ERROR();
}

// ---- the errors of §5.1 ----------------------------------------------------------

// Each failing call records `error` and leaves the map as it was.
void ExpectMap1Fails(GLenum error, const std::function<void()>& call) {
  call();
  EXPECT_GL_ERROR(error);
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_3, GL_ORDER, 1)[0], 1.0f);
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_3, GL_DOMAIN, 2)[1], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, Map1Errors) {
  GLfloat pts[4 * 40] = {};
  // GL_INVALID_ENUM: not a 1D map name
  for (GLenum bad : {static_cast<GLenum>(GL_MAP2_VERTEX_3), static_cast<GLenum>(GL_VERTEX_ARRAY),
                     static_cast<GLenum>(GL_AUTO_NORMAL), static_cast<GLenum>(0xFFFF)}) {
    SCOPED_TRACE(::testing::Message() << "target 0x" << std::hex << bad);
    ExpectMap1Fails(GL_INVALID_ENUM, [&] { glMap1f(bad, 0, 1, 4, 2, pts); });
  }
  // GL_INVALID_VALUE: u1 == u2; order out of 1..GL_MAX_EVAL_ORDER; stride < k
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0.5f, 0.5f, 3, 2, pts); });
  const std::vector<GLdouble> dpts(12, 0.0);
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1d(GL_MAP1_VERTEX_3, 2.0, 2.0, 3, 2, dpts.data()); });
  const GLint maxOrder = GetInt(GL_MAX_EVAL_ORDER);
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, pts); });
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, -1, pts); });
  std::vector<GLfloat> big(4 * (maxOrder + 1), 0.0f);
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, maxOrder + 1, big.data()); });
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, pts); });
  ExpectMap1Fails(GL_INVALID_VALUE, [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 0, 2, pts); });
  // the largest order is accepted
  glMap1f(GL_MAP1_VERTEX_4, 0, 1, 4, maxOrder, big.data());
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_4, GL_ORDER, 1)[0], static_cast<GLfloat>(maxOrder));
  // stride == k is enough for every target
  for (int i = 0; i < 9; ++i) {
    glMap1f(kMap1Targets[i], 0, 1, kComponents[i], 2, pts);
    EXPECT_NO_GL_ERROR() << i;
  }
}

TEST_F(EvalTest, Map2Errors) {
  GLfloat pts[4 * 4 * 4] = {};
  auto expectFails = [&](GLenum error, const std::function<void()>& call) {
    call();
    EXPECT_GL_ERROR(error);
    std::vector<GLfloat> order = GetMapF(GL_MAP2_VERTEX_3, GL_ORDER, 2);
    EXPECT_EQ(order[0], 1.0f);
    EXPECT_EQ(order[1], 1.0f);
    EXPECT_NO_GL_ERROR();
  };
  for (GLenum bad : {static_cast<GLenum>(GL_MAP1_VERTEX_3), static_cast<GLenum>(GL_LIGHTING),
                     static_cast<GLenum>(0xFFFF)}) {
    SCOPED_TRACE(::testing::Message() << "target 0x" << std::hex << bad);
    expectFails(GL_INVALID_ENUM, [&] { glMap2f(bad, 0, 1, 3, 2, 0, 1, 6, 2, pts); });
  }
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 1, 1, 3, 2, 0, 1, 6, 2, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, -2, -2, 6, 2, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 0, 0, 1, 6, 2, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 0, pts); });
  const GLint maxOrder = GetInt(GL_MAX_EVAL_ORDER);
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, maxOrder + 1, 0, 1, 6, 2, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, maxOrder + 1, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 2, 2, 0, 1, 6, 2, pts); });
  expectFails(GL_INVALID_VALUE, [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 2, 2, pts); });
  // ustride and vstride each >= k, in either nesting
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, pts);
  EXPECT_NO_GL_ERROR();
  glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, std::vector<GLdouble>(12).data());
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, GridAndMeshErrors) {
  glMapGrid1f(0, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid1d(-3, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid2f(0, 0, 1, 4, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glMapGrid2f(4, 0, 1, 0, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 1);
  std::array<GLint, 2> s2 = GetInts<2>(GL_MAP2_GRID_SEGMENTS);
  EXPECT_EQ(s2[0], 1);
  EXPECT_EQ(s2[1], 1);
  // a grid whose u1 == u2 is allowed
  glMapGrid1f(2, 0.5f, 0.5f);
  EXPECT_NO_GL_ERROR();

  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP2_VERTEX_3);
  glEvalMesh1(GL_FILL, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh1(GL_TRIANGLES, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh2(GL_LINE_STRIP, 0, 1, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEvalMesh2(0xFFFF, 0, 1, 0, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// GL_POINT and GL_LINE meshes of both dimensions run without an error (their
// vertices are compared with Mesa's by tests/pipeline/mesa_eval for GL_POINT;
// lines are not rasterized yet, so no pixels are checked here).
TEST_F(EvalTest, PointAndLineMeshesRaiseNoError) {
  const GLfloat curve[12] = {-0.5f, -0.5f, 0, 0, 0.5f, 0, 0.5f, -0.5f, 0, 0.6f, 0.2f, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, curve);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, curve);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid1f(8, 0, 1);
  glMapGrid2f(4, 0, 1, 3, 0, 1);
  for (GLenum mode : {GL_POINT, GL_LINE}) {
    glEvalMesh1(mode, 0, 8);
    glEvalMesh1(mode, 5, 2);  // empty
    glEvalMesh2(mode, 0, 4, 0, 3);
    glEvalMesh2(mode, -1, 5, 2, 2);
    EXPECT_NO_GL_ERROR();
  }
  glEvalMesh2(GL_FILL, 0, 4, 0, 3);
  glFinish();
  EXPECT_NO_GL_ERROR();
}

TEST_F(EvalTest, GetMapErrors) {
  GLfloat f[16];
  GLdouble d[16];
  GLint i[16];
  glGetMapfv(GL_VERTEX_ARRAY, GL_COEFF, f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetMapdv(0xFFFF, GL_ORDER, d);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetMapiv(GL_AUTO_NORMAL, GL_DOMAIN, i);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetMapfv(GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_3, f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetMapiv(GL_MAP2_COLOR_4, 0xFFFF, i);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// §2.6.3: only glEvalCoord and glEvalPoint may come between glBegin and glEnd.
TEST_F(EvalTest, RefusedBetweenBeginAndEnd) {
  const GLfloat pts[12] = {};
  GLfloat f[16];
  const std::function<void()> calls[] = {
      [&] { glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts); },
      [&] { glMap1d(GL_MAP1_VERTEX_3, 0, 1, 3, 2, std::vector<GLdouble>(6).data()); },
      [&] { glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, pts); },
      [&] { glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, std::vector<GLdouble>(12).data()); },
      [&] { glMapGrid1f(4, 0, 1); },
      [&] { glMapGrid2d(4, 0, 1, 4, 0, 1); },
      [&] { glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f); },
      [&] { glEvalMesh1(GL_LINE, 0, 2); },
      [&] { glEvalMesh2(GL_FILL, 0, 2, 0, 2); },
      [&] { glEnable(GL_MAP1_VERTEX_3); },
  };
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP2_VERTEX_3);
  int n = 0;
  for (const auto& call : calls) {
    SCOPED_TRACE(::testing::Message() << "call " << n++);
    glBegin(GL_POINTS);
    call();
    glEnd();
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    EXPECT_NO_GL_ERROR();
  }
  EXPECT_EQ(GetMapF(GL_MAP1_VERTEX_3, GL_ORDER, 1)[0], 1.0f);
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 1);
  // glEvalCoord and glEvalPoint are allowed there.
  glBegin(GL_POINTS);
  glEvalCoord1f(0.5f);
  glEvalCoord2f(0.5f, 0.5f);
  glEvalCoord1d(0.5);
  glEvalCoord2dv(std::array<GLdouble, 2>{0.5, 0.5}.data());
  glEvalPoint1(1);
  glEvalPoint2(1, 1);
  glEnd();
  EXPECT_NO_GL_ERROR();
}

// ---- evaluation ------------------------------------------------------------------

// The evaluated colour, normal and texture coordinates go to the vertex only:
// the current values stay as they were (Mesa restores them after the vertex.
// The maps first make these attributes vertex data here, where Mesa copies
// stale vertex memory into the current values, as the next test shows; that
// memory happens to hold what glColor/glNormal/glTexCoord put there.)
TEST_F(EvalTest, EvalCoordLeavesTheCurrentValues) {
  const GLfloat color[8] = {0.25f, 0.5f, 0.75f, 1.0f, 0.5f, 0.25f, 0.0f, 0.5f};
  const GLfloat normal[6] = {1, 0, 0, 0, 1, 0};
  const GLfloat tex[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  const GLfloat vtx[6] = {0, 0, 0, 1, 1, 0};
  glMap1f(GL_MAP1_COLOR_4, 0, 1, 4, 2, color);
  glMap1f(GL_MAP1_NORMAL, 0, 1, 3, 2, normal);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0, 1, 2, 2, tex);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, vtx);
  for (GLenum cap : {GL_MAP1_COLOR_4, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_VERTEX_3})
    glEnable(cap);
  glColor4f(0.125f, 0.375f, 0.625f, 0.875f);
  glNormal3f(0.0f, 0.6f, 0.8f);
  glTexCoord4f(5, 6, 7, 8);
  glBegin(GL_POINTS);
  glEvalCoord1f(0.5f);
  glEnd();
  glEvalCoord1f(0.25f);  // outside glBegin/glEnd as well
  ASSERT_NO_GL_ERROR();
  std::array<GLfloat, 4> c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_EQ(c[0], 0.125f);
  EXPECT_EQ(c[1], 0.375f);
  EXPECT_EQ(c[2], 0.625f);
  EXPECT_EQ(c[3], 0.875f);
  std::array<GLfloat, 3> n = GetFloats<3>(GL_CURRENT_NORMAL);
  EXPECT_EQ(n[0], 0.0f);
  EXPECT_EQ(n[1], 0.6f);
  EXPECT_EQ(n[2], 0.8f);
  std::array<GLfloat, 4> t = GetFloats<4>(GL_CURRENT_TEXTURE_COORDS);
  EXPECT_EQ(t[0], 5.0f);
  EXPECT_EQ(t[1], 6.0f);
  EXPECT_EQ(t[2], 7.0f);
  EXPECT_EQ(t[3], 8.0f);
}

// The same after a whole glEvalMesh2 whose colour and normal maps first made
// those attributes vertex data, once the draw is flushed. Mesa copies stale
// vertex memory into the current values there (here (0,0,0,0) and (0,0,0)).
TEST_F(EvalTest, EvalMeshLeavesTheCurrentValues) {
  GLFX_SKIP_ON_MESA("a map that first makes an attribute vertex data leaves its current value undefined");
  const GLfloat square[12] = {-0.5f, -0.5f, 0, -0.5f, 0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0};
  const GLfloat red[16] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, square);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, red);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(3, 0, 1, 3, 0, 1);
  glEvalMesh2(GL_FILL, 0, 3, 0, 3);
  glFinish();
  ASSERT_NO_GL_ERROR();
  std::array<GLfloat, 4> c = GetFloats<4>(GL_CURRENT_COLOR);
  for (GLfloat x : c) EXPECT_EQ(x, 1.0f);
  std::array<GLfloat, 3> n = GetFloats<3>(GL_CURRENT_NORMAL);
  EXPECT_EQ(n[0], 0.0f);
  EXPECT_EQ(n[1], 0.0f);
  EXPECT_EQ(n[2], 1.0f);
}

// Pixel (x, y) of the 64x64 buffer (row 0 at the bottom).
const unsigned char* Pixel(const unsigned char* p, int x, int y) { return p + (y * kWidth + x) * 4; }

// A flat square from a bilinear MAP2_VERTEX_3, coloured by a constant
// MAP2_COLOR_4, drawn by glEvalMesh2(GL_FILL); nothing without a vertex map.
TEST_F(EvalTest, EvalMesh2FillDrawsTheSurface) {
  const GLfloat square[12] = {-0.5f, -0.5f, 0, -0.5f, 0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0};
  const GLfloat red[16] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, square);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, red);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(4, 0, 1, 4, 0, 1);
  glEvalMesh2(GL_FILL, 0, 4, 0, 4);  // no vertex map enabled: nothing
  ASSERT_NO_GL_ERROR();
  const unsigned char* p = pixels();
  EXPECT_EQ(Pixel(p, 32, 32)[0], 0);
  glEnable(GL_MAP2_VERTEX_3);
  glColor3f(0, 1, 0);
  glEvalMesh2(GL_FILL, 0, 4, 0, 4);
  ASSERT_NO_GL_ERROR();
  p = pixels();
  const unsigned char* centre = Pixel(p, 32, 32);
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[1], 0);
  EXPECT_EQ(centre[2], 0);
  EXPECT_EQ(Pixel(p, 4, 4)[0], 0) << "outside the square";
  EXPECT_EQ(Pixel(p, 60, 60)[0], 0) << "outside the square";
  // A mesh over part of the grid: i in [0, 2] covers u in [0, 0.5]; with
  // ustride 3 and vstride 6, u runs along y here: the lower half.
  glClear(GL_COLOR_BUFFER_BIT);
  glEvalMesh2(GL_FILL, 0, 2, 0, 4);
  p = pixels();
  EXPECT_EQ(Pixel(p, 32, 24)[0], 255);
  EXPECT_EQ(Pixel(p, 32, 40)[0], 0);
  EXPECT_EQ(Pixel(p, 20, 24)[0], 255);
  EXPECT_EQ(Pixel(p, 44, 24)[0], 255);
}

// Every glEvalCoord variant makes the same vertex: a triangle of the lower
// left quarter, from a 2D square map or (1D) a fan on a straight MAP1 edge.
TEST_F(EvalTest, EveryEvalCoordVariantDraws) {
  const GLfloat square[12] = {-1, -1, 0, -1, 1, 0, 1, -1, 0, 1, 1, 0};  // u along y, v along x
  const GLfloat edge[6] = {-0.9f, 0.1f, 0, 0.1f, -0.9f, 0};             // 1D: u from (-0.9,0.1) to (0.1,-0.9)
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, square);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, edge);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP1_VERTEX_3);
  glClearColor(0, 0, 0, 0);
  const std::function<void(float, float)> variants[] = {
      [](float u, float v) { glEvalCoord2f(u, v); },
      [](float u, float v) {
        const GLfloat p[2] = {u, v};
        glEvalCoord2fv(p);
      },
      [](float u, float v) { glEvalCoord2d(u, v); },
      [](float u, float v) {
        const GLdouble p[2] = {u, v};
        glEvalCoord2dv(p);
      },
  };
  const std::function<void(float)> variants1[] = {
      [](float u) { glEvalCoord1f(u); },
      [](float u) { glEvalCoord1fv(&u); },
      [](float u) { glEvalCoord1d(u); },
      [](float u) {
        const GLdouble d = u;
        glEvalCoord1dv(&d);
      },
  };
  for (int i = 0; i < 8; ++i) {
    SCOPED_TRACE(::testing::Message() << "variant " << i);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0, 1, 0);
    if (i < 4) {
      glBegin(GL_TRIANGLES);
      variants[i](0.05f, 0.05f);
      variants[i](0.45f, 0.05f);
      variants[i](0.05f, 0.45f);
      glEnd();
    } else {
      glBegin(GL_TRIANGLE_FAN);
      glVertex2f(-0.9f, -0.9f);
      variants1[i - 4](1.0f);
      variants1[i - 4](0.0f);
      glEnd();
    }
    ASSERT_NO_GL_ERROR();
    const unsigned char* p = pixels();
    EXPECT_EQ(Pixel(p, 12, 12)[1], 255) << "inside";
    EXPECT_EQ(Pixel(p, 40, 40)[1], 0) << "outside";
  }
}

// glEvalCoord2 and glEvalPoint2 inside glBegin/glEnd make the vertices of an
// ordinary primitive; the evaluated colour is theirs only.
TEST_F(EvalTest, EvalCoordInsideBeginEnd) {
  const GLfloat square[12] = {-1, -1, 0, -1, 1, 0, 1, -1, 0, 1, 1, 0};
  const GLfloat blue[16] = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1};
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, square);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, blue);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glColor3f(1, 1, 0);
  glBegin(GL_TRIANGLES);  // the lower-left half of [-0.5, 0.5]^2
  glEvalCoord2f(0.25f, 0.25f);
  glEvalCoord2f(0.75f, 0.25f);
  glEvalCoord2f(0.25f, 0.75f);
  glEnd();
  glMapGrid2f(4, 0, 1, 4, 0, 1);
  glDisable(GL_MAP2_COLOR_4);
  glBegin(GL_TRIANGLES);  // the upper-right half, by grid points, in the current colour
  glEvalPoint2(3, 1);
  glEvalPoint2(3, 3);
  glEvalPoint2(1, 3);
  glEnd();
  ASSERT_NO_GL_ERROR();
  const unsigned char* p = pixels();
  const unsigned char* lowerLeft = Pixel(p, 24, 24);
  EXPECT_EQ(lowerLeft[0], 0);
  EXPECT_EQ(lowerLeft[2], 255);
  const unsigned char* upperRight = Pixel(p, 40, 40);
  EXPECT_EQ(upperRight[0], 255);
  EXPECT_EQ(upperRight[1], 255);
  EXPECT_EQ(upperRight[2], 0);
  EXPECT_EQ(Pixel(p, 8, 8)[0], 0);
  EXPECT_EQ(Pixel(p, 8, 8)[2], 0);
}

}  // namespace
}  // namespace glfx_test
