// What the library says it is (../shared/DROPIN.md, "Say only what is true"):
// programs choose their code paths from GL_VERSION, GL_EXTENSIONS and
// GetProcAddress, so these promise only what works.
//
// GL 2.0 needs GLSL, which the library does not have: the version is 1.5,
// the last one without shaders. Textures, fog, blending, stencil and the
// pixel rectangles of GL 1.0-1.4 come later (issues 14 and 15); no version
// can be claimed without them, and programs use them at any version.
// The extensions listed are those whose every command and enum works.
#pragma once

namespace glfixed {

constexpr int kGLMajorVersion = 1;
constexpr int kGLMinorVersion = 5;
constexpr const char* kGLVersionString = "1.5 libglfixed 0.1.0";
constexpr const char* kGLVendorString = "libglfixed";
constexpr const char* kGLRendererString = "libglfixed fixed-function software renderer";
constexpr const char* kGLExtensionsString =
    "GL_ARB_point_parameters GL_ARB_provoking_vertex GL_ARB_transpose_matrix GL_ARB_vertex_buffer_object "
    "GL_EXT_draw_range_elements GL_EXT_multi_draw_arrays GL_EXT_point_parameters GL_EXT_provoking_vertex "
    "GL_EXT_rescale_normal GL_EXT_separate_specular_color GL_EXT_vertex_array ";  // a space after the last name, as Mesa's (piglit's glinfo prints it as it is)

// True if a context of version major.minor can be had (the library's own
// version or an earlier one): glXCreateContextAttribsARB, eglCreateContext.
constexpr bool glVersionAvailable(int major, int minor) {
  return major < kGLMajorVersion || (major == kGLMajorVersion && minor <= kGLMinorVersion);
}

}  // namespace glfixed
