// GLX (platform/glx*.cpp) on a private Xvfb: configurations, contexts,
// current drawables, swaps, pixmaps, pbuffers, glXGetProcAddress, errors.
// Skipped where no Xvfb binary exists. The comparison of whole programs with
// Mesa is tests/programs/'s; these check behaviour that can fail here.
// gtest first: X11 headers define None, Bool, Status as macros.
#include <GL/gl.h>
#include <gtest/gtest.h>
#define GLX_GLXEXT_PROTOTYPES
#include <GL/glx.h>
#include <X11/Xutil.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

int gXErrors = 0;
int countXError(Display*, XErrorEvent*) {
  ++gXErrors;
  return 0;
}

std::string findXvfb() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"}) {
    std::string p = std::string(dir) + "/Xvfb";
    if (access(p.c_str(), X_OK) == 0) return p;
  }
  return {};
}

class GlxTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string xvfb = findXvfb();
    if (xvfb.empty()) GTEST_SKIP() << "no Xvfb";
    // Displays :61 to :65 (a lock file says one is taken).
    for (int n = 61; n <= 65 && !dpy_; ++n) {
      const std::string lock = "/tmp/.X" + std::to_string(n) + "-lock";
      if (access(lock.c_str(), F_OK) == 0) continue;
      const std::string name = ":" + std::to_string(n);
      pid_ = fork();
      if (pid_ == 0) {
        // The server ends with the test, and keeps none of its output pipes.
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        const int null = open("/dev/null", O_RDWR);
        dup2(null, 1);
        dup2(null, 2);
        execl(xvfb.c_str(), "Xvfb", name.c_str(), "-screen", "0", "320x240x24", "-nolisten", "tcp", nullptr);
        _exit(127);
      }
      for (int i = 0; i < 100 && !dpy_; ++i) {
        usleep(50000);
        int status;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {  // lost the race for this number
          pid_ = -1;
          break;
        }
        dpy_ = XOpenDisplay(name.c_str());
      }
      if (!dpy_ && pid_ > 0) stopServer();
    }
    if (!dpy_) GTEST_SKIP() << "no free display among :61-:65";
    gXErrors = 0;
    XSetErrorHandler(countXError);
  }

  void TearDown() override {
    if (dpy_) {
      glXMakeCurrent(dpy_, None, nullptr);
      XCloseDisplay(dpy_);
    }
    stopServer();
    EXPECT_EQ(gXErrors, 0) << "an X error reached the program's handler";
  }

  void stopServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    pid_ = -1;
  }

  XVisualInfo* chooseVisual(std::initializer_list<int> attributes) {
    std::vector<int> list(attributes);
    list.push_back(None);
    return glXChooseVisual(dpy_, DefaultScreen(dpy_), list.data());
  }

  // A mapped window of `vis`, shown (Expose received).
  Window makeWindow(XVisualInfo* vis, int width, int height) {
    const Window root = RootWindow(dpy_, vis->screen);
    XSetWindowAttributes a{};
    a.colormap = XCreateColormap(dpy_, root, vis->visual, AllocNone);
    a.border_pixel = 0;
    a.background_pixel = 0x0000ff;  // blue until GL draws
    a.event_mask = ExposureMask | StructureNotifyMask;
    const Window w = XCreateWindow(dpy_, root, 0, 0, width, height, 0, vis->depth, InputOutput, vis->visual,
                                   CWColormap | CWBorderPixel | CWBackPixel | CWEventMask, &a);
    XMapWindow(dpy_, w);
    XEvent e;
    do XNextEvent(dpy_, &e);
    while (e.type != Expose);
    return w;
  }

  unsigned long pixelAt(Drawable d, int x, int y) {
    XSync(dpy_, False);
    XImage* image = XGetImage(dpy_, d, x, y, 1, 1, AllPlanes, ZPixmap);
    if (!image) return ~0ul;
    const unsigned long p = XGetPixel(image, 0, 0) & 0xffffff;
    XDestroyImage(image);
    return p;
  }

  int config(XVisualInfo* vis, int attribute) {
    int v = -1;
    EXPECT_EQ(glXGetConfig(dpy_, vis, attribute, &v), Success) << attribute;
    return v;
  }

  Display* dpy_ = nullptr;
  pid_t pid_ = -1;
};

TEST_F(GlxTest, ChooseVisualFollowsTheAttributes) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_RED_SIZE, 1, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_USE_GL), True);
  EXPECT_EQ(config(vis, GLX_RGBA), True);
  EXPECT_EQ(config(vis, GLX_DOUBLEBUFFER), True);
  EXPECT_EQ(config(vis, GLX_RED_SIZE), 8);
  EXPECT_EQ(config(vis, GLX_DEPTH_SIZE), 24);   // the largest depth of at least 1
  EXPECT_EQ(config(vis, GLX_STENCIL_SIZE), 0);  // the smallest stencil
  EXPECT_EQ(config(vis, GLX_ALPHA_SIZE), 0);
  EXPECT_EQ(config(vis, GLX_X_VISUAL_TYPE), GLX_TRUE_COLOR);
  EXPECT_EQ(vis->depth, 24);
  int v;
  EXPECT_EQ(glXGetConfig(dpy_, vis, 0x7777, &v), GLX_BAD_ATTRIBUTE);
  XFree(vis);

  // Without GLX_DOUBLEBUFFER only single-buffered visuals match.
  vis = chooseVisual({GLX_RGBA});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_DOUBLEBUFFER), False);
  EXPECT_EQ(config(vis, GLX_DEPTH_SIZE), 0);
  XFree(vis);

  vis = chooseVisual({GLX_RGBA, GLX_ALPHA_SIZE, 1, GLX_STENCIL_SIZE, 1});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_ALPHA_SIZE), 8);
  EXPECT_EQ(config(vis, GLX_STENCIL_SIZE), 8);
  EXPECT_EQ(vis->depth, 32);
  XFree(vis);

  EXPECT_EQ(chooseVisual({GLX_RGBA, GLX_STEREO}), nullptr);
  // Without an accumulation buffer asked for, none of the accumulation
  // configurations (GLX_SLOW_CONFIG, as Mesa's) comes first.
  vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_ACCUM_RED_SIZE), 0);
  XFree(vis);
  // As Mesa: no GLX_RGBA still gives an RGBA visual; an unknown attribute
  // is skipped with its value.
  vis = chooseVisual({GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_RGBA), True);
  EXPECT_EQ(config(vis, GLX_DOUBLEBUFFER), True);
  XFree(vis);
  vis = chooseVisual({GLX_RGBA, 0x7777, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_DOUBLEBUFFER), False);  // GLX_DOUBLEBUFFER was 0x7777's value
  EXPECT_EQ(config(vis, GLX_DEPTH_SIZE), 24);
  XFree(vis);
}

// Mesa's GLX offers every configuration also with a 16-bit accumulation
// buffer (caveat GLX_SLOW_CONFIG); a context made with one has the buffer.
TEST_F(GlxTest, AccumulationBufferConfigs) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, GLX_ACCUM_RED_SIZE, 1});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_ACCUM_RED_SIZE), 16);
  EXPECT_EQ(config(vis, GLX_ACCUM_ALPHA_SIZE), 16);
  EXPECT_EQ(config(vis, GLX_DOUBLEBUFFER), True);
  const Window win = makeWindow(vis, 16, 16);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  GLint bits = 0;
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
  EXPECT_EQ(bits, 16);
  glClearColor(0.5f, 0.5f, 0.5f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLubyte px[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_NEAR(px[0], 64, 1);
  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  glXDestroyContext(dpy_, ctx);
  XFree(vis);

  int n = 0;
  const int slow[] = {GLX_CONFIG_CAVEAT, GLX_SLOW_CONFIG, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, slow, &n);
  ASSERT_NE(configs, nullptr);
  for (int i = 0; i < n; ++i) {
    int v = 0;
    glXGetFBConfigAttrib(dpy_, configs[i], GLX_ACCUM_GREEN_SIZE, &v);
    EXPECT_EQ(v, 16);
  }
  XFree(configs);
  // A context without one: glAccum is GL_INVALID_OPERATION.
  vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(config(vis, GLX_ACCUM_RED_SIZE), 0);
  const Window plain = makeWindow(vis, 16, 16);
  ctx = glXCreateContext(dpy_, vis, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy_, plain, ctx));
  glAccum(GL_LOAD, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  glXDestroyContext(dpy_, ctx);
  XFree(vis);
}

TEST_F(GlxTest, ChooseFBConfigSortsAndFilters) {
  int n = 0;
  const int all[] = {None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, all, &n);
  ASSERT_NE(configs, nullptr);
  ASSERT_GT(n, 1);
  auto attrib = [&](GLXFBConfig c, int a) {
    int v = -1;
    EXPECT_EQ(glXGetFBConfigAttrib(dpy_, c, a, &v), Success);
    return v;
  };
  // Mesa's order: no alpha first, single before double buffering.
  EXPECT_EQ(attrib(configs[0], GLX_ALPHA_SIZE), 0);
  EXPECT_EQ(attrib(configs[0], GLX_DOUBLEBUFFER), False);
  for (int i = 0; i < n; ++i) EXPECT_TRUE(attrib(configs[i], GLX_DRAWABLE_TYPE) & GLX_WINDOW_BIT);
  XFree(configs);

  const int wanted[] = {GLX_DOUBLEBUFFER,
                        True,
                        GLX_DEPTH_SIZE,
                        16,
                        GLX_STENCIL_SIZE,
                        8,
                        GLX_RENDER_TYPE,
                        GLX_RGBA_BIT,
                        GLX_X_RENDERABLE,
                        True,
                        None};
  configs = glXChooseFBConfig(dpy_, 0, wanted, &n);
  ASSERT_NE(configs, nullptr);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(attrib(configs[i], GLX_DOUBLEBUFFER), True);
    EXPECT_GE(attrib(configs[i], GLX_DEPTH_SIZE), 16);
    EXPECT_GE(attrib(configs[i], GLX_STENCIL_SIZE), 8);
    XVisualInfo* vis = glXGetVisualFromFBConfig(dpy_, configs[i]);
    ASSERT_NE(vis, nullptr);
    EXPECT_EQ(static_cast<int>(vis->visualid), attrib(configs[i], GLX_VISUAL_ID));
    XFree(vis);
  }
  int v;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], 0x7777, &v), GLX_BAD_ATTRIBUTE);
  // GLX_FBCONFIG_ID alone decides.
  const int id = attrib(configs[0], GLX_FBCONFIG_ID);
  XFree(configs);
  const int byId[] = {GLX_FBCONFIG_ID, id, GLX_DOUBLEBUFFER, False, None};
  configs = glXChooseFBConfig(dpy_, 0, byId, &n);
  ASSERT_EQ(n, 1);
  EXPECT_EQ(attrib(configs[0], GLX_FBCONFIG_ID), id);
  XFree(configs);

  const int unknown[] = {0x7777, 1, GLX_DOUBLEBUFFER, True, None};  // skipped, as Mesa does
  configs = glXChooseFBConfig(dpy_, 0, unknown, &n);
  ASSERT_GT(n, 0);
  EXPECT_EQ(attrib(configs[0], GLX_DOUBLEBUFFER), True);
  XFree(configs);
  const int stereo[] = {GLX_STEREO, True, None};
  EXPECT_EQ(glXChooseFBConfig(dpy_, 0, stereo, &n), nullptr);
  EXPECT_EQ(n, 0);
}

TEST_F(GlxTest, TheClearedColourReachesTheWindowAtTheSwapNotBefore) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 24});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 64, 48);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  EXPECT_EQ(glXGetCurrentDrawable(), win);
  EXPECT_EQ(glXGetCurrentDisplay(), dpy_);
  GLboolean db = GL_FALSE;
  glGetBooleanv(GL_DOUBLEBUFFER, &db);
  EXPECT_EQ(db, GL_TRUE);
  GLint drawBuffer = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  EXPECT_EQ(drawBuffer, GL_BACK);
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 64);
  EXPECT_EQ(viewport[3], 48);

  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(pixelAt(win, 10, 10), 0x0000ffu);  // the back buffer is not shown
  glXSwapBuffers(dpy_, win);
  EXPECT_EQ(pixelAt(win, 10, 10), 0xff0000u);
  EXPECT_EQ(pixelAt(win, 63, 47), 0xff0000u);

  // A lit triangle over a green background, drawn in the back buffer.
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_EQ(pixelAt(win, 32, 30), 0xff0000u);
  glXSwapBuffers(dpy_, win);
  // Default light 0 on the default material: 0.2*0.2 + 0.8*1.0 = 0.84 grey.
  const unsigned long lit = pixelAt(win, 32, 30);
  EXPECT_EQ(lit, 0xd6d6d6u) << std::hex << lit;
  EXPECT_EQ(pixelAt(win, 1, 1), 0x00ff00u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  EXPECT_EQ(glXGetCurrentDrawable(), static_cast<GLXDrawable>(None));
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, SingleBufferedDrawingShowsAtGlFlush) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 32, 32);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  GLint drawBuffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  EXPECT_EQ(drawBuffer, GL_FRONT);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(pixelAt(win, 5, 5), 0xffff00u);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, TheSurfaceFollowsAResizedWindow) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 40, 30);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  XResizeWindow(dpy_, win, 100, 80);
  XSync(dpy_, False);
  glViewport(0, 0, 100, 80);  // where the window's size is looked at again
  glClearColor(0, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  EXPECT_EQ(pixelAt(win, 99, 79), 0x00ffffu);
  unsigned width = 0;
  glXQueryDrawable(dpy_, win, GLX_WIDTH, &width);
  EXPECT_EQ(width, 100u);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, PbufferAndPixmapDrawables) {
  const int attrs[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT | GLX_PIXMAP_BIT, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attrs, &n);
  ASSERT_GT(n, 0);
  GLXFBConfig config = configs[0];
  XFree(configs);
  GLXContext ctx = glXCreateNewContext(dpy_, config, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);

  const int size[] = {GLX_PBUFFER_WIDTH, 24, GLX_PBUFFER_HEIGHT, 16, None};
  GLXPbuffer pbuffer = glXCreatePbuffer(dpy_, config, size);
  ASSERT_NE(pbuffer, static_cast<GLXPbuffer>(None));
  unsigned w = 0, h = 0;
  glXQueryDrawable(dpy_, pbuffer, GLX_WIDTH, &w);
  glXQueryDrawable(dpy_, pbuffer, GLX_HEIGHT, &h);
  EXPECT_EQ(w, 24u);
  EXPECT_EQ(h, 16u);
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, pbuffer, pbuffer, ctx));
  EXPECT_EQ(glXGetCurrentReadDrawable(), pbuffer);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte rgba[4] = {};
  glReadPixels(23, 15, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 0);
  EXPECT_EQ(rgba[2], 255);

  XVisualInfo* vis = glXGetVisualFromFBConfig(dpy_, config);
  ASSERT_NE(vis, nullptr);
  const Pixmap pixmap = XCreatePixmap(dpy_, RootWindow(dpy_, 0), 16, 16, vis->depth);
  GLXPixmap glxPixmap = glXCreatePixmap(dpy_, config, pixmap, nullptr);
  ASSERT_NE(glxPixmap, static_cast<GLXPixmap>(None));
  ASSERT_TRUE(glXMakeCurrent(dpy_, glxPixmap, ctx));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(pixelAt(pixmap, 15, 15), 0x00ff00u);

  // The older entry point on the same pixmap.
  GLXPixmap old = glXCreateGLXPixmap(dpy_, vis, pixmap);
  ASSERT_NE(old, static_cast<GLXPixmap>(None));
  ASSERT_TRUE(glXMakeCurrent(dpy_, old, ctx));
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXWaitGL();
  EXPECT_EQ(pixelAt(pixmap, 0, 0), 0xff00ffu);
  XFree(vis);

  // Destroyed while current: still drawn into until released.
  glXDestroyGLXPixmap(dpy_, old);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  glXDestroyPixmap(dpy_, glxPixmap);
  glXDestroyPbuffer(dpy_, pbuffer);
  XFreePixmap(dpy_, pixmap);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, ContextsShareDisplayListsAndFailQuietly) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 16, 16);
  GLXContext a = glXCreateContext(dpy_, vis, nullptr, True);
  GLXContext b = glXCreateContext(dpy_, vis, a, True);
  GLXContext c = glXCreateContext(dpy_, vis, nullptr, True);
  ASSERT_TRUE(a && b && c);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, a));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEndList();
  glClearColor(0.5f, 0.25f, 1, 1);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, b));
  EXPECT_TRUE(glIsList(list));
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, c));
  EXPECT_FALSE(glIsList(list));

  // glXCopyContext: a's clear colour into b (not current).
  glXCopyContext(dpy_, a, b, GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, b));
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_FLOAT_EQ(clear[1], 0.25f);

  // Failures return False and raise no X error in the program.
  EXPECT_FALSE(glXMakeCurrent(dpy_, 0x7ffffff, a));  // not a drawable
  EXPECT_FALSE(glXMakeCurrent(dpy_, win, nullptr));  // BadMatch
  EXPECT_EQ(glXGetCurrentContext(), b);
  int id = 0;
  EXPECT_EQ(glXQueryContext(dpy_, b, GLX_SCREEN, &id), Success);
  EXPECT_EQ(glXQueryContext(dpy_, b, 0x7777, &id), GLX_BAD_ATTRIBUTE);

  // Destroyed while current: still current until released.
  glXDestroyContext(dpy_, b);
  EXPECT_EQ(glXGetCurrentContext(), b);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, a));
  EXPECT_EQ(glXGetCurrentContext(), a);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, a);
  glXDestroyContext(dpy_, c);
  XFree(vis);
}

TEST_F(GlxTest, CreateContextAttribsGivesAtMostTheLibrarysVersion) {
  auto create = reinterpret_cast<PFNGLXCREATECONTEXTATTRIBSARBPROC>(
      glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
  ASSERT_NE(create, nullptr);
  int n = 0;
  const int db[] = {GLX_DOUBLEBUFFER, True, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, db, &n);
  ASSERT_GT(n, 0);
  // The library is GL 1.5 (no GLSL, api/gl_version.h).
  const int v15[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5, None};
  GLXContext ctx = create(dpy_, configs[0], nullptr, True, v15);
  EXPECT_NE(ctx, nullptr);
  const int v20[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, v20), nullptr);
  const int v32core[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
                         GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, v32core), nullptr);
  const int v30[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, v30), nullptr);
  const int v16[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 6, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, v16), nullptr);
  const int badProfile[] = {GLX_CONTEXT_PROFILE_MASK_ARB, 0x40, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, badProfile), nullptr);
  const int unknown[] = {0x7777, 1, None};
  EXPECT_EQ(create(dpy_, configs[0], nullptr, True, unknown), nullptr);
  XFree(configs);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, ProcAddressesAndStrings) {
  auto proc = [](const char* name) { return glXGetProcAddress(reinterpret_cast<const GLubyte*>(name)); };
  EXPECT_EQ(proc("glXSwapBuffers"), reinterpret_cast<__GLXextFuncPtr>(&glXSwapBuffers));
  EXPECT_EQ(proc("glXCreateContextAttribsARB"),
            reinterpret_cast<__GLXextFuncPtr>(&glXCreateContextAttribsARB));
  EXPECT_EQ(proc("glClear"), reinterpret_cast<__GLXextFuncPtr>(&glClear));
  EXPECT_EQ(proc("glXNoSuchFunction"), nullptr);
  EXPECT_EQ(proc("glNoSuchFunction"), nullptr);
  EXPECT_STREQ(glXGetClientString(dpy_, GLX_VENDOR), "libglfixed");
  EXPECT_STREQ(glXGetClientString(dpy_, GLX_VERSION), "1.4");
  EXPECT_STREQ(glXQueryServerString(dpy_, 0, GLX_VENDOR), "libglfixed");
  const std::string ext = glXQueryExtensionsString(dpy_, 0);
  EXPECT_NE(ext.find("GLX_ARB_create_context "), std::string::npos);
  EXPECT_NE(ext.find("GLX_ARB_get_proc_address"), std::string::npos);
  int major = 0, minor = 0, errorBase = -1, eventBase = -1;
  EXPECT_TRUE(glXQueryVersion(dpy_, &major, &minor));
  EXPECT_EQ(major * 10 + minor, 14);
  EXPECT_TRUE(glXQueryExtension(dpy_, &errorBase, &eventBase));
}

TEST_F(GlxTest, UseXFontMakesListsThatAdvanceTheRasterPosition) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 32, 32);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  XFontStruct* font = XLoadQueryFont(dpy_, "fixed");
  if (!font) GTEST_SKIP() << "the X server has no font 'fixed'";
  const GLuint base = glGenLists(96);
  glXUseXFont(font->fid, 32, 96, base);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(glIsList(base + 'A' - 32));
  // The space has no ink: its list is a glBitmap of no pixels that moves the
  // raster position by the glyph's advance. (A glyph with ink records
  // GL_INVALID_OPERATION until glBitmap draws: issue 15.)
  auto advance = [&](unsigned c) {
    return font->per_char ? font->per_char[c - font->min_char_or_byte2].width : font->max_bounds.width;
  };
  ASSERT_GT(advance(' '), 0);
  glRasterPos2f(-1, 0);
  GLfloat before[4], after[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, before);
  glCallList(base + ' ' - 32);
  glCallList(base + ' ' - 32);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, after);
  EXPECT_FLOAT_EQ(after[0] - before[0], 2.0f * advance(' '));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  XFreeFont(dpy_, font);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, SwapIntervalSpacesSwaps) {
  EXPECT_EQ(glXSwapIntervalMESA(1), GLX_BAD_CONTEXT);  // no current context
  EXPECT_EQ(glXSwapIntervalSGI(1), GLX_BAD_CONTEXT);
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 16, 16);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  unsigned interval = 99;
  glXQueryDrawable(dpy_, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 0u);
  glXSwapIntervalEXT(dpy_, win, 2);
  glXQueryDrawable(dpy_, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 2u);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 2);
  EXPECT_EQ(glXSwapIntervalSGI(0), GLX_BAD_VALUE);
  glXSwapBuffers(dpy_, win);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 4; ++i) glXSwapBuffers(dpy_, win);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(ms, 4 * 2 * 16.0);  // four swaps, two 60 Hz periods apart
  EXPECT_EQ(glXSwapIntervalMESA(0), 0);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 0);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, GlxWindowDrawsLikeItsWindow) {
  const int attrs[] = {GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attrs, &n);
  ASSERT_GT(n, 0);
  XVisualInfo* vis = glXGetVisualFromFBConfig(dpy_, configs[0]);
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 20, 20);
  XFree(vis);
  GLXWindow glxWin = glXCreateWindow(dpy_, configs[0], win, nullptr);
  ASSERT_NE(glxWin, static_cast<GLXWindow>(None));
  EXPECT_EQ(glXCreateWindow(dpy_, configs[0], win, nullptr), static_cast<GLXWindow>(None));  // one per window
  GLXContext ctx = glXCreateNewContext(dpy_, configs[0], GLX_RGBA_TYPE, nullptr, True);
  XFree(configs);
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, glxWin, glxWin, ctx));
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, glxWin);
  EXPECT_EQ(pixelAt(win, 19, 19), 0xff00ffu);
  // Destroyed while current: drawn into and swapped until released.
  glXDestroyWindow(dpy_, glxWin);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, glxWin);
  EXPECT_EQ(pixelAt(win, 0, 0), 0x00ff00u);
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, None, None, nullptr));
  glXDestroyContext(dpy_, ctx);
}

TEST_F(GlxTest, AWindowDestroyedUnderTheContextFailsQuietly) {
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  const Window win = makeWindow(vis, 20, 20);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  XFree(vis);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  XDestroyWindow(dpy_, win);
  XSync(dpy_, False);
  for (int i = 0; i < 3; ++i) {
    glClear(GL_COLOR_BUFFER_BIT);
    glViewport(0, 0, 20, 20);
    glXSwapBuffers(dpy_, win);
  }
  glDrawBuffer(GL_FRONT);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  glXWaitGL();
  EXPECT_EQ(gXErrors, 0);
  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  glXDestroyContext(dpy_, ctx);
}

long residentKilobytes() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long kb = -1;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "VmRSS:", 6) == 0) kb = std::atol(line + 6);
  std::fclose(f);
  return kb;
}

TEST_F(GlxTest, TheBuffersOfDestroyedWindowsAreLetGo) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed memory resident";
#endif
  XVisualInfo* vis = chooseVisual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vis, nullptr);
  GLXContext ctx = glXCreateContext(dpy_, vis, nullptr, True);
  long before = 0;
  // 80 windows of 512x512, double-buffered: 160 MB if every surface stayed.
  for (int i = 0; i < 80; ++i) {
    const Window win = makeWindow(vis, 512, 512);
    ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy_, win);
    ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
    XDestroyWindow(dpy_, win);
    if (i == 4) before = residentKilobytes();
  }
  const long after = residentKilobytes();
  ASSERT_GT(before, 0);
  EXPECT_LT(after - before, 32 * 1024) << before << " kB, then " << after << " kB";
  glXDestroyContext(dpy_, ctx);
  XFree(vis);
}

}  // namespace
