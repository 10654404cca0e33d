// The ARB and EXT names legacy programs call for the vertex array and buffer
// object commands (ARB_vertex_buffer_object, EXT_draw_range_elements,
// EXT_multi_draw_arrays, ARB_multitexture's glClientActiveTextureARB,
// ARB/EXT_point_parameters, ARB_transpose_matrix, EXT_vertex_array): the
// same functions under their extension names, exported and known to
// OSMesaGetProcAddress. Mesa's gl.h/glext.h declare them; ours does not.
#include <GL/gl.h>

#include <cstring>

#include "api/entry_points.h"

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
