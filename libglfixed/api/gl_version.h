// What the library says it is (../shared/DROPIN.md, "Say only what is true"):
// programs choose their code paths from GL_VERSION, GL_EXTENSIONS and
// GetProcAddress, so these promise only what works.
//
// GL 2.0 needs GLSL, which the library does not have: the version is 1.5,
// the last one without shaders. Blending and the logic op
// (fragment/blend.inc), the stencil test, fog (fragment/fog.inc) and most
// pixel rectangles are here; so are framebuffer objects (ARB and
// EXT_framebuffer_object, EXT_framebuffer_blit), with EXT_packed_depth_stencil
// (renderbuffers, textures, and the pixel commands of GL_DEPTH_STENCIL).
// The extensions listed are those whose every command and enum works.
#pragma once

namespace glfixed {

constexpr int kGLMajorVersion = 1;
constexpr int kGLMinorVersion = 5;
constexpr const char* kGLVersionString = "1.5 libglfixed 0.1.0";
constexpr const char* kGLVendorString = "libglfixed";
constexpr const char* kGLRendererString = "libglfixed fixed-function software renderer";
constexpr const char* kGLExtensionsString =
    "GL_ARB_copy_buffer GL_ARB_depth_clamp GL_ARB_depth_texture GL_ARB_draw_elements_base_vertex GL_ARB_framebuffer_object GL_ARB_map_buffer_range "
    "GL_ARB_multisample GL_ARB_multitexture GL_ARB_occlusion_query GL_ARB_pixel_buffer_object "
    "GL_ARB_point_parameters GL_ARB_point_sprite GL_ARB_provoking_vertex "
    "GL_ARB_shadow GL_ARB_texture_border_clamp "
    "GL_ARB_texture_cube_map GL_ARB_texture_env_add GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar "
    "GL_ARB_texture_env_dot3 GL_ARB_texture_float GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two "
    "GL_ARB_transpose_matrix GL_ARB_vertex_array_object GL_ARB_vertex_buffer_object GL_ARB_window_pos GL_ATI_blend_equation_separate "
    "GL_ATI_separate_stencil GL_EXT_bgra "
    "GL_EXT_blend_color GL_EXT_blend_equation_separate GL_EXT_blend_func_separate GL_EXT_blend_minmax "
    "GL_EXT_blend_subtract GL_EXT_copy_texture "
    "GL_EXT_draw_range_elements GL_EXT_fog_coord GL_EXT_framebuffer_blit GL_EXT_framebuffer_object "
    "GL_EXT_multi_draw_arrays GL_EXT_packed_depth_stencil GL_EXT_packed_pixels GL_EXT_pixel_buffer_object "
    "GL_EXT_point_parameters GL_EXT_provoking_vertex GL_EXT_rescale_normal GL_EXT_separate_specular_color "
    "GL_EXT_shadow_funcs GL_EXT_stencil_two_side GL_EXT_stencil_wrap GL_EXT_subtexture "
    "GL_EXT_texture GL_EXT_texture3D GL_EXT_texture_edge_clamp GL_EXT_texture_env_add "
    "GL_EXT_texture_env_combine GL_EXT_texture_env_dot3 GL_EXT_texture_lod_bias GL_EXT_texture_object "
    "GL_EXT_vertex_array GL_EXT_vertex_array_bgra GL_INGR_blend_func_separate GL_MESA_pack_invert GL_NV_blend_square GL_NV_fog_distance GL_NV_primitive_restart GL_SGIS_generate_mipmap GL_SGIS_texture_border_clamp GL_SGIS_texture_edge_clamp "
    "GL_SGIS_texture_lod ";  // a space after the last name, as Mesa's (piglit's glinfo prints it as it is)

// True if a context of version major.minor can be had (the library's own
// version or an earlier one): glXCreateContextAttribsARB, eglCreateContext.
constexpr bool glVersionAvailable(int major, int minor) {
  return major < kGLMajorVersion || (major == kGLMajorVersion && minor <= kGLMinorVersion);
}

}  // namespace glfixed
