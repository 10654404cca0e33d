// Which stored format a GL internal format gets (GL 2.1 §3.8.1, table 3.16,
// 3.17), as Mesa 22.3.6's state tracker picks it for llvmpipe: probed with
// glGetTexLevelParameter(GL_TEXTURE_*_SIZE) and ramps read back with
// glGetTexImage (reference/MESA_FACTS.md "Textures: storage").
#pragma once

#include <GL/gl.h>

#include "texture/texel_format.h"

namespace glfixed::texture {

// The base internal format of an internal format (GL_RGBA, GL_RGB,
// GL_LUMINANCE, ... GL_DEPTH_COMPONENT, or EXT_packed_depth_stencil's
// GL_DEPTH_STENCIL); 0 if it is not one of those.
GLenum baseInternalFormat(GLint internalFormat);

// The stored format. For the unsized GL_RGB, GL_RGBA and GL_DEPTH_COMPONENT
// (not 3, 4), Mesa picks by the client data's type: GL_RGBA with
// GL_UNSIGNED_SHORT is stored at 16 bits, with 4_4_4_4 at 4 bits, ...
// Only called with a valid internal format.
TexelFormat chooseTexelFormat(GLint internalFormat, GLenum format, GLenum type);

// The generic compressed internal formats (GL_COMPRESSED_RGB, ...).
bool isGenericCompressed(GLint internalFormat);

// What glGetTexLevelParameter(GL_TEXTURE_INTERNAL_FORMAT) reports: the
// format as given, but a generic compressed one as the uncompressed format
// it is stored in (Mesa does so where it has no compressed format for it:
// GL_COMPRESSED_ALPHA reads GL_ALPHA).
GLint reportedInternalFormat(GLint internalFormat);

}  // namespace glfixed::texture
