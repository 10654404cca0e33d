// glPixelMap and glGetPixelMap (GL 2.1 §3.6.3, §6.1.3): the initial maps,
// the fv/uiv/usv conversions both ways, the sizes, errors, display lists and
// pixel buffers; and the pixel transfer that reads them (§3.6.5): glReadPixels
// with scale, bias and GL_MAP_COLOR, glDrawPixels through the maps. The
// values are Mesa's (measured; reference/MESA_FACTS.md "Pixel maps"), and
// the tests run on libglfixed and on Mesa.
#include <array>
#include <cmath>
#include <vector>

#include "gl_test_fixture.h"
#include "pixel_readback.h"

namespace glfx_test {
namespace {

using PixelMapTest = GLTest;

const GLenum kMaps[10] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_G,
                          GL_PIXEL_MAP_I_TO_B, GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G,
                          GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A};

GLint MapSize(GLenum map) {
  GLint v = -1;
  glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE + (map - GL_PIXEL_MAP_I_TO_I), &v);
  return v;
}

TEST_F(PixelMapTest, EveryMapStartsWithOneZeroEntry) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, &max);
  EXPECT_EQ(max, 256);
  for (GLenum m : kMaps) {
    EXPECT_EQ(MapSize(m), 1) << std::hex << m;
    GLfloat f[2] = {-9, -9};
    glGetPixelMapfv(m, f);
    EXPECT_EQ(f[0], 0.0f);
    EXPECT_EQ(f[1], -9.0f);  // one value written
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, FloatColourMapsAreClampedAndConvertedOnTheWayOut) {
  const GLfloat v[4] = {-0.5f, 0.25f, 1.5f, 0.7f};
  for (GLenum m : kMaps) {
    if (m == GL_PIXEL_MAP_I_TO_I || m == GL_PIXEL_MAP_S_TO_S) continue;
    glPixelMapfv(m, 4, v);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(MapSize(m), 4);
    GLfloat f[4];
    glGetPixelMapfv(m, f);
    EXPECT_EQ(f[0], 0.0f);
    EXPECT_EQ(f[1], 0.25f);
    EXPECT_EQ(f[2], 1.0f);
    EXPECT_EQ(f[3], 0.7f);
    GLuint u[4];
    glGetPixelMapuiv(m, u);
    EXPECT_EQ(u[0], 0u);
    EXPECT_EQ(u[1], 1073741823u);
    EXPECT_EQ(u[2], 4294967295u);
    EXPECT_EQ(u[3], 3006477055u);
    GLushort s[4];
    glGetPixelMapusv(m, s);
    EXPECT_EQ(s[0], 0);
    EXPECT_EQ(s[1], 16384);
    EXPECT_EQ(s[2], 65535);
    EXPECT_EQ(s[3], 45874);
  }
}

TEST_F(PixelMapTest, IndexMapsKeepTheirValues) {
  const GLfloat v[4] = {-3.6f, 2.5f, 3.5f, 70000.7f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, v);
  GLfloat f[4];
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  EXPECT_EQ(f[0], -3.6f);
  EXPECT_EQ(f[3], 70000.7f);
  GLushort s[4];
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_I, s);  // clamped, truncated
  EXPECT_EQ((std::array<int, 4>{s[0], s[1], s[2], s[3]}), (std::array<int, 4>{0, 2, 3, 65535}));
  GLuint u[4];
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, u);  // Mesa's FLOAT_TO_UINT, wrapped
  EXPECT_EQ(u[0], 1717987332u);
  EXPECT_EQ(u[1], 2147483645u);
  // S_TO_S holds integers, rounded.
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, v);
  glGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, f);
  EXPECT_EQ((std::array<float, 4>{f[0], f[1], f[2], f[3]}), (std::array<float, 4>{-4, 3, 4, 70001}));
  glGetPixelMapusv(GL_PIXEL_MAP_S_TO_S, s);
  EXPECT_EQ((std::array<int, 4>{s[0], s[1], s[2], s[3]}), (std::array<int, 4>{0, 3, 4, 65535}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, UnsignedValuesAreNormalizedForColourMapsOnly) {
  const GLuint ui[4] = {0, 1, 0x80000000u, 0xffffffffu};
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_R, 4, ui);
  GLfloat f[4];
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_R, f);
  EXPECT_EQ(f[1], 1.0f / 4294967295.0f);
  EXPECT_EQ(f[2], 0.5f);
  EXPECT_EQ(f[3], 1.0f);
  GLuint u[4];
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_R, u);
  EXPECT_EQ(u[2], 2147483647u);
  EXPECT_EQ(u[3], 4294967295u);
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, ui);
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  EXPECT_EQ(f[1], 1.0f);
  EXPECT_EQ(f[2], 2147483648.0f);
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, u);
  EXPECT_EQ((std::array<GLuint, 4>{u[0], u[1], u[2], u[3]}),
            (std::array<GLuint, 4>{0, 4294967295u, 2147483648u, 0}));
  const GLushort us[4] = {0, 1, 32768, 65535};
  glPixelMapusv(GL_PIXEL_MAP_G_TO_G, 4, us);
  glGetPixelMapfv(GL_PIXEL_MAP_G_TO_G, f);
  EXPECT_EQ(f[1], 1.0f / 65535.0f);
  EXPECT_EQ(f[2], 32768.0f / 65535.0f);
  GLushort s[4];
  glGetPixelMapusv(GL_PIXEL_MAP_G_TO_G, s);
  EXPECT_EQ((std::array<int, 4>{s[0], s[1], s[2], s[3]}), (std::array<int, 4>{0, 1, 32768, 65535}));
  glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 4, us);
  glGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, f);
  EXPECT_EQ(f[3], 65535.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, SizesOutOfRangeOrNotPowersOfTwoAreInvalid) {
  static GLfloat v[300];
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, -1, v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, v);
  EXPECT_NO_GL_ERROR();
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, v);  // colour maps: any size
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(MapSize(GL_PIXEL_MAP_R_TO_R), 3);
  for (GLenum m : {GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_A}) {
    glPixelMapfv(m, 3, v);
    EXPECT_GL_ERROR(GL_INVALID_VALUE);
    EXPECT_EQ(MapSize(m), 1);
  }
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, v);  // Mesa: I_TO_I is not checked
  EXPECT_NO_GL_ERROR();
  glPixelMapfv(GL_TEXTURE_2D, 2, v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glPixelMapfv(GL_TEXTURE_2D, 0, v);  // the size first
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetPixelMapfv(GL_TEXTURE_2D, v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, v);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(PixelMapTest, MapsBelongToNoAttributeGroup) {
  const GLfloat v[2] = {0.5f, 1};
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, v);
  glPopAttrib();
  EXPECT_EQ(MapSize(GL_PIXEL_MAP_R_TO_R), 2);
}

TEST_F(PixelMapTest, ListsKeepTheValuesAndCheckWhenTheyRun) {
  GLfloat v[2] = {0.25f, 0.75f};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, v);
  GLfloat f[2] = {-1, -1};
  glGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, f);  // executed at once
  EXPECT_EQ(f[0], 0.0f);
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(MapSize(GL_PIXEL_MAP_B_TO_B), 1);
  v[0] = 0.5f;
  glCallList(list);
  EXPECT_EQ(MapSize(GL_PIXEL_MAP_B_TO_B), 2);
  glGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, f);
  EXPECT_EQ(f[0], 0.25f);
  EXPECT_EQ(f[1], 0.75f);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 0, v);
  EXPECT_NO_GL_ERROR();
  glEndList();
  glCallList(list);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteLists(list, 1);
}

TEST_F(PixelMapTest, PixelBuffersHoldTheValues) {
  const GLfloat v[8] = {0.1f, 0.25f, 0.5f, 0.7f, 0.3f, 0.4f, 0.6f, 0.9f};
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof v, v, GL_STATIC_DRAW);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, reinterpret_cast<const GLfloat*>(16));
  EXPECT_NO_GL_ERROR();
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 4, reinterpret_cast<const GLfloat*>(20));  // past the end
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, reinterpret_cast<const GLfloat*>(2));  // not a float's offset
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 2, reinterpret_cast<const GLushort*>(3));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  GLfloat f[2];
  glGetPixelMapfv(GL_PIXEL_MAP_A_TO_A, f);
  EXPECT_EQ(f[0], 0.3f);
  EXPECT_EQ(f[1], 0.4f);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
  glGetPixelMapusv(GL_PIXEL_MAP_A_TO_A, reinterpret_cast<GLushort*>(28));  // 2 shorts: the last 4 bytes
  EXPECT_NO_GL_ERROR();
  glGetPixelMapfv(GL_PIXEL_MAP_A_TO_A, reinterpret_cast<GLfloat*>(28));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetPixelMapfv(GL_PIXEL_MAP_A_TO_A, reinterpret_cast<GLfloat*>(2));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLushort s[2];
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 28, 4, s);
  EXPECT_EQ(s[0], 19660);  // 0.3f * 65535 is 19660.5 in float, rounded to even
  EXPECT_EQ(s[1], 26214);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &b);
}

// The pixel transfer tests restore the identity transfer before reading
// back: glReadPixels applies it too.
void ResetTransfer() {
  glPixelTransferi(GL_MAP_COLOR, 0);
  for (GLenum s : {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE}) glPixelTransferf(s, 1);
  for (GLenum b : {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS}) glPixelTransferf(b, 0);
}

// A 16 x 4 image whose every texel differs.
struct Image {
  GLubyte p[4][16][4];
  Image() {
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 16; ++i) {
        p[j][i][0] = static_cast<GLubyte>(i * 16 + j);
        p[j][i][1] = static_cast<GLubyte>(j * 64 + i * 3);
        p[j][i][2] = static_cast<GLubyte>((i * 37 + j * 11) & 255);
        p[j][i][3] = static_cast<GLubyte>((j * 80 + i * 5) & 255);
      }
  }
};

// A column of Mesa's map lookup: floor(c * size), clamped (NEAREST, CLAMP_TO_EDGE).
int Column(float c, int size) {
  const int x = static_cast<int>(std::floor(c * static_cast<float>(size)));
  return x < 0 ? 0 : x >= size ? size - 1 : x;
}
// An entry of a map through Mesa's 256-wide RGBA8 map texture.
int Entry(const GLfloat* map, int size, float c) {
  return static_cast<int>(std::nearbyint(map[Column(c, 256) * size / 256] * 255.0f));
}

const GLfloat kRedMap[4] = {0.1f, 0.4f, 0.6f, 0.9f};
const GLfloat kGreenMap[3] = {0.2f, 0.5f, 0.8f};
const GLfloat kBlueMap[2] = {1, 0};
const GLfloat kAlphaMap[2] = {0.2f, 0.8f};

void SetColourMaps() {
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, kRedMap);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, kGreenMap);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, kBlueMap);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, kAlphaMap);
}

// What Mesa's glDrawPixels shader makes of image texel (i, j) with
// GL_MAP_COLOR (measured): red and green through their maps, blue and alpha
// the red and green of the image texel at (b, a). `topRowFirst`: the texture
// of glCopyPixels, whose row 0 is the top row.
std::array<int, 4> MesaMapped(const Image& im, int i, int j, float redScale, bool topRowFirst) {
  const GLubyte* t = im.p[j][i];
  const float r = t[0] / 255.0f * redScale, g = t[1] / 255.0f, b = t[2] / 255.0f, a = t[3] / 255.0f;
  int row = Column(a, 4);
  if (topRowFirst) row = 3 - row;
  const GLubyte* second = im.p[row][Column(b, 16)];
  return {Entry(kRedMap, 4, r), Entry(kGreenMap, 3, g), second[0], second[1]};
}

TEST_F(PixelMapTest, DrawPixelsMapsColourAsMesasShaderDoes) {
  PixelProjection();
  ClearBlack();
  const Image im;
  SetColourMaps();
  glPixelTransferi(GL_MAP_COLOR, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(2, 3);
  glDrawPixels(16, 4, GL_RGBA, GL_UNSIGNED_BYTE, im.p);
  glRasterPos2i(30, 3);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glDrawPixels(16, 4, GL_RGBA, GL_UNSIGNED_BYTE, im.p);
  EXPECT_NO_GL_ERROR();
  ResetTransfer();
  const std::vector<unsigned char> p = ReadAll();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 16; ++i) {
      EXPECT_EQ(At(p, 2 + i, 3 + j), MesaMapped(im, i, j, 1, false)) << i << "," << j;
      EXPECT_EQ(At(p, 30 + i, 3 + j), MesaMapped(im, i, j, 0.5f, false)) << i << "," << j;
    }
}

TEST_F(PixelMapTest, CopyPixelsMapsColourAsDrawPixelsDoes) {
  PixelProjection();
  ClearBlack();
  const Image im;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(2, 3);
  glDrawPixels(16, 4, GL_RGBA, GL_UNSIGNED_BYTE, im.p);
  SetColourMaps();
  glPixelTransferi(GL_MAP_COLOR, 1);
  glRasterPos2i(30, 20);
  glCopyPixels(2, 3, 16, 4, GL_COLOR);
  EXPECT_NO_GL_ERROR();
  ResetTransfer();
  const std::vector<unsigned char> p = ReadAll();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 16; ++i)
      EXPECT_EQ(At(p, 30 + i, 20 + j), MesaMapped(im, i, j, 1, true)) << i << "," << j;
}

TEST_F(PixelMapTest, ReadPixelsScalesBiasesAndMaps) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[4] = {230, 51, 100, 255};
  glRasterPos2i(5, 5);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  GLubyte b[4];
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
  EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{115, 115, 100, 255}));
  glPixelTransferf(GL_GREEN_BIAS, 0.9f);
  GLfloat f[4];
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_FLOAT, f);  // floats are not clamped
  EXPECT_FLOAT_EQ(f[0], 230 / 255.0f * 0.5f);
  EXPECT_FLOAT_EQ(f[1], 51 / 255.0f + 0.9f);
  ResetTransfer();
  // A drawn pixel scaled once by glDrawPixels and once by glReadPixels.
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  const GLubyte hundred[4] = {100, 100, 100, 255};
  glRasterPos2i(6, 5);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, hundred);
  glReadPixels(6, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
  EXPECT_EQ(b[0], 25);
  ResetTransfer();
  glReadPixels(6, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
  EXPECT_EQ(b[0], 50);
  // The maps as the spec rounds: entry round(c * (size - 1)).
  const GLfloat invert[2] = {1, 0};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, kGreenMap);
  glPixelTransferi(GL_MAP_COLOR, 1);
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
  EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{0, 51, 0, 0}));
  ResetTransfer();
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, ReadPixelsIntoSignedAndWideTypes) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[4] = {100, 150, 200, 50};
  glRasterPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  GLshort s[4];
  GLbyte b[4];
  GLuint u[4];
  GLint i[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_SHORT, s);
  EXPECT_EQ((std::array<int, 4>{s[0], s[1], s[2], s[3]}), (std::array<int, 4>{12850, 19275, 25700, 6425}));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BYTE, b);
  EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{50, 75, 100, 25}));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT, u);
  EXPECT_EQ(u[0], 1684300900u);
  EXPECT_EQ(u[1], 2526451350u);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_INT, i);
  EXPECT_EQ(i[0], 842150450);
  EXPECT_EQ(i[1], 1263225675);
  glPixelTransferf(GL_RED_BIAS, -0.5f);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_SHORT, s);
  EXPECT_EQ(s[0], -3534);  // clamped to [-1, 1] only
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT, u);
  EXPECT_EQ(u[1], 2526451456u);  // through float with the transfer on
  ResetTransfer();
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, ReadPixelsScalesAndBiasesDepth) {
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.1f);
  GLfloat d;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_FLOAT_EQ(d, 0.35f);
  GLushort s;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &s);
  EXPECT_EQ(s, 22937);
  GLuint u;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u);
  EXPECT_NEAR(static_cast<double>(u), 0.35 * 4294967295.0, 512.0);
  glPixelTransferf(GL_DEPTH_SCALE, 3);
  glPixelTransferf(GL_DEPTH_BIAS, 0);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_EQ(d, 1.0f);  // clamped
  glPixelTransferf(GL_DEPTH_SCALE, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, TexImageMapsColourAsTheSpecRounds) {
  const GLubyte px[6][4] = {{0, 255, 0, 0},       {51, 204, 101, 151}, {102, 153, 202, 46},
                            {153, 102, 47, 197}, {204, 51, 148, 92},  {255, 0, 249, 243}};
  const GLfloat invert[2] = {1, 0}, green[2] = {0.3f, 0.6f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, green);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, invert);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, kAlphaMap);
  glPixelTransferi(GL_MAP_COLOR, 1);
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 6, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  ResetTransfer();
  GLubyte back[6][4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  const int expected[6][4] = {{255, 153, 255, 51}, {255, 153, 255, 204}, {255, 153, 0, 51},
                              {0, 76, 255, 204},   {0, 76, 0, 51},       {0, 76, 0, 204}};
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ((std::array<int, 4>{back[i][0], back[i][1], back[i][2], back[i][3]}),
              (std::array<int, 4>{expected[i][0], expected[i][1], expected[i][2], expected[i][3]}))
        << i;
  glDeleteTextures(1, &t);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, CopyTexImageMapsColourAsTexImageDoes) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[4][4] = {{0, 255, 0, 0}, {51, 204, 101, 151}, {153, 102, 47, 197}, {255, 0, 249, 243}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(0, 0);
  glDrawPixels(4, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  const GLfloat invert[2] = {1, 0};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, kGreenMap);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, invert);
  glPixelTransferi(GL_MAP_COLOR, 1);
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 1, 0);
  ResetTransfer();
  GLubyte o[4][4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, o);
  const int expected[4][4] = {{255, 204, 255, 0}, {255, 204, 255, 0}, {0, 128, 255, 0}, {0, 51, 0, 0}};
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ((std::array<int, 4>{o[i][0], o[i][1], o[i][2], o[i][3]}),
              (std::array<int, 4>{expected[i][0], expected[i][1], expected[i][2], expected[i][3]}))
        << i;
  glDeleteTextures(1, &t);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PixelMapTest, ColourIndexImagesGoThroughTheIndexMaps) {
  PixelProjection();
  ClearBlack();
  const GLfloat r[4] = {0.1f, 0.5f, 0.9f, 1}, g[4] = {1, 0.7f, 0.3f, 0}, b[4] = {0.2f, 0.4f, 0.6f, 0.8f},
                a[4] = {1, 1, 0.5f, 0.25f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
  const std::array<int, 4> colour[4] = {
      {26, 255, 51, 255}, {128, 178, 102, 255}, {230, 76, 153, 128}, {255, 0, 204, 64}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte ub[8] = {0, 1, 2, 3, 4, 5, 6, 255};
  glRasterPos2i(0, 0);
  glDrawPixels(8, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
  // Mesa unpacks with the transfer off: no index shift and offset, no scale.
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glRasterPos2i(0, 1);
  glDrawPixels(8, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  ResetTransfer();
  const GLubyte bits[1] = {0xA5};
  glRasterPos2i(0, 2);
  glDrawPixels(8, 1, GL_COLOR_INDEX, GL_BITMAP, bits);
  const GLfloat fl[4] = {0.4f, 1.6f, 2.5f, -1};
  glRasterPos2i(0, 3);
  glDrawPixels(4, 1, GL_COLOR_INDEX, GL_FLOAT, fl);
  const GLshort sh[4] = {-1, 1, 2, -4};
  glRasterPos2i(0, 4);
  glDrawPixels(4, 1, GL_COLOR_INDEX, GL_SHORT, sh);
  const GLuint ui[4] = {3, 5, 7, 0xffffffffu};
  glRasterPos2i(0, 5);
  glDrawPixels(4, 1, GL_COLOR_INDEX, GL_UNSIGNED_INT, ui);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> p = ReadAll();
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(At(p, i, 0), colour[ub[i] & 3]) << i;
    EXPECT_EQ(At(p, i, 1), colour[ub[i] & 3]) << i;
    EXPECT_EQ(At(p, i, 2), colour[(bits[0] >> (7 - i)) & 1]) << i;
  }
  const int flIndex[4] = {0, 1, 2, 3}, shIndex[4] = {3, 1, 2, 0}, uiIndex[4] = {3, 1, 3, 3};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(At(p, i, 3), colour[flIndex[i]]) << i;
    EXPECT_EQ(At(p, i, 4), colour[shIndex[i]]) << i;
    EXPECT_EQ(At(p, i, 5), colour[uiIndex[i]]) << i;
  }
}

const std::array<int, 4> kIndexColour[4] = {
    {26, 255, 51, 255}, {128, 178, 102, 255}, {230, 76, 153, 128}, {255, 0, 204, 64}};

void SetIndexMaps() {
  const GLfloat r[4] = {0.1f, 0.5f, 0.9f, 1}, g[4] = {1, 0.7f, 0.3f, 0}, b[4] = {0.2f, 0.4f, 0.6f, 0.8f},
                a[4] = {1, 1, 0.5f, 0.25f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
}

TEST_F(PixelMapTest, ColourIndexTexturesAreShiftedOffsetAndMapped) {
  SetIndexMaps();
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte idx[4] = {0, 1, 2, 3};
  GLubyte o[4][4];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, o);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ((std::array<int, 4>{o[i][0], o[i][1], o[i][2], o[i][3]}), kIndexColour[i]) << i;
  // Unlike glDrawPixels, texstore shifts and offsets the index; no scale or colour map.
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferi(GL_MAP_COLOR, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  ResetTransfer();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, o);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ((std::array<int, 4>{o[i][0], o[i][1], o[i][2], o[i][3]}), kIndexColour[(i * 2 + 1) & 3]) << i;
  glDeleteTextures(1, &t);
  EXPECT_NO_GL_ERROR();
}

// Mesa reads GL_BITMAP colour indices as one run of bits: a row starts at
// bit row * width, not at the next (aligned) byte.
TEST_F(PixelMapTest, BitmapIndexRowsAreOneRunOfBits) {
  SetIndexMaps();
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const GLubyte padded[8] = {0xA0, 0, 0, 0, 0x40, 0, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 2, 0, GL_COLOR_INDEX, GL_BITMAP, padded);
  GLubyte o[24][4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, o);
  const int expected4x2[8] = {1, 0, 1, 0, 0, 0, 0, 0};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(o[i][0], kIndexColour[expected4x2[i]][0]) << i;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte bits[4] = {0xA5, 0x3C, 0xF0, 0x0F};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 12, 2, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, o);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(o[i][0], kIndexColour[(bits[i / 8] >> (7 - i % 8)) & 1][0]) << i;
  glDeleteTextures(1, &t);
  PixelProjection();
  ClearBlack();
  glRasterPos2i(0, 0);
  glDrawPixels(12, 2, GL_COLOR_INDEX, GL_BITMAP, bits);
  const std::vector<unsigned char> p = ReadAll();
  for (int i = 0; i < 24; ++i)
    EXPECT_EQ(At(p, i % 12, i / 12), kIndexColour[(bits[i / 8] >> (7 - i % 8)) & 1]) << i;
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
