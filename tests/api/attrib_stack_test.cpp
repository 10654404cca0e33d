// The server attribute stack (GL 2.1 §6.1.14): glPushAttrib/glPopAttrib, the
// stack depth and its errors, and which state each group restores (the
// "attribute" column of tables 6.5-6.37).
#include <functional>
#include <string>
#include <vector>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using AttribStackTest = GLTest;

// The GL 2.1 server groups (table 6.x's attribute column), but GL_EVAL_BIT and
// GL_LIST_BIT, whose state comes with evaluators and display lists.
const GLbitfield kGroups[] = {
    GL_CURRENT_BIT,        GL_POINT_BIT,    GL_LINE_BIT,      GL_POLYGON_BIT,      GL_POLYGON_STIPPLE_BIT,
    GL_PIXEL_MODE_BIT,     GL_LIGHTING_BIT, GL_FOG_BIT,       GL_DEPTH_BUFFER_BIT, GL_ACCUM_BUFFER_BIT,
    GL_STENCIL_BUFFER_BIT, GL_VIEWPORT_BIT, GL_TRANSFORM_BIT, GL_ENABLE_BIT,       GL_COLOR_BUFFER_BIT,
    GL_HINT_BIT,           GL_SCISSOR_BIT,  GL_TEXTURE_BIT,   GL_MULTISAMPLE_BIT,
};

std::vector<double> Doubles(GLenum pname, int n) {
  GLdouble v[16];
  for (double& x : v) x = -12345;
  glGetDoublev(pname, v);
  return std::vector<double>(v, v + n);
}
std::vector<double> Light(GLenum light, GLenum pname, int n) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetLightfv(light, pname, v);
  return std::vector<double>(v, v + n);
}
std::vector<double> Material(GLenum pname, int n) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetMaterialfv(GL_FRONT, pname, v);
  return std::vector<double>(v, v + n);
}
std::vector<double> Enabled(GLenum cap) { return {double(glIsEnabled(cap))}; }

// A piece of state: how to set it to one of two values, how to read it back,
// and the groups that hold it.
struct Piece {
  const char* name;
  GLbitfield groups;
  std::function<void(int)> set;  // 0 or 1
  std::function<std::vector<double>()> read;
};

const std::vector<Piece>& Pieces() {
  static const std::vector<Piece> pieces = {
      {"current colour", GL_CURRENT_BIT,
       [](int v) { glColor4f(0.25f + v * 0.5f, 0.5f, 0.75f, 1.0f - v * 0.5f); },
       [] { return Doubles(GL_CURRENT_COLOR, 4); }},
      {"current normal", GL_CURRENT_BIT, [](int v) { glNormal3f(v, 1 - v, 0.5f); },
       [] { return Doubles(GL_CURRENT_NORMAL, 3); }},
      {"current texture coordinates", GL_CURRENT_BIT, [](int v) { glTexCoord4f(v, 2, 3, 4 + v); },
       [] { return Doubles(GL_CURRENT_TEXTURE_COORDS, 4); }},
      {"current secondary colour", GL_CURRENT_BIT, [](int v) { glSecondaryColor3f(v, 0.5f, 0.25f); },
       [] { return Doubles(GL_CURRENT_SECONDARY_COLOR, 3); }},
      {"current fog coordinate", GL_CURRENT_BIT, [](int v) { glFogCoordf(2.0f + v); },
       [] { return Doubles(GL_CURRENT_FOG_COORD, 1); }},
      {"current index", GL_CURRENT_BIT, [](int v) { glIndexf(3.0f + v); },
       [] { return Doubles(GL_CURRENT_INDEX, 1); }},
      {"edge flag", GL_CURRENT_BIT, [](int v) { glEdgeFlag(v ? GL_FALSE : GL_TRUE); },
       [] { return Doubles(GL_EDGE_FLAG, 1); }},
      {"matrix mode", GL_TRANSFORM_BIT, [](int v) { glMatrixMode(v ? GL_PROJECTION : GL_MODELVIEW); },
       [] { return Doubles(GL_MATRIX_MODE, 1); }},
      {"normalize", GL_TRANSFORM_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_NORMALIZE) : glDisable(GL_NORMALIZE); },
       [] { return Enabled(GL_NORMALIZE); }},
      {"rescale normal", GL_TRANSFORM_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_RESCALE_NORMAL) : glDisable(GL_RESCALE_NORMAL); },
       [] { return Enabled(GL_RESCALE_NORMAL); }},
      {"modelview matrix (in no group)", 0,
       [](int v) {
         glMatrixMode(GL_MODELVIEW);
         glLoadIdentity();
         glTranslatef(v, 2, 3);
       },
       [] { return Doubles(GL_MODELVIEW_MATRIX, 16); }},
      {"viewport", GL_VIEWPORT_BIT, [](int v) { glViewport(v, 2, 30 + v, 40); },
       [] { return Doubles(GL_VIEWPORT, 4); }},
      {"depth range", GL_VIEWPORT_BIT, [](int v) { glDepthRange(0.25 * v, 0.75); },
       [] { return Doubles(GL_DEPTH_RANGE, 2); }},
      {"depth test", GL_DEPTH_BUFFER_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST); },
       [] { return Enabled(GL_DEPTH_TEST); }},
      {"depth func", GL_DEPTH_BUFFER_BIT, [](int v) { glDepthFunc(v ? GL_GEQUAL : GL_LESS); },
       [] { return Doubles(GL_DEPTH_FUNC, 1); }},
      {"depth mask", GL_DEPTH_BUFFER_BIT, [](int v) { glDepthMask(v ? GL_FALSE : GL_TRUE); },
       [] { return Doubles(GL_DEPTH_WRITEMASK, 1); }},
      {"depth clear value", GL_DEPTH_BUFFER_BIT, [](int v) { glClearDepth(0.5 + 0.25 * v); },
       [] { return Doubles(GL_DEPTH_CLEAR_VALUE, 1); }},
      {"colour clear value", GL_COLOR_BUFFER_BIT, [](int v) { glClearColor(0.25f, 0.5f * v, 0.75f, 1); },
       [] { return Doubles(GL_COLOR_CLEAR_VALUE, 4); }},
      {"colour write mask", GL_COLOR_BUFFER_BIT,
       [](int v) { glColorMask(GL_TRUE, v ? GL_FALSE : GL_TRUE, GL_TRUE, GL_FALSE); },
       [] { return Doubles(GL_COLOR_WRITEMASK, 4); }},
      {"dither", GL_COLOR_BUFFER_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glDisable(GL_DITHER) : glEnable(GL_DITHER); }, [] { return Enabled(GL_DITHER); }},
      {"cull face", GL_POLYGON_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE); },
       [] { return Enabled(GL_CULL_FACE); }},
      {"cull face mode", GL_POLYGON_BIT, [](int v) { glCullFace(v ? GL_FRONT_AND_BACK : GL_FRONT); },
       [] { return Doubles(GL_CULL_FACE_MODE, 1); }},
      {"front face", GL_POLYGON_BIT, [](int v) { glFrontFace(v ? GL_CW : GL_CCW); },
       [] { return Doubles(GL_FRONT_FACE, 1); }},
      {"perspective correction hint", GL_HINT_BIT,
       [](int v) { glHint(GL_PERSPECTIVE_CORRECTION_HINT, v ? GL_NICEST : GL_FASTEST); },
       [] { return Doubles(GL_PERSPECTIVE_CORRECTION_HINT, 1); }},
      {"fog hint", GL_HINT_BIT, [](int v) { glHint(GL_FOG_HINT, v ? GL_NICEST : GL_FASTEST); },
       [] { return Doubles(GL_FOG_HINT, 1); }},
      {"shade model", GL_LIGHTING_BIT, [](int v) { glShadeModel(v ? GL_FLAT : GL_SMOOTH); },
       [] { return Doubles(GL_SHADE_MODEL, 1); }},
      {"lighting", GL_LIGHTING_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_LIGHTING) : glDisable(GL_LIGHTING); },
       [] { return Enabled(GL_LIGHTING); }},
      {"light 3 enable", GL_LIGHTING_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_LIGHT3) : glDisable(GL_LIGHT3); }, [] { return Enabled(GL_LIGHT3); }},
      {"light diffuse", GL_LIGHTING_BIT,
       [](int v) {
         const GLfloat c[4] = {0.5f * v, 0.25f, 0.75f, 1};
         glLightfv(GL_LIGHT1, GL_DIFFUSE, c);
       },
       [] { return Light(GL_LIGHT1, GL_DIFFUSE, 4); }},
      {"light position", GL_LIGHTING_BIT,
       [](int v) {
         const GLfloat p[4] = {1, 2.0f + v, 3, 1};
         glLightfv(GL_LIGHT2, GL_POSITION, p);
       },
       [] { return Light(GL_LIGHT2, GL_POSITION, 4); }},
      {"light spot cutoff", GL_LIGHTING_BIT,
       [](int v) { glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30.0f + v * 10); },
       [] { return Light(GL_LIGHT0, GL_SPOT_CUTOFF, 1); }},
      {"light model ambient", GL_LIGHTING_BIT,
       [](int v) {
         const GLfloat c[4] = {0.5f, 0.25f * v, 0.75f, 1};
         glLightModelfv(GL_LIGHT_MODEL_AMBIENT, c);
       },
       [] { return Doubles(GL_LIGHT_MODEL_AMBIENT, 4); }},
      {"light model two side", GL_LIGHTING_BIT, [](int v) { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, v); },
       [] { return Doubles(GL_LIGHT_MODEL_TWO_SIDE, 1); }},
      {"light model local viewer", GL_LIGHTING_BIT,
       [](int v) { glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, v); },
       [] { return Doubles(GL_LIGHT_MODEL_LOCAL_VIEWER, 1); }},
      {"light model colour control", GL_LIGHTING_BIT,
       [](int v) {
         glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, v ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
       },
       [] { return Doubles(GL_LIGHT_MODEL_COLOR_CONTROL, 1); }},
      {"material diffuse", GL_LIGHTING_BIT,
       [](int v) {
         const GLfloat c[4] = {0.5f, 0.25f, 0.75f * v, 1};
         glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, c);
       },
       [] { return Material(GL_DIFFUSE, 4); }},
      {"material shininess", GL_LIGHTING_BIT,
       [](int v) { glMaterialf(GL_FRONT, GL_SHININESS, 10.0f + v * 20); },
       [] { return Material(GL_SHININESS, 1); }},
      {"colour material enable", GL_LIGHTING_BIT | GL_ENABLE_BIT,
       [](int v) { v ? glEnable(GL_COLOR_MATERIAL) : glDisable(GL_COLOR_MATERIAL); },
       [] { return Enabled(GL_COLOR_MATERIAL); }},
      {"colour material face and mode", GL_LIGHTING_BIT,
       [](int v) { glColorMaterial(v ? GL_BACK : GL_FRONT, v ? GL_SPECULAR : GL_EMISSION); },
       [] {
         std::vector<double> r = Doubles(GL_COLOR_MATERIAL_FACE, 1);
         r.push_back(Doubles(GL_COLOR_MATERIAL_PARAMETER, 1)[0]);
         return r;
       }},
      {"provoking vertex (in no group)", 0,
       [](int v) { glProvokingVertex(v ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION); },
       [] { return Doubles(GL_PROVOKING_VERTEX, 1); }},
  };
  return pieces;
}

std::string Show(const std::vector<double>& v) {
  std::string s;
  for (double d : v) s += std::to_string(d) + " ";
  return s;
}

TEST_F(AttribStackTest, DepthStartsAtZeroAndHoldsSixteen) {
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(GetInt(GL_MAX_ATTRIB_STACK_DEPTH), 16);
  for (int i = 1; i <= 16; ++i) {
    glPushAttrib(GL_DEPTH_BUFFER_BIT);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), i);
  }
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 16);
  for (int i = 15; i >= 0; --i) {
    glPopAttrib();
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), i);
  }
  glPopAttrib();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);
}

TEST_F(AttribStackTest, OverflowPushesNothing) {
  glDepthFunc(GL_LESS);
  for (int i = 0; i < 16; ++i) glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_GREATER);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);  // refused: GREATER is not saved
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  glDepthFunc(GL_EQUAL);
  glPopAttrib();  // the 16th push's LESS
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 15);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AttribStackTest, PushAndPopBetweenBeginAndEndAreInvalidOperation) {
  glBegin(GL_TRIANGLES);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);

  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_ALWAYS);
  glBegin(GL_TRIANGLES);
  glPopAttrib();
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 1);
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_ALWAYS);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_NO_GL_ERROR();
}

// Each piece of state comes back after a pop of exactly the groups that hold
// it, and only of those; a context per piece, so that pieces do not meet.
TEST_F(AttribStackTest, EachGroupRestoresExactlyItsState) {
  for (const Piece& p : Pieces()) {
    for (GLbitfield g : kGroups) {
      SCOPED_TRACE(::testing::Message() << p.name << ", group 0x" << std::hex << g);
      // Tested on its own: Mesa's GL_ENABLE_BIT forgets the lights.
      if (g == GL_ENABLE_BIT && std::string(p.name) == "light 3 enable") continue;
      ScopedContext c(OSMESA_RGBA, 24, kWidth, kHeight, 4);
      ASSERT_TRUE(c.makeCurrent());
      p.set(0);
      const std::vector<double> pushed = p.read();
      glPushAttrib(g);
      p.set(1);
      const std::vector<double> changed = p.read();
      ASSERT_NE(pushed, changed) << "the piece's two values are the same";
      glPopAttrib();
      const std::vector<double> popped = p.read();
      if (p.groups & g)
        EXPECT_EQ(popped, pushed) << "not restored: " << Show(popped);
      else
        EXPECT_EQ(popped, changed) << "restored by a group that does not hold it: " << Show(popped);
      EXPECT_NO_GL_ERROR();
    }
  }
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
}

TEST_F(AttribStackTest, AllAttribBitsRestoresEveryPiece) {
  for (const Piece& p : Pieces()) p.set(0);
  std::vector<std::vector<double>> pushed;
  for (const Piece& p : Pieces()) pushed.push_back(p.read());
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  for (const Piece& p : Pieces()) p.set(1);
  glPopAttrib();
  EXPECT_NO_GL_ERROR();
  for (size_t i = 0; i < Pieces().size(); ++i) {
    const Piece& p = Pieces()[i];
    SCOPED_TRACE(p.name);
    if (p.groups)
      EXPECT_EQ(p.read(), pushed[i]);
    else
      EXPECT_NE(p.read(), pushed[i]);
  }
}

// Light positions are kept in eye space (§2.14.2): a pop gives back the eye
// position of the push, whatever the modelview matrix is now.
TEST_F(AttribStackTest, LightPositionRestoresInEyeSpace) {
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1, 2, 3);
  const GLfloat origin[4] = {0, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, origin);
  glPushAttrib(GL_LIGHTING_BIT);
  glLoadIdentity();
  const GLfloat other[4] = {5, 5, 5, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, other);
  glPopAttrib();
  EXPECT_EQ(Light(GL_LIGHT0, GL_POSITION, 4), (std::vector<double>{1, 2, 3, 1}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(AttribStackTest, NestedPushesRestoreInTurn) {
  glDepthFunc(GL_GREATER);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_EQUAL);
  glPushAttrib(GL_DEPTH_BUFFER_BIT | GL_ENABLE_BIT);
  glDepthFunc(GL_ALWAYS);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_EQUAL);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_GREATER);
  EXPECT_NO_GL_ERROR();
}

// GL_ENABLE_BIT holds every light's enable (table 6.12).
TEST_F(AttribStackTest, EnableBitRestoresTheLights) {
  GLFX_SKIP_ON_MESA("Mesa 22.3.6's glPopAttrib of GL_ENABLE_BIT restores GL_LIGHTING but no GL_LIGHTi");
  for (int i = 0; i < 8; ++i) {
    SCOPED_TRACE(i);
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_LIGHT0 + i);
    glPopAttrib();
    EXPECT_EQ(glIsEnabled(GL_LIGHT0 + i), GL_FALSE);
    glEnable(GL_LIGHT0 + i);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHT0 + i);
    glPopAttrib();
    EXPECT_EQ(glIsEnabled(GL_LIGHT0 + i), GL_TRUE);
  }
  EXPECT_NO_GL_ERROR();
}

// A change made under an inner push of other groups is still restored by the
// outer pop.
TEST_F(AttribStackTest, ChangesUnderAnInnerPushAreRestoredByTheOuterPop) {
  GLFX_SKIP_ON_MESA(
      "Mesa 22.3.6's glPopAttrib forgets what changed under it for the outer pop: "
      "the outer glPopAttrib does not restore GL_DEPTH_FUNC");
  glDepthFunc(GL_GREATER);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glPushAttrib(GL_ENABLE_BIT);
  glDepthFunc(GL_LESS);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_LESS);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_GREATER);
  EXPECT_NO_GL_ERROR();
}

// A change made before an inner push that changed nothing is restored by the
// outer pop.
TEST_F(AttribStackTest, ChangesBeforeAnInnerPushAreRestoredByTheOuterPop) {
  glDepthFunc(GL_GREATER);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_NEVER);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_NEVER);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_GREATER);
  EXPECT_NO_GL_ERROR();
}

// State whose stage comes later still has its initial value, is queried, and
// is pushed and popped.
TEST_F(AttribStackTest, HeldEnablesHaveTheirInitialValues) {
  for (GLenum cap : {GL_ALPHA_TEST,
                     GL_BLEND,
                     GL_COLOR_LOGIC_OP,
                     GL_INDEX_LOGIC_OP,
                     GL_CLIP_PLANE0,
                     GL_CLIP_PLANE5,
                     GL_FOG,
                     GL_COLOR_SUM,
                     GL_LINE_SMOOTH,
                     GL_LINE_STIPPLE,
                     GL_POINT_SMOOTH,
                     GL_POINT_SPRITE,
                     GL_POLYGON_SMOOTH,
                     GL_POLYGON_STIPPLE,
                     GL_POLYGON_OFFSET_POINT,
                     GL_POLYGON_OFFSET_LINE,
                     GL_POLYGON_OFFSET_FILL,
                     GL_SCISSOR_TEST,
                     GL_STENCIL_TEST,
                     GL_SAMPLE_ALPHA_TO_COVERAGE,
                     GL_SAMPLE_ALPHA_TO_ONE,
                     GL_SAMPLE_COVERAGE,
                     GL_TEXTURE_1D,
                     GL_TEXTURE_2D,
                     GL_TEXTURE_3D,
                     GL_TEXTURE_CUBE_MAP,
                     GL_TEXTURE_GEN_S,
                     GL_TEXTURE_GEN_T,
                     GL_TEXTURE_GEN_R,
                     GL_TEXTURE_GEN_Q}) {
    SCOPED_TRACE(::testing::Message() << "cap 0x" << std::hex << cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
    EXPECT_EQ(GetBool(cap), GL_FALSE);
    EXPECT_NO_GL_ERROR();
  }
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_FOG), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

// The capability table: enabling one capability changes its own flag only.
TEST_F(AttribStackTest, EachCapabilityHasItsOwnFlag) {
  const GLenum caps[] = {GL_DEPTH_TEST, GL_CULL_FACE, GL_DITHER,         GL_LIGHTING,  GL_LIGHT0,
                         GL_LIGHT1,     GL_LIGHT2,    GL_LIGHT3,         GL_LIGHT4,    GL_LIGHT5,
                         GL_LIGHT6,     GL_LIGHT7,    GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL};
  const size_t n = sizeof(caps) / sizeof(caps[0]);
  for (size_t i = 0; i < n; ++i) {
    const GLenum cap = caps[i];
    SCOPED_TRACE(::testing::Message() << "cap 0x" << std::hex << cap);
    std::vector<GLboolean> before;
    for (GLenum c : caps) before.push_back(glIsEnabled(c));
    before[i] = !before[i];
    if (before[i])
      glEnable(cap);
    else
      glDisable(cap);
    EXPECT_NO_GL_ERROR();
    std::vector<GLboolean> after;
    for (GLenum c : caps) after.push_back(glIsEnabled(c));
    EXPECT_EQ(after, before);
    EXPECT_EQ(GetBool(cap), after[i]);
    // GL_ENABLE_BIT gives it back (the lights: EnableBitRestoresTheLights).
    if (cap >= GL_LIGHT0 && cap <= GL_LIGHT7) continue;
    glPushAttrib(GL_ENABLE_BIT);
    if (after[i])
      glDisable(cap);
    else
      glEnable(cap);
    glPopAttrib();
    EXPECT_EQ(glIsEnabled(cap), after[i]);
  }
}

}  // namespace
}  // namespace glfx_test

namespace glfx_test {
namespace {

// The held groups' state reads back its initial value (GL 2.1 tables 6.x),
// before and after a push and pop of every group.
TEST_F(AttribStackTest, HeldStateHasItsInitialValues) {
  struct Value {
    GLenum pname;
    std::vector<double> value;
  };
  const Value values[] = {
      {GL_FOG_MODE, {GL_EXP}},
      {GL_FOG_DENSITY, {1}},
      {GL_FOG_START, {0}},
      {GL_FOG_END, {1}},
      {GL_FOG_INDEX, {0}},
      {GL_FOG_COLOR, {0, 0, 0, 0}},
      {GL_FOG_COORD_SRC, {GL_FRAGMENT_DEPTH}},
      {GL_LINE_WIDTH, {1}},
      {GL_LINE_STIPPLE_PATTERN, {0xffff}},
      {GL_LINE_STIPPLE_REPEAT, {1}},
      {GL_POINT_SIZE, {1}},
      {GL_POINT_SIZE_MIN, {0}},
      {GL_POINT_FADE_THRESHOLD_SIZE, {1}},
      {GL_POINT_DISTANCE_ATTENUATION, {1, 0, 0}},
      {GL_POINT_SPRITE_COORD_ORIGIN, {GL_UPPER_LEFT}},
      {GL_SCISSOR_BOX, {0, 0, kWidth, kHeight}},
      {GL_STENCIL_FUNC, {GL_ALWAYS}},
      {GL_STENCIL_REF, {0}},
      {GL_STENCIL_FAIL, {GL_KEEP}},
      {GL_STENCIL_PASS_DEPTH_FAIL, {GL_KEEP}},
      {GL_STENCIL_PASS_DEPTH_PASS, {GL_KEEP}},
      {GL_STENCIL_BACK_FUNC, {GL_ALWAYS}},
      {GL_STENCIL_BACK_REF, {0}},
      {GL_STENCIL_BACK_FAIL, {GL_KEEP}},
      {GL_STENCIL_BACK_PASS_DEPTH_FAIL, {GL_KEEP}},
      {GL_STENCIL_BACK_PASS_DEPTH_PASS, {GL_KEEP}},
      {GL_STENCIL_CLEAR_VALUE, {0}},
      {GL_ACCUM_CLEAR_VALUE, {0, 0, 0, 0}},
      {GL_ALPHA_TEST_FUNC, {GL_ALWAYS}},
      {GL_ALPHA_TEST_REF, {0}},
      {GL_BLEND_SRC_RGB, {GL_ONE}},
      {GL_BLEND_DST_RGB, {GL_ZERO}},
      {GL_BLEND_SRC_ALPHA, {GL_ONE}},
      {GL_BLEND_DST_ALPHA, {GL_ZERO}},
      {GL_BLEND_EQUATION_RGB, {GL_FUNC_ADD}},
      {GL_BLEND_EQUATION_ALPHA, {GL_FUNC_ADD}},
      {GL_BLEND_COLOR, {0, 0, 0, 0}},
      {GL_LOGIC_OP_MODE, {GL_COPY}},
      {GL_DRAW_BUFFER, {GL_FRONT}},
      {GL_READ_BUFFER, {GL_FRONT}},
      {GL_INDEX_CLEAR_VALUE, {0}},
      {GL_POLYGON_MODE, {GL_FILL, GL_FILL}},
      {GL_POLYGON_OFFSET_FACTOR, {0}},
      {GL_POLYGON_OFFSET_UNITS, {0}},
      {GL_MAP_COLOR, {0}},
      {GL_MAP_STENCIL, {0}},
      {GL_INDEX_SHIFT, {0}},
      {GL_INDEX_OFFSET, {0}},
      {GL_RED_SCALE, {1}},
      {GL_GREEN_SCALE, {1}},
      {GL_BLUE_SCALE, {1}},
      {GL_ALPHA_SCALE, {1}},
      {GL_RED_BIAS, {0}},
      {GL_GREEN_BIAS, {0}},
      {GL_BLUE_BIAS, {0}},
      {GL_ALPHA_BIAS, {0}},
      {GL_DEPTH_SCALE, {1}},
      {GL_DEPTH_BIAS, {0}},
      {GL_ZOOM_X, {1}},
      {GL_ZOOM_Y, {1}},
      {GL_ACTIVE_TEXTURE, {GL_TEXTURE0}},
      {GL_SAMPLE_COVERAGE_VALUE, {1}},
      {GL_SAMPLE_COVERAGE_INVERT, {0}},
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (const Value& v : values) {
      SCOPED_TRACE(::testing::Message() << "pname 0x" << std::hex << v.pname << (pass ? " after a pop" : ""));
      EXPECT_EQ(Doubles(v.pname, int(v.value.size())), v.value);
      EXPECT_NO_GL_ERROR();
    }
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPopAttrib();
  }
}

}  // namespace
}  // namespace glfx_test
