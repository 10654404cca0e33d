// EGL displays (EGL 1.5 §3.2): the registry, eglInitialize and
// eglTerminate, handle validation, and binding a context to the thread.
#include <X11/Xutil.h>

#include <algorithm>
#include <cstdlib>

#include "pipeline/immediate_mode.h"
#include "platform/egl_objects.h"

namespace glfixed::platform::egl {

ThreadState& thread() {
  thread_local ThreadState state;
  return state;
}

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

namespace {

// Displays are never freed: an EGLDisplay stays a valid handle for the life
// of the process (§3.2), terminated or not. Not even at exit, when a context
// may still be current on a surface and the X connection may be gone.
std::vector<std::unique_ptr<EglDisplay>>& displays() {
  static auto* all = new std::vector<std::unique_ptr<EglDisplay>>;
  return *all;
}

EglDisplay* makeDisplay(Platform platform, void* nativeDisplay, int screen) {
  displays().push_back(std::make_unique<EglDisplay>());
  EglDisplay* d = displays().back().get();
  d->platform = platform;
  d->nativeDisplay = nativeDisplay;
  d->screen = screen;
  return d;
}

// A TrueColor visual of `depth` with the surfaces' byte order (x11_present.h);
// for depth 24 the screen's default visual when it is one, since that is the
// visual of the root window and of windows made without naming one.
Visual* findVisual(Display* x11, int screen, int depth) {
  auto usable = [](const Visual* v) {
    return v && v->c_class == TrueColor && v->red_mask == 0xff0000 && v->green_mask == 0xff00 &&
           v->blue_mask == 0xff;
  };
  Visual* def = DefaultVisual(x11, screen);
  if (depth == DefaultDepth(x11, screen) && usable(def)) return def;
  XVisualInfo info;
  if (XMatchVisualInfo(x11, screen, depth, TrueColor, &info) && usable(info.visual)) return info.visual;
  return nullptr;
}

}  // namespace

EglDisplay* findDisplay(EGLDisplay handle) {
  for (const auto& d : displays())
    if (d.get() == handle) return d.get();
  return fail(EGL_BAD_DISPLAY, nullptr);
}

EglDisplay* initializedDisplay(EGLDisplay handle) {
  EglDisplay* d = findDisplay(handle);
  if (d && !d->initialized) return fail(EGL_NOT_INITIALIZED, nullptr);
  return d;
}

EglDisplay* displayFor(Platform platform, void* nativeDisplay, int screen) {
  for (const auto& d : displays())
    if (d->platform == platform && d->nativeDisplay == nativeDisplay && d->screen == screen) return d.get();
  return makeDisplay(platform, nativeDisplay, screen);
}

EglDisplay* defaultDisplay() {
  static EglDisplay* chosen = nullptr;
  if (chosen) return chosen;
  const char* name = std::getenv("DISPLAY");
  Display* x11 = name && *name ? XOpenDisplay(nullptr) : nullptr;
  if (x11) {
    // The connection is the library's and stays open: the display may be
    // initialized again after eglTerminate.
    chosen = makeDisplay(Platform::kX11, x11, -1);
    chosen->x11 = x11;
    chosen->ownsX11 = true;
  } else {
    chosen = displayFor(Platform::kSurfaceless, nullptr, -1);
  }
  return chosen;
}

bool initialize(EglDisplay& d) {
  if (d.initialized) return true;
  if (d.platform == Platform::kX11) {
    if (d.nativeDisplay && !d.ownsX11) {
      d.x11 = static_cast<Display*>(d.nativeDisplay);
    } else if (!d.x11) {
      // EGL_DEFAULT_DISPLAY on the X11 platform: $DISPLAY, opened now and
      // kept for the next eglInitialize.
      d.x11 = XOpenDisplay(nullptr);
      d.ownsX11 = true;
      if (!d.x11) return false;
    }
    const int screen = d.screen >= 0 && d.screen < ScreenCount(d.x11) ? d.screen : DefaultScreen(d.x11);
    d.visual24 = findVisual(d.x11, screen, 24);
    d.visual32 = findVisual(d.x11, screen, 32);
  }
  d.initialized = true;
  return true;
}

namespace {

// Frees what was destroyed while bound and is bound no longer.
void reap(EglDisplay& d) {
  auto& contexts = d.doomedContexts;
  contexts.erase(std::remove_if(contexts.begin(), contexts.end(), [](const auto& c) { return !c->current; }),
                 contexts.end());
  auto& surfaces = d.doomedSurfaces;
  surfaces.erase(
      std::remove_if(surfaces.begin(), surfaces.end(), [](const auto& s) { return s->boundCount == 0; }),
      surfaces.end());
}

}  // namespace

void terminate(EglDisplay& d) {
  // §3.2: every handle of the display becomes invalid; what is current
  // somewhere stays alive until it is released.
  for (auto& c : d.contexts) {
    c->destroyed = true;
    d.doomedContexts.push_back(std::move(c));
  }
  for (auto& s : d.surfaces) {
    s->destroyed = true;
    d.doomedSurfaces.push_back(std::move(s));
  }
  d.contexts.clear();
  d.surfaces.clear();
  d.syncs.clear();
  reap(d);
  d.initialized = false;
}

EglSurface* findSurface(EglDisplay& d, EGLSurface handle) {
  for (const auto& s : d.surfaces)
    if (s.get() == handle) return s.get();
  return fail(EGL_BAD_SURFACE, nullptr);
}

EglContext* findContext(EglDisplay& d, EGLContext handle) {
  for (const auto& c : d.contexts)
    if (c.get() == handle) return c.get();
  return fail(EGL_BAD_CONTEXT, nullptr);
}

const FramebufferConfig* findConfig(EglDisplay& d, EGLConfig handle) {
  for (const FramebufferConfig* c : eglConfigs())
    if (c == handle) return c;
  return fail(EGL_BAD_CONFIG, nullptr);
}

namespace {

// Lets `c`'s GL context go of its surfaces without changing the thread's
// current GL context.
void letGoOfSurfaces(EglContext& c) {
  Context& gl = *c.context;
  if (c.draw) c.draw->surface->detach(&gl);
  if (c.read) c.read->surface->detach(&gl);
  bindSurfaces(gl, nullptr, nullptr);
}

}  // namespace

bool bindCurrent(EglContext* ctx, EglSurface* draw, EglSurface* read) {
  ThreadState& t = thread();
  EglContext* old = t.context;
  // OSMesaMakeCurrent may have made another context current on this thread
  // since: releasing the EGL context must leave that one current.
  const bool oldIsCurrentGL = old && currentContext() == old->context.get();
  if (old) {
    // eglMakeCurrent flushes the context it replaces (§3.7.3); what it drew
    // into a single-buffered window or a pixmap reaches it.
    pipeline::flushVertices(*old->context);
    if (old->draw && !old->draw->surface->doubleBuffered()) old->draw->surface->presentFront();
    if (!oldIsCurrentGL) letGoOfSurfaces(*old);
    old->current = false;
    if (old->draw) --old->draw->boundCount;
    if (old->read && old->read != old->draw) --old->read->boundCount;
    old->draw = old->read = nullptr;
  }
  bool bound = true;
  if (ctx || oldIsCurrentGL) {
    try {
      makeCurrent(ctx ? ctx->context.get() : nullptr, draw ? draw->surface.get() : nullptr,
                  read ? read->surface.get() : nullptr);
    } catch (const std::bad_alloc&) {
      // The depth buffer for the draw surface: nothing is bound then.
      bindSurfaces(*ctx->context, nullptr, nullptr);
      makeCurrent(nullptr, nullptr, nullptr);
      ctx = nullptr;
      bound = false;
    }
  }
  t.context = ctx;
  if (ctx) {
    ctx->current = true;
    ctx->draw = draw;
    ctx->read = read;
    if (draw) ++draw->boundCount;
    if (read && read != draw) ++read->boundCount;
  }
  if (old) reap(*old->display);  // may free `old`
  return bound;
}

}  // namespace glfixed::platform::egl
