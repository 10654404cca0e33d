// drawPrimitives end to end: provoking vertices, culling, two-sided colour,
// clipping, viewport.
#include <gtest/gtest.h>

#include "primitive/cull.h"
#include "primitive/primitive.h"
#include "raster/test_surface.h"
#include "state/lighting_attrib.h"

namespace glfixed::primitive {
namespace {

using test::TestSurface;

// Distinct, exactly representable colours per vertex.
glm::vec4 colourOf(int i) { return glm::vec4((i % 4) / 4.0f, (i / 4 % 4) / 4.0f, 0.25f + (i % 3) / 4.0f, 1); }

struct Scene {
  TestSurface surface{16, 16};
  PrimitiveState state;
  ShadedVertices v;
  Scene() {
    state.viewportWidth = 16;
    state.viewportHeight = 16;
    state.raster = surface.state();
  }
  // Position in NDC (w = 1), colour i.
  void add(float x, float y, int colour, float z = 0) {
    v.clip.push_back(glm::vec4(x, y, z, 1));
    v.primary[kFront].push_back(colourOf(colour));
    v.primary[kBack].push_back(glm::vec4(1, 0, 1, 1) - colourOf(colour) * glm::vec4(1, 0, 1, 0));
  }
  void draw(GLenum mode) {
    state.mode = mode;
    drawPrimitives(state, v, surface.fb);
  }
  glm::vec4 pixel(int x, int y) const {
    const uint8_t* p = surface.at(x, y);
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  }
  bool is(int x, int y, glm::vec4 c) const {
    const uint8_t* p = surface.at(x, y);
    return p[0] == raster::colorToUnorm8(c.r) && p[1] == raster::colorToUnorm8(c.g) &&
           p[2] == raster::colorToUnorm8(c.b) && p[3] == raster::colorToUnorm8(c.a);
  }
};

// Every mode, flat, both conventions: the pixel colour is the provoking
// vertex's (REFERENCE.md, "Primitives and flat shading").
struct ProvokingCase {
  GLenum mode;
  bool first;
  int provoking;
};

TEST(DrawPrimitives, ProvokingVertexPerMode) {
  const ProvokingCase cases[] = {
      {GL_TRIANGLES, false, 2},     {GL_TRIANGLES, true, 0},     {GL_TRIANGLE_STRIP, false, 3},
      {GL_TRIANGLE_STRIP, true, 1}, {GL_TRIANGLE_FAN, false, 3}, {GL_TRIANGLE_FAN, true, 2},
      {GL_QUADS, false, 3},         {GL_QUADS, true, 3},         {GL_QUAD_STRIP, false, 3},
      {GL_QUAD_STRIP, true, 3},     {GL_POLYGON, false, 0},      {GL_POLYGON, true, 0},
  };
  for (const ProvokingCase& c : cases) {
    Scene s;
    s.state.flat = true;
    s.state.firstVertexConvention = c.first;
    // The probe pixel (8, 8) lies in the second triangle of strips and fans,
    // in the first quad of quad strips.
    switch (c.mode) {
      case GL_TRIANGLES:
        s.add(-1, -1, 0);
        s.add(3, -1, 1);
        s.add(-1, 3, 2);
        break;
      case GL_TRIANGLE_STRIP:
        s.add(-1, -1, 0);
        s.add(-1, 1, 1);
        s.add(-0.2f, -1, 2);
        s.add(1, 1, 3);
        break;
      case GL_TRIANGLE_FAN:
        s.add(-1, -1, 0);
        s.add(1, -1, 1);
        s.add(1, 0.2f, 2);
        s.add(0.2f, 1, 3);
        break;
      case GL_QUADS:
        s.add(-1, -1, 0);
        s.add(1, -1, 1);
        s.add(1, 1, 2);
        s.add(-1, 1, 3);
        break;
      case GL_QUAD_STRIP:
        s.add(-1, -1, 0);
        s.add(1, -1, 1);
        s.add(-1, 1, 2);
        s.add(1, 1, 3);
        break;
      default:
        s.add(-1, -1, 0);
        s.add(1, -1, 1);
        s.add(1, 1, 2);
        s.add(-1, 1, 3);
        break;
    }
    s.draw(c.mode);
    EXPECT_TRUE(s.is(8, 8, colourOf(c.provoking))) << "mode " << c.mode << " first " << c.first;
  }
}

TEST(DrawPrimitives, SmoothQuadIsSplitAlongV0V2) {
  Scene s;
  s.add(-1, -1, 0);
  s.add(1, -1, 1);
  s.add(1, 1, 2);
  s.add(-1, 1, 3);
  s.v.primary[kFront][0] = glm::vec4(1, 0, 0, 1);
  s.v.primary[kFront][1] = glm::vec4(0, 1, 0, 1);
  s.v.primary[kFront][2] = glm::vec4(0, 0, 1, 1);
  s.v.primary[kFront][3] = glm::vec4(0, 0, 0, 1);
  s.draw(GL_QUADS);
  // On the v0-v2 diagonal the colour mixes v0 and v2 only.
  glm::vec4 c = s.pixel(7, 7);
  EXPECT_GT(c.r, 0.4f);
  EXPECT_GT(c.b, 0.4f);
  EXPECT_LT(c.g, 0.1f);
}

TEST(DrawPrimitives, CullingAndFrontFace) {
  for (GLenum front : {GL_CCW, GL_CW})
    for (GLenum mode : {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK})
      for (bool ccwTriangle : {true, false}) {
        Scene s;
        s.state.cullFace = true;
        s.state.cullFaceMode = mode;
        s.state.frontFace = front;
        s.add(-1, -1, 0);
        if (ccwTriangle) {
          s.add(1, -1, 1);
          s.add(-1, 1, 2);
        } else {
          s.add(-1, 1, 2);
          s.add(1, -1, 1);
        }
        s.draw(GL_TRIANGLES);
        const bool isFront = ccwTriangle == (front == GL_CCW);
        const bool culled = mode == GL_FRONT_AND_BACK || (mode == GL_FRONT) == isFront;
        EXPECT_EQ(s.surface.covered(2, 2), !culled) << front << " " << mode << " " << ccwTriangle;
      }
}

TEST(DrawPrimitives, TwoSidedColourSelection) {
  for (bool ccwTriangle : {true, false}) {
    Scene s;
    s.state.flat = true;
    s.v.hasBack = true;
    s.add(-1, -1, 0);
    if (ccwTriangle) {
      s.add(1, -1, 1);
      s.add(-1, 1, 2);
    } else {
      s.add(-1, 1, 3);
      s.add(1, -1, 2);
    }
    s.draw(GL_TRIANGLES);
    const glm::vec4 expected = ccwTriangle ? s.v.primary[kFront][2] : s.v.primary[kBack][2];
    EXPECT_TRUE(s.is(2, 2, expected)) << ccwTriangle;
  }
}

TEST(DrawPrimitives, ClippedTriangleStaysInsideTheViewport) {
  Scene s;
  s.state.viewportX = 4;
  s.state.viewportY = 4;
  s.state.viewportWidth = 8;
  s.state.viewportHeight = 8;
  s.add(-5, -5, 0);
  s.add(5, -5, 0);
  s.add(0, 5, 0);
  s.draw(GL_TRIANGLES);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const bool inViewport = x >= 4 && x < 12 && y >= 4 && y < 12;
      if (!inViewport) EXPECT_FALSE(s.surface.covered(x, y)) << x << "," << y;
    }
  EXPECT_TRUE(s.surface.covered(8, 6));
}

TEST(DrawPrimitives, BehindTheEyeAndPastTheFarPlane) {
  // A ground plane y = -1 under a perspective camera (90 degrees, near 0.5,
  // far 10), with one corner behind the eye: only the part in front of the
  // near plane is drawn, in the lower half of the image.
  const float n = 0.5f, f = 10;
  auto project = [&](float x, float y, float z) {
    return glm::vec4(x, y, -(f + n) / (f - n) * z - 2 * f * n / (f - n), -z);
  };
  Scene s;
  s.v.clip = {project(-1, -1, -2), project(1, -1, -2), project(0, -1, 1)};
  EXPECT_LT(s.v.clip[2].w, 0.0f);
  for (int i = 0; i < 3; ++i) s.v.primary[kFront].push_back(glm::vec4(1));
  s.draw(GL_TRIANGLES);
  const int behind = s.surface.coveredCount();
  EXPECT_GT(behind, 0);
  for (int y = 8; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_FALSE(s.surface.covered(x, y)) << x << "," << y;

  Scene far;
  far.v.clip = {glm::vec4(-1, -1, 2, 1), glm::vec4(1, -1, 2, 1), glm::vec4(0, 1, 2, 1)};  // all beyond far
  for (int i = 0; i < 3; ++i) far.v.primary[kFront].push_back(glm::vec4(1));
  far.draw(GL_TRIANGLES);
  EXPECT_EQ(far.surface.coveredCount(), 0);
}

// Size-1 points inside the view cover one pixel each (the region points
// may cover defaults to the whole buffer).
TEST(DrawPrimitives, PointsCoverOnePixelEach) {
  Scene s;
  s.add(-0.5f, -0.5f, 0);
  s.add(0.5f, -0.5f, 1);
  s.add(-0.5f, 0.5f, 2);
  s.draw(GL_POINTS);
  EXPECT_EQ(s.surface.coveredCount(), 3);
}

// A 16x16 view: the loop around the lower-left half draws its three edges
// (about 16 pixels each), not the inside.
TEST(DrawPrimitives, LineLoopDrawsItsEdgesOnly) {
  Scene s;
  s.add(-0.95f, -0.95f, 0);
  s.add(0.95f, -0.95f, 1);
  s.add(-0.95f, 0.95f, 2);
  s.draw(GL_LINE_LOOP);
  EXPECT_GE(s.surface.coveredCount(), 40);
  EXPECT_LE(s.surface.coveredCount(), 48);
}

TEST(DrawPrimitives, NineVertexTrianglesQuirk) {
  // llvmpipe draws nothing for a smooth 9-vertex GL_TRIANGLES draw whose last
  // triangle is horizontal in window space (measured).
  Scene s;
  s.add(-1, -1, 0);
  s.add(1, -1, 1);
  s.add(0, 1, 2);
  s.add(-0.5f, -0.5f, 0);
  s.add(0.5f, -0.5f, 1);
  s.add(0, 0.5f, 2);
  s.add(-0.5f, 0.25f, 0);
  s.add(0.5f, 0.25f, 1);
  s.add(0, 0.25f, 2);
  s.draw(GL_TRIANGLES);
  EXPECT_EQ(s.surface.coveredCount(), 0);
  s.state.flat = true;
  s.draw(GL_TRIANGLES);
  EXPECT_GT(s.surface.coveredCount(), 0);
}

TEST(DrawPrimitives, ConstantColourIsExactUnderPerspective) {
  // Mesa reads a colour that is not per vertex as a constant: 0.3 * 255 is a
  // tie, and every fragment gets rint(76.5) = 76, where interpolating it in
  // perspective would give 76 or 77.
  Scene s;
  s.state.constantPrimary = true;
  const glm::vec4 c(0.3f, 0.7f, 0.3f, 1);
  s.v.clip = {glm::vec4(-1.5f, -1.5f, 0, 1.5f), glm::vec4(6, -6, 0, 6), glm::vec4(6, 6, 0, 6),
              glm::vec4(-1.5f, 1.5f, 0, 1.5f)};
  s.v.primary[kFront].assign(4, c);
  s.draw(GL_QUADS);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(s.surface.at(x, y)[0], 76) << x << "," << y;
      ASSERT_EQ(s.surface.at(x, y)[1], 178) << x << "," << y;
    }
}

TEST(DrawPrimitives, FlatWithConstantColourSplitsQuadsLikeSmooth) {
  // GL_FLAT without a colour input: a non-planar quad's depth follows the
  // smooth split (v0,v1,v2) (v0,v2,v3), not (v0,v1,v3) (v1,v2,v3).
  auto depthAt = [](bool flat, bool constant) {
    Scene s;
    s.state.flat = flat;
    s.state.constantPrimary = constant;
    s.state.raster.depthTest = true;
    s.state.raster.depthFunc = GL_ALWAYS;
    s.add(-1, -1, 0, -0.5f);
    s.add(1, -1, 0, 0.5f);
    s.add(1, 1, 0, -0.5f);
    s.add(-1, 1, 0, 0.9f);
    if (constant) s.v.primary[kFront].assign(4, colourOf(0));
    s.draw(GL_QUADS);
    return s.surface.fb.depth.get(4, 12);
  };
  EXPECT_EQ(depthAt(true, true), depthAt(false, false));
  EXPECT_NE(depthAt(true, false), depthAt(false, false));
}

TEST(FaceRule, DrawModuleCullTreatsZeroAreaAsBack) {
  FaceRule r{true, GL_BACK, GL_CCW};
  const float a[4] = {0, 0, 0, 1}, b[4] = {1, 1, 0, 1}, c[4] = {2, 2, 0, 1};
  EXPECT_TRUE(drawModuleCulls(r, a, b, c));
  r.cullFaceMode = GL_FRONT;
  EXPECT_FALSE(drawModuleCulls(r, a, b, c));
  // y is down: (0,0) (0,1) (1,0) is counter-clockwise in GL window space.
  const float d[4] = {0, 1, 0, 1}, e[4] = {1, 0, 0, 1};
  EXPECT_TRUE(drawModuleCulls(r, a, d, e));
  r.cullFaceMode = GL_BACK;
  EXPECT_FALSE(drawModuleCulls(r, a, d, e));
}

}  // namespace
}  // namespace glfixed::primitive
