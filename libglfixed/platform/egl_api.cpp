// The EGL 1.5 entry points (libEGL.so.1 is this library): displays,
// configurations, contexts, thread state. Surfaces are in egl_surface_api.cpp.
// Errors as EGL 1.5 gives them; every handle is looked up before use.
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>

#include "api/entry_points.h"
#include "api/gl_version.h"
#include "pipeline/immediate_mode.h"
#include "platform/egl_objects.h"

using namespace glfixed::platform::egl;
using glfixed::platform::FramebufferConfig;

namespace {

using Lock = std::lock_guard<std::mutex>;

// Client extensions (EGL_EXT_client_extensions): the platforms that work.
constexpr const char* kClientExtensions =
    "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_platform_x11 EGL_EXT_platform_x11 "
    "EGL_MESA_platform_surfaceless";
constexpr const char* kDisplayExtensions = "EGL_KHR_create_context EGL_KHR_surfaceless_context";

// An OpenGL version that exists (§2.1 of each GL specification): 1.0-1.5,
// 2.0, 2.1, 3.0-3.3, 4.0-4.6.
bool isGLVersion(EGLint major, EGLint minor) {
  static const int kLastMinor[] = {-1, 5, 1, 3, 6};
  return major >= 1 && major <= 4 && minor >= 0 && minor <= kLastMinor[major];
}

EGLDisplay platformDisplay(EGLenum platform, void* native, const EGLAttrib* attribs) {
  Lock lock(registryMutex());
  switch (platform) {
    case EGL_PLATFORM_X11_KHR: {
      int screen = -1;
      for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
        if (attribs[i] != EGL_PLATFORM_X11_SCREEN_KHR) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
        screen = static_cast<int>(attribs[i + 1]);
      }
      return succeed(static_cast<EGLDisplay>(displayFor(Platform::kX11, native, screen)));
    }
    case EGL_PLATFORM_SURFACELESS_MESA:
      if (native) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
      if (attribs && attribs[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
      return succeed(static_cast<EGLDisplay>(displayFor(Platform::kSurfaceless, nullptr, -1)));
    default:
      // GBM, Wayland, devices, Android: not platforms of this library.
      return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  }
}

// eglCreateContext's attributes (§3.7.1, EGL_KHR_create_context).
struct ContextRequest {
  EGLint major = 1, minor = 0;
  EGLint profile = EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
  bool forwardCompatible = false, robust = false;
  EGLint resetStrategy = EGL_NO_RESET_NOTIFICATION;
};

EGLint parseContextAttribs(const EGLint* attribs, ContextRequest* r) {
  for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    const EGLint value = attribs[i + 1];
    switch (attribs[i]) {
      case EGL_CONTEXT_MAJOR_VERSION: r->major = value; break;
      case EGL_CONTEXT_MINOR_VERSION: r->minor = value; break;
      case EGL_CONTEXT_OPENGL_PROFILE_MASK:
        if (value & ~(EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT | EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT))
          return EGL_BAD_ATTRIBUTE;
        r->profile = value;
        break;
      case EGL_CONTEXT_OPENGL_DEBUG: break;  // a debug context may be an ordinary one
      case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE: r->forwardCompatible = value == EGL_TRUE; break;
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS: r->robust = value == EGL_TRUE; break;
      case EGL_CONTEXT_FLAGS_KHR:
        if (value & ~(EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                      EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR))
          return EGL_BAD_ATTRIBUTE;
        r->forwardCompatible = value & EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR;
        r->robust = value & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
        break;
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
        if (value != EGL_NO_RESET_NOTIFICATION && value != EGL_LOSE_CONTEXT_ON_RESET)
          return EGL_BAD_ATTRIBUTE;
        r->resetStrategy = value;
        break;
      default: return EGL_BAD_ATTRIBUTE;
    }
  }
  if (!isGLVersion(r->major, r->minor)) return EGL_BAD_MATCH;
  // Nothing above the version the library reports. Below 3.2 the profile
  // mask is ignored (EGL 1.5 §3.7.1.1), so a core request there gets a
  // compatibility context, as on Mesa; from 3.2 on the version refuses it.
  if (r->major > glfixed::kGLMajorVersion ||
      (r->major == glfixed::kGLMajorVersion && r->minor > glfixed::kGLMinorVersion))
    return EGL_BAD_MATCH;
  // Forward compatibility means GL 3.0 and later; there is no robustness.
  if (r->forwardCompatible || r->robust || r->resetStrategy != EGL_NO_RESET_NOTIFICATION)
    return EGL_BAD_MATCH;
  return EGL_SUCCESS;
}

}  // namespace

// EGLAPI is empty on Linux: the entry points are made visible here.
#pragma GCC visibility push(default)
extern "C" {

EGLAPI EGLint EGLAPIENTRY eglGetError(void) {
  ThreadState& t = thread();
  const EGLint e = t.error;
  t.error = EGL_SUCCESS;
  return e;
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetDisplay(EGLNativeDisplayType display_id) {
  Lock lock(registryMutex());
  if (display_id == EGL_DEFAULT_DISPLAY) return succeed(static_cast<EGLDisplay>(defaultDisplay()));
  return succeed(
      static_cast<EGLDisplay>(displayFor(Platform::kX11, reinterpret_cast<void*>(display_id), -1)));
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetPlatformDisplay(EGLenum platform, void* native_display,
                                                    const EGLAttrib* attrib_list) {
  return platformDisplay(platform, native_display, attrib_list);
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetPlatformDisplayEXT(EGLenum platform, void* native_display,
                                                       const EGLint* attrib_list) {
  std::vector<EGLAttrib> attribs;
  for (int i = 0; attrib_list && attrib_list[i] != EGL_NONE; i += 2) {
    attribs.push_back(attrib_list[i]);
    attribs.push_back(attrib_list[i + 1]);
  }
  attribs.push_back(EGL_NONE);
  return platformDisplay(platform, native_display, attribs.data());
}

EGLAPI EGLBoolean EGLAPIENTRY eglInitialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  Lock lock(registryMutex());
  EglDisplay* d = findDisplay(dpy);
  if (!d) return EGL_FALSE;
  if (!initialize(*d)) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
  if (major) *major = 1;
  if (minor) *minor = 5;
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglTerminate(EGLDisplay dpy) {
  Lock lock(registryMutex());
  EglDisplay* d = findDisplay(dpy);
  if (!d) return EGL_FALSE;
  terminate(*d);
  return succeed(EGL_TRUE);
}

EGLAPI const char* EGLAPIENTRY eglQueryString(EGLDisplay dpy, EGLint name) {
  Lock lock(registryMutex());
  if (dpy == EGL_NO_DISPLAY) {
    // EGL 1.5 §3.3: the client extensions, and the client's version.
    if (name == EGL_EXTENSIONS) return succeed(kClientExtensions);
    if (name == EGL_VERSION) return succeed("1.5 libglfixed");
    return fail(EGL_BAD_DISPLAY, static_cast<const char*>(nullptr));
  }
  if (!initializedDisplay(dpy)) return nullptr;
  switch (name) {
    case EGL_VENDOR: return succeed("libglfixed");
    case EGL_VERSION: return succeed("1.5 libglfixed");
    case EGL_CLIENT_APIS: return succeed("OpenGL");
    case EGL_EXTENSIONS: return succeed(kDisplayExtensions);
    default: return fail(EGL_BAD_PARAMETER, static_cast<const char*>(nullptr));
  }
}

EGLAPI EGLBoolean EGLAPIENTRY eglGetConfigs(EGLDisplay dpy, EGLConfig* configs, EGLint config_size,
                                            EGLint* num_config) {
  Lock lock(registryMutex());
  if (!initializedDisplay(dpy)) return EGL_FALSE;
  if (!num_config) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  const auto all = eglConfigs();
  EGLint n = 0;
  for (const FramebufferConfig* c : all) {
    if (configs && n >= config_size) break;
    if (configs) configs[n] = const_cast<FramebufferConfig*>(c);
    ++n;
  }
  *num_config = n;
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglChooseConfig(EGLDisplay dpy, const EGLint* attrib_list, EGLConfig* configs,
                                              EGLint config_size, EGLint* num_config) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  if (!num_config) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  std::vector<const FramebufferConfig*> chosen;
  EGLint error = EGL_SUCCESS;
  if (!chooseConfigs(*d, attrib_list, &chosen, &error)) return fail(error, EGL_FALSE);
  EGLint n = 0;
  for (const FramebufferConfig* c : chosen) {
    if (configs && n >= config_size) break;
    if (configs) configs[n] = const_cast<FramebufferConfig*>(c);
    ++n;
  }
  *num_config = n;
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute,
                                                 EGLint* value) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  const FramebufferConfig* c = findConfig(*d, config);
  if (!c) return EGL_FALSE;
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  if (!configAttrib(*d, *c, attribute, value)) return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglBindAPI(EGLenum api) {
  // There is no OpenGL ES and no OpenVG (§3.7).
  if (api != EGL_OPENGL_API) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  thread().api = api;
  return succeed(EGL_TRUE);
}

EGLAPI EGLenum EGLAPIENTRY eglQueryAPI(void) { return succeed(thread().api); }

EGLAPI EGLContext EGLAPIENTRY eglCreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share_context,
                                               const EGLint* attrib_list) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_NO_CONTEXT;
  const FramebufferConfig* c = findConfig(*d, config);
  if (!c) return EGL_NO_CONTEXT;
  if (thread().api != EGL_OPENGL_API) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  EglContext* share = nullptr;
  if (share_context != EGL_NO_CONTEXT && !(share = findContext(*d, share_context))) return EGL_NO_CONTEXT;
  ContextRequest request;
  const EGLint error = parseContextAttribs(attrib_list, &request);
  if (error != EGL_SUCCESS) return fail(error, EGL_NO_CONTEXT);
  auto ctx = std::unique_ptr<EglContext>(new (std::nothrow) EglContext);
  if (!ctx) return fail(EGL_BAD_ALLOC, EGL_NO_CONTEXT);
  try {
    ctx->context = std::make_unique<glfixed::Context>(c->depthBits, c->stencilBits);
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_CONTEXT);
  }
  ctx->display = d;
  ctx->config = c;
  ctx->majorVersion = request.major;
  ctx->minorVersion = request.minor;
  if (share) ctx->context->shareObjectsWith(*share->context);
  d->contexts.push_back(std::move(ctx));
  return succeed(static_cast<EGLContext>(d->contexts.back().get()));
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroyContext(EGLDisplay dpy, EGLContext ctx) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglContext* c = findContext(*d, ctx);
  if (!c) return EGL_FALSE;
  auto it = std::find_if(d->contexts.begin(), d->contexts.end(), [c](const auto& p) { return p.get() == c; });
  // §3.7.2: a current context lives on until it is released.
  if (c->current) {
    c->destroyed = true;
    d->doomedContexts.push_back(std::move(*it));
  }
  d->contexts.erase(it);
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read,
                                             EGLContext ctx) {
  Lock lock(registryMutex());
  EglDisplay* d = findDisplay(dpy);
  if (!d) return EGL_FALSE;
  const bool release = ctx == EGL_NO_CONTEXT && draw == EGL_NO_SURFACE && read == EGL_NO_SURFACE;
  if (!d->initialized) {
    // Releasing works on a terminated display (what was current there is
    // freed then), as on Mesa.
    if (!release) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
    bindCurrent(nullptr, nullptr, nullptr);
    return succeed(EGL_TRUE);
  }
  if (ctx == EGL_NO_CONTEXT) {
    if (!release) return fail(EGL_BAD_MATCH, EGL_FALSE);
    bindCurrent(nullptr, nullptr, nullptr);
    return succeed(EGL_TRUE);
  }
  EglContext* c = findContext(*d, ctx);
  if (!c) return EGL_FALSE;
  // Both surfaces or neither (surfaceless: EGL_KHR_surfaceless_context).
  if ((draw == EGL_NO_SURFACE) != (read == EGL_NO_SURFACE)) return fail(EGL_BAD_MATCH, EGL_FALSE);
  EglSurface* ds = nullptr;
  EglSurface* rs = nullptr;
  if (draw != EGL_NO_SURFACE && (!(ds = findSurface(*d, draw)) || !(rs = findSurface(*d, read))))
    return EGL_FALSE;
  ThreadState& t = thread();
  if (c->current && c != t.context) return fail(EGL_BAD_ACCESS, EGL_FALSE);
  // A surface may be bound on one thread only.
  auto boundElsewhere = [&t](const EglSurface* s) {
    const EglContext* mine = t.context;
    const int mineCount = mine && (mine->draw == s || mine->read == s) ? 1 : 0;
    return s && s->boundCount > mineCount;
  };
  if (boundElsewhere(ds) || boundElsewhere(rs)) return fail(EGL_BAD_ACCESS, EGL_FALSE);
  if ((ds && ds->config != c->config) || (rs && rs->config != c->config))
    return fail(EGL_BAD_MATCH, EGL_FALSE);
  if (!bindCurrent(c, ds, rs)) return fail(EGL_BAD_ALLOC, EGL_FALSE);
  return succeed(EGL_TRUE);
}

EGLAPI EGLContext EGLAPIENTRY eglGetCurrentContext(void) {
  Lock lock(registryMutex());
  return succeed(static_cast<EGLContext>(thread().context));
}

EGLAPI EGLSurface EGLAPIENTRY eglGetCurrentSurface(EGLint readdraw) {
  Lock lock(registryMutex());
  const EglContext* c = thread().context;
  if (readdraw != EGL_DRAW && readdraw != EGL_READ) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  if (!c) return succeed(EGL_NO_SURFACE);
  return succeed(static_cast<EGLSurface>(readdraw == EGL_DRAW ? c->draw : c->read));
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetCurrentDisplay(void) {
  Lock lock(registryMutex());
  const EglContext* c = thread().context;
  return succeed(c ? static_cast<EGLDisplay>(c->display) : EGL_NO_DISPLAY);
}

EGLAPI EGLBoolean EGLAPIENTRY eglQueryContext(EGLDisplay dpy, EGLContext ctx, EGLint attribute,
                                              EGLint* value) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  const EglContext* c = findContext(*d, ctx);
  if (!c) return EGL_FALSE;
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  switch (attribute) {
    case EGL_CONFIG_ID: *value = c->config->id; break;
    case EGL_CONTEXT_CLIENT_TYPE: *value = EGL_OPENGL_API; break;
    case EGL_CONTEXT_CLIENT_VERSION: *value = c->majorVersion; break;
    case EGL_RENDER_BUFFER:
      if (!c->draw)
        *value = EGL_NONE;
      else if (c->draw->type == EGL_PIXMAP_BIT)
        *value = EGL_SINGLE_BUFFER;
      else
        *value = c->draw->renderBuffer;
      break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitClient(void) {
  Lock lock(registryMutex());
  if (EglContext* c = thread().context) {
    glfixed::pipeline::flushVertices(*c->context);
    if (c->draw && !c->draw->surface->doubleBuffered()) c->draw->surface->presentFront();
  }
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitGL(void) { return eglWaitClient(); }

EGLAPI EGLBoolean EGLAPIENTRY eglWaitNative(EGLint engine) {
  Lock lock(registryMutex());
  if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  // X rendering the program asked for is done before GL draws again.
  if (const EglContext* c = thread().context; c && c->display->x11) XSync(c->display->x11, False);
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglReleaseThread(void) {
  Lock lock(registryMutex());
  bindCurrent(nullptr, nullptr, nullptr);
  thread().api = EGL_NONE;
  return succeed(EGL_TRUE);
}

EGLAPI __eglMustCastToProperFunctionPointerType EGLAPIENTRY eglGetProcAddress(const char* procname) {
  return reinterpret_cast<__eglMustCastToProperFunctionPointerType>(glfixed::api::procAddress(procname));
}

}  // extern "C"
#pragma GCC visibility pop
