// EGL 1.5 through the library's exported ABI: with no X server (the test
// unsets DISPLAY before its first EGL call, so EGL_DEFAULT_DISPLAY is the
// surfaceless platform), and on an X11 window under Xvfb (skipped where
// Xvfb is missing). Expected pixels come from GL 2.1's lighting equations
// (§2.14.1), not from the library; tests/platform/egl_pbuffer_compare.sh
// compares a pbuffer program with Mesa's EGL.
// gtest before Xlib.h, whose None and Bool macros it cannot take.
#include <gtest/gtest.h>

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

// Runs before any test: no X server for the default display.
const bool kNoDisplay = [] {
  unsetenv("DISPLAY");
  return true;
}();

EGLDisplay initializedDefault() {
  EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  EXPECT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  return dpy;
}

EGLConfig pbufferConfig(EGLDisplay dpy, EGLint depth = 16) {
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,   EGL_DEPTH_SIZE,  depth,
                            EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  EXPECT_TRUE(eglChooseConfig(dpy, attribs, &config, 1, &n));
  EXPECT_EQ(n, 1);
  return config;
}

EGLint attrib(EGLDisplay dpy, EGLConfig c, EGLint name) {
  EGLint v = -12345;
  EXPECT_TRUE(eglGetConfigAttrib(dpy, c, name, &v)) << std::hex << name;
  return v;
}

bool hasWord(const char* list, const char* word) {
  if (!list) return false;
  const std::string s = std::string(" ") + list + " ";
  return s.find(std::string(" ") + word + " ") != std::string::npos;
}

// A triangle lit by one directional light along its normal: GL 2.1
// §2.14.1 gives colour = scene ambient (0.2) x material ambient (0.2)
// + diffuse x 1, here (0.04 + 0.5, 0.04 + 0.25, 0.04 + 0.75): 137.7, 73.95
// and 201.45 of 255, converted to the nearest integer (§2.19.9).
constexpr uint8_t kLit[3] = {138, 74, 201};
void drawLitTriangle() {
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat position[] = {0, 0, 1, 0};
  const GLfloat diffuse[] = {0.5f, 0.25f, 0.75f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex2f(-0.8f, -0.8f);
  glVertex2f(0.8f, -0.8f);
  glVertex2f(0.0f, 0.8f);
  glEnd();
  glDisable(GL_LIGHTING);
}

TEST(EglNoDisplay, DefaultDisplayIsSurfaceless) {
  ASSERT_TRUE(kNoDisplay);
  EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  ASSERT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetDisplay(EGL_DEFAULT_DISPLAY), dpy);  // the same display every time
  EGLint major = 0, minor = 0;
  ASSERT_TRUE(eglInitialize(dpy, &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 5);
  EXPECT_STREQ(eglQueryString(dpy, EGL_VENDOR), "libglfixed");
  EXPECT_STREQ(eglQueryString(dpy, EGL_VERSION), "1.5 libglfixed");
  EXPECT_STREQ(eglQueryString(dpy, EGL_CLIENT_APIS), "OpenGL");
  EXPECT_TRUE(hasWord(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"));
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  for (const char* e : {"EGL_EXT_client_extensions", "EGL_EXT_platform_base", "EGL_KHR_platform_x11",
                        "EGL_EXT_platform_x11", "EGL_MESA_platform_surfaceless"})
    EXPECT_TRUE(hasWord(client, e)) << e;
  EXPECT_FALSE(hasWord(client, "EGL_MESA_platform_gbm"));
  // The surfaceless platform is the same display.
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), dpy);
}

TEST(EglNoDisplay, ConfigsAndAttributes) {
  EGLDisplay dpy = initializedDefault();
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  ASSERT_EQ(n, 8);  // RGB and RGBA, each with depth 0, 16, 24, 24 + stencil 8
  std::vector<EGLConfig> configs(n);
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), n, &n));
  for (EGLConfig c : configs) {
    EXPECT_EQ(attrib(dpy, c, EGL_RED_SIZE), 8);
    EXPECT_EQ(attrib(dpy, c, EGL_BUFFER_SIZE), 24 + attrib(dpy, c, EGL_ALPHA_SIZE));
    EXPECT_EQ(attrib(dpy, c, EGL_RENDERABLE_TYPE), EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT);  // egl_config.cpp says why
    EXPECT_EQ(attrib(dpy, c, EGL_SURFACE_TYPE), EGL_PBUFFER_BIT);  // no windows without X
    EXPECT_EQ(attrib(dpy, c, EGL_NATIVE_VISUAL_ID), 0);
    EXPECT_EQ(attrib(dpy, c, EGL_CONFIG_CAVEAT), EGL_NONE);
    EXPECT_EQ(attrib(dpy, c, EGL_COLOR_BUFFER_TYPE), EGL_RGB_BUFFER);
  }
  EGLint v;
  EXPECT_FALSE(eglGetConfigAttrib(dpy, configs[0], 0x7777, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglGetConfigAttrib(dpy, reinterpret_cast<EGLConfig>(0x1234), EGL_RED_SIZE, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  // Two configurations fit in an array of two.
  EGLint two = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), 2, &two));
  EXPECT_EQ(two, 2);
}

TEST(EglNoDisplay, ChooseConfigMatchesAndSorts) {
  EGLDisplay dpy = initializedDefault();
  EGLint n = -1;
  // EGL_SURFACE_TYPE defaults to EGL_WINDOW_BIT: nothing on surfaceless.
  ASSERT_TRUE(eglChooseConfig(dpy, nullptr, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  // OpenGL ES 2 is not offered; an ES 1 request matches (xscreensaver's,
  // egl_config.cpp), but the ES API cannot be bound.
  const EGLint es[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(dpy, es, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  const EGLint es1[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(dpy, es1, nullptr, 0, &n));
  EXPECT_EQ(n, 8);
  EXPECT_FALSE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // Sorting (§3.4.1): smaller buffer size, then smaller depth first.
  const EGLint any[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig c[8];
  ASSERT_TRUE(eglChooseConfig(dpy, any, c, 8, &n));
  ASSERT_EQ(n, 8);
  EXPECT_EQ(attrib(dpy, c[0], EGL_ALPHA_SIZE), 0);
  EXPECT_EQ(attrib(dpy, c[0], EGL_DEPTH_SIZE), 0);
  EXPECT_EQ(attrib(dpy, c[1], EGL_DEPTH_SIZE), 16);
  EXPECT_EQ(attrib(dpy, c[3], EGL_STENCIL_SIZE), 8);
  EXPECT_EQ(attrib(dpy, c[4], EGL_ALPHA_SIZE), 8);
  // Asking for alpha puts the larger colour sum first, and only alpha configs match.
  const EGLint alpha[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_ALPHA_SIZE, 1, EGL_DEPTH_SIZE, 17, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(dpy, alpha, c, 8, &n));
  ASSERT_EQ(n, 2);
  EXPECT_EQ(attrib(dpy, c[0], EGL_ALPHA_SIZE), 8);
  EXPECT_EQ(attrib(dpy, c[0], EGL_STENCIL_SIZE), 0);
  EXPECT_EQ(attrib(dpy, c[1], EGL_STENCIL_SIZE), 8);
  // EGL_CONFIG_ID overrides every other attribute.
  const EGLint id = attrib(dpy, c[1], EGL_CONFIG_ID);
  const EGLint byId[] = {EGL_CONFIG_ID, id, EGL_RED_SIZE, 9, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(dpy, byId, c, 8, &n));
  ASSERT_EQ(n, 1);
  EXPECT_EQ(attrib(dpy, c[0], EGL_CONFIG_ID), id);
  // Bad lists.
  const EGLint unknown[] = {0x7777, 1, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, unknown, c, 8, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint badValue[] = {EGL_COLOR_BUFFER_TYPE, 0x1234, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, badValue, c, 8, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglChooseConfig(dpy, any, c, 8, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST(EglNoDisplay, Errors) {
  EGLDisplay dpy = initializedDefault();
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EGLDisplay bogus = reinterpret_cast<EGLDisplay>(0x5678);
  EXPECT_FALSE(eglInitialize(bogus, nullptr, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);  // reading the error clears it
  EXPECT_EQ(eglQueryString(bogus, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglQueryString(dpy, 0x7777), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // Platforms that are not the library's.
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_GBM_MESA, nullptr, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglGetPlatformDisplayEXT(EGL_PLATFORM_WAYLAND_EXT, nullptr, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // OpenGL ES and OpenVG are refused; OpenGL is not bound until asked for.
  EXPECT_FALSE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglBindAPI(EGL_OPENVG_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  std::thread([&] {
    EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_NONE));
    EXPECT_EQ(eglCreateContext(dpy, pbufferConfig(dpy), EGL_NO_CONTEXT, nullptr), EGL_NO_CONTEXT);
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  }).join();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  // Context versions above the library's (2.1), and versions that do not exist.
  for (EGLint version : {30, 32, 22, 16}) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, version / 10, EGL_CONTEXT_MINOR_VERSION,
                              version % 10, EGL_NONE};
    EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, attribs), EGL_NO_CONTEXT) << version;
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH) << version;
  }
  const EGLint core[] = {EGL_CONTEXT_MAJOR_VERSION,
                         3,
                         EGL_CONTEXT_MINOR_VERSION,
                         2,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                         EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, core), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint badAttrib[] = {0x7777, 0, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, badAttrib), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglCreateContext(dpy, reinterpret_cast<EGLConfig>(0x99), EGL_NO_CONTEXT, nullptr),
            EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_EQ(eglCreateContext(dpy, config, reinterpret_cast<EGLContext>(0x99), nullptr), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  // The library is GL 1.5 (no GLSL, api/gl_version.h): 2.0 is refused,
  // 1.5 compatibility asked for by number is made.
  const EGLint v20[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, v20), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint v15[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 5, EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, v15);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  // Bad handles in eglMakeCurrent, and surfaces without a context.
  EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, reinterpret_cast<EGLContext>(0x99)));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_FALSE(
      eglMakeCurrent(dpy, reinterpret_cast<EGLSurface>(0x98), reinterpret_cast<EGLSurface>(0x98), ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, size);
  ASSERT_NE(pb, EGL_NO_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(dpy, pb, pb, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(dpy, pb, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  // A surface of another configuration.
  EGLSurface other = eglCreatePbufferSurface(dpy, pbufferConfig(dpy, 24), size);
  EXPECT_FALSE(eglMakeCurrent(dpy, other, other, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  // Swapping a surface that is not current.
  EXPECT_FALSE(eglSwapBuffers(dpy, pb));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  // Pbuffer attributes.
  const EGLint negative[] = {EGL_WIDTH, -1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, negative), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  const EGLint texture[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                            EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, texture), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint huge[] = {EGL_WIDTH, 100000, EGL_HEIGHT, 4, EGL_LARGEST_PBUFFER, EGL_TRUE, EGL_NONE};
  EGLSurface largest = eglCreatePbufferSurface(dpy, config, huge);
  ASSERT_NE(largest, EGL_NO_SURFACE);
  EGLint w = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, largest, EGL_WIDTH, &w));
  EXPECT_EQ(w, 16384);
  // No window surface without X.
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, 0x400001, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_TRUE(eglDestroySurface(dpy, largest));
  EXPECT_FALSE(eglDestroySurface(dpy, largest));  // gone
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_TRUE(eglDestroySurface(dpy, other));
  EXPECT_TRUE(eglDestroySurface(dpy, pb));
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
  EXPECT_FALSE(eglDestroyContext(dpy, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

TEST(EglNoDisplay, NotInitializedAndTerminate) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  ASSERT_TRUE(eglTerminate(dpy));
  // The context stays current until released, but no handle is valid.
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EGLint n;
  EXPECT_FALSE(eglGetConfigs(dpy, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_EQ(eglQueryString(dpy, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  // Initialized again, the display works as before; old handles stay invalid.
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  EXPECT_EQ(n, 8);
}

TEST(EglNoDisplay, PbufferRendersLitTriangle) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  const EGLint size[] = {EGL_WIDTH, 40, EGL_HEIGHT, 30, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(pb, EGL_NO_SURFACE);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, pb, pb, ctx));
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), pb);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), pb);
  EXPECT_EQ(eglGetCurrentDisplay(), dpy);
  EXPECT_NE(std::strstr(reinterpret_cast<const char*>(glGetString(GL_RENDERER)), "libglfixed"), nullptr);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 40);
  EXPECT_EQ(viewport[3], 30);
  GLint drawBuffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  EXPECT_EQ(drawBuffer, GL_BACK);  // as on Mesa
  EGLint v = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, pb, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_BACK_BUFFER);
  EXPECT_TRUE(eglQuerySurface(dpy, pb, EGL_HEIGHT, &v));
  EXPECT_EQ(v, 30);
  EXPECT_TRUE(eglQuerySurface(dpy, pb, EGL_CONFIG_ID, &v));
  EXPECT_EQ(v, attrib(dpy, config, EGL_CONFIG_ID));
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &v));
  EXPECT_EQ(v, EGL_OPENGL_API);
  EXPECT_TRUE(eglSwapInterval(dpy, 0));
  drawLitTriangle();
  EXPECT_TRUE(eglSwapBuffers(dpy, pb));  // no effect on a pbuffer
  std::vector<uint8_t> pixels(40 * 30 * 4);
  glReadPixels(0, 0, 40, 30, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  auto at = [&](int x, int y) { return &pixels[(y * 40 + x) * 4]; };
  const uint8_t* centre = at(20, 15);
  EXPECT_EQ(centre[0], kLit[0]);
  EXPECT_EQ(centre[1], kLit[1]);
  EXPECT_EQ(centre[2], kLit[2]);
  const uint8_t* corner = at(1, 28);
  EXPECT_EQ(corner[0], 0);
  EXPECT_EQ(corner[2], 255);
  int lit = 0;
  for (int i = 0; i < 40 * 30; ++i) lit += pixels[i * 4] == kLit[0] && pixels[i * 4 + 2] == kLit[2];
  // Half of the middle 80% of the surface: 0.5 * 32 * 24 = 384 pixels.
  EXPECT_NEAR(lit, 384, 40);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_TRUE(eglDestroySurface(dpy, pb));
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
}

TEST(EglNoDisplay, SurfacelessContextAndDeferredDestruction) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
  EXPECT_NE(glGetString(GL_VERSION), nullptr);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  glFinish();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // A surface destroyed while current keeps working until released.
  const EGLint size[] = {EGL_WIDTH, 4, EGL_HEIGHT, 4, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, size);
  ASSERT_TRUE(eglMakeCurrent(dpy, pb, pb, ctx));
  ASSERT_TRUE(eglDestroySurface(dpy, pb));
  ASSERT_TRUE(eglDestroyContext(dpy, ctx));
  EGLint v;
  EXPECT_FALSE(eglQuerySurface(dpy, pb, EGL_WIDTH, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  uint8_t p[4] = {};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[1], 0);
  ASSERT_TRUE(eglReleaseThread());
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_NONE));
}

TEST(EglNoDisplay, SharedDisplayListsAndThreads) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  EGLContext first = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  EGLContext second = eglCreateContext(dpy, config, first, nullptr);
  EGLContext alone = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(first && second && alone);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, first));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEndList();
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, second));
  EXPECT_TRUE(glIsList(list));
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, alone));
  EXPECT_FALSE(glIsList(list));
  // A context current here cannot be made current on another thread; errors
  // are per thread.
  std::thread([&] {
    EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, alone));
    EXPECT_EQ(eglGetError(), EGL_BAD_ACCESS);
    EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
    EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, first));
    EXPECT_TRUE(eglReleaseThread());
  }).join();
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(eglGetCurrentContext(), alone);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  for (EGLContext c : {first, second, alone}) EXPECT_TRUE(eglDestroyContext(dpy, c));
}

// One library serves OSMesa and EGL: a context each, on one thread.
TEST(EglNoDisplay, OSMesaContextMadeCurrentOverAnEglOne) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EGLConfig config = pbufferConfig(dpy);
  const EGLint size[] = {EGL_WIDTH, 4, EGL_HEIGHT, 4, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, pb, pb, ctx));
  OSMesaContext os = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  ASSERT_NE(os, nullptr);
  std::vector<uint8_t> buffer(4 * 4 * 4, 0);
  ASSERT_TRUE(OSMesaMakeCurrent(os, buffer.data(), GL_UNSIGNED_BYTE, 4, 4));
  // Releasing the EGL context leaves OSMesa's current; the EGL objects can go.
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(OSMesaGetCurrentContext(), os);
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
  EXPECT_TRUE(eglDestroySurface(dpy, pb));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(buffer[1], 255);
  EXPECT_EQ(buffer[0], 0);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(os);
}

TEST(EglNoDisplay, FencesAreSignaledAtOnce) {
  EGLDisplay dpy = initializedDefault();
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr), EGL_NO_SYNC);  // no current context
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EGLContext ctx = eglCreateContext(dpy, pbufferConfig(dpy), EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_REUSABLE_KHR, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EGLSync sync = eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr);
  ASSERT_NE(sync, EGL_NO_SYNC);
  EGLAttrib status = 0;
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_STATUS, &status));
  EXPECT_EQ(status, EGL_SIGNALED);
  EXPECT_EQ(eglClientWaitSync(dpy, sync, EGL_SYNC_FLUSH_COMMANDS_BIT, EGL_FOREVER), EGL_CONDITION_SATISFIED);
  EXPECT_TRUE(eglWaitSync(dpy, sync, 0));
  EXPECT_TRUE(eglDestroySync(dpy, sync));
  EXPECT_FALSE(eglDestroySync(dpy, sync));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
}

TEST(EglNoDisplay, GetProcAddress) {
  EXPECT_EQ(reinterpret_cast<void*>(eglGetProcAddress("glBegin")), reinterpret_cast<void*>(&glBegin));
  EXPECT_EQ(reinterpret_cast<void*>(eglGetProcAddress("eglGetPlatformDisplayEXT")),
            reinterpret_cast<void*>(&eglGetPlatformDisplayEXT));
  EXPECT_EQ(reinterpret_cast<void*>(eglGetProcAddress("eglCreatePlatformWindowSurface")),
            reinterpret_cast<void*>(&eglCreatePlatformWindowSurface));
  EXPECT_EQ(eglGetProcAddress("glNoSuchFunction"), nullptr);
  EXPECT_NE(eglGetProcAddress("glGenerateMipmap"), nullptr);  // textures: implemented (xscreensaver imports it)
  EXPECT_EQ(eglGetProcAddress("eglQueryDevicesEXT"), nullptr);  // no device platform
  EXPECT_EQ(eglGetProcAddress(nullptr), nullptr);
}

// --- X11 ------------------------------------------------------------------

// An Xvfb of its own on the first free display of :71-:75.
class Xvfb {
 public:
  Xvfb() {
    for (int n = 71; n <= 75 && !display_; ++n) {
      const std::string name = ":" + std::to_string(n);
      if (access(("/tmp/.X" + std::to_string(n) + "-lock").c_str(), F_OK) == 0) continue;
      pid_ = fork();
      if (pid_ == 0) {
        // Dies with the test, and keeps no pipe of ctest's open after it.
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "320x240x24", "-nolisten", "tcp", nullptr);
        _exit(127);
      }
      for (int i = 0; i < 100 && !display_; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        int status;
        if (waitpid(pid_, &status, WNOHANG) == pid_) break;  // could not start there
        display_ = XOpenDisplay(name.c_str());
      }
      if (!display_) stop();
    }
  }
  ~Xvfb() {
    if (display_) XCloseDisplay(display_);
    stop();
  }
  Display* display() const { return display_; }

 private:
  void stop() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    pid_ = -1;
  }
  pid_t pid_ = -1;
  Display* display_ = nullptr;
};

bool haveXvfb() { return std::system("command -v Xvfb > /dev/null 2>&1") == 0; }

TEST(EglX11, WindowSurfaceSwapsToTheWindow) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb is not installed";
  Xvfb server;
  Display* x = server.display();
  ASSERT_NE(x, nullptr) << "Xvfb did not start on :71-:75";
  EGLDisplay dpy = eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(x));
  ASSERT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x, nullptr), dpy);
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  const EGLint attribs[] = {EGL_SURFACE_TYPE,
                            EGL_WINDOW_BIT,
                            EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,
                            EGL_RED_SIZE,
                            8,
                            EGL_DEPTH_SIZE,
                            16,
                            EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(dpy, attribs, &config, 1, &n));
  ASSERT_EQ(n, 1);
  EXPECT_EQ(attrib(dpy, config, EGL_SURFACE_TYPE), EGL_WINDOW_BIT | EGL_PBUFFER_BIT | EGL_PIXMAP_BIT);
  // The configuration's visual is the screen's default one (the root window's).
  const EGLint visualId = attrib(dpy, config, EGL_NATIVE_VISUAL_ID);
  EXPECT_EQ(static_cast<VisualID>(visualId), XVisualIDFromVisual(DefaultVisual(x, DefaultScreen(x))));
  EXPECT_EQ(attrib(dpy, config, EGL_NATIVE_VISUAL_TYPE), TrueColor);

  const Window win = XCreateSimpleWindow(x, DefaultRootWindow(x), 0, 0, 64, 48, 0, 0, 0);
  XMapWindow(x, win);
  XSync(x, False);
  EGLSurface surface = eglCreatePlatformWindowSurface(dpy, config, const_cast<Window*>(&win), nullptr);
  ASSERT_NE(surface, EGL_NO_SURFACE);
  // One surface per window; a window that does not exist.
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, win, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, 0x3fffff, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  EGLint v = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, surface, EGL_WIDTH, &v));
  EXPECT_EQ(v, 64);
  EXPECT_TRUE(eglQuerySurface(dpy, surface, EGL_HEIGHT, &v));
  EXPECT_EQ(v, 48);

  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, surface, surface, ctx));
  GLint drawBuffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  EXPECT_EQ(drawBuffer, GL_BACK);
  drawLitTriangle();
  glFinish();
  // Nothing reaches the window before the swap.
  XImage* before = XGetImage(x, win, 0, 0, 64, 48, AllPlanes, ZPixmap);
  ASSERT_NE(before, nullptr);
  EXPECT_EQ(XGetPixel(before, 32, 24) & 0xffffff, 0u);
  XDestroyImage(before);
  ASSERT_TRUE(eglSwapBuffers(dpy, surface));
  XImage* image = XGetImage(x, win, 0, 0, 64, 48, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  const unsigned long centre = XGetPixel(image, 32, 24);  // X rows go down; the triangle's middle
  EXPECT_EQ((centre >> 16) & 0xff, kLit[0]);
  EXPECT_EQ((centre >> 8) & 0xff, kLit[1]);
  EXPECT_EQ(centre & 0xff, kLit[2]);
  EXPECT_EQ(XGetPixel(image, 1, 1) & 0xffffff, 0x0000ffu);  // the clear colour, top left
  XDestroyImage(image);

  // A resized window gets buffers of its size at the next swap.
  XResizeWindow(x, win, 80, 60);
  XSync(x, False);
  ASSERT_TRUE(eglSwapBuffers(dpy, surface));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(dpy, surface));
  image = XGetImage(x, win, 0, 0, 80, 60, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(XGetPixel(image, 79, 59) & 0xffffff, 0x00ff00u);
  XDestroyImage(image);

  // eglCopyBuffers: the window surface's colour buffer into a pixmap.
  const Pixmap copy = XCreatePixmap(x, win, 80, 60, 24);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglCopyBuffers(dpy, surface, copy));
  image = XGetImage(x, copy, 0, 0, 80, 60, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(XGetPixel(image, 40, 30) & 0xffffff, 0xffff00u);
  XDestroyImage(image);
  XFreePixmap(x, copy);
  EXPECT_FALSE(eglCopyBuffers(dpy, surface, 0x3ffffe));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_PIXMAP);

  // A pixmap surface: glFinish brings what was drawn to the pixmap.
  const Pixmap pixmap = XCreatePixmap(x, win, 16, 16, 24);
  EGLSurface pix = eglCreatePixmapSurface(dpy, config, pixmap, nullptr);
  ASSERT_NE(pix, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(dpy, pix, pix, ctx));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  image = XGetImage(x, pixmap, 0, 0, 16, 16, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(XGetPixel(image, 8, 8) & 0xffffff, 0xff0000u);
  XDestroyImage(image);

  // A window destroyed under its surface: the swap goes on, as on Mesa, and
  // no X error reaches the program's handler (whose default would exit).
  const Window doomed = XCreateSimpleWindow(x, DefaultRootWindow(x), 0, 0, 16, 16, 0, 0, 0);
  XMapWindow(x, doomed);
  XSync(x, False);
  EGLSurface gone = eglCreateWindowSurface(dpy, config, doomed, nullptr);
  ASSERT_NE(gone, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(dpy, gone, gone, ctx));
  XDestroyWindow(x, doomed);
  XSync(x, False);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_TRUE(eglSwapBuffers(dpy, gone));
  glViewport(0, 0, 8, 8);
  EXPECT_TRUE(eglSwapBuffers(dpy, gone));
  XSync(x, False);
  EXPECT_TRUE(eglDestroySurface(dpy, gone));

  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroySurface(dpy, pix));
  EXPECT_TRUE(eglDestroySurface(dpy, surface));
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
  EXPECT_TRUE(eglTerminate(dpy));
  XFreePixmap(x, pixmap);
  XDestroyWindow(x, win);
}

}  // namespace
