#include "api/entry_points.h"

#include <GL/gl.h>
#include <GL/osmesa.h>
// GLX (platform/glx*.cpp): the declarations of the GLX block below.
#define GLX_GLXEXT_PROTOTYPES
#include <GL/glx.h>

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

const Entry* find(const char* name) {
  if (!name) return nullptr;
  for (const Entry& e : kGlEntries)
    if (std::strcmp(e.name, name) == 0) return &e;
  for (const Entry& e : kOsmesaEntries)
    if (std::strcmp(e.name, name) == 0) return &e;
  for (const Entry& e : kGlxEntries)
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
