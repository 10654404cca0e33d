// EGL surfaces (EGL 1.5 §3.5, §3.9, §3.10): X11 windows and pixmaps,
// pbuffers, and presenting them. The colour buffers are a platform::Surface;
// X11 windows and pixmaps reach the server through the X11 presenter that
// GLX uses too.
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <vector>

#include "pipeline/immediate_mode.h"
#include "pipeline/pixel_rect.h"
#include "platform/egl_objects.h"
#include "platform/x11_present.h"

using namespace glfixed::platform::egl;
using glfixed::platform::FramebufferConfig;

namespace {

using Lock = std::lock_guard<std::mutex>;

std::vector<EGLAttrib> widen(const EGLint* attribs) {
  std::vector<EGLAttrib> out;
  for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    out.push_back(attribs[i]);
    out.push_back(attribs[i + 1]);
  }
  out.push_back(EGL_NONE);
  return out;
}

// The attributes every kind of surface takes (§3.5.1): linear colour only,
// and OpenVG's, which mean nothing here, at their defaults.
EGLint commonAttrib(EGLAttrib name, EGLAttrib value) {
  switch (name) {
    case EGL_GL_COLORSPACE:
      if (value == EGL_GL_COLORSPACE_LINEAR) return EGL_SUCCESS;
      return value == EGL_GL_COLORSPACE_SRGB ? EGL_BAD_MATCH : EGL_BAD_ATTRIBUTE;
    case EGL_VG_ALPHA_FORMAT:
      if (value == EGL_VG_ALPHA_FORMAT_NONPRE) return EGL_SUCCESS;
      return value == EGL_VG_ALPHA_FORMAT_PRE ? EGL_BAD_MATCH : EGL_BAD_ATTRIBUTE;
    case EGL_VG_COLORSPACE:
      return value == EGL_VG_COLORSPACE_sRGB || value == EGL_VG_COLORSPACE_LINEAR ? EGL_SUCCESS
                                                                                  : EGL_BAD_ATTRIBUTE;
    default: return EGL_BAD_ATTRIBUTE;
  }
}

EGLSurface addSurface(EglDisplay& d, std::unique_ptr<EglSurface> s) {
  s->display = &d;
  d.surfaces.push_back(std::move(s));
  return succeed(static_cast<EGLSurface>(d.surfaces.back().get()));
}

// The display and configuration of a surface to be made, with the errors
// of §3.5 in their order; null after recording one.
const FramebufferConfig* surfaceConfig(EGLDisplay dpy, EGLConfig config, EGLint type, EglDisplay** out) {
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return nullptr;
  const FramebufferConfig* c = findConfig(*d, config);
  if (!c) return nullptr;
  if (!(surfaceTypes(*d, *c) & type)) return fail(EGL_BAD_MATCH, nullptr);
  *out = d;
  return c;
}

EGLSurface newWindowSurface(EGLDisplay dpy, EGLConfig config, Window window, const EGLAttrib* attribs) {
  EglDisplay* d = nullptr;
  const FramebufferConfig* c = surfaceConfig(dpy, config, EGL_WINDOW_BIT, &d);
  if (!c) return EGL_NO_SURFACE;
  EGLint renderBuffer = EGL_BACK_BUFFER;
  for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    if (attribs[i] == EGL_RENDER_BUFFER) {
      if (attribs[i + 1] != EGL_BACK_BUFFER && attribs[i + 1] != EGL_SINGLE_BUFFER)
        return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
      renderBuffer = static_cast<EGLint>(attribs[i + 1]);
      continue;
    }
    const EGLint e = commonAttrib(attribs[i], attribs[i + 1]);
    if (e != EGL_SUCCESS) return fail(e, EGL_NO_SURFACE);
  }
  int width, height, depth;
  if (!window || !glfixed::platform::x11DrawableSize(d->x11, window, &width, &height, &depth))
    return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
  // One EGL surface per window (§3.5.1).
  for (const auto& s : d->surfaces)
    if (s->type == EGL_WINDOW_BIT && s->nativeHandle == window) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  if (!d->drawableVisual(*c, depth)) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  auto presenter = glfixed::platform::makeX11Presenter(d->x11, window, nullptr);
  if (!presenter) return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
  auto s = std::make_unique<EglSurface>();
  s->type = EGL_WINDOW_BIT;
  s->config = c;
  s->nativeHandle = window;
  s->renderBuffer = renderBuffer;
  s->surface = std::make_unique<glfixed::platform::Surface>(width, height, renderBuffer == EGL_BACK_BUFFER,
                                                            c->alphaBits, std::move(presenter));
  return addSurface(*d, std::move(s));
}

EGLSurface createWindowSurface(EGLDisplay dpy, EGLConfig config, Window window, const EGLAttrib* attribs) {
  Lock lock(registryMutex());
  return guarded(EGL_NO_SURFACE, [&] { return newWindowSurface(dpy, config, window, attribs); });
}

EGLSurface newPixmapSurface(EGLDisplay dpy, EGLConfig config, Pixmap pixmap, const EGLAttrib* attribs) {
  EglDisplay* d = nullptr;
  const FramebufferConfig* c = surfaceConfig(dpy, config, EGL_PIXMAP_BIT, &d);
  if (!c) return EGL_NO_SURFACE;
  for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    const EGLint e = commonAttrib(attribs[i], attribs[i + 1]);
    if (e != EGL_SUCCESS) return fail(e, EGL_NO_SURFACE);
  }
  int width, height, depth;
  if (!pixmap || !glfixed::platform::x11DrawableSize(d->x11, pixmap, &width, &height, &depth))
    return fail(EGL_BAD_NATIVE_PIXMAP, EGL_NO_SURFACE);
  Visual* visual = d->drawableVisual(*c, depth);
  if (!visual) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  auto presenter = glfixed::platform::makeX11Presenter(d->x11, pixmap, visual);
  if (!presenter) return fail(EGL_BAD_NATIVE_PIXMAP, EGL_NO_SURFACE);
  auto s = std::make_unique<EglSurface>();
  s->type = EGL_PIXMAP_BIT;
  s->config = c;
  s->nativeHandle = pixmap;
  s->renderBuffer = EGL_SINGLE_BUFFER;
  s->surface =
      std::make_unique<glfixed::platform::Surface>(width, height, false, c->alphaBits, std::move(presenter));
  return addSurface(*d, std::move(s));
}

EGLSurface createPixmapSurface(EGLDisplay dpy, EGLConfig config, Pixmap pixmap, const EGLAttrib* attribs) {
  Lock lock(registryMutex());
  return guarded(EGL_NO_SURFACE, [&] { return newPixmapSurface(dpy, config, pixmap, attribs); });
}

// The calling thread's context, if `s` is its draw surface.
EglContext* contextDrawingTo(const EglSurface* s) {
  EglContext* c = thread().context;
  return c && c->draw == s ? c : nullptr;
}

}  // namespace

// EGLAPI is empty on Linux: the entry points are made visible here.
#pragma GCC visibility push(default)
extern "C" {

EGLAPI EGLSurface EGLAPIENTRY eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config,
                                                     EGLNativeWindowType win, const EGLint* attrib_list) {
  return createWindowSurface(dpy, config, static_cast<Window>(win), widen(attrib_list).data());
}

// The platform variants take a pointer to the Window (EGL_KHR_platform_x11).
EGLAPI EGLSurface EGLAPIENTRY eglCreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig config,
                                                             void* native_window,
                                                             const EGLAttrib* attrib_list) {
  const Window window = native_window ? *static_cast<const Window*>(native_window) : 0;
  return createWindowSurface(dpy, config, window, attrib_list);
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePlatformWindowSurfaceEXT(EGLDisplay dpy, EGLConfig config,
                                                                void* native_window,
                                                                const EGLint* attrib_list) {
  const Window window = native_window ? *static_cast<const Window*>(native_window) : 0;
  return createWindowSurface(dpy, config, window, widen(attrib_list).data());
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePixmapSurface(EGLDisplay dpy, EGLConfig config,
                                                     EGLNativePixmapType pixmap, const EGLint* attrib_list) {
  return createPixmapSurface(dpy, config, static_cast<Pixmap>(pixmap), widen(attrib_list).data());
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig config,
                                                             void* native_pixmap,
                                                             const EGLAttrib* attrib_list) {
  const Pixmap pixmap = native_pixmap ? *static_cast<const Pixmap*>(native_pixmap) : 0;
  return createPixmapSurface(dpy, config, pixmap, attrib_list);
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePlatformPixmapSurfaceEXT(EGLDisplay dpy, EGLConfig config,
                                                                void* native_pixmap,
                                                                const EGLint* attrib_list) {
  const Pixmap pixmap = native_pixmap ? *static_cast<const Pixmap*>(native_pixmap) : 0;
  return createPixmapSurface(dpy, config, pixmap, widen(attrib_list).data());
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePbufferSurface(EGLDisplay dpy, EGLConfig config,
                                                      const EGLint* attrib_list) {
  Lock lock(registryMutex());
  EglDisplay* d = nullptr;
  const FramebufferConfig* c = surfaceConfig(dpy, config, EGL_PBUFFER_BIT, &d);
  if (!c) return EGL_NO_SURFACE;
  EGLint width = 0, height = 0;
  bool largest = false;
  for (int i = 0; attrib_list && attrib_list[i] != EGL_NONE; i += 2) {
    const EGLint value = attrib_list[i + 1];
    switch (attrib_list[i]) {
      case EGL_WIDTH: width = value; break;
      case EGL_HEIGHT: height = value; break;
      case EGL_LARGEST_PBUFFER: largest = value != EGL_FALSE; break;
      // No configuration binds to a texture (EGL_BIND_TO_TEXTURE_*: false).
      case EGL_TEXTURE_FORMAT:
      case EGL_TEXTURE_TARGET:
        if (value == EGL_NO_TEXTURE) break;
        if (value == EGL_TEXTURE_RGB || value == EGL_TEXTURE_RGBA || value == EGL_TEXTURE_2D)
          return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
        return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
      case EGL_MIPMAP_TEXTURE: break;
      default: {
        const EGLint e = commonAttrib(attrib_list[i], value);
        if (e != EGL_SUCCESS) return fail(e, EGL_NO_SURFACE);
      }
    }
  }
  if (width < 0 || height < 0) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  if (width > glfixed::kMaxViewportSize || height > glfixed::kMaxViewportSize) {
    if (!largest) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
    width = std::min(width, glfixed::kMaxViewportSize);
    height = std::min(height, glfixed::kMaxViewportSize);
  }
  auto s = std::make_unique<EglSurface>();
  s->type = EGL_PBUFFER_BIT;
  s->config = c;
  s->requestedWidth = width;
  s->requestedHeight = height;
  s->largestPbuffer = largest;
  s->renderBuffer = EGL_BACK_BUFFER;
  // Mesa's pbuffers draw to GL_BACK (MESA_FACTS.md, "EGL"): a back buffer
  // that no swap ever shows. A 0x0 pbuffer holds one pixel.
  try {
    s->surface = std::make_unique<glfixed::platform::Surface>(std::max(width, 1), std::max(height, 1), true,
                                                              c->alphaBits, nullptr);
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  }
  return addSurface(*d, std::move(s));
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum buftype,
                                                               EGLClientBuffer buffer, EGLConfig config,
                                                               const EGLint* attrib_list) {
  Lock lock(registryMutex());
  if (!initializedDisplay(dpy)) return EGL_NO_SURFACE;
  // The only client buffers EGL names are OpenVG images, and there is no OpenVG.
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroySurface(EGLDisplay dpy, EGLSurface surface) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglSurface* s = findSurface(*d, surface);
  if (!s) return EGL_FALSE;
  auto it = std::find_if(d->surfaces.begin(), d->surfaces.end(), [s](const auto& p) { return p.get() == s; });
  // §3.5.5: a bound surface lives on until no context holds it.
  if (s->boundCount > 0) {
    s->destroyed = true;
    d->doomedSurfaces.push_back(std::move(*it));
  }
  d->surfaces.erase(it);
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglQuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attribute,
                                              EGLint* value) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  const EglSurface* s = findSurface(*d, surface);
  if (!s) return EGL_FALSE;
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  switch (attribute) {
    case EGL_CONFIG_ID: *value = s->config->id; break;
    case EGL_WIDTH:
    case EGL_HEIGHT: {
      int w = s->surface->width(), h = s->surface->height(), depth;
      if (s->type == EGL_PBUFFER_BIT) {
        w = s->requestedWidth;
        h = s->requestedHeight;
      } else if (s->type == EGL_WINDOW_BIT) {
        glfixed::platform::x11DrawableSize(d->x11, s->nativeHandle, &w, &h,
                                           &depth);  // the window as it is now
      }
      *value = attribute == EGL_WIDTH ? w : h;
      break;
    }
    case EGL_LARGEST_PBUFFER:
      if (s->type == EGL_PBUFFER_BIT) *value = s->largestPbuffer;  // others: left as it was (§3.5.6)
      break;
    case EGL_RENDER_BUFFER: *value = s->renderBuffer; break;
    case EGL_SWAP_BEHAVIOR: *value = s->swapBehavior; break;
    case EGL_MULTISAMPLE_RESOLVE: *value = s->multisampleResolve; break;
    case EGL_TEXTURE_FORMAT:
    case EGL_TEXTURE_TARGET: *value = EGL_NO_TEXTURE; break;
    case EGL_MIPMAP_TEXTURE: *value = EGL_FALSE; break;
    case EGL_MIPMAP_LEVEL: *value = 0; break;
    case EGL_HORIZONTAL_RESOLUTION:
    case EGL_VERTICAL_RESOLUTION:
    case EGL_PIXEL_ASPECT_RATIO: *value = EGL_UNKNOWN; break;
    case EGL_GL_COLORSPACE: *value = EGL_GL_COLORSPACE_LINEAR; break;
    case EGL_VG_ALPHA_FORMAT: *value = EGL_VG_ALPHA_FORMAT_NONPRE; break;
    case EGL_VG_COLORSPACE: *value = EGL_VG_COLORSPACE_sRGB; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglSurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute,
                                               EGLint value) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglSurface* s = findSurface(*d, surface);
  if (!s) return EGL_FALSE;
  switch (attribute) {
    case EGL_MIPMAP_LEVEL:
      break;  // no effect on a surface that is not a texture
    // No configuration has EGL_MULTISAMPLE_RESOLVE_BOX_BIT or
    // EGL_SWAP_BEHAVIOR_PRESERVED_BIT (§3.5.6).
    case EGL_MULTISAMPLE_RESOLVE:
      if (value == EGL_MULTISAMPLE_RESOLVE_BOX) return fail(EGL_BAD_MATCH, EGL_FALSE);
      if (value != EGL_MULTISAMPLE_RESOLVE_DEFAULT) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
      break;
    case EGL_SWAP_BEHAVIOR:
      if (value == EGL_BUFFER_PRESERVED) return fail(EGL_BAD_MATCH, EGL_FALSE);
      if (value != EGL_BUFFER_DESTROYED) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
      break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglSwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglSurface* s = findSurface(*d, surface);
  if (!s) return EGL_FALSE;
  // §3.10.1: only the draw surface of the calling thread's context.
  EglContext* c = contextDrawingTo(s);
  if (!c) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  glfixed::pipeline::flushVertices(*c->context);
  glfixed::pipeline::flushBitmapCache(*c->context);
  if (s->type != EGL_WINDOW_BIT) return succeed(EGL_TRUE);  // pbuffers and pixmaps: no effect
  // The swap reallocates the buffers of a window whose size changed.
  return guarded(EGL_FALSE, [s] {
    s->surface->swapBuffers();
    return succeed(EGL_TRUE);
  });
}

EGLAPI EGLBoolean EGLAPIENTRY eglSwapInterval(EGLDisplay dpy, EGLint interval) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglContext* c = thread().context;
  if (!c || c->display != d) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  if (!c->draw) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  c->draw->swapInterval = std::clamp(interval, 0, 1);  // EGL_MIN/MAX_SWAP_INTERVAL
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglCopyBuffers(EGLDisplay dpy, EGLSurface surface, EGLNativePixmapType target) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglSurface* s = findSurface(*d, surface);
  if (!s) return EGL_FALSE;
  const Pixmap pixmap = static_cast<Pixmap>(target);
  int width, height, depth;
  if (d->platform != Platform::kX11 || !pixmap ||
      !glfixed::platform::x11DrawableSize(d->x11, pixmap, &width, &height, &depth))
    return fail(EGL_BAD_NATIVE_PIXMAP, EGL_FALSE);
  Visual* visual = d->drawableVisual(*s->config, depth);
  if (!visual) return fail(EGL_BAD_MATCH, EGL_FALSE);
  auto presenter = glfixed::platform::makeX11Presenter(d->x11, pixmap, visual);
  if (!presenter) return fail(EGL_BAD_NATIVE_PIXMAP, EGL_FALSE);
  // §3.10.3: the surface's colour buffer, after what was drawn into it.
  if (EglContext* c = contextDrawingTo(s)) glfixed::pipeline::flushVertices(*c->context);
  presenter->present(s->surface->doubleBuffered() ? s->surface->backView() : s->surface->frontView());
  return succeed(EGL_TRUE);
}

// No surface is a texture (EGL_TEXTURE_FORMAT is EGL_NO_TEXTURE): §3.6.1.
EGLAPI EGLBoolean EGLAPIENTRY eglBindTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d || !findSurface(*d, surface)) return EGL_FALSE;
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  return fail(EGL_BAD_MATCH, EGL_FALSE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglReleaseTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  return eglBindTexImage(dpy, surface, buffer);
}

}  // extern "C"
#pragma GCC visibility pop
