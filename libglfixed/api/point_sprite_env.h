// Point sprites (GL 2.0 §3.3.1): GL_COORD_REPLACE, set through glTexEnv with
// target GL_POINT_SPRITE and read through glGetTexEnv, but point state
// (PointAttrib::coordReplace, GL_POINT_BIT), per texture unit (the active one).
// The texture environment's glTexEnv/glGetTexEnv call these for that target.
#pragma once

#include <GL/gl.h>

namespace glfixed {
class Context;
}

namespace glfixed::api {

// glTexEnv(GL_POINT_SPRITE, pname, value) (values as GLint, as Mesa's
// texenv.c converts them): GL_COORD_REPLACE takes GL_TRUE or GL_FALSE, else
// GL_INVALID_VALUE; another pname is GL_INVALID_ENUM. Records the error
// itself; returns false when it did.
bool setPointSpriteEnv(Context& ctx, GLenum pname, GLint value);

// glGetTexEnv(GL_POINT_SPRITE, pname): GL_COORD_REPLACE of the active unit in
// *value; false (GL_INVALID_ENUM recorded) for another pname.
bool getPointSpriteEnv(Context& ctx, GLenum pname, GLint* value);

}  // namespace glfixed::api
