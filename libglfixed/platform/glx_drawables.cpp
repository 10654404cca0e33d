// GLX drawables (GLX 1.4 §3.3.4-3.3.7, §3.3.11): X windows, GLXWindows,
// GLX pixmaps and pbuffers, each with the Surface that holds its colour
// buffers; glXSwapBuffers; glXQueryDrawable and the GLX events.
#include <X11/Xutil.h>

#include <thread>

#include "pipeline/immediate_mode.h"
#include "pipeline/pixel_rect.h"
#include "platform/glx_internal.h"
#include "platform/x11_error_trap.h"
#include "platform/x11_present.h"

namespace glfixed::platform::glx {

namespace {

// A window's or pixmap's surface: the drawable's size now, presented to it.
std::shared_ptr<Surface> x11Surface(Display* display, Drawable drawable, Visual* visual, bool doubleBuffered,
                                    const FBConfig& config) {
  int width, height, depth;
  if (!x11DrawableSize(display, drawable, &width, &height, &depth)) return nullptr;
  std::unique_ptr<Presenter> presenter = makeX11Presenter(display, drawable, visual);
  if (!presenter) return nullptr;
  return std::make_shared<Surface>(width, height, doubleBuffered, config.config->alphaBits,
                                   std::move(presenter));
}

bool isWindow(Display* display, Window window) {
  XWindowAttributes attributes;
  ErrorTrap trap(display);
  const Status ok = XGetWindowAttributes(display, window, &attributes);
  return !trap.failed() && ok;
}

Visual* visualOf(Display* display, const FBConfig& config) {
  XVisualInfo* info = visualInfoFor(display, config);
  if (!info) return nullptr;
  Visual* v = info->visual;
  XFree(info);
  return v;
}

GLXDrawable addDrawable(DisplayState& ds, std::shared_ptr<GlxDrawable> d) {
  const GLXDrawable id = d->id;
  ds.drawables[id] = std::move(d);
  return id;
}

// GLX 1.4 §3.3.5: the pixmap's surface; `visual` is the one it was made for.
GLXPixmap createPixmap(Display* dpy, const FBConfig* config, Pixmap pixmap) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !config || !config->visualId) return None;
  Visual* visual = visualOf(dpy, *config);
  auto surface = visual ? x11Surface(dpy, pixmap, visual, false, *config) : nullptr;
  if (!surface) return None;  // not a pixmap of the configuration's depth
  auto d = std::make_shared<GlxDrawable>();
  d->kind = GlxDrawable::Kind::kGlxPixmap;
  d->id = newDrawableId(dpy);
  d->x11 = pixmap;
  d->config = config;
  d->surface = std::move(surface);
  return addDrawable(*ds, std::move(d));
}

void destroy(Display* dpy, XID id, GlxDrawable::Kind kind) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds) return;
  auto it = ds->drawables.find(id);
  // The surface lives on while a context still draws to it (shared_ptr).
  if (it != ds->drawables.end() && it->second->kind == kind) ds->drawables.erase(it);
}

// GLX_EXT_swap_control and friends. There is no vertical retrace to wait for
// on a surface the library draws itself; a swap interval N > 0 spaces swaps
// N periods of a nominal 60 Hz display apart. The interval starts at 0, as
// measured on Mesa's llvmpipe under Xvfb (glxgears reports no
// synchronisation there and swaps as fast as it draws).
constexpr int kMaxSwapInterval = 8;
constexpr std::chrono::microseconds kRefreshPeriod(16667);

void paceSwap(GlxDrawable& d) {
  const auto now = std::chrono::steady_clock::now();
  if (d.swapInterval > 0) {
    const auto due = d.lastSwap + d.swapInterval * kRefreshPeriod;
    if (due > now) {
      std::this_thread::sleep_until(due);
      d.lastSwap = due;
      return;
    }
  }
  d.lastSwap = now;
}

// The drawable the calling thread's GLX context draws into, or null.
std::shared_ptr<GlxDrawable> currentDrawable() {
  __GLXcontextRec* c = currentGlxContext();
  return c ? c->draw : nullptr;
}

// X tells no one when a window is destroyed: the surfaces of windows used
// directly (not GLXWindows, which glXDestroyWindow ends) that no context
// holds any more are dropped once their window is gone, each time a new
// window appears, so that a program making many windows does not keep the
// buffers of all of them.
void forgetDestroyedWindows(DisplayState& ds) {
  for (auto it = ds.drawables.begin(); it != ds.drawables.end();) {
    int width, height, depth;
    if (it->second->kind == GlxDrawable::Kind::kWindow && it->second.use_count() == 1 &&
        !x11DrawableSize(ds.display, it->second->x11, &width, &height, &depth))
      it = ds.drawables.erase(it);
    else
      ++it;
  }
}

}  // namespace

std::shared_ptr<GlxDrawable> drawableFor(DisplayState& ds, GLXDrawable id, const FBConfig* config) {
  auto it = ds.drawables.find(id);
  if (it != ds.drawables.end()) {
    // A GLX drawable made for one configuration serves only contexts of
    // that configuration's buffers (a window seen first keeps the buffering
    // of its first context's configuration).
    return it->second;
  }
  if (!config || !isWindow(ds.display, id)) return nullptr;
  forgetDestroyedWindows(ds);
  auto surface = x11Surface(ds.display, id, nullptr, config->config->doubleBuffered, *config);
  if (!surface) return nullptr;
  auto d = std::make_shared<GlxDrawable>();
  d->kind = GlxDrawable::Kind::kWindow;
  d->id = d->x11 = id;
  d->config = config;
  d->surface = std::move(surface);
  ds.drawables[id] = d;
  return d;
}

}  // namespace glfixed::platform::glx

using namespace glfixed::platform::glx;
using glfixed::platform::Surface;

extern "C" {

GLAPI void APIENTRY glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  std::shared_ptr<GlxDrawable> d;
  {
    std::lock_guard<std::recursive_mutex> lock(glxMutex());
    DisplayState* ds = displayState(dpy);
    if (!ds) return;
    auto it = ds->drawables.find(drawable);
    if (it != ds->drawables.end()) d = it->second;
  }
  __GLXcontextRec* current = currentGlxContext();
  // A drawable destroyed while current is still the current context's.
  if (!d && current && current->draw && current->draw->id == drawable) d = current->draw;
  if (!d || !d->surface) return;  // GLXBadDrawable; a window never made current has nothing to show
  // The current context's buffered vertices belong in the back buffer first
  // (GLX 1.4 §3.3.11: an implicit glFlush).
  if (current && current->draw == d) {
    glfixed::pipeline::flushVertices(current->context);
    glfixed::pipeline::flushBitmapCache(current->context);
  }
  paceSwap(*d);
  d->surface->swapBuffers();
}

GLAPI GLXWindow APIENTRY glXCreateWindow(Display* dpy, GLXFBConfig config, Window win,
                                         const int* attribList) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !isConfigOf(*ds, config) || !config->visualId) return None;
  // BadAlloc if a GLXWindow exists for it already; a window used directly
  // before becomes the GLXWindow (a context still bound keeps its surface).
  auto existing = ds->drawables.find(win);
  if (existing != ds->drawables.end() && existing->second->kind != GlxDrawable::Kind::kWindow) return None;
  auto surface =
      isWindow(dpy, win) ? x11Surface(dpy, win, nullptr, config->config->doubleBuffered, *config) : nullptr;
  if (!surface) return None;
  auto d = std::make_shared<GlxDrawable>();
  d->kind = GlxDrawable::Kind::kGlxWindow;
  d->id = d->x11 = win;  // as Mesa's xlib GLX: the window's own id
  d->config = config;
  d->surface = std::move(surface);
  return addDrawable(*ds, std::move(d));
}

GLAPI void APIENTRY glXDestroyWindow(Display* dpy, GLXWindow window) {
  destroy(dpy, window, GlxDrawable::Kind::kGlxWindow);
}

GLAPI GLXPixmap APIENTRY glXCreateGLXPixmap(Display* dpy, XVisualInfo* visual, Pixmap pixmap) {
  const FBConfig* config = nullptr;
  {
    std::lock_guard<std::recursive_mutex> lock(glxMutex());
    DisplayState* ds = displayState(dpy);
    if (ds) config = configForVisual(*ds, visual);
  }
  return createPixmap(dpy, config, pixmap);
}

GLAPI void APIENTRY glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap) {
  destroy(dpy, pixmap, GlxDrawable::Kind::kGlxPixmap);
}

GLAPI GLXPixmap APIENTRY glXCreatePixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap,
                                         const int* attribList) {
  {
    std::lock_guard<std::recursive_mutex> lock(glxMutex());
    DisplayState* ds = displayState(dpy);
    if (!ds || !isConfigOf(*ds, config)) return None;
  }
  return createPixmap(dpy, config, pixmap);
}

GLAPI void APIENTRY glXDestroyPixmap(Display* dpy, GLXPixmap pixmap) {
  destroy(dpy, pixmap, GlxDrawable::Kind::kGlxPixmap);
}

GLAPI GLXPbuffer APIENTRY glXCreatePbuffer(Display* dpy, GLXFBConfig config, const int* attribList) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !isConfigOf(*ds, config)) return None;
  auto d = std::make_shared<GlxDrawable>();
  for (int i = 0; attribList && attribList[i] != None; i += 2) {
    const int v = attribList[i + 1];
    switch (attribList[i]) {
      case GLX_PBUFFER_WIDTH: d->width = v; break;
      case GLX_PBUFFER_HEIGHT: d->height = v; break;
      case GLX_PRESERVED_CONTENTS: d->preserved = v != False; break;
      case GLX_LARGEST_PBUFFER: d->largest = v != False; break;
      default: return None;  // BadMatch
    }
  }
  const int max = glfixed::kMaxViewportSize;
  if (d->width < 0 || d->height < 0) return None;
  if (d->width > max || d->height > max) {
    if (!d->largest) return None;  // BadAlloc
    d->width = std::min(d->width, max);
    d->height = std::min(d->height, max);
  }
  d->kind = GlxDrawable::Kind::kPbuffer;
  d->id = newDrawableId(dpy);
  d->config = config;
  // A 0x0 pbuffer (the defaults) is allowed; its surface holds one pixel.
  d->surface = std::make_shared<Surface>(std::max(d->width, 1), std::max(d->height, 1),
                                         config->config->doubleBuffered, config->config->alphaBits, nullptr);
  return addDrawable(*ds, std::move(d));
}

GLAPI void APIENTRY glXDestroyPbuffer(Display* dpy, GLXPbuffer pbuf) {
  destroy(dpy, pbuf, GlxDrawable::Kind::kPbuffer);
}

GLAPI void APIENTRY glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute, unsigned int* value) {
  if (!value) return;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds) return;
  std::shared_ptr<GlxDrawable> d;
  auto it = ds->drawables.find(draw);
  if (it != ds->drawables.end()) d = it->second;
  int width = 0, height = 0, depth = 0;
  if (d && d->kind == GlxDrawable::Kind::kPbuffer) {
    width = d->width;
    height = d->height;
  } else if (!glfixed::platform::x11DrawableSize(dpy, d ? d->x11 : draw, &width, &height, &depth)) {
    return;  // GLXBadDrawable
  }
  switch (attribute) {
    case GLX_WIDTH: *value = width; break;
    case GLX_HEIGHT: *value = height; break;
    case GLX_PRESERVED_CONTENTS: *value = d ? d->preserved : True; break;
    case GLX_LARGEST_PBUFFER: *value = d ? d->largest : False; break;
    case GLX_FBCONFIG_ID: *value = d && d->config ? d->config->id() : 0; break;
    case GLX_SWAP_INTERVAL_EXT: *value = d ? d->swapInterval : 0; break;
    case GLX_MAX_SWAP_INTERVAL_EXT: *value = kMaxSwapInterval; break;
    default: break;  // BadValue: *value is left alone
  }
}

// No GLX_PBUFFER_CLOBBER event is ever sent: the library never takes a
// pbuffer's memory back. The mask is kept for glXGetSelectedEvent.
GLAPI void APIENTRY glXSelectEvent(Display* dpy, GLXDrawable draw, unsigned long eventMask) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds) return;
  auto it = ds->drawables.find(draw);
  if (it != ds->drawables.end()) it->second->eventMask = eventMask;
}

GLAPI void APIENTRY glXGetSelectedEvent(Display* dpy, GLXDrawable draw, unsigned long* eventMask) {
  if (!eventMask) return;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  *eventMask = 0;
  if (!ds) return;
  auto it = ds->drawables.find(draw);
  if (it != ds->drawables.end()) *eventMask = it->second->eventMask;
}

GLAPI void APIENTRY glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || interval < 0) return;  // BadValue
  auto it = ds->drawables.find(drawable);
  if (it != ds->drawables.end()) it->second->swapInterval = std::min(interval, kMaxSwapInterval);
}

GLAPI int APIENTRY glXSwapIntervalMESA(unsigned int interval) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  std::shared_ptr<GlxDrawable> d = currentDrawable();
  if (!d) return GLX_BAD_CONTEXT;
  d->swapInterval = static_cast<int>(std::min<unsigned>(interval, kMaxSwapInterval));
  return 0;
}

GLAPI int APIENTRY glXGetSwapIntervalMESA(void) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  std::shared_ptr<GlxDrawable> d = currentDrawable();
  return d ? d->swapInterval : 0;
}

GLAPI int APIENTRY glXSwapIntervalSGI(int interval) {
  if (interval <= 0) return GLX_BAD_VALUE;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  std::shared_ptr<GlxDrawable> d = currentDrawable();
  if (!d) return GLX_BAD_CONTEXT;
  d->swapInterval = std::min(interval, kMaxSwapInterval);
  return 0;
}

}  // extern "C"
