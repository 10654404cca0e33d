// Texture coordinates per vertex, as GL_FEEDBACK reports them (GL 2.1 §5.3,
// §2.11.4): each vertex's unit-0 coordinates after texgen and the texture
// matrix, clipped vertices' interpolated; and the raster position's
// (§2.13). Built against Mesa too: the values the checks expect are the
// GL's, exact where the arithmetic is exact, within a float's rounding for
// the sphere, reflection and normal maps.
//
// Mesa applies texgen and the texture matrix to the vertices only for a unit
// whose texture is enabled and complete; the tests that need them enable a
// 1x1 GL_TEXTURE_2D (the image upload may not be implemented where the
// texture stage is not: its error is drained).
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

class TexCoordFeedbackTest : public GLTest {
 protected:
  void SetUp() override {
    GLTest::SetUp();
    glViewport(0, 0, kWidth, kHeight);
  }
  void EnableTexture() {
    const GLubyte texel[4] = {255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glEnable(GL_TEXTURE_2D);
    DrainErrors();
  }
  // Draws `draw` in GL_FEEDBACK with GL_4D_COLOR_TEXTURE; returns the values.
  template <typename Draw>
  std::vector<GLfloat> Feedback(Draw draw) {
    std::vector<GLfloat> buffer(1024, -999.0f);
    glFeedbackBuffer(static_cast<GLsizei>(buffer.size()), GL_4D_COLOR_TEXTURE, buffer.data());
    glRenderMode(GL_FEEDBACK);
    draw();
    const GLint n = glRenderMode(GL_RENDER);
    buffer.resize(n > 0 ? static_cast<size_t>(n) : 0);
    return buffer;
  }
  // The texture coordinates of each vertex of a feedback buffer of polygons,
  // lines and points (12 values a vertex: x y z w, r g b a, s t r q).
  static std::vector<std::array<GLfloat, 4>> TexCoords(const std::vector<GLfloat>& f) {
    std::vector<std::array<GLfloat, 4>> out;
    size_t i = 0;
    while (i < f.size()) {
      const GLenum token = static_cast<GLenum>(f[i++]);
      size_t count = 1;
      if (token == GL_POLYGON_TOKEN)
        count = static_cast<size_t>(f[i++]);
      else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN)
        count = 2;
      for (size_t v = 0; v < count && i + 12 <= f.size(); ++v, i += 12)
        out.push_back({f[i + 8], f[i + 9], f[i + 10], f[i + 11]});
    }
    return out;
  }
  static std::vector<std::array<GLfloat, 2>> WindowXY(const std::vector<GLfloat>& f) {
    std::vector<std::array<GLfloat, 2>> out;
    size_t i = 0;
    while (i < f.size()) {
      const GLenum token = static_cast<GLenum>(f[i++]);
      size_t count = 1;
      if (token == GL_POLYGON_TOKEN)
        count = static_cast<size_t>(f[i++]);
      else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN)
        count = 2;
      for (size_t v = 0; v < count && i + 12 <= f.size(); ++v, i += 12) out.push_back({f[i], f[i + 1]});
    }
    return out;
  }
};

void Triangle() {
  glBegin(GL_TRIANGLES);
  glTexCoord4f(0.25f, 0.5f, 0.75f, 1.0f);
  glVertex2f(-0.5f, -0.5f);
  glTexCoord4f(1.0f, 2.0f, 3.0f, 4.0f);
  glVertex2f(0.5f, -0.5f);
  glTexCoord2f(-1.0f, 8.0f);
  glVertex2f(0.0f, 0.5f);
  glEnd();
}

TEST_F(TexCoordFeedbackTest, EachVertexKeepsItsCoordinatesWithoutTexturing) {
  auto t = TexCoords(Feedback(Triangle));
  ASSERT_EQ(t.size(), 3u);
  const std::array<GLfloat, 4> want[3] = {{0.25f, 0.5f, 0.75f, 1.0f}, {1, 2, 3, 4}, {-1, 8, 0, 1}};
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(t[v][k], want[v][k]) << v << " " << k;
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, ArraysGiveEachVertexItsCoordinates) {
  const GLfloat pos[] = {-0.5f, -0.5f, 0.5f, -0.5f, 0.0f, 0.5f};
  const GLfloat tex[] = {1, 2, 3, 4, 5, 6};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glTexCoordPointer(2, GL_FLOAT, 0, tex);
  auto t = TexCoords(Feedback([] { glDrawArrays(GL_TRIANGLES, 0, 3); }));
  ASSERT_EQ(t.size(), 3u);
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(t[v][0], tex[2 * v]);
    EXPECT_EQ(t[v][1], tex[2 * v + 1]);
    EXPECT_EQ(t[v][2], 0.0f);
    EXPECT_EQ(t[v][3], 1.0f);
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, TextureMatrixOfAnEnabledUnit) {
  EnableTexture();
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0.25f, 0.0f);
  glScalef(2.0f, 4.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  auto t = TexCoords(Feedback(Triangle));
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0][0], 0.25f * 2 + 0.5f);
  EXPECT_EQ(t[0][1], 0.5f * 4 + 0.25f);
  // q = 4: the translation is scaled by q.
  EXPECT_EQ(t[1][0], 1.0f * 2 + 0.5f * 4);
  EXPECT_EQ(t[1][1], 2.0f * 4 + 0.25f * 4);
  EXPECT_EQ(t[1][2], 3.0f);
  EXPECT_EQ(t[1][3], 4.0f);
  EXPECT_EQ(t[2][0], -2.0f + 0.5f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, ObjectAndEyeLinear) {
  EnableTexture();
  const GLfloat sPlane[4] = {2, 0, 0, 0.5f};
  const GLfloat tPlane[4] = {0, 1, 0, 1};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
  glTranslatef(0, 0.25f, 0);  // the eye plane is stored through this modelview's inverse
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_T, GL_EYE_PLANE, tPlane);
  glLoadIdentity();
  glTranslatef(0, 0.5f, 0);  // drawn with another modelview
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  auto t = TexCoords(Feedback(Triangle));
  ASSERT_EQ(t.size(), 3u);
  const GLfloat x[3] = {-0.5f, 0.5f, 0.0f}, y[3] = {-0.5f, -0.5f, 0.5f};
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(t[v][0], 2 * x[v] + 0.5f) << v;
    // Eye plane (0, 1, 0, 1 - 0.25), eye y = y + 0.5.
    EXPECT_EQ(t[v][1], (y[v] + 0.5f) + 0.75f) << v;
  }
  EXPECT_EQ(t[0][2], 0.75f);  // r and q as given
  EXPECT_EQ(t[1][3], 4.0f);
  EXPECT_NO_GL_ERROR();
}

// The GL's sphere map, reflection map and normal map of one vertex (§2.11.4), in double.
struct Maps {
  double sphere[2], reflection[3], normal[3];
};
Maps ExpectedMaps(const double eye[3], const double n[3]) {
  Maps m;
  const double len = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  const double u[3] = {eye[0] / len, eye[1] / len, eye[2] / len};
  const double nu = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = u[i] - 2 * nu * n[i];
  const double mm = 2 * std::sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1) * (r[2] + 1));
  m.sphere[0] = r[0] / mm + 0.5;
  m.sphere[1] = r[1] / mm + 0.5;
  for (int i = 0; i < 3; ++i) m.reflection[i] = r[i], m.normal[i] = n[i];
  return m;
}

TEST_F(TexCoordFeedbackTest, SphereReflectionAndNormalMaps) {
  EnableTexture();
  glTranslatef(0, 0, -3);  // the eye position is (x, y, -3)
  const GLfloat normal[3] = {0.6f, 0.0f, 0.8f};
  for (GLenum mode : {GL_SPHERE_MAP, GL_REFLECTION_MAP, GL_NORMAL_MAP}) {
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
    if (mode != GL_SPHERE_MAP) glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, mode);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    if (mode != GL_SPHERE_MAP) glEnable(GL_TEXTURE_GEN_R);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    auto t = TexCoords(Feedback([&] {
      glNormal3fv(normal);
      Triangle();
    }));
    ASSERT_EQ(t.size(), 3u) << mode;
    const double x[3] = {-0.5, 0.5, 0.0}, y[3] = {-0.5, -0.5, 0.5};
    const double n[3] = {normal[0], normal[1], normal[2]};
    for (int v = 0; v < 3; ++v) {
      const double eye[3] = {x[v], y[v], -3};
      const Maps m = ExpectedMaps(eye, n);
      const double* want = mode == GL_SPHERE_MAP       ? m.sphere
                           : mode == GL_REFLECTION_MAP ? m.reflection
                                                       : m.normal;
      const int comps = mode == GL_SPHERE_MAP ? 2 : 3;
      for (int k = 0; k < comps; ++k) EXPECT_NEAR(t[v][k], want[k], 2e-6) << mode << " " << v << " " << k;
    }
    glDisable(GL_TEXTURE_GEN_R);
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, ClippedVerticesInterpolateTheCoordinates) {
  // s = x and t = y at every vertex: a vertex the clipper makes on x = 1
  // has s = 1 (the projection is the identity, so clip x is object x).
  std::vector<GLfloat> f = Feedback([] {
    glBegin(GL_TRIANGLES);
    glTexCoord2f(-0.5f, -0.5f);
    glVertex2f(-0.5f, -0.5f);
    glTexCoord2f(2.0f, 0.0f);
    glVertex2f(2.0f, 0.0f);
    glTexCoord2f(-0.5f, 0.5f);
    glVertex2f(-0.5f, 0.5f);
    glEnd();
  });
  auto xy = WindowXY(f);
  auto t = TexCoords(f);
  ASSERT_GE(t.size(), 4u);
  ASSERT_EQ(t.size(), xy.size());
  for (size_t v = 0; v < t.size(); ++v) {
    const double ndcX = xy[v][0] / (kWidth / 2.0) - 1.0, ndcY = xy[v][1] / (kHeight / 2.0) - 1.0;
    EXPECT_NEAR(t[v][0], ndcX, 1e-5) << v;
    EXPECT_NEAR(t[v][1], ndcY, 1e-5) << v;
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, RasterPositionCoordinates) {
  // GL 2.1 §2.13: texgen and the texture matrix, whatever the texture enables.
  const GLfloat sPlane[4] = {1, 1, 0, 0};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
  glEnable(GL_TEXTURE_GEN_S);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 2, 2);
  glMatrixMode(GL_MODELVIEW);
  glTexCoord4f(9, 0.5f, 0.25f, 1);
  glRasterPos2f(0.25f, 0.5f);
  auto rt = GetFloats<4>(GL_CURRENT_RASTER_TEXTURE_COORDS);
  EXPECT_EQ(rt[0], 2 * (0.25f + 0.5f));
  EXPECT_EQ(rt[1], 1.0f);
  EXPECT_EQ(rt[2], 0.5f);
  EXPECT_EQ(rt[3], 1.0f);
  // Another unit: its own matrix and coordinates.
  glActiveTexture(GL_TEXTURE1);
  glMultiTexCoord2f(GL_TEXTURE1, 3, 4);
  glRasterPos2f(0.25f, 0.5f);
  auto r1 = GetFloats<4>(GL_CURRENT_RASTER_TEXTURE_COORDS);
  EXPECT_EQ(r1[0], 3.0f);
  EXPECT_EQ(r1[1], 4.0f);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_RASTER_TEXTURE_COORDS)[0], 1.5f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexCoordFeedbackTest, CurrentTextureCoordsOfTheActiveUnit) {
  glMultiTexCoord2f(GL_TEXTURE2, 5, 6);
  glActiveTexture(GL_TEXTURE2);
  auto c = GetFloats<4>(GL_CURRENT_TEXTURE_COORDS);
  EXPECT_EQ(c[0], 5.0f);
  EXPECT_EQ(c[1], 6.0f);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
