// The OpenGL version the library reports in GL_VERSION, in one place: the
// window-system layers compare a context's requested version with it
// (EGL_CONTEXT_MAJOR_VERSION, GLX_CONTEXT_MAJOR_VERSION_ARB).
#pragma once

namespace glfixed {

constexpr int kGLMajorVersion = 2;
constexpr int kGLMinorVersion = 1;

}  // namespace glfixed
