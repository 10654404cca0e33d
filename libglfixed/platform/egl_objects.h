// The objects behind EGL's handles (EGL 1.5): displays, surfaces and
// contexts, and the calling thread's EGL state. A handle is the address of
// one of these, but it is only ever used after it was found in its display's
// lists (egl_display.cpp), so a bad or stale handle is an EGL error, never a
// read of freed memory.
//
// EGL displays are process-wide by the specification (eglGetDisplay of the
// same native display gives the same EGLDisplay on every thread), so they
// live in one registry guarded by one mutex, held by every entry point.
#pragma once

#include <EGL/egl.h>
#include <X11/Xlib.h>

#include <memory>
#include <mutex>
#include <new>
#include <vector>

#include "platform/configs.h"
#include "platform/surface.h"
#include "state/context.h"

namespace glfixed::platform::egl {

enum class Platform { kX11, kSurfaceless };

struct EglDisplay;

struct EglSurface {
  EglDisplay* display = nullptr;
  EGLint type = EGL_PBUFFER_BIT;  // EGL_WINDOW_BIT, EGL_PBUFFER_BIT or EGL_PIXMAP_BIT
  const FramebufferConfig* config = nullptr;
  std::unique_ptr<Surface> surface;
  unsigned long nativeHandle = 0;               // the X11 window or pixmap
  int requestedWidth = 0, requestedHeight = 0;  // a pbuffer's EGL_WIDTH, EGL_HEIGHT
  EGLint renderBuffer = EGL_BACK_BUFFER;
  bool largestPbuffer = false;
  EGLint swapBehavior = EGL_BUFFER_DESTROYED;
  EGLint multisampleResolve = EGL_MULTISAMPLE_RESOLVE_DEFAULT;
  EGLint swapInterval = 1;
  int boundCount = 0;      // current contexts that draw to or read from it
  bool destroyed = false;  // eglDestroySurface or eglTerminate while bound
};

struct EglContext {
  EglDisplay* display = nullptr;
  const FramebufferConfig* config = nullptr;
  std::unique_ptr<Context> context;
  EGLint majorVersion = 1, minorVersion = 0;
  EglSurface* draw = nullptr;
  EglSurface* read = nullptr;
  bool current = false;    // current on some thread
  bool destroyed = false;  // eglDestroyContext or eglTerminate while current
};

// A fence (EGL 1.5 §3.8.1). Drawing is done when the commands before it are
// flushed, so a fence is signaled as soon as it exists.
struct EglSync {
  EGLenum type = EGL_SYNC_FENCE;
};

struct EglDisplay {
  Platform platform = Platform::kSurfaceless;
  void* nativeDisplay = nullptr;  // as the program named it (null: the default one)
  int screen = -1;                // EGL_PLATFORM_X11_SCREEN_KHR; -1: the default screen
  Display* x11 = nullptr;         // the open connection while initialized (X11)
  bool ownsX11 = false;           // opened by us from $DISPLAY
  bool initialized = false;
  // The X visuals of the configurations' depths (24, 32); null if the screen
  // has none.
  Visual* visual24 = nullptr;
  Visual* visual32 = nullptr;
  std::vector<std::unique_ptr<EglSurface>> surfaces;
  std::vector<std::unique_ptr<EglContext>> contexts;
  std::vector<std::unique_ptr<EglSync>> syncs;
  // Destroyed while current: no longer valid handles, freed once released.
  std::vector<std::unique_ptr<EglSurface>> doomedSurfaces;
  std::vector<std::unique_ptr<EglContext>> doomedContexts;

  // Every configuration draws into depth-24 windows and pixmaps, alpha or
  // not, as on Mesa, whose RGBA configurations name the depth-24 visual
  // (MESA_FACTS.md, "EGL"); those with alpha into depth-32 ones too.
  Visual* nativeVisual(const FramebufferConfig& c) const {
    return visual24 ? visual24 : c.alphaBits ? visual32 : nullptr;
  }
  Visual* drawableVisual(const FramebufferConfig& c, int depth) const {
    if (depth == 24) return visual24;
    return depth == 32 && c.alphaBits ? visual32 : nullptr;
  }
};

// The calling thread's EGL state (EGL 1.5 §3.1, §3.7).
struct ThreadState {
  EGLint error = EGL_SUCCESS;
  EGLenum api = EGL_NONE;  // no OpenGL ES here, so EGL_NONE until eglBindAPI (§3.7)
  EglContext* context = nullptr;
};
ThreadState& thread();

// The one lock over every display and its objects.
std::mutex& registryMutex();

// Records `error` as the thread's last error and returns `result`.
template <typename T>
T fail(EGLint error, T result) {
  thread().error = error;
  return result;
}
template <typename T>
T succeed(T result) {
  thread().error = EGL_SUCCESS;
  return result;
}
// Runs `body`: an allocation that fails inside is EGL_BAD_ALLOC, so that no
// exception leaves an entry point.
template <typename T, typename F>
T guarded(T onFailure, F body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, onFailure);
  }
}

// --- Displays (egl_display.cpp) ------------------------------------------
// Null, with the error recorded, unless `handle` is a display of ours (and,
// for initializedDisplay, initialized).
EglDisplay* findDisplay(EGLDisplay handle);
EglDisplay* initializedDisplay(EGLDisplay handle);
// The display for (platform, native display, screen), made at its first request.
EglDisplay* displayFor(Platform platform, void* nativeDisplay, int screen);
// eglGetDisplay(EGL_DEFAULT_DISPLAY): X11 if $DISPLAY names a server that
// answers, else the surfaceless platform. No connection is opened otherwise.
EglDisplay* defaultDisplay();
bool initialize(EglDisplay& d);
void terminate(EglDisplay& d);

// Null, with EGL_BAD_SURFACE / EGL_BAD_CONTEXT / EGL_BAD_CONFIG recorded,
// unless the handle names a live object of `d`.
EglSurface* findSurface(EglDisplay& d, EGLSurface handle);
EglContext* findContext(EglDisplay& d, EGLContext handle);
const FramebufferConfig* findConfig(EglDisplay& d, EGLConfig handle);

// Binds (ctx, draw, read) to this thread, releasing what it had, and frees
// what was destroyed while bound once nothing holds it. False (nothing
// current then) if the context's depth buffer could not be allocated.
bool bindCurrent(EglContext* ctx, EglSurface* draw, EglSurface* read);

// --- Configurations (egl_config.cpp) -------------------------------------
// The configurations an EGL display offers: the double-buffered entries of
// configs.h (EGL has no single-buffered configs; a surface's render buffer
// says that).
std::vector<const FramebufferConfig*> eglConfigs();
EGLint surfaceTypes(const EglDisplay& d, const FramebufferConfig& c);
// False (EGL_BAD_ATTRIBUTE) for an attribute EGL does not define for configs.
bool configAttrib(const EglDisplay& d, const FramebufferConfig& c, EGLint attribute, EGLint* value);
// eglChooseConfig: the matching configurations, best first (EGL 1.5 §3.4.1).
// False with `error` set for a bad attribute list.
bool chooseConfigs(const EglDisplay& d, const EGLint* attribs, std::vector<const FramebufferConfig*>* out,
                   EGLint* error);

}  // namespace glfixed::platform::egl
