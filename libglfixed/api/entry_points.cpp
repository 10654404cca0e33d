#include "api/entry_points.h"

#include <GL/gl.h>
#include <GL/osmesa.h>
// GLX (platform/glx*.cpp): the declarations of the GLX block below.
#define GLX_GLXEXT_PROTOTYPES
#include <GL/glx.h>
// EGL (platform/egl*.cpp): eglGetProcAddress answers EGL names too.
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <string>

#include "state/context.h"

namespace glfixed::api {

namespace {

// A command that is exported but not implemented: say so (once, when
// GLFIXED_DEBUG is set), record GL_INVALID_OPERATION, return a harmless value.
template <typename T>
T unimplemented(const char* name) {
  if (debugOutputEnabled()) {
    static std::mutex m;
    static std::set<std::string> said;
    std::lock_guard<std::mutex> lock(m);
    if (said.insert(name).second) std::fprintf(stderr, "libglfixed: %s is not implemented\n", name);
  }
  if (Context* ctx = currentContext()) ctx->recordError(GL_INVALID_OPERATION);
  return T();
}
template <>
void unimplemented<void>(const char* name) {
  unimplemented<int>(name);
}

}  // namespace

}  // namespace glfixed::api

// Every command of gl.h gets a weak definition that forwards to its stub; the
// real entry point, where one exists, is a strong definition and wins at link
// time. Comparing the two addresses tells which commands are implemented.
#define GLFX_COMMAND(ret, name, params, args)                                    \
  extern "C" ret glfx_stub_##name params { return glfixed::api::unimplemented<ret>(#name); } \
  extern "C" GLAPI ret APIENTRY name params __attribute__((weak, alias("glfx_stub_" #name)));
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "api/gl_commands.inc"
#pragma GCC diagnostic pop
#undef GLFX_COMMAND

// EGL programs: Debian's xscreensaver GL hacks, linked BIND_NOW, import
// glGenerateMipmap (GL 3.0) and do not start without it. A stub like those
// above: it records GL_INVALID_OPERATION and its name resolves to null.
extern "C" void glfx_stub_glGenerateMipmap(GLenum target) {
  glfixed::api::unimplemented<void>("glGenerateMipmap");
}
extern "C" GLAPI void APIENTRY glGenerateMipmap(GLenum target)
    __attribute__((weak, alias("glfx_stub_glGenerateMipmap")));
// Textures: the EXT_framebuffer_object name of glGenerateMipmap (api/gl_tex_image_api.cpp).
extern "C" GLAPI void APIENTRY glGenerateMipmapEXT(GLenum target);

namespace glfixed::api {

namespace {

struct Entry {
  const char* name;
  void* address;
  void* stub;
};

#define GLFX_COMMAND(ret, name, params, args) \
  {#name, reinterpret_cast<void*>(&name), reinterpret_cast<void*>(&glfx_stub_##name)},
const Entry kGlEntries[] = {
#include "api/gl_commands.inc"
};
#undef GLFX_COMMAND

#define OSMESA_ENTRY(name) {#name, reinterpret_cast<void*>(&name), nullptr}
const Entry kOsmesaEntries[] = {
    OSMESA_ENTRY(OSMesaCreateContext),  OSMESA_ENTRY(OSMesaCreateContextExt),
    OSMESA_ENTRY(OSMesaCreateContextAttribs), OSMESA_ENTRY(OSMesaDestroyContext),
    OSMESA_ENTRY(OSMesaMakeCurrent),    OSMESA_ENTRY(OSMesaGetCurrentContext),
    OSMESA_ENTRY(OSMesaPixelStore),     OSMESA_ENTRY(OSMesaGetIntegerv),
    OSMESA_ENTRY(OSMesaGetDepthBuffer), OSMESA_ENTRY(OSMesaGetColorBuffer),
    OSMESA_ENTRY(OSMesaGetProcAddress), OSMESA_ENTRY(OSMesaColorClamp),
    OSMESA_ENTRY(OSMesaPostprocess),
};
#undef OSMESA_ENTRY

// GLX (platform/glx*.cpp): GLX 1.4 and the GLX extensions offered, so that
// glXGetProcAddress answers for GLX names too.
#define GLX_ENTRY(name) {#name, reinterpret_cast<void*>(&name), nullptr}
const Entry kGlxEntries[] = {
    GLX_ENTRY(glXChooseVisual),          GLX_ENTRY(glXCreateContext),
    GLX_ENTRY(glXDestroyContext),        GLX_ENTRY(glXMakeCurrent),
    GLX_ENTRY(glXCopyContext),           GLX_ENTRY(glXSwapBuffers),
    GLX_ENTRY(glXCreateGLXPixmap),       GLX_ENTRY(glXDestroyGLXPixmap),
    GLX_ENTRY(glXQueryExtension),        GLX_ENTRY(glXQueryVersion),
    GLX_ENTRY(glXIsDirect),              GLX_ENTRY(glXGetConfig),
    GLX_ENTRY(glXGetCurrentContext),     GLX_ENTRY(glXGetCurrentDrawable),
    GLX_ENTRY(glXWaitGL),                GLX_ENTRY(glXWaitX),
    GLX_ENTRY(glXUseXFont),              GLX_ENTRY(glXQueryExtensionsString),
    GLX_ENTRY(glXQueryServerString),     GLX_ENTRY(glXGetClientString),
    GLX_ENTRY(glXGetCurrentDisplay),     GLX_ENTRY(glXGetFBConfigs),
    GLX_ENTRY(glXChooseFBConfig),        GLX_ENTRY(glXGetFBConfigAttrib),
    GLX_ENTRY(glXGetVisualFromFBConfig), GLX_ENTRY(glXCreateWindow),
    GLX_ENTRY(glXDestroyWindow),         GLX_ENTRY(glXCreatePixmap),
    GLX_ENTRY(glXDestroyPixmap),         GLX_ENTRY(glXCreatePbuffer),
    GLX_ENTRY(glXDestroyPbuffer),        GLX_ENTRY(glXQueryDrawable),
    GLX_ENTRY(glXCreateNewContext),      GLX_ENTRY(glXMakeContextCurrent),
    GLX_ENTRY(glXGetCurrentReadDrawable), GLX_ENTRY(glXQueryContext),
    GLX_ENTRY(glXSelectEvent),           GLX_ENTRY(glXGetSelectedEvent),
    GLX_ENTRY(glXGetProcAddress),        GLX_ENTRY(glXGetProcAddressARB),
    GLX_ENTRY(glXCreateContextAttribsARB), GLX_ENTRY(glXQueryContextInfoEXT),
    GLX_ENTRY(glXSwapIntervalEXT),       GLX_ENTRY(glXSwapIntervalMESA),
    GLX_ENTRY(glXGetSwapIntervalMESA),   GLX_ENTRY(glXSwapIntervalSGI),
};
#undef GLX_ENTRY
// EGL (platform/egl*.cpp): every EGL 1.5 entry point and the extension
// names of the client and display extensions offered.
#define EGL_ENTRY(name) {#name, reinterpret_cast<void*>(&name), nullptr}
const Entry kEglEntries[] = {
    EGL_ENTRY(eglBindAPI), EGL_ENTRY(eglBindTexImage), EGL_ENTRY(eglChooseConfig),
    EGL_ENTRY(eglClientWaitSync), EGL_ENTRY(eglCopyBuffers), EGL_ENTRY(eglCreateContext),
    EGL_ENTRY(eglCreateImage), EGL_ENTRY(eglCreatePbufferFromClientBuffer),
    EGL_ENTRY(eglCreatePbufferSurface),
    EGL_ENTRY(eglCreatePixmapSurface), EGL_ENTRY(eglCreatePlatformPixmapSurface),
    EGL_ENTRY(eglCreatePlatformPixmapSurfaceEXT), EGL_ENTRY(eglCreatePlatformWindowSurface),
    EGL_ENTRY(eglCreatePlatformWindowSurfaceEXT), EGL_ENTRY(eglCreateSync), EGL_ENTRY(eglCreateWindowSurface),
    EGL_ENTRY(eglDestroyContext), EGL_ENTRY(eglDestroyImage), EGL_ENTRY(eglDestroySurface),
    EGL_ENTRY(eglDestroySync), EGL_ENTRY(eglGetConfigAttrib), EGL_ENTRY(eglGetConfigs),
    EGL_ENTRY(eglGetCurrentContext), EGL_ENTRY(eglGetCurrentDisplay), EGL_ENTRY(eglGetCurrentSurface),
    EGL_ENTRY(eglGetDisplay), EGL_ENTRY(eglGetError), EGL_ENTRY(eglGetPlatformDisplay),
    EGL_ENTRY(eglGetPlatformDisplayEXT), EGL_ENTRY(eglGetProcAddress), EGL_ENTRY(eglGetSyncAttrib),
    EGL_ENTRY(eglInitialize), EGL_ENTRY(eglMakeCurrent), EGL_ENTRY(eglQueryAPI), EGL_ENTRY(eglQueryContext),
    EGL_ENTRY(eglQueryString), EGL_ENTRY(eglQuerySurface), EGL_ENTRY(eglReleaseTexImage),
    EGL_ENTRY(eglReleaseThread), EGL_ENTRY(eglSurfaceAttrib), EGL_ENTRY(eglSwapBuffers),
    EGL_ENTRY(eglSwapInterval), EGL_ENTRY(eglTerminate), EGL_ENTRY(eglWaitClient), EGL_ENTRY(eglWaitGL),
    EGL_ENTRY(eglWaitNative), EGL_ENTRY(eglWaitSync),
    {"glGenerateMipmap", reinterpret_cast<void*>(&glGenerateMipmap),
     reinterpret_cast<void*>(&glfx_stub_glGenerateMipmap)},
    {"glGenerateMipmapEXT", reinterpret_cast<void*>(&glGenerateMipmapEXT), nullptr},  // textures
};
#undef EGL_ENTRY

const Entry* find(const char* name) {
  if (!name) return nullptr;
  for (const Entry& e : kGlEntries)
    if (std::strcmp(e.name, name) == 0) return &e;
  for (const Entry& e : kOsmesaEntries)
    if (std::strcmp(e.name, name) == 0) return &e;
  for (const Entry& e : kGlxEntries)  // GLX
    if (std::strcmp(e.name, name) == 0) return &e;
  for (const Entry& e : kEglEntries)  // EGL
    if (std::strcmp(e.name, name) == 0) return &e;
  return nullptr;
}

}  // namespace

bool isImplemented(const char* name) {
  const Entry* e = find(name);
  return e && e->address != e->stub;
}

void* procAddress(const char* name) {
  if (isImplemented(name)) return find(name)->address;
  return extensionAliasAddress(name);
}

}  // namespace glfixed::api
