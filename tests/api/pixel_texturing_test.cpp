// The fragment operations Mesa's fixed-function fragment program applies to
// pixel rectangles (GL 2.1 §3.6.4, §3.7, §3.8, §3.9, §3.10): glDrawPixels,
// glCopyPixels and glBitmap are textured at the CURRENT texture coordinates,
// never fogged; the unlit colour sum; the raster distance of the fog
// coordinate; a display list's fog coordinates. Every expected value was
// measured on Mesa (llvmpipe); run on libglfixed and on Mesa.
#include <array>
#include <vector>

#include "gl_test_fixture.h"
#include "pixel_readback.h"

namespace glfx_test {
namespace {

using PixelTexturingTest = GLTest;

// A 2 x 2 NEAREST texture: (0, 0) red, (1, 0) green, (0, 1) blue, (1, 1) yellow.
GLuint Texture2x2() {
  static const GLubyte t[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
  GLuint id;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  return id;
}

// A 4 x 4 texture whose texel (i, j) is (80 i, 80 j, 0, 255).
GLuint Texture4x4(GLenum filter) {
  GLubyte t[4 * 4 * 4];
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      GLubyte* q = t + (j * 4 + i) * 4;
      q[0] = static_cast<GLubyte>(i * 80);
      q[1] = static_cast<GLubyte>(j * 80);
      q[2] = 0;
      q[3] = 255;
    }
  GLuint id;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  return id;
}

const GLubyte kOnes[8] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};

std::vector<GLubyte> Grey(GLubyte v) { return std::vector<GLubyte>(4 * 4 * 4, v); }

TEST_F(PixelTexturingTest, DrawPixelsIsTexturedAtTheCurrentCoordinates) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  Texture2x2();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const std::vector<GLubyte> img = Grey(200);
  glTexCoord2f(0.75f, 0.25f);  // the raster position's: green
  glRasterPos2f(-0.5f, -0.5f);
  glTexCoord2f(0.25f, 0.75f);  // the current: blue
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // A texture matrix changes neither (the current coordinates, untransformed).
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0, 0);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos2f(-0.5f, 0.5f);
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 17, 17), (std::array<int, 4>{0, 0, 200, 200}));
  EXPECT_EQ(At(p, 19, 19), (std::array<int, 4>{0, 0, 200, 200}));
  EXPECT_EQ(At(p, 17, 50), (std::array<int, 4>{0, 0, 200, 200}));
}

// glDrawPixels reads every coordinate as a varying (Mesa overrides the vertex
// program): unit 1's is one the quad does not carry, (0, 0, 0, 0), whose
// projection is NaN: NEAREST REPEAT reads texel 0, LINEAR REPEAT the mean of
// the first and last texels, CLAMP_TO_BORDER the border.
TEST_F(PixelTexturingTest, DrawPixelsSecondUnitReadsZeroCoordinates) {
  struct Case {
    GLenum filter;
    bool border;
    std::array<int, 4> want;
  };
  for (const Case& c : {Case{GL_LINEAR, false, {120, 120, 0, 255}}, Case{GL_NEAREST, true, {0, 0, 255, 255}},
                        Case{GL_NEAREST, false, {0, 0, 0, 255}}}) {
    ClearBlack();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glActiveTexture(GL_TEXTURE1);
    const GLuint id = Texture4x4(c.filter);
    if (c.border) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
      const float blue[4] = {0, 0, 1, 1};
      glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, blue);
    }
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glMultiTexCoord2f(GL_TEXTURE1, 0.6f, 0.3f);
    const std::vector<GLubyte> img = Grey(200);
    glRasterPos2f(-0.5f, -0.5f);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
    EXPECT_NO_GL_ERROR();
    const std::vector<unsigned char> p = ReadAll();
    EXPECT_EQ(At(p, 17, 17), c.want) << "filter " << c.filter << " border " << c.border;
    EXPECT_EQ(At(p, 19, 19), c.want);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &id);
    glActiveTexture(GL_TEXTURE0);
  }
}

// glBitmap leaves the vertex program alone: a unit whose coordinates would not
// vary reads the current ones as constants, also on unit 1; one with a
// texture matrix reads a varying the bitmap does not carry (0, 0, 0, 0).
TEST_F(PixelTexturingTest, BitmapIsTexturedAtTheCurrentCoordinates) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glActiveTexture(GL_TEXTURE0);
  Texture2x2();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  Texture4x4(GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glActiveTexture(GL_TEXTURE0);
  glColor4f(1, 1, 1, 1);
  glMultiTexCoord2f(GL_TEXTURE0, 0.25f, 0.75f);  // blue
  glMultiTexCoord2f(GL_TEXTURE1, 0.6f, 0.3f);    // texel (2, 1): (160, 80, 0)
  glRasterPos2f(0.5f, 0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  glFlush();  // drawn now, with this state (the bitmap cache)
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0, 0);
  glMatrixMode(GL_MODELVIEW);
  glActiveTexture(GL_TEXTURE0);
  glRasterPos2f(-0.5f, 0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  glFlush();  // drawn now, with this state (the bitmap cache)
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 50, 50), (std::array<int, 4>{160, 80, 255, 255}));
  EXPECT_EQ(At(p, 17, 50), (std::array<int, 4>{0, 0, 255, 255}));  // unit 1 at texel (0, 0): + 0
}

// Unit 0 with a texture matrix reads a varying: the bitmap's own texture
// coordinates, 0 to 1 over the 512 x 32 bitmap cache (the bitmap centred
// vertically in it): at window (x, y) s = (x + 0.5 - x0) / 512, t = (y + 0.5 -
// y0) / 32, y0 = 5 - 12 for an 8 x 8 bitmap at (3, 5).
TEST_F(PixelTexturingTest, BitmapUnitZeroVaryingReadsTheCacheCoordinates) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<GLubyte> t(32 * 32 * 4);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      GLubyte* q = t.data() + (j * 32 + i) * 4;
      q[0] = static_cast<GLubyte>(i * 8);
      q[1] = static_cast<GLubyte>(j * 8);
      q[2] = 0;
      q[3] = 255;
    }
  GLuint id;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0, 0);
  glMatrixMode(GL_MODELVIEW);
  glWindowPos2i(3, 5);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 3, 5), (std::array<int, 4>{0, 96, 0, 255}));
  EXPECT_EQ(At(p, 10, 8), (std::array<int, 4>{0, 120, 0, 255}));
  EXPECT_EQ(At(p, 10, 12), (std::array<int, 4>{0, 152, 0, 255}));
}

// No fog on pixel rectangles: Mesa's drawpixels and bitmap variants of the
// fixed-function program have none, whatever the fog coordinate source.
TEST_F(PixelTexturingTest, PixelRectanglesAreNotFogged) {
  for (GLenum source : {GL_FRAGMENT_DEPTH, GL_FOG_COORD}) {
    ClearBlack();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 5);
    const float blue[4] = {0, 0, 1, 1};
    glFogfv(GL_FOG_COLOR, blue);
    glFogi(GL_FOG_COORD_SRC, static_cast<GLint>(source));
    glFogCoordf(3.0f);
    glColor4f(1, 1, 1, 1);
    const std::vector<GLubyte> img = Grey(200);
    glRasterPos3f(-0.5f, -0.5f, 0.5f);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
    glRasterPos3f(0.5f, 0.5f, 0.5f);
    glBitmap(8, 8, 0, 0, 0, 0, kOnes);
    glBegin(GL_TRIANGLES);  // a triangle is fogged
    glVertex2f(-1, 0.8f);
    glVertex2f(1, 0.8f);
    glVertex2f(0, 1);
    glEnd();
    EXPECT_NO_GL_ERROR();
    const std::vector<unsigned char> p = ReadAll();
    EXPECT_EQ(At(p, 17, 17), (std::array<int, 4>{200, 200, 200, 200}));
    EXPECT_EQ(At(p, 50, 50), (std::array<int, 4>{255, 255, 255, 255}));
    if (source == GL_FOG_COORD) EXPECT_EQ(At(p, 32, 60), (std::array<int, 4>{0, 0, 255, 255}));
    glDisable(GL_FOG);
  }
}

// GL_COLOR_SUM on a bitmap without lighting adds the current secondary colour
// (not the raster position's), clamped; under lighting the program reads a
// varying the bitmap lacks, so nothing is added. glDrawPixels never adds.
TEST_F(PixelTexturingTest, BitmapColourSumAddsTheCurrentSecondaryColour) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_COLOR_SUM);
  glSecondaryColor3f(0.2f, 0.1f, 0.05f);
  glColor4f(0.5f, 0.5f, 0.5f, 1);
  glRasterPos2f(-0.5f, -0.5f);
  glSecondaryColor3f(0.1f, 0.3f, 0.0f);
  const std::vector<GLubyte> img = Grey(200);
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glRasterPos2f(0.5f, 0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  glFlush();  // drawn now, with this state (the bitmap cache)
  glSecondaryColor3f(2.0f, -1.0f, 0.2f);  // clamped: (1, 0, 0.2)
  glRasterPos2f(-0.5f, 0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  glFlush();  // drawn now, with this state (the bitmap cache)
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glRasterPos2f(0.5f, -0.5f);
  float raster[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, raster);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  glFlush();  // drawn now, with this state (the bitmap cache)
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 17, 17), (std::array<int, 4>{200, 200, 200, 200}));
  EXPECT_EQ(At(p, 50, 50), (std::array<int, 4>{153, 204, 128, 255}));
  EXPECT_EQ(At(p, 17, 50), (std::array<int, 4>{255, 128, 178, 255}));
  const int lit = static_cast<int>(std::lrint(raster[0] * 255.0f));
  EXPECT_EQ(At(p, 50, 17), (std::array<int, 4>{lit, lit, lit, 255}));
}

// After a draw with per-vertex secondary colours (colour sum off during it),
// Mesa's program reads the bitmap's secondary colour as a varying: 0.
TEST_F(PixelTexturingTest, BitmapColourSumAfterPerVertexSecondaryColours) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBegin(GL_TRIANGLES);
  glSecondaryColor3f(0.1f, 0.2f, 0.3f);
  glVertex2f(-1, -1);
  glVertex2f(-0.9f, -1);
  glVertex2f(-1, -0.9f);
  glEnd();
  glEnable(GL_COLOR_SUM);
  glColor3f(0.5f, 0.5f, 0.5f);
  glSecondaryColor3f(0.2f, 0.0f, 0.0f);
  glRasterPos2f(0.5f, 0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, kOnes);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 50, 50), (std::array<int, 4>{128, 128, 128, 255}));
}

// glCopyPixels drawn as a quad (blending on) is textured; the blit Mesa uses
// without fragment operations is not.
TEST_F(PixelTexturingTest, CopyPixelsQuadIsTexturedTheBlitIsNot) {
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<GLubyte> img = Grey(200);
  glRasterPos2f(-0.5f, -0.5f);
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  Texture2x2();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexCoord2f(0.75f, 0.25f);  // green
  glRasterPos2f(0.5f, 0.5f);
  glCopyPixels(16, 16, 4, 4, GL_COLOR);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glRasterPos2f(0.5f, -0.5f);
  glCopyPixels(16, 16, 4, 4, GL_COLOR);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 49, 49), (std::array<int, 4>{200, 200, 200, 200}));
  EXPECT_EQ(At(p, 49, 17), (std::array<int, 4>{0, 200, 0, 200}));
}

// GL_CURRENT_RASTER_DISTANCE: with GL_FOG_COORD as the fog source, the current
// fog coordinate as it is (negative too), for glRasterPos and glWindowPos;
// else the eye distance, and 0 for glWindowPos. Fog need not be enabled.
TEST_F(PixelTexturingTest, RasterDistanceOfTheFogCoordinate) {
  float d = 0;
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glFogCoordf(-3.5f);
  glRasterPos3f(0.1f, 0.2f, -0.3f);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, -3.5f);
  glFogCoordf(7.0f);
  glWindowPos2f(3, 4);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 7.0f);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glRasterPos3f(0.1f, 0.2f, -0.3f);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_FLOAT_EQ(d, std::sqrt(0.01f + 0.04f + 0.09f));
  glWindowPos2f(3, 4);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 0.0f);
  // From a display list: the list's fog coordinate, which becomes current.
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glFogCoordf(9.0f);
  glRasterPos2f(0, 0);
  glEndList();
  glFogCoordf(1.0f);
  glCallList(list);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 9.0f);
  EXPECT_NO_GL_ERROR();
}

// Fog coordinates in display lists across non-vertex commands: a vertex
// without its own takes the one before it (the format carried, or the
// current one the node before set at replay), one given outside glBegin/glEnd
// holds for the vertices after it. Linear fog 0..10 toward blue: red is
// 255 (1 - c / 10).
TEST_F(PixelTexturingTest, DisplayListFogCoordinatesAcrossOtherCommands) {
  ClearBlack();
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 10);
  const float blue[4] = {0, 0, 1, 1};
  glFogfv(GL_FOG_COLOR, blue);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glColor3f(1, 1, 1);
  auto point = [](float x) { glVertex2f(x, 0); };
  const GLuint l = glGenLists(4);
  glNewList(l, GL_COMPILE);
  glBegin(GL_POINTS);
  glFogCoordf(2);
  point(-0.9f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_POINTS);
  point(-0.8f);
  glEnd();
  glEndList();
  glNewList(l + 1, GL_COMPILE);
  glFogCoordf(4);
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_POINTS);
  point(-0.5f);
  glFogCoordf(6);
  point(-0.4f);
  glEnd();
  glEndList();
  glNewList(l + 2, GL_COMPILE);
  glBegin(GL_POINTS);
  glFogCoordf(8);
  point(0.0f);
  glEnd();
  glLineWidth(1);
  glBegin(GL_POINTS);
  point(0.1f);
  glFogCoordf(3);
  point(0.2f);
  glEnd();
  glEndList();
  glNewList(l + 3, GL_COMPILE);
  glFogCoordf(5);
  glBegin(GL_POINTS);
  point(0.5f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glFogCoordf(7);
  glColor3f(1, 1, 1);
  glBegin(GL_POINTS);
  point(0.6f);
  glEnd();
  glEndList();
  for (GLuint i = 0; i < 4; ++i) {
    glFogCoordf(9.5f);
    glCallList(l + i);
  }
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  const int xs[9] = {3, 6, 16, 19, 32, 35, 38, 48, 51};
  const int red[9] = {204, 204, 153, 102, 51, 51, 178, 128, 76};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(At(p, xs[i], 32)[0], red[i]) << "point " << i;
  float current = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &current);
  EXPECT_EQ(current, 7.0f);
}

// The same after a compiled glDrawArrays with a fog coordinate array, in
// GL_COMPILE_AND_EXECUTE, and with a glFogCoord outside glBegin/glEnd between
// other commands.
TEST_F(PixelTexturingTest, DisplayListFogCoordinatesFromArraysAndCompileAndExecute) {
  ClearBlack();
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 10);
  const float blue[4] = {0, 0, 1, 1};
  glFogfv(GL_FOG_COLOR, blue);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glColor3f(1, 1, 1);
  auto point = [](float x) { glVertex2f(x, 0); };
  static const float verts[4] = {-0.9f, 0, -0.8f, 0};
  static const float coords[2] = {2, 6};
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glEnableClientState(GL_VERTEX_ARRAY);
  glFogCoordPointer(GL_FLOAT, 0, coords);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  const GLuint l = glGenLists(3);
  glNewList(l, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, 2);
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_POINTS);
  point(-0.5f);
  glEnd();
  glEndList();
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glFogCoordf(9.5f);
  glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_POINTS);
  glFogCoordf(8);
  point(0.0f);
  glEnd();
  glEnable(GL_FOG);
  glBegin(GL_POINTS);
  point(0.1f);
  glEnd();
  glEndList();
  glNewList(l + 2, GL_COMPILE);
  glBegin(GL_POINTS);
  glFogCoordf(3);
  point(0.3f);
  glEnd();
  glPointSize(1);
  glFogCoordf(1);
  glPushMatrix();
  glPopMatrix();
  glBegin(GL_POINTS);
  point(0.4f);
  glEnd();
  glEndList();
  ClearBlack();
  for (GLuint i = 0; i < 3; ++i) {
    glFogCoordf(9.5f);
    glCallList(l + i);
  }
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  const int xs[7] = {3, 6, 16, 32, 35, 41, 44};
  const int red[7] = {204, 102, 13, 51, 51, 178, 230};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(At(p, xs[i], 32)[0], red[i]) << "point " << i;
  float current = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &current);
  EXPECT_EQ(current, 1.0f);
}

// Per-vertex secondary colours (glSecondaryColor between glBegin and glEnd)
// are varyings of the unlit colour sum, clamped at the vertex: 3 on the left
// edge and 0 on the right read about 0.47 at x = 8 of 16, not 1.
TEST_F(PixelTexturingTest, PerVertexSecondaryColoursAreInterpolated) {
  ClearBlack();
  glEnable(GL_COLOR_SUM);
  glColor4f(0, 0, 0, 1);
  glBegin(GL_QUADS);
  glSecondaryColor3f(3, 0, 0);
  glVertex2f(-1, 0);
  glSecondaryColor3f(0, 0, 0);
  glVertex2f(-0.5f, 0);
  glVertex2f(-0.5f, 0.5f);
  glSecondaryColor3f(3, 0, 0);
  glVertex2f(-1, 0.5f);
  glEnd();
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 8, 40), (std::array<int, 4>{120, 0, 0, 255}));
  EXPECT_EQ(At(p, 0, 40), (std::array<int, 4>{247, 0, 0, 255}));
}

// The same from a display list, whose vertex node keeps them per vertex; the
// last one becomes current at replay, and a glSecondaryColor compiled
// outside glBegin/glEnd holds for the quad after it.
TEST_F(PixelTexturingTest, DisplayListKeepsPerVertexSecondaryColours) {
  ClearBlack();
  glEnable(GL_COLOR_SUM);
  glColor4f(0, 0, 0, 1);
  const GLuint l = glGenLists(1);
  glNewList(l, GL_COMPILE);
  glBegin(GL_QUADS);
  glSecondaryColor3f(3, 0, 0);
  glVertex2f(-1, 0);
  glSecondaryColor3f(0, 0, 0);
  glVertex2f(-0.5f, 0);
  glVertex2f(-0.5f, 0.5f);
  glSecondaryColor3f(3, 0, 0);
  glVertex2f(-1, 0.5f);
  glEnd();
  glSecondaryColor3f(0, 0.5f, 0);
  glBegin(GL_QUADS);
  glVertex2f(0, 0);
  glVertex2f(0.5f, 0);
  glVertex2f(0.5f, 0.5f);
  glVertex2f(0, 0.5f);
  glEnd();
  glEndList();
  glSecondaryColor3f(0, 0, 0.25f);
  glCallList(l);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 8, 40), (std::array<int, 4>{120, 0, 0, 255}));
  EXPECT_EQ(At(p, 40, 40), (std::array<int, 4>{0, 128, 0, 255}));
  float c[4] = {};
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 0.0f);
}

}  // namespace
}  // namespace glfx_test
