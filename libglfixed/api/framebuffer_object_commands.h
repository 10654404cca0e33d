// The commands of EXT/ARB_framebuffer_object, EXT_framebuffer_blit and
// EXT_framebuffer_multisample (api/gl_framebuffer_object_api.cpp), which
// the project's gl.h (GL 2.1) does not declare.
#pragma once

#include <GL/gl.h>

namespace glfixed {
class Context;
}

extern "C" {
#define GLFX_FBO_COMMANDS(S)                                                                                   \
  GLAPI GLboolean APIENTRY glIsRenderbuffer##S(GLuint renderbuffer);                                           \
  GLAPI void APIENTRY glBindRenderbuffer##S(GLenum target, GLuint renderbuffer);                               \
  GLAPI void APIENTRY glDeleteRenderbuffers##S(GLsizei n, const GLuint* renderbuffers);                        \
  GLAPI void APIENTRY glGenRenderbuffers##S(GLsizei n, GLuint* renderbuffers);                                 \
  GLAPI void APIENTRY glRenderbufferStorage##S(GLenum target, GLenum internalformat, GLsizei width,            \
                                               GLsizei height);                                                \
  GLAPI void APIENTRY glRenderbufferStorageMultisample##S(GLenum target, GLsizei samples, GLenum internalformat, \
                                                          GLsizei width, GLsizei height);                      \
  GLAPI void APIENTRY glGetRenderbufferParameteriv##S(GLenum target, GLenum pname, GLint* params);             \
  GLAPI GLboolean APIENTRY glIsFramebuffer##S(GLuint framebuffer);                                             \
  GLAPI void APIENTRY glBindFramebuffer##S(GLenum target, GLuint framebuffer);                                 \
  GLAPI void APIENTRY glDeleteFramebuffers##S(GLsizei n, const GLuint* framebuffers);                          \
  GLAPI void APIENTRY glGenFramebuffers##S(GLsizei n, GLuint* framebuffers);                                   \
  GLAPI GLenum APIENTRY glCheckFramebufferStatus##S(GLenum target);                                            \
  GLAPI void APIENTRY glFramebufferTexture1D##S(GLenum target, GLenum attachment, GLenum textarget,            \
                                                GLuint texture, GLint level);                                  \
  GLAPI void APIENTRY glFramebufferTexture2D##S(GLenum target, GLenum attachment, GLenum textarget,            \
                                                GLuint texture, GLint level);                                  \
  GLAPI void APIENTRY glFramebufferTexture3D##S(GLenum target, GLenum attachment, GLenum textarget,            \
                                                GLuint texture, GLint level, GLint zoffset);                   \
  GLAPI void APIENTRY glFramebufferRenderbuffer##S(GLenum target, GLenum attachment, GLenum renderbuffertarget, \
                                                   GLuint renderbuffer);                                       \
  GLAPI void APIENTRY glGetFramebufferAttachmentParameteriv##S(GLenum target, GLenum attachment, GLenum pname, \
                                                               GLint* params);
GLFX_FBO_COMMANDS()
GLFX_FBO_COMMANDS(EXT)
#undef GLFX_FBO_COMMANDS
GLAPI void APIENTRY glFramebufferTextureLayer(GLenum target, GLenum attachment, GLuint texture, GLint level,
                                              GLint layer);
GLAPI void APIENTRY glDrawBuffersARB(GLsizei n, const GLenum* bufs);
GLAPI void APIENTRY glBlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                      GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);
GLAPI void APIENTRY glBlitFramebufferEXT(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                         GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);
}

namespace glfixed::api {
// glDeleteTextures: the bound framebuffers let go of the texture.
void textureDeleted(Context& ctx, GLuint name);
}  // namespace glfixed::api
