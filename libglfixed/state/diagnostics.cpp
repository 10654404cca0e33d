#include "state/diagnostics.h"

#include <dlfcn.h>
#include <execinfo.h>
#include <link.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace glfixed {

namespace {

const char* errorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return nullptr;
  }
}

// The exported entry point on the call stack: the innermost frame that lies
// inside an exported symbol of this library. Internal functions are hidden, so
// dladdr alone would name the nearest exported symbol before them; the
// symbol's extent [st_value, st_value + st_size) says whether the frame really
// is inside it. The api/ sources are compiled without sibling calls
// (CMakeLists.txt), so an entry point's frame stays on the stack.
const char* entryPointOnStack() {
  Dl_info self;
  if (!dladdr(reinterpret_cast<void*>(&reportError), &self)) return nullptr;
  void* frames[64];
  const int count = backtrace(frames, 64);
  for (int i = 0; i < count; ++i) {
    // A return address: the call instruction ends just before it.
    const uintptr_t pc = reinterpret_cast<uintptr_t>(frames[i]) - 1;
    Dl_info info;
    void* symbol = nullptr;
    if (!dladdr1(reinterpret_cast<void*>(pc), &info, &symbol, RTLD_DL_SYMENT)) continue;
    if (info.dli_fbase != self.dli_fbase || !symbol || !info.dli_sname) continue;
    const uintptr_t start = reinterpret_cast<uintptr_t>(info.dli_saddr);
    if (pc >= start && pc < start + static_cast<const ElfW(Sym)*>(symbol)->st_size) return info.dli_sname;
  }
  return nullptr;
}

}  // namespace

bool debugOutputEnabled() {
  static const bool enabled = [] {
    const char* value = std::getenv("GLFIXED_DEBUG");
    return value && *value && std::strcmp(value, "0") != 0;
  }();
  return enabled;
}

void reportError(GLenum error) {
  const char* entryPoint = entryPointOnStack();
  if (!entryPoint) entryPoint = "(unknown entry point)";
  if (const char* name = errorName(error))
    std::fprintf(stderr, "libglfixed: %s in %s\n", name, entryPoint);
  else
    std::fprintf(stderr, "libglfixed: GL error 0x%04X in %s\n", error, entryPoint);
}

}  // namespace glfixed
