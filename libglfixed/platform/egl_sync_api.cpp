// EGL 1.5 fences (§3.8) and images (§3.9). The library draws synchronously
// once a context's buffered vertices are flushed, so a fence is signaled
// when it is made. No client buffer or texture can become an EGLImage.
#include <EGL/egl.h>

#include <algorithm>

#include "pipeline/immediate_mode.h"
#include "platform/egl_objects.h"

using namespace glfixed::platform::egl;

namespace {

using Lock = std::lock_guard<std::mutex>;

EglSync* findSync(EglDisplay& d, EGLSync handle) {
  for (const auto& s : d.syncs)
    if (s.get() == handle) return s.get();
  return fail(EGL_BAD_PARAMETER, nullptr);
}

// The calling thread's context, if it belongs to `d` (§3.8.1: EGL_BAD_MATCH otherwise).
EglContext* currentOn(const EglDisplay& d) {
  EglContext* c = thread().context;
  return c && c->display == &d ? c : nullptr;
}

}  // namespace

// EGLAPI is empty on Linux: the entry points are made visible here.
#pragma GCC visibility push(default)
extern "C" {

EGLAPI EGLSync EGLAPIENTRY eglCreateSync(EGLDisplay dpy, EGLenum type, const EGLAttrib* attrib_list) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_NO_SYNC;
  if (type != EGL_SYNC_FENCE) return fail(EGL_BAD_PARAMETER, EGL_NO_SYNC);
  if (attrib_list && attrib_list[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SYNC);
  EglContext* c = currentOn(*d);
  if (!c) return fail(EGL_BAD_MATCH, EGL_NO_SYNC);
  glfixed::pipeline::flushVertices(*c->context);
  d->syncs.push_back(std::make_unique<EglSync>());
  return succeed(static_cast<EGLSync>(d->syncs.back().get()));
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroySync(EGLDisplay dpy, EGLSync sync) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d) return EGL_FALSE;
  EglSync* s = findSync(*d, sync);
  if (!s) return EGL_FALSE;
  d->syncs.erase(std::find_if(d->syncs.begin(), d->syncs.end(), [s](const auto& p) { return p.get() == s; }));
  return succeed(EGL_TRUE);
}

EGLAPI EGLint EGLAPIENTRY eglClientWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags, EGLTime timeout) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d || !findSync(*d, sync)) return EGL_FALSE;
  return succeed(EGL_CONDITION_SATISFIED);
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d || !findSync(*d, sync)) return EGL_FALSE;
  if (flags != 0) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  if (!currentOn(*d)) return fail(EGL_BAD_MATCH, EGL_FALSE);
  return succeed(EGL_TRUE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglGetSyncAttrib(EGLDisplay dpy, EGLSync sync, EGLint attribute,
                                               EGLAttrib* value) {
  Lock lock(registryMutex());
  EglDisplay* d = initializedDisplay(dpy);
  if (!d || !findSync(*d, sync)) return EGL_FALSE;
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  switch (attribute) {
    case EGL_SYNC_TYPE: *value = EGL_SYNC_FENCE; break;
    case EGL_SYNC_STATUS: *value = EGL_SIGNALED; break;
    case EGL_SYNC_CONDITION: *value = EGL_SYNC_PRIOR_COMMANDS_COMPLETE; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  return succeed(EGL_TRUE);
}

EGLAPI EGLImage EGLAPIENTRY eglCreateImage(EGLDisplay dpy, EGLContext ctx, EGLenum target,
                                           EGLClientBuffer buffer, const EGLAttrib* attrib_list) {
  Lock lock(registryMutex());
  if (!initializedDisplay(dpy)) return EGL_NO_IMAGE;
  return fail(EGL_BAD_PARAMETER, EGL_NO_IMAGE);  // no target is supported
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroyImage(EGLDisplay dpy, EGLImage image) {
  Lock lock(registryMutex());
  if (!initializedDisplay(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_PARAMETER, EGL_FALSE);  // there are no images
}

}  // extern "C"
#pragma GCC visibility pop
