// Assembly and clipping for GL_SELECT and GL_FEEDBACK (primitive/unrasterized.h):
// which primitives reach the sink, with which vertices. The exact values are
// compared with Mesa's by reference/feedback/.
#include "primitive/unrasterized.h"

#include <gtest/gtest.h>

#include <vector>

#include "primitive/viewport.h"
#include "state/lighting_attrib.h"

namespace glfixed::primitive {
namespace {

struct Recorded {
  char kind;                    // 'p', 'l', 't'
  std::vector<glm::vec4> clip;  // the vertices' clip coordinates
  std::vector<float> red;       // their colours' red
  int color = kSinkFrontColor;
};

class RecordingSink : public PrimitiveSink {
 public:
  std::vector<Recorded> out;
  void point(const ClipVertex& v) override { out.push_back({'p', {v.clip}, {v.attr[0]}}); }
  void line(const ClipVertex& a, const ClipVertex& b) override {
    out.push_back({'l', {a.clip, b.clip}, {a.attr[0], b.attr[0]}});
  }
  void triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int color) override {
    out.push_back({'t', {a.clip, b.clip, c.clip}, {a.attr[color], b.attr[color], c.attr[color]}, color});
  }
};

ShadedVertices shaded(const std::vector<glm::vec4>& clip) {
  ShadedVertices s;
  s.clip = clip;
  for (size_t i = 0; i < clip.size(); ++i) s.primary[kFront].push_back(glm::vec4(float(i) / 8, 0, 0, 1));
  return s;
}

PrimitiveState stateFor(GLenum mode) {
  PrimitiveState s;
  s.mode = mode;
  s.viewportWidth = 100;
  s.viewportHeight = 100;
  return s;
}

std::vector<Recorded> run(GLenum mode, const std::vector<glm::vec4>& clip, PrimitiveState s) {
  s.mode = mode;
  RecordingSink sink;
  drawUnrasterized(s, shaded(clip), 100, sink);
  return sink.out;
}
std::vector<Recorded> run(GLenum mode, const std::vector<glm::vec4>& clip) {
  return run(mode, clip, stateFor(mode));
}

TEST(Unrasterized, PointsOutsideAnyPlaneAreDropped) {
  auto r = run(GL_POINTS, {{0, 0, 0, 1}, {2, 0, 0, 1}, {0, 0, -1.5f, 1}, {1, 1, 1, 1}});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].clip[0], glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(r[1].clip[0], glm::vec4(1, 1, 1, 1));  // on the planes is inside
}

TEST(Unrasterized, LineStripsAndLoops) {
  const std::vector<glm::vec4> v = {{0, 0, 0, 1}, {0.5f, 0, 0, 1}, {0.5f, 0.5f, 0, 1}};
  EXPECT_EQ(run(GL_LINES, v).size(), 1u);  // the odd vertex is dropped
  EXPECT_EQ(run(GL_LINE_STRIP, v).size(), 2u);
  auto loop = run(GL_LINE_LOOP, v);
  ASSERT_EQ(loop.size(), 3u);
  EXPECT_EQ(loop[2].clip[0], v[2]);  // the closing segment, last
  EXPECT_EQ(loop[2].clip[1], v[0]);
  EXPECT_EQ(run(GL_LINE_LOOP, {v[0], v[1]}).size(), 2u);  // (0,1) and (1,0), as Mesa
}

TEST(Unrasterized, LineClippedAtEachEndFromTheEndOutside) {
  // From x = -3 to x = 1 (w = 1): the left plane cuts at t = 0.5 from v0.
  auto r = run(GL_LINES, {{-3, 0, 0, 1}, {1, 0.5f, 0, 1}});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FLOAT_EQ(r[0].clip[0].x, -1.0f);
  EXPECT_FLOAT_EQ(r[0].clip[0].y, 0.25f);
  EXPECT_EQ(r[0].clip[1], glm::vec4(1, 0.5f, 0, 1));  // inside: untouched
  EXPECT_FLOAT_EQ(r[0].red[0], 0.0625f);              // the colour interpolated too
  // Both ends outside different planes: both cut.
  r = run(GL_LINES, {{-3, 0, 0, 1}, {3, 0, 0, 1}});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FLOAT_EQ(r[0].clip[0].x, -1.0f);
  EXPECT_FLOAT_EQ(r[0].clip[1].x, 1.0f);
  // Outside one plane at both ends, or cut away entirely by two planes.
  EXPECT_TRUE(run(GL_LINES, {{-3, 0, 0, 1}, {-2, 1, 0, 1}}).empty());
  EXPECT_TRUE(run(GL_LINES, {{-3, 0, 0, 1}, {0, 3.5f, 0, 1}}).empty());
}

TEST(Unrasterized, FlatClippedLineEndTakesTheProvokingColour) {
  PrimitiveState s = stateFor(GL_LINES);
  s.flat = true;
  auto r = run(GL_LINES, {{-3, 0, 0, 1}, {1, 0, 0, 1}}, s);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].red[0], 0.125f);  // vertex 1's
  s.firstVertexConvention = true;
  r = run(GL_LINES, {{1, 0, 0, 1}, {-3, 0, 0, 1}}, s);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].red[1], 0.0f);  // vertex 0's
}

TEST(Unrasterized, QuadsAlwaysTakeThePipelineSplit) {
  const std::vector<glm::vec4> q = {
      {-0.5f, -0.5f, 0, 1}, {0.5f, -0.5f, 0, 1}, {0.5f, 0.5f, 0, 1}, {-0.5f, 0.5f, 0, 1}};
  auto r = run(GL_QUADS, q);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].clip[0], q[0]);
  EXPECT_EQ(r[0].clip[1], q[1]);
  EXPECT_EQ(r[0].clip[2], q[3]);
  EXPECT_EQ(r[1].clip[0], q[1]);
  EXPECT_EQ(r[1].clip[1], q[2]);
  EXPECT_EQ(r[1].clip[2], q[3]);
}

TEST(Unrasterized, ClippedTriangleIsAFanOfTriangles) {
  // One vertex beyond the right plane: a quadrilateral, two triangles.
  auto r = run(GL_TRIANGLES, {{0, -0.5f, 0, 1}, {2, 0, 0, 1}, {0, 0.5f, 0, 1}});
  ASSERT_EQ(r.size(), 2u);
  for (const Recorded& t : r)
    for (const glm::vec4& c : t.clip) EXPECT_LE(c.x, 1.0f);
  EXPECT_TRUE(run(GL_TRIANGLES, {{2, 0, 0, 1}, {3, 0, 0, 1}, {2, 1, 0, 1}}).empty());
}

TEST(Unrasterized, CullingAndTwoSidedColours) {
  const std::vector<glm::vec4> ccw = {{-0.5f, -0.5f, 0, 1}, {0.5f, -0.5f, 0, 1}, {0, 0.5f, 0, 1}};
  const std::vector<glm::vec4> cw = {ccw[0], ccw[2], ccw[1]};
  PrimitiveState s = stateFor(GL_TRIANGLES);
  s.cullFace = true;
  EXPECT_EQ(run(GL_TRIANGLES, ccw, s).size(), 1u);
  EXPECT_TRUE(run(GL_TRIANGLES, cw, s).empty());
  s.cullFaceMode = GL_FRONT;
  EXPECT_TRUE(run(GL_TRIANGLES, ccw, s).empty());
  s.cullFaceMode = GL_FRONT_AND_BACK;
  EXPECT_TRUE(run(GL_TRIANGLES, cw, s).empty());

  ShadedVertices two = shaded(cw);
  two.hasBack = true;
  for (int i = 0; i < 3; ++i) two.primary[kBack].push_back(glm::vec4(0.75f, 0, 0, 1));
  RecordingSink sink;
  drawUnrasterized(stateFor(GL_TRIANGLES), two, 100, sink);
  ASSERT_EQ(sink.out.size(), 1u);
  EXPECT_EQ(sink.out[0].color, kSinkBackColor);
  EXPECT_EQ(sink.out[0].red[0], 0.75f);
}

}  // namespace
}  // namespace glfixed::primitive
