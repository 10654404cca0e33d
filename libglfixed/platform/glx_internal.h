// GLX 1.4, client-side: what glx.cpp (contexts, current, strings),
// glx_configs.cpp (FBConfigs and visuals), glx_drawables.cpp (windows,
// pixmaps, pbuffers, swaps) and glx_font.cpp (glXUseXFont) share.
//
// Everything happens in this process: the X server's own GLX extension is
// never used (nor needed), X is only asked for visuals, window sizes and
// XPutImage. The GLX state of a Display (its FBConfigs, its drawables) lives
// until XCloseDisplay.
#pragma once

#ifndef GLX_GLXEXT_PROTOTYPES
#define GLX_GLXEXT_PROTOTYPES
#endif
#include <GL/glx.h>

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "platform/configs.h"
#include "platform/surface.h"
#include "state/context.h"

// The opaque handles of glx.h point to these.
struct __GLXFBConfigRec {
  const glfixed::platform::FramebufferConfig* config;
  int screen;
  VisualID visualId;  // 0: no visual (a pbuffer-only configuration)
  int visualDepth;
  // GLX offers each configuration twice, as Mesa's GLX does: without an
  // accumulation buffer, and with a 16-bit one (RGBA), caveat
  // GLX_SLOW_CONFIG. EGL has no accumulation buffer and offers the first.
  int accumBits = 0;
  int id() const;  // GLX_FBCONFIG_ID: the twin with accumulation after all the others
};

namespace glfixed::platform::glx {

using FBConfig = __GLXFBConfigRec;

// A GLX drawable: an X window (made current as it is, or by glXCreateWindow),
// a GLX pixmap or a pbuffer. Its Surface (the colour buffers) belongs to the
// drawable and is shared by every context drawing into it. A drawable
// destroyed while current lives on until released (shared_ptr).
struct GlxDrawable {
  enum class Kind { kWindow, kGlxWindow, kGlxPixmap, kPbuffer };
  Kind kind = Kind::kWindow;
  XID id = 0;        // the GLXDrawable (a window's own id for windows)
  Drawable x11 = 0;  // the X window or pixmap; 0 for a pbuffer
  const FBConfig* config = nullptr;
  std::shared_ptr<Surface> surface;
  unsigned long eventMask = 0;  // glXSelectEvent
  int width = 0, height = 0;    // a pbuffer's, as asked
  bool preserved = true, largest = false;
  // GLX_EXT_swap_control: swaps are paced to `swapInterval` periods of a
  // nominal 60 Hz display (glx_drawables.cpp).
  int swapInterval = 0;
  std::chrono::steady_clock::time_point lastSwap{};
};

struct DisplayState {
  Display* display = nullptr;
  std::vector<std::vector<std::unique_ptr<FBConfig>>> screens;  // FBConfigs by screen, id order
  std::map<XID, std::shared_ptr<GlxDrawable>> drawables;
  // Where configurations share an X visual (a server with few visuals), the
  // one glXChooseVisual or glXGetVisualFromFBConfig last gave for it.
  std::map<VisualID, const FBConfig*> visualChoice;
};

// All GLX state is guarded by one lock (GLX calls are few; drawing is not
// under it).
std::recursive_mutex& glxMutex();

// The Display's GLX state, made at first use; null for a null display.
DisplayState* displayState(Display* display);

// A fresh XID for a GLX drawable that is no X resource (a pbuffer, a GLX
// pixmap), from the range Xlib allocates from.
XID newDrawableId(Display* display);

// glx_configs.cpp.
// Fills ds.screens (at the Display's first use).
void makeConfigs(DisplayState& ds);
// The configuration of an X visual of ours, or null (not a GL visual).
const FBConfig* configForVisual(DisplayState& ds, const XVisualInfo* visual);
// An XVisualInfo the program frees with XFree; null without a visual.
XVisualInfo* visualInfoFor(Display* display, const FBConfig& config);
// Success, or GLX_BAD_ATTRIBUTE.
int configAttrib(const FBConfig& config, int attribute, int* value);
bool isConfigOf(DisplayState& ds, const FBConfig* config);

// glx_drawables.cpp.
// The drawable `id` names: a known GLX drawable, or an X window seen for the
// first time (given a surface for `config`). Null if it is neither.
std::shared_ptr<GlxDrawable> drawableFor(DisplayState& ds, GLXDrawable id, const FBConfig* config);

}  // namespace glfixed::platform::glx

struct __GLXcontextRec {
  glfixed::Context context;
  Display* display;
  const glfixed::platform::glx::FBConfig* config;
  unsigned long id;  // GLX_CONTEXT_ID (glXQueryContextInfoEXT)
  unsigned long shareId = 0;
  bool current = false;    // current on some thread
  bool destroyed = false;  // glXDestroyContext while current: freed at release
  std::shared_ptr<glfixed::platform::glx::GlxDrawable> draw, read;
  __GLXcontextRec(Display* d, const glfixed::platform::glx::FBConfig* c, unsigned long contextId)
      : context(c->config->depthBits, c->config->stencilBits), display(d), config(c), id(contextId) {
    context.requestedAccum = c->accumBits > 0;
  }
};

namespace glfixed::platform::glx {
// The calling thread's current GLX context, or null (none, or an OSMesa or
// EGL context is current).
__GLXcontextRec* currentGlxContext();
}  // namespace glfixed::platform::glx
