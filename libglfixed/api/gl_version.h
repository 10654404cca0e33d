// The GL version the library reports, in one place: GL_VERSION
// (api/gl_get_api.cpp) and the version checks of context creation
// (glXCreateContextAttribsARB, eglCreateContext) read it here.
#pragma once

namespace glfixed::api {

constexpr int kGlVersionMajor = 2;
constexpr int kGlVersionMinor = 1;
constexpr const char* kGlVersionString = "2.1 libglfixed 0.1";

// True if a context of version major.minor can be had (the library's own
// version or an earlier one).
constexpr bool glVersionAvailable(int major, int minor) {
  return major < kGlVersionMajor || (major == kGlVersionMajor && minor <= kGlVersionMinor);
}

}  // namespace glfixed::api
