// The ARB and EXT names legacy programs call for the vertex array and buffer
// object commands (ARB_vertex_buffer_object, EXT_draw_range_elements,
// EXT_multi_draw_arrays, ARB_multitexture's glClientActiveTextureARB,
// ARB/EXT_point_parameters, ARB_transpose_matrix, EXT_vertex_array): the
// same functions under their extension names, exported and known to
// OSMesaGetProcAddress. Mesa's gl.h/glext.h declare them; ours does not.
#include <GL/gl.h>

#include <cstring>

#include "api/entry_points.h"
#include "api/framebuffer_object_commands.h"

extern "C" {

GLAPI void APIENTRY glBindBufferARB(GLenum target, GLuint buffer) { glBindBuffer(target, buffer); }
GLAPI void APIENTRY glDeleteBuffersARB(GLsizei n, const GLuint* buffers) { glDeleteBuffers(n, buffers); }
GLAPI void APIENTRY glGenBuffersARB(GLsizei n, GLuint* buffers) { glGenBuffers(n, buffers); }
GLAPI GLboolean APIENTRY glIsBufferARB(GLuint buffer) { return glIsBuffer(buffer); }
GLAPI void APIENTRY glBufferDataARB(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  glBufferData(target, size, data, usage);
}
GLAPI void APIENTRY glBufferSubDataARB(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  glBufferSubData(target, offset, size, data);
}
GLAPI void APIENTRY glGetBufferSubDataARB(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  glGetBufferSubData(target, offset, size, data);
}
GLAPI void* APIENTRY glMapBufferARB(GLenum target, GLenum access) { return glMapBuffer(target, access); }
GLAPI GLboolean APIENTRY glUnmapBufferARB(GLenum target) { return glUnmapBuffer(target); }
GLAPI void APIENTRY glGetBufferParameterivARB(GLenum target, GLenum pname, GLint* params) {
  glGetBufferParameteriv(target, pname, params);
}
GLAPI void APIENTRY glGetBufferPointervARB(GLenum target, GLenum pname, void** params) {
  glGetBufferPointerv(target, pname, params);
}
GLAPI void APIENTRY glDrawRangeElementsEXT(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                           const void* indices) {
  glDrawRangeElements(mode, start, end, count, type, indices);
}
GLAPI void APIENTRY glMultiDrawArraysEXT(GLenum mode, const GLint* first, const GLsizei* count,
                                         GLsizei drawcount) {
  glMultiDrawArrays(mode, first, count, drawcount);
}
GLAPI void APIENTRY glMultiDrawElementsEXT(GLenum mode, const GLsizei* count, GLenum type,
                                           const void* const* indices, GLsizei drawcount) {
  glMultiDrawElements(mode, count, type, indices, drawcount);
}
GLAPI void APIENTRY glClientActiveTextureARB(GLenum texture) { glClientActiveTexture(texture); }
GLAPI void APIENTRY glActiveTextureARB(GLenum texture) { glActiveTexture(texture); }

// ARB_point_parameters, EXT_point_parameters.
GLAPI void APIENTRY glPointParameterfARB(GLenum pname, GLfloat param) { glPointParameterf(pname, param); }
GLAPI void APIENTRY glPointParameterfvARB(GLenum pname, const GLfloat* params) { glPointParameterfv(pname, params); }
GLAPI void APIENTRY glPointParameterfEXT(GLenum pname, GLfloat param) { glPointParameterf(pname, param); }
GLAPI void APIENTRY glPointParameterfvEXT(GLenum pname, const GLfloat* params) { glPointParameterfv(pname, params); }

// EXT_vertex_array: the GL 1.1 arrays with an element count, which GL 1.1
// ignores too (the arrays are read where the draw says).
GLAPI void APIENTRY glArrayElementEXT(GLint i) { glArrayElement(i); }
GLAPI void APIENTRY glDrawArraysEXT(GLenum mode, GLint first, GLsizei count) { glDrawArrays(mode, first, count); }
GLAPI void APIENTRY glGetPointervEXT(GLenum pname, void** params) { glGetPointerv(pname, params); }
GLAPI void APIENTRY glVertexPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glVertexPointer(size, type, stride, pointer);
}
GLAPI void APIENTRY glNormalPointerEXT(GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glNormalPointer(type, stride, pointer);
}
GLAPI void APIENTRY glColorPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glColorPointer(size, type, stride, pointer);
}
GLAPI void APIENTRY glIndexPointerEXT(GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glIndexPointer(type, stride, pointer);
}
GLAPI void APIENTRY glTexCoordPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glTexCoordPointer(size, type, stride, pointer);
}
GLAPI void APIENTRY glEdgeFlagPointerEXT(GLsizei stride, GLsizei, const GLboolean* pointer) {
  glEdgeFlagPointer(stride, pointer);
}

// ARB_transpose_matrix.
GLAPI void APIENTRY glLoadTransposeMatrixfARB(const GLfloat* m) { glLoadTransposeMatrixf(m); }
GLAPI void APIENTRY glLoadTransposeMatrixdARB(const GLdouble* m) { glLoadTransposeMatrixd(m); }
GLAPI void APIENTRY glMultTransposeMatrixfARB(const GLfloat* m) { glMultTransposeMatrixf(m); }
GLAPI void APIENTRY glMultTransposeMatrixdARB(const GLdouble* m) { glMultTransposeMatrixd(m); }

// ARB_multitexture (glMultiTexCoord*ARB), EXT_texture3D, EXT_texture_object,
// EXT_copy_texture, EXT_subtexture: the texture commands' older names.
GLAPI void APIENTRY glMultiTexCoord1sARB(GLenum target, GLshort s) { glMultiTexCoord1s(target, s); }
GLAPI void APIENTRY glMultiTexCoord1svARB(GLenum target, const GLshort* v) { glMultiTexCoord1sv(target, v); }
GLAPI void APIENTRY glMultiTexCoord1iARB(GLenum target, GLint s) { glMultiTexCoord1i(target, s); }
GLAPI void APIENTRY glMultiTexCoord1ivARB(GLenum target, const GLint* v) { glMultiTexCoord1iv(target, v); }
GLAPI void APIENTRY glMultiTexCoord1fARB(GLenum target, GLfloat s) { glMultiTexCoord1f(target, s); }
GLAPI void APIENTRY glMultiTexCoord1fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord1fv(target, v); }
GLAPI void APIENTRY glMultiTexCoord1dARB(GLenum target, GLdouble s) { glMultiTexCoord1d(target, s); }
GLAPI void APIENTRY glMultiTexCoord1dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord1dv(target, v); }
GLAPI void APIENTRY glMultiTexCoord2sARB(GLenum target, GLshort s, GLshort t) { glMultiTexCoord2s(target, s, t); }
GLAPI void APIENTRY glMultiTexCoord2svARB(GLenum target, const GLshort* v) { glMultiTexCoord2sv(target, v); }
GLAPI void APIENTRY glMultiTexCoord2iARB(GLenum target, GLint s, GLint t) { glMultiTexCoord2i(target, s, t); }
GLAPI void APIENTRY glMultiTexCoord2ivARB(GLenum target, const GLint* v) { glMultiTexCoord2iv(target, v); }
GLAPI void APIENTRY glMultiTexCoord2fARB(GLenum target, GLfloat s, GLfloat t) { glMultiTexCoord2f(target, s, t); }
GLAPI void APIENTRY glMultiTexCoord2fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord2fv(target, v); }
GLAPI void APIENTRY glMultiTexCoord2dARB(GLenum target, GLdouble s, GLdouble t) { glMultiTexCoord2d(target, s, t); }
GLAPI void APIENTRY glMultiTexCoord2dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord2dv(target, v); }
GLAPI void APIENTRY glMultiTexCoord3sARB(GLenum target, GLshort s, GLshort t, GLshort r) { glMultiTexCoord3s(target, s, t, r); }
GLAPI void APIENTRY glMultiTexCoord3svARB(GLenum target, const GLshort* v) { glMultiTexCoord3sv(target, v); }
GLAPI void APIENTRY glMultiTexCoord3iARB(GLenum target, GLint s, GLint t, GLint r) { glMultiTexCoord3i(target, s, t, r); }
GLAPI void APIENTRY glMultiTexCoord3ivARB(GLenum target, const GLint* v) { glMultiTexCoord3iv(target, v); }
GLAPI void APIENTRY glMultiTexCoord3fARB(GLenum target, GLfloat s, GLfloat t, GLfloat r) { glMultiTexCoord3f(target, s, t, r); }
GLAPI void APIENTRY glMultiTexCoord3fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord3fv(target, v); }
GLAPI void APIENTRY glMultiTexCoord3dARB(GLenum target, GLdouble s, GLdouble t, GLdouble r) { glMultiTexCoord3d(target, s, t, r); }
GLAPI void APIENTRY glMultiTexCoord3dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord3dv(target, v); }
GLAPI void APIENTRY glMultiTexCoord4sARB(GLenum target, GLshort s, GLshort t, GLshort r, GLshort q) { glMultiTexCoord4s(target, s, t, r, q); }
GLAPI void APIENTRY glMultiTexCoord4svARB(GLenum target, const GLshort* v) { glMultiTexCoord4sv(target, v); }
GLAPI void APIENTRY glMultiTexCoord4iARB(GLenum target, GLint s, GLint t, GLint r, GLint q) { glMultiTexCoord4i(target, s, t, r, q); }
GLAPI void APIENTRY glMultiTexCoord4ivARB(GLenum target, const GLint* v) { glMultiTexCoord4iv(target, v); }
GLAPI void APIENTRY glMultiTexCoord4fARB(GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { glMultiTexCoord4f(target, s, t, r, q); }
GLAPI void APIENTRY glMultiTexCoord4fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord4fv(target, v); }
GLAPI void APIENTRY glMultiTexCoord4dARB(GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q) { glMultiTexCoord4d(target, s, t, r, q); }
GLAPI void APIENTRY glMultiTexCoord4dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord4dv(target, v); }
GLAPI void APIENTRY glTexImage3DEXT(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height,
                                     GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  glTexImage3D(target, level, static_cast<GLint>(internalformat), width, height, depth, border, format, type, pixels);
}
GLAPI void APIENTRY glTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                                        GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                                        const void* pixels) {
  glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}
GLAPI void APIENTRY glTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                                        GLenum type, const void* pixels) {
  glTexSubImage1D(target, level, xoffset, width, format, type, pixels);
}
GLAPI void APIENTRY glTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                                        GLsizei height, GLenum format, GLenum type, const void* pixels) {
  glTexSubImage2D(target, level, xoffset, yoffset, width, height, format, type, pixels);
}
GLAPI void APIENTRY glCopyTexImage1DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                         GLsizei width, GLint border) {
  glCopyTexImage1D(target, level, internalformat, x, y, width, border);
}
GLAPI void APIENTRY glCopyTexImage2DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                         GLsizei width, GLsizei height, GLint border) {
  glCopyTexImage2D(target, level, internalformat, x, y, width, height, border);
}
GLAPI void APIENTRY glCopyTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                                            GLsizei width) {
  glCopyTexSubImage1D(target, level, xoffset, x, y, width);
}
GLAPI void APIENTRY glCopyTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                                            GLint y, GLsizei width, GLsizei height) {
  glCopyTexSubImage2D(target, level, xoffset, yoffset, x, y, width, height);
}
GLAPI void APIENTRY glCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                                            GLint x, GLint y, GLsizei width, GLsizei height) {
  glCopyTexSubImage3D(target, level, xoffset, yoffset, zoffset, x, y, width, height);
}
GLAPI GLboolean APIENTRY glAreTexturesResidentEXT(GLsizei n, const GLuint* textures, GLboolean* residences) {
  return glAreTexturesResident(n, textures, residences);
}
GLAPI void APIENTRY glBindTextureEXT(GLenum target, GLuint texture) { glBindTexture(target, texture); }
GLAPI void APIENTRY glDeleteTexturesEXT(GLsizei n, const GLuint* textures) { glDeleteTextures(n, textures); }
GLAPI void APIENTRY glGenTexturesEXT(GLsizei n, GLuint* textures) { glGenTextures(n, textures); }
GLAPI GLboolean APIENTRY glIsTextureEXT(GLuint texture) { return glIsTexture(texture); }
GLAPI void APIENTRY glPrioritizeTexturesEXT(GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  glPrioritizeTextures(n, textures, priorities);
}

// EXT_fog_coord: the GL 1.4 fog coordinate commands' older names.
GLAPI void APIENTRY glFogCoordfEXT(GLfloat coord) { glFogCoordf(coord); }
GLAPI void APIENTRY glFogCoordfvEXT(const GLfloat* coord) { glFogCoordfv(coord); }
GLAPI void APIENTRY glFogCoorddEXT(GLdouble coord) { glFogCoordd(coord); }
GLAPI void APIENTRY glFogCoorddvEXT(const GLdouble* coord) { glFogCoorddv(coord); }
GLAPI void APIENTRY glFogCoordPointerEXT(GLenum type, GLsizei stride, const void* pointer) {
  glFogCoordPointer(type, stride, pointer);
}

// Blending (api/gl_blend_api.cpp): EXT_blend_color, EXT_blend_minmax,
// EXT/INGR_blend_func_separate, EXT/ATI_blend_equation_separate.
GLAPI void APIENTRY glBlendColorEXT(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
GLAPI void APIENTRY glBlendEquationEXT(GLenum mode);
GLAPI void APIENTRY glBlendFuncSeparateEXT(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha);
GLAPI void APIENTRY glBlendFuncSeparateINGR(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha);
GLAPI void APIENTRY glBlendEquationSeparateEXT(GLenum modeRGB, GLenum modeAlpha);
GLAPI void APIENTRY glBlendEquationSeparateATI(GLenum modeRGB, GLenum modeAlpha);

// ARB_window_pos: glWindowPos under its extension names (api/gl_raster_pos_api.cpp).
GLAPI void APIENTRY glWindowPos2sARB(GLshort x, GLshort y) { glWindowPos2s(x, y); }
GLAPI void APIENTRY glWindowPos2svARB(const GLshort* v) { glWindowPos2sv(v); }
GLAPI void APIENTRY glWindowPos2iARB(GLint x, GLint y) { glWindowPos2i(x, y); }
GLAPI void APIENTRY glWindowPos2ivARB(const GLint* v) { glWindowPos2iv(v); }
GLAPI void APIENTRY glWindowPos2fARB(GLfloat x, GLfloat y) { glWindowPos2f(x, y); }
GLAPI void APIENTRY glWindowPos2fvARB(const GLfloat* v) { glWindowPos2fv(v); }
GLAPI void APIENTRY glWindowPos2dARB(GLdouble x, GLdouble y) { glWindowPos2d(x, y); }
GLAPI void APIENTRY glWindowPos2dvARB(const GLdouble* v) { glWindowPos2dv(v); }
GLAPI void APIENTRY glWindowPos3sARB(GLshort x, GLshort y, GLshort z) { glWindowPos3s(x, y, z); }
GLAPI void APIENTRY glWindowPos3svARB(const GLshort* v) { glWindowPos3sv(v); }
GLAPI void APIENTRY glWindowPos3iARB(GLint x, GLint y, GLint z) { glWindowPos3i(x, y, z); }
GLAPI void APIENTRY glWindowPos3ivARB(const GLint* v) { glWindowPos3iv(v); }
GLAPI void APIENTRY glWindowPos3fARB(GLfloat x, GLfloat y, GLfloat z) { glWindowPos3f(x, y, z); }
GLAPI void APIENTRY glWindowPos3fvARB(const GLfloat* v) { glWindowPos3fv(v); }
GLAPI void APIENTRY glWindowPos3dARB(GLdouble x, GLdouble y, GLdouble z) { glWindowPos3d(x, y, z); }
GLAPI void APIENTRY glWindowPos3dvARB(const GLdouble* v) { glWindowPos3dv(v); }

// ATI_separate_stencil and EXT_stencil_two_side (api/gl_stencil_api.cpp).
GLAPI void APIENTRY glStencilFuncSeparateATI(GLenum frontfunc, GLenum backfunc, GLint ref, GLuint mask);
GLAPI void APIENTRY glStencilOpSeparateATI(GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass);
GLAPI void APIENTRY glActiveStencilFaceEXT(GLenum face);

// ARB_occlusion_query (api/gl_query_api.cpp).
GLAPI void APIENTRY glGenQueriesARB(GLsizei n, GLuint* ids);
GLAPI void APIENTRY glDeleteQueriesARB(GLsizei n, const GLuint* ids);
GLAPI GLboolean APIENTRY glIsQueryARB(GLuint id);
GLAPI void APIENTRY glBeginQueryARB(GLenum target, GLuint id);
GLAPI void APIENTRY glEndQueryARB(GLenum target);
GLAPI void APIENTRY glGetQueryivARB(GLenum target, GLenum pname, GLint* params);
GLAPI void APIENTRY glGetQueryObjectivARB(GLuint id, GLenum pname, GLint* params);
GLAPI void APIENTRY glGetQueryObjectuivARB(GLuint id, GLenum pname, GLuint* params);

// ARB_multisample (api/gl_multisample_api.cpp).
GLAPI void APIENTRY glSampleCoverageARB(GLfloat value, GLboolean invert);

}  // extern "C"

namespace glfixed::api {

namespace {
struct Alias {
  const char* name;
  void* address;
};
// clang-format off
#define GLFX_ALIAS(name) {#name, reinterpret_cast<void*>(&name)}
// clang-format on
const Alias kAliases[] = {
    GLFX_ALIAS(glBindBufferARB),          GLFX_ALIAS(glDeleteBuffersARB),
    GLFX_ALIAS(glGenBuffersARB),          GLFX_ALIAS(glIsBufferARB),
    GLFX_ALIAS(glBufferDataARB),          GLFX_ALIAS(glBufferSubDataARB),
    GLFX_ALIAS(glGetBufferSubDataARB),    GLFX_ALIAS(glMapBufferARB),
    GLFX_ALIAS(glUnmapBufferARB),         GLFX_ALIAS(glGetBufferParameterivARB),
    GLFX_ALIAS(glGetBufferPointervARB),   GLFX_ALIAS(glDrawRangeElementsEXT),
    GLFX_ALIAS(glMultiDrawArraysEXT),     GLFX_ALIAS(glMultiDrawElementsEXT),
    GLFX_ALIAS(glClientActiveTextureARB),
    GLFX_ALIAS(glActiveTextureARB),
    GLFX_ALIAS(glPointParameterfARB),     GLFX_ALIAS(glPointParameterfvARB),
    GLFX_ALIAS(glPointParameterfEXT),     GLFX_ALIAS(glPointParameterfvEXT),
    GLFX_ALIAS(glLoadTransposeMatrixfARB), GLFX_ALIAS(glLoadTransposeMatrixdARB),
    GLFX_ALIAS(glMultTransposeMatrixfARB), GLFX_ALIAS(glMultTransposeMatrixdARB),
    GLFX_ALIAS(glArrayElementEXT),        GLFX_ALIAS(glDrawArraysEXT),
    GLFX_ALIAS(glGetPointervEXT),         GLFX_ALIAS(glVertexPointerEXT),
    GLFX_ALIAS(glNormalPointerEXT),       GLFX_ALIAS(glColorPointerEXT),
    GLFX_ALIAS(glIndexPointerEXT),        GLFX_ALIAS(glTexCoordPointerEXT),
    GLFX_ALIAS(glEdgeFlagPointerEXT),
    GLFX_ALIAS(glFogCoordfEXT),           GLFX_ALIAS(glFogCoordfvEXT),
    GLFX_ALIAS(glFogCoorddEXT),           GLFX_ALIAS(glFogCoorddvEXT),
    GLFX_ALIAS(glFogCoordPointerEXT),
    GLFX_ALIAS(glMultiTexCoord1sARB),
    GLFX_ALIAS(glMultiTexCoord1svARB),
    GLFX_ALIAS(glMultiTexCoord1iARB),
    GLFX_ALIAS(glMultiTexCoord1ivARB),
    GLFX_ALIAS(glMultiTexCoord1fARB),
    GLFX_ALIAS(glMultiTexCoord1fvARB),
    GLFX_ALIAS(glMultiTexCoord1dARB),
    GLFX_ALIAS(glMultiTexCoord1dvARB),
    GLFX_ALIAS(glMultiTexCoord2sARB),
    GLFX_ALIAS(glMultiTexCoord2svARB),
    GLFX_ALIAS(glMultiTexCoord2iARB),
    GLFX_ALIAS(glMultiTexCoord2ivARB),
    GLFX_ALIAS(glMultiTexCoord2fARB),
    GLFX_ALIAS(glMultiTexCoord2fvARB),
    GLFX_ALIAS(glMultiTexCoord2dARB),
    GLFX_ALIAS(glMultiTexCoord2dvARB),
    GLFX_ALIAS(glMultiTexCoord3sARB),
    GLFX_ALIAS(glMultiTexCoord3svARB),
    GLFX_ALIAS(glMultiTexCoord3iARB),
    GLFX_ALIAS(glMultiTexCoord3ivARB),
    GLFX_ALIAS(glMultiTexCoord3fARB),
    GLFX_ALIAS(glMultiTexCoord3fvARB),
    GLFX_ALIAS(glMultiTexCoord3dARB),
    GLFX_ALIAS(glMultiTexCoord3dvARB),
    GLFX_ALIAS(glMultiTexCoord4sARB),
    GLFX_ALIAS(glMultiTexCoord4svARB),
    GLFX_ALIAS(glMultiTexCoord4iARB),
    GLFX_ALIAS(glMultiTexCoord4ivARB),
    GLFX_ALIAS(glMultiTexCoord4fARB),
    GLFX_ALIAS(glMultiTexCoord4fvARB),
    GLFX_ALIAS(glMultiTexCoord4dARB),
    GLFX_ALIAS(glMultiTexCoord4dvARB),
    GLFX_ALIAS(glTexImage3DEXT),
    GLFX_ALIAS(glTexSubImage3DEXT),
    GLFX_ALIAS(glTexSubImage1DEXT),
    GLFX_ALIAS(glTexSubImage2DEXT),
    GLFX_ALIAS(glCopyTexImage1DEXT),
    GLFX_ALIAS(glCopyTexImage2DEXT),
    GLFX_ALIAS(glCopyTexSubImage1DEXT),
    GLFX_ALIAS(glCopyTexSubImage2DEXT),
    GLFX_ALIAS(glCopyTexSubImage3DEXT),
    GLFX_ALIAS(glAreTexturesResidentEXT),
    GLFX_ALIAS(glBindTextureEXT),
    GLFX_ALIAS(glDeleteTexturesEXT),
    GLFX_ALIAS(glGenTexturesEXT),
    GLFX_ALIAS(glIsTextureEXT),
    GLFX_ALIAS(glPrioritizeTexturesEXT),
    GLFX_ALIAS(glBlendColorEXT),          GLFX_ALIAS(glBlendEquationEXT),
    GLFX_ALIAS(glBlendFuncSeparateEXT),   GLFX_ALIAS(glBlendFuncSeparateINGR),
    GLFX_ALIAS(glBlendEquationSeparateEXT), GLFX_ALIAS(glBlendEquationSeparateATI),
    GLFX_ALIAS(glWindowPos2sARB),
    GLFX_ALIAS(glWindowPos2svARB),
    GLFX_ALIAS(glWindowPos2iARB),
    GLFX_ALIAS(glWindowPos2ivARB),
    GLFX_ALIAS(glWindowPos2fARB),
    GLFX_ALIAS(glWindowPos2fvARB),
    GLFX_ALIAS(glWindowPos2dARB),
    GLFX_ALIAS(glWindowPos2dvARB),
    GLFX_ALIAS(glWindowPos3sARB),
    GLFX_ALIAS(glWindowPos3svARB),
    GLFX_ALIAS(glWindowPos3iARB),
    GLFX_ALIAS(glWindowPos3ivARB),
    GLFX_ALIAS(glWindowPos3fARB),
    GLFX_ALIAS(glWindowPos3fvARB),
    GLFX_ALIAS(glWindowPos3dARB),
    GLFX_ALIAS(glWindowPos3dvARB),
    GLFX_ALIAS(glStencilFuncSeparateATI),
    GLFX_ALIAS(glStencilOpSeparateATI),
    GLFX_ALIAS(glActiveStencilFaceEXT),
    GLFX_ALIAS(glGenQueriesARB),          GLFX_ALIAS(glDeleteQueriesARB),
    GLFX_ALIAS(glIsQueryARB),             GLFX_ALIAS(glBeginQueryARB),
    GLFX_ALIAS(glEndQueryARB),            GLFX_ALIAS(glGetQueryivARB),
    GLFX_ALIAS(glGetQueryObjectivARB),    GLFX_ALIAS(glGetQueryObjectuivARB),
    GLFX_ALIAS(glSampleCoverageARB),

    // Framebuffer objects (api/gl_framebuffer_object_api.cpp).
    GLFX_ALIAS(glIsRenderbuffer),
    GLFX_ALIAS(glBindRenderbuffer),
    GLFX_ALIAS(glDeleteRenderbuffers),
    GLFX_ALIAS(glGenRenderbuffers),
    GLFX_ALIAS(glRenderbufferStorage),
    GLFX_ALIAS(glRenderbufferStorageMultisample),
    GLFX_ALIAS(glGetRenderbufferParameteriv),
    GLFX_ALIAS(glIsFramebuffer),
    GLFX_ALIAS(glBindFramebuffer),
    GLFX_ALIAS(glDeleteFramebuffers),
    GLFX_ALIAS(glGenFramebuffers),
    GLFX_ALIAS(glCheckFramebufferStatus),
    GLFX_ALIAS(glFramebufferTexture1D),
    GLFX_ALIAS(glFramebufferTexture2D),
    GLFX_ALIAS(glFramebufferTexture3D),
    GLFX_ALIAS(glFramebufferRenderbuffer),
    GLFX_ALIAS(glGetFramebufferAttachmentParameteriv),
    GLFX_ALIAS(glIsRenderbufferEXT),
    GLFX_ALIAS(glBindRenderbufferEXT),
    GLFX_ALIAS(glDeleteRenderbuffersEXT),
    GLFX_ALIAS(glGenRenderbuffersEXT),
    GLFX_ALIAS(glRenderbufferStorageEXT),
    GLFX_ALIAS(glRenderbufferStorageMultisampleEXT),
    GLFX_ALIAS(glGetRenderbufferParameterivEXT),
    GLFX_ALIAS(glIsFramebufferEXT),
    GLFX_ALIAS(glBindFramebufferEXT),
    GLFX_ALIAS(glDeleteFramebuffersEXT),
    GLFX_ALIAS(glGenFramebuffersEXT),
    GLFX_ALIAS(glCheckFramebufferStatusEXT),
    GLFX_ALIAS(glFramebufferTexture1DEXT),
    GLFX_ALIAS(glFramebufferTexture2DEXT),
    GLFX_ALIAS(glFramebufferTexture3DEXT),
    GLFX_ALIAS(glFramebufferRenderbufferEXT),
    GLFX_ALIAS(glGetFramebufferAttachmentParameterivEXT),
    GLFX_ALIAS(glFramebufferTextureLayer),
    GLFX_ALIAS(glDrawBuffersARB),
    GLFX_ALIAS(glBlitFramebuffer),
    GLFX_ALIAS(glBlitFramebufferEXT),
};
#undef GLFX_ALIAS
}  // namespace

void* extensionAliasAddress(const char* name) {
  if (!name) return nullptr;
  for (const Alias& a : kAliases)
    if (std::strcmp(a.name, name) == 0) return a.address;
  return nullptr;
}

}  // namespace glfixed::api
