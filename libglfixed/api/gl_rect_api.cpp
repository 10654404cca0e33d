// glRect (GL 2.1 §2.10): a rectangle in the z = 0 plane of object space.
// The spec defines it as a GL_POLYGON of the four corners; Mesa issues
// glBegin(GL_QUADS) with the corners (x1,y1) (x2,y1) (x2,y2) (x1,y2) and
// glEnd (main/draw.c, _mesa_Rectf), and compiles it into a list the same way,
// into the list's vertex store (vbo_save_api.c, save_Rectf). The mode decides
// the flat-shaded colour (a quad's provoking vertex is its fourth) and the
// split of the rectangle under smooth shading, so we follow Mesa: the calls
// below are the ones it makes, through our own entry points, so they execute,
// compile and merge like any glBegin/glEnd. The other forms convert their
// arguments to float first, as Mesa does.
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

GLAPI void APIENTRY glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) {
  Context* ctx = currentContext();
  if (!ctx) return;
  // Not allowed between glBegin and glEnd (§2.6.3), executed or compiled.
  pipeline::ListCompiler* list = api::listCompiler(ctx);
  if (list ? list->insideBeginEnd() : ctx->insideBeginEnd) {
    if (list)
      list->recordError(*ctx, GL_INVALID_OPERATION);
    else
      ctx->recordError(GL_INVALID_OPERATION);
    return;
  }
  glBegin(GL_QUADS);
  glVertex2f(x1, y1);
  glVertex2f(x2, y1);
  glVertex2f(x2, y2);
  glVertex2f(x1, y2);
  glEnd();
}

GLAPI void APIENTRY glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) {
  glRectf(static_cast<GLfloat>(x1), static_cast<GLfloat>(y1), static_cast<GLfloat>(x2),
          static_cast<GLfloat>(y2));
}
GLAPI void APIENTRY glRecti(GLint x1, GLint y1, GLint x2, GLint y2) {
  glRectf(static_cast<GLfloat>(x1), static_cast<GLfloat>(y1), static_cast<GLfloat>(x2),
          static_cast<GLfloat>(y2));
}
GLAPI void APIENTRY glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { glRectf(x1, y1, x2, y2); }

// The vector forms: a NULL pointer is bad input at the library's edge (Mesa
// would crash); like every v-form here, the call then does nothing.
namespace {
template <typename T>
void rectFromVectors(const T* v1, const T* v2) {
  if (!v1 || !v2) return;
  glRectf(static_cast<GLfloat>(v1[0]), static_cast<GLfloat>(v1[1]), static_cast<GLfloat>(v2[0]),
          static_cast<GLfloat>(v2[1]));
}
}  // namespace

GLAPI void APIENTRY glRectdv(const GLdouble* v1, const GLdouble* v2) { rectFromVectors(v1, v2); }
GLAPI void APIENTRY glRectfv(const GLfloat* v1, const GLfloat* v2) { rectFromVectors(v1, v2); }
GLAPI void APIENTRY glRectiv(const GLint* v1, const GLint* v2) { rectFromVectors(v1, v2); }
GLAPI void APIENTRY glRectsv(const GLshort* v1, const GLshort* v2) { rectFromVectors(v1, v2); }
