// GLX 1.4 contexts (§3.3.7), the current context and drawables (thread-local),
// the version and extension strings, glXGetProcAddress, glXWaitGL/glXWaitX.
//
// Errors: where GLX would raise an X protocol error (BadMatch, BadAccess,
// GLXBadContext...), the call fails and returns what its failure returns
// (False, NULL, None) without an X error, since no server extension is
// involved; the program's error handler is never called for our requests.
#include <atomic>
#include <cstring>

#include "api/entry_points.h"
#include "api/gl_version.h"
#include "pipeline/immediate_mode.h"
#include "platform/glx_internal.h"
#include "state/attrib_stack.h"
// XESetCloseDisplay; last, since it defines min and max as macros.
#include <X11/Xlibint.h>
#undef min
#undef max

namespace glfixed::platform::glx {

namespace {

// The extensions implemented (GLX_ARB_create_context_profile: a profile
// request below GL 3.2 is ignored, as the extension says; nothing above 2.1
// is offered).
constexpr const char* kExtensions =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address "
    "GLX_EXT_swap_control GLX_EXT_visual_info GLX_EXT_visual_rating GLX_MESA_swap_control "
    "GLX_SGI_swap_control";

std::map<Display*, std::unique_ptr<DisplayState>>& registry() {
  static auto* r = new std::map<Display*, std::unique_ptr<DisplayState>>();
  return *r;
}

thread_local __GLXcontextRec* tCurrent = nullptr;
thread_local Display* tCurrentDisplay = nullptr;
std::atomic<unsigned long> gNextContextId{1};

int closeDisplay(Display* display, XExtCodes*) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  auto it = registry().find(display);
  if (it == registry().end()) return 0;
  // Surfaces still bound to a context outlive the state: none may talk to
  // the closing connection.
  for (auto& [id, drawable] : it->second->drawables)
    if (drawable->surface) drawable->surface->connectionClosing();
  if (tCurrent && tCurrent->display == display) {
    for (auto* d : {tCurrent->draw.get(), tCurrent->read.get()})
      if (d && d->surface) d->surface->connectionClosing();
  }
  registry().erase(it);
  return 0;
}

}  // namespace

std::recursive_mutex& glxMutex() {
  static auto* m = new std::recursive_mutex();
  return *m;
}

DisplayState* displayState(Display* display) {
  if (!display) return nullptr;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  auto& r = registry();
  auto it = r.find(display);
  if (it != r.end()) return it->second.get();
  auto ds = std::make_unique<DisplayState>();
  ds->display = display;
  makeConfigs(*ds);
  // Forget the display's state when the program closes it (another Display
  // may get the same address later).
  if (XExtCodes* codes = XAddExtension(display)) XESetCloseDisplay(display, codes->extension, closeDisplay);
  return r.emplace(display, std::move(ds)).first->second.get();
}

// Xlib's XAllocID hands out one id and has the next made only when a
// request goes through its sync handler: two calls in a row (ours, then
// Xlib's own inside XCreatePixmap) would find none ready. _XAllocIDs asks
// xcb for ids directly, under the display lock as Xlib's own callers do.
XID newDrawableId(Display* display) {
  XID id = 0;
  LockDisplay(display);
  _XAllocIDs(display, &id, 1);
  UnlockDisplay(display);
  return id;
}

__GLXcontextRec* currentGlxContext() {
  return tCurrent && currentContext() == &tCurrent->context ? tCurrent : nullptr;
}

namespace {

GLXContext createContext(Display* dpy, const FBConfig* config, GLXContext share) {
  DisplayState* ds = displayState(dpy);
  if (!ds || !isConfigOf(*ds, config)) return nullptr;
  if (share && share->display != dpy) return nullptr;  // BadMatch
  auto* c = new (std::nothrow) __GLXcontextRec(dpy, config, gNextContextId++);
  if (!c) return nullptr;
  if (share) {
    c->context.shareObjectsWith(share->context);
    // Texture objects are shared with the display lists once they exist
    // (issue 14).
    c->shareId = share->id;
  }
  return c;
}

// Lets go of the GLX side of `c` after it stopped being current.
void released(__GLXcontextRec* c) {
  c->current = false;
  // No pointer into the surfaces is left behind (platform::makeCurrent has
  // done so already unless another API's makeCurrent displaced it).
  if (c->draw) c->draw->surface->detach(&c->context);
  if (c->read) c->read->surface->detach(&c->context);
  glfixed::platform::bindSurfaces(c->context, nullptr, nullptr);
  c->draw.reset();
  c->read.reset();
  if (c->destroyed) delete c;
}

bool makeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  __GLXcontextRec* previous = currentGlxContext();
  // A GLX context displaced by an OSMesa or EGL context on this thread is
  // no longer current.
  if (tCurrent && tCurrent != previous) {
    released(tCurrent);
    tCurrent = nullptr;
  }
  if (!ctx) {
    if (draw != None || read != None) return false;  // BadMatch
    if (previous) {                                  // another API's current context is not GLX's to release
      makeCurrent(nullptr, nullptr, nullptr);
      released(previous);
    }
    tCurrent = nullptr;
    tCurrentDisplay = nullptr;
    return true;
  }
  if (ctx->destroyed) return false;                   // GLXBadContext
  if (ctx->current && ctx != previous) return false;  // BadAccess: current on another thread
  if (draw == None || read == None) return false;     // BadMatch (no surfaceless GLX)
  DisplayState* ds = displayState(dpy);
  if (!ds || ctx->display != dpy) return false;
  std::shared_ptr<GlxDrawable> d = drawableFor(*ds, draw, ctx->config);
  std::shared_ptr<GlxDrawable> r = read == draw ? d : drawableFor(*ds, read, ctx->config);
  if (!d || !r) return false;  // GLXBadDrawable
  makeCurrent(&ctx->context, d->surface.get(), r->surface.get());
  if (previous && previous != ctx) released(previous);
  ctx->current = true;
  ctx->draw = std::move(d);
  ctx->read = std::move(r);
  tCurrent = ctx;
  tCurrentDisplay = dpy;
  return true;
}

// GLX 1.4 §3.3.3 names GL versions 1.0-1.5 and 2.0-2.1 (and later ones).
bool validVersion(int major, int minor) {
  if (major < 1 || minor < 0) return false;
  if (major == 1) return minor <= 5;
  if (major == 2) return minor <= 1;
  return true;
}

}  // namespace

}  // namespace glfixed::platform::glx

using namespace glfixed::platform::glx;

extern "C" {

GLAPI Bool APIENTRY glXQueryExtension(Display* dpy, int* errorBase, int* eventBase) {
  // Everything is client-side: no server extension is needed, and none of
  // its errors or events are sent.
  if (errorBase) *errorBase = 0;
  if (eventBase) *eventBase = 0;
  return dpy ? True : False;
}

GLAPI Bool APIENTRY glXQueryVersion(Display* dpy, int* major, int* minor) {
  if (major) *major = 1;
  if (minor) *minor = 4;
  return dpy ? True : False;
}

GLAPI const char* APIENTRY glXGetClientString(Display* dpy, int name) {
  switch (name) {
    case GLX_VENDOR: return "libglfixed";
    case GLX_VERSION: return "1.4";
    case GLX_EXTENSIONS: return kExtensions;
    default: return nullptr;
  }
}

GLAPI const char* APIENTRY glXQueryServerString(Display* dpy, int screen, int name) {
  if (!dpy || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return glXGetClientString(dpy, name);
}

GLAPI const char* APIENTRY glXQueryExtensionsString(Display* dpy, int screen) {
  if (!dpy || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return kExtensions;
}

GLAPI GLXContext APIENTRY glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext shareList,
                                           Bool direct) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds) return nullptr;
  const FBConfig* config = configForVisual(*ds, vis);
  return config ? createContext(dpy, config, shareList) : nullptr;  // BadValue: not a GL visual
}

GLAPI GLXContext APIENTRY glXCreateNewContext(Display* dpy, GLXFBConfig config, int renderType,
                                              GLXContext shareList, Bool direct) {
  if (renderType != GLX_RGBA_TYPE) return nullptr;  // no colour-index contexts
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  return createContext(dpy, config, shareList);
}

// GLX_ARB_create_context: a compatibility context of the library's GL
// version or an earlier one. A higher version, a forward-compatible or ES
// context, or an unknown attribute gives NULL (Mesa raises BadMatch or
// GLXBadProfileARB there; NULL lets the program take its fallback).
GLAPI GLXContext APIENTRY glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config,
                                                     GLXContext shareContext, Bool direct,
                                                     const int* attribList) {
  int major = 1, minor = 0, flags = 0, profile = GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
  int renderType = GLX_RGBA_TYPE;
  for (int i = 0; attribList && attribList[i] != None; i += 2) {
    const int v = attribList[i + 1];
    switch (attribList[i]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB: major = v; break;
      case GLX_CONTEXT_MINOR_VERSION_ARB: minor = v; break;
      case GLX_CONTEXT_FLAGS_ARB: flags = v; break;
      case GLX_CONTEXT_PROFILE_MASK_ARB: profile = v; break;
      case GLX_RENDER_TYPE: renderType = v; break;
      default: return nullptr;  // BadValue
    }
  }
  if (!validVersion(major, minor) || !glfixed::glVersionAvailable(major, minor)) return nullptr;
  if (flags & ~GLX_CONTEXT_DEBUG_BIT_ARB) return nullptr;  // forward-compatible needs GL 3.0
  // Below GL 3.2 the profile is ignored, but must be one of the two bits.
  if (profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB && profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB)
    return nullptr;
  if (renderType != GLX_RGBA_TYPE) return nullptr;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  return createContext(dpy, config, shareContext);
}

GLAPI void APIENTRY glXDestroyContext(Display* dpy, GLXContext ctx) {
  if (!ctx) return;
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  if (ctx->destroyed) return;
  // Freed when it stops being current (GLX 1.4 §3.3.7).
  if (ctx->current) {
    ctx->destroyed = true;
    return;
  }
  delete ctx;
}

GLAPI Bool APIENTRY glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return makeContextCurrent(dpy, drawable, drawable, ctx) ? True : False;
}

GLAPI Bool APIENTRY glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx) {
  return makeContextCurrent(dpy, draw, read, ctx) ? True : False;
}

GLAPI void APIENTRY glXCopyContext(Display* dpy, GLXContext src, GLXContext dst, unsigned long mask) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  // BadAccess if dst is current; BadMatch across displays.
  if (!src || !dst || src == dst || dst->current || src->display != dst->display) return;
  glfixed::pipeline::flushVertices(src->context);
  glfixed::copyAttribGroups(src->context, dst->context, static_cast<GLbitfield>(mask));
}

GLAPI Bool APIENTRY glXIsDirect(Display* dpy, GLXContext ctx) {
  // Rendering happens in the calling process.
  return ctx ? True : False;
}

GLAPI GLXContext APIENTRY glXGetCurrentContext(void) { return currentGlxContext(); }

GLAPI GLXDrawable APIENTRY glXGetCurrentDrawable(void) {
  __GLXcontextRec* c = currentGlxContext();
  return c && c->draw ? c->draw->id : None;
}

GLAPI GLXDrawable APIENTRY glXGetCurrentReadDrawable(void) {
  __GLXcontextRec* c = currentGlxContext();
  return c && c->read ? c->read->id : None;
}

GLAPI Display* APIENTRY glXGetCurrentDisplay(void) { return currentGlxContext() ? tCurrentDisplay : nullptr; }

GLAPI int APIENTRY glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  if (!ctx || !value) return GLX_BAD_CONTEXT;
  switch (attribute) {
    case GLX_FBCONFIG_ID: *value = ctx->config->id(); return Success;
    case GLX_RENDER_TYPE: *value = GLX_RGBA_TYPE; return Success;
    case GLX_SCREEN: *value = ctx->config->screen; return Success;
    default: return GLX_BAD_ATTRIBUTE;
  }
}

// GLX_EXT_import_context's query (the extension itself is not offered:
// contexts cannot be imported into another process).
GLAPI int APIENTRY glXQueryContextInfoEXT(Display* dpy, GLXContext ctx, int attribute, int* value) {
  if (!ctx || !value) return GLX_BAD_CONTEXT;
  switch (attribute) {
    case GLX_SHARE_CONTEXT_EXT: *value = static_cast<int>(ctx->shareId); return Success;
    case GLX_VISUAL_ID_EXT: *value = static_cast<int>(ctx->config->visualId); return Success;
    case GLX_SCREEN_EXT: *value = ctx->config->screen; return Success;
    default: return glXQueryContext(dpy, ctx, attribute, value);
  }
}

// glXWaitGL: GL's drawing done, and what the front buffer holds on the
// screen (the buffers are the client's: the X server sees them only when
// presented).
GLAPI void APIENTRY glXWaitGL(void) {
  __GLXcontextRec* c = currentGlxContext();
  if (!c) return;
  glfixed::pipeline::flushVertices(c->context);
  if (c->draw && c->draw->surface && c->draw->surface->isWindow()) c->draw->surface->presentFront();
}

GLAPI void APIENTRY glXWaitX(void) {
  if (currentGlxContext() && tCurrentDisplay) XSync(tCurrentDisplay, False);
}

GLAPI __GLXextFuncPtr APIENTRY glXGetProcAddressARB(const GLubyte* procName) {
  return reinterpret_cast<__GLXextFuncPtr>(
      glfixed::api::procAddress(reinterpret_cast<const char*>(procName)));
}

GLAPI __GLXextFuncPtr APIENTRY glXGetProcAddress(const GLubyte* procName) {
  return glXGetProcAddressARB(procName);
}

}  // extern "C"
