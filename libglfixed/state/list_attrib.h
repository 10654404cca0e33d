// GL_LIST_BIT (GL 2.1 §5.4, table 6.41): the display list base of glCallLists.
#pragma once

#include <GL/gl.h>

namespace glfixed {

struct ListAttrib {
  GLuint base = 0;
};

// GL 2.1 table 6.46: at least 64 levels of glCallList nesting (Mesa: 64).
constexpr int kMaxListNesting = 64;

}  // namespace glfixed
