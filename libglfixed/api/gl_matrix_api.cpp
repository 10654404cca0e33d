// Matrix entry points (GL 2.1 §2.11.2).
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

// The derived state a change of the current matrix invalidates (the texture
// matrices are read at each draw: nothing is derived from them).
uint32_t currentMatrixDirty(const Context& ctx) {
  switch (ctx.transform.matrixMode) {
    case GL_PROJECTION: return kDirtyProjection;
    case GL_TEXTURE: return 0;
    default: return kDirtyModelview;
  }
}

void multiplyCurrent(Context& ctx, const glm::mat4& m) {
  MatrixStack& stack = ctx.currentMatrixStack();
  stack.top() = stack.top() * m;
  stack.markChanged();
  ctx.markDirty(currentMatrixDirty(ctx));
}

void loadCurrent(Context& ctx, const glm::mat4& m) {
  ctx.currentMatrixStack().top() = m;
  ctx.currentMatrixStack().markChanged();
  ctx.markDirty(currentMatrixDirty(ctx));
}

glm::mat4 fromDoubles(const double d[16]) {
  glm::mat4 m;
  for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(d[i]);
  return m;
}

// The rotation matrix of GL 2.1 §2.11.2, in single precision as Mesa builds it
// (the arithmetic order matters for bit-exact vertices): an axis-aligned
// rotation is exact, any other axis is normalised first.
glm::mat4 rotationMatrix(float angleDegrees, float x, float y, float z, bool* valid) {
  float s = std::sin(static_cast<float>(angleDegrees * M_PI / 180.0));
  float c = std::cos(static_cast<float>(angleDegrees * M_PI / 180.0));
  glm::mat4 r(1.0f);  // r[col][row]
  *valid = true;
  if (x == 0 && y == 0 && z != 0) {
    r[0][0] = c; r[1][1] = c;
    r[1][0] = z < 0 ? s : -s;
    r[0][1] = -r[1][0];
    return r;
  }
  if (x == 0 && z == 0 && y != 0) {
    r[0][0] = c; r[2][2] = c;
    r[2][0] = y < 0 ? -s : s;
    r[0][2] = -r[2][0];
    return r;
  }
  if (y == 0 && z == 0 && x != 0) {
    r[1][1] = c; r[2][2] = c;
    r[2][1] = x < 0 ? s : -s;
    r[1][2] = -r[2][1];
    return r;
  }
  float mag = std::sqrt(x * x + y * y + z * z);
  if (mag <= 1.0e-4f) {  // no rotation: the matrix is left as it is
    *valid = false;
    return r;
  }
  x /= mag;
  y /= mag;
  z /= mag;
  float xx = x * x, yy = y * y, zz = z * z, xy = x * y, yz = y * z, zx = z * x;
  float xs = x * s, ys = y * s, zs = z * s, oneC = 1.0f - c;
  r[0][0] = oneC * xx + c;  r[1][0] = oneC * xy - zs; r[2][0] = oneC * zx + ys;
  r[0][1] = oneC * xy + zs; r[1][1] = oneC * yy + c;  r[2][1] = oneC * yz - xs;
  r[0][2] = oneC * zx - ys; r[1][2] = oneC * yz + xs; r[2][2] = oneC * zz + c;
  return r;
}

void rotate(float angleDegrees, float x, float y, float z) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  bool valid;
  glm::mat4 r = rotationMatrix(angleDegrees, x, y, z, &valid);
  if (valid) multiplyCurrent(*ctx, r);
}

void translate(float x, float y, float z) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  glm::mat4 t(1.0f);
  t[3] = glm::vec4(x, y, z, 1.0f);
  multiplyCurrent(*ctx, t);
}

void scale(float x, float y, float z) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  glm::mat4 s(1.0f);
  s[0][0] = x;
  s[1][1] = y;
  s[2][2] = z;
  multiplyCurrent(*ctx, s);
}

}  // namespace

extern "C" {

// Mesa does not draw the buffered vertices at glMatrixMode.
GLAPI void APIENTRY glMatrixMode(GLenum mode) {
  if (api::compiled(&glMatrixMode, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    // GL_COLOR needs the imaging subset, not implemented.
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  api::setStateWithoutFlush(*ctx, ctx->transform.matrixMode, mode, GL_TRANSFORM_BIT);
}

GLAPI void APIENTRY glLoadIdentity(void) {
  if (api::compiled(&glLoadIdentity)) return;
  Context* ctx = api::contextFlushed();
  if (ctx) loadCurrent(*ctx, glm::mat4(1.0f));
}

GLAPI void APIENTRY glLoadMatrixf(const GLfloat* m) {
  if (api::compiled(&glLoadMatrixf, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) loadCurrent(*ctx, glm::make_mat4(m));
}

GLAPI void APIENTRY glLoadMatrixd(const GLdouble* m) {
  if (api::compiled(&glLoadMatrixd, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) loadCurrent(*ctx, fromDoubles(m));
}

GLAPI void APIENTRY glMultMatrixf(const GLfloat* m) {
  if (api::compiled(&glMultMatrixf, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) multiplyCurrent(*ctx, glm::make_mat4(m));
}

GLAPI void APIENTRY glMultMatrixd(const GLdouble* m) {
  if (api::compiled(&glMultMatrixd, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) multiplyCurrent(*ctx, fromDoubles(m));
}

// GL 1.3: the same with row-major input (GL 2.1 §2.11.2).
GLAPI void APIENTRY glLoadTransposeMatrixf(const GLfloat* m) {
  if (api::compiled(&glLoadTransposeMatrixf, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) loadCurrent(*ctx, glm::transpose(glm::make_mat4(m)));
}

GLAPI void APIENTRY glLoadTransposeMatrixd(const GLdouble* m) {
  if (api::compiled(&glLoadTransposeMatrixd, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) loadCurrent(*ctx, glm::transpose(fromDoubles(m)));
}

GLAPI void APIENTRY glMultTransposeMatrixf(const GLfloat* m) {
  if (api::compiled(&glMultTransposeMatrixf, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) multiplyCurrent(*ctx, glm::transpose(glm::make_mat4(m)));
}

GLAPI void APIENTRY glMultTransposeMatrixd(const GLdouble* m) {
  if (api::compiled(&glMultTransposeMatrixd, api::copied(m, 16))) return;
  Context* ctx = api::contextFlushed();
  if (ctx && m) multiplyCurrent(*ctx, glm::transpose(fromDoubles(m)));
}

// Mesa flushes neither at glPushMatrix nor at a glPopMatrix whose top was not
// changed since the push: vertices before and after stay one draw.
GLAPI void APIENTRY glPushMatrix(void) {
  if (api::compiled(&glPushMatrix)) return;
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!ctx->currentMatrixStack().push()) ctx->recordError(GL_STACK_OVERFLOW);
}

GLAPI void APIENTRY glPopMatrix(void) {
  if (api::compiled(&glPopMatrix)) return;
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  MatrixStack& stack = ctx->currentMatrixStack();
  if (stack.depth() > 1 && stack.changedSincePush()) pipeline::flushVertices(*ctx);
  if (!stack.pop()) {
    ctx->recordError(GL_STACK_UNDERFLOW);
    return;
  }
  ctx->markDirty(currentMatrixDirty(*ctx));
}

GLAPI void APIENTRY glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) {
  if (api::compiled(&glRotatef, angle, x, y, z)) return;
  rotate(angle, x, y, z);
}
GLAPI void APIENTRY glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  if (api::compiled(&glRotated, angle, x, y, z)) return;
  rotate(static_cast<float>(angle), static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}
GLAPI void APIENTRY glTranslatef(GLfloat x, GLfloat y, GLfloat z) {
  if (api::compiled(&glTranslatef, x, y, z)) return;
  translate(x, y, z);
}
GLAPI void APIENTRY glTranslated(GLdouble x, GLdouble y, GLdouble z) {
  if (api::compiled(&glTranslated, x, y, z)) return;
  translate(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}
GLAPI void APIENTRY glScalef(GLfloat x, GLfloat y, GLfloat z) {
  if (api::compiled(&glScalef, x, y, z)) return;
  scale(x, y, z);
}
GLAPI void APIENTRY glScaled(GLdouble x, GLdouble y, GLdouble z) {
  if (api::compiled(&glScaled, x, y, z)) return;
  scale(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

// glFrustum and glOrtho (GL 2.1 §2.11.2) take doubles, but Mesa rounds the
// arguments to float and builds the matrix in float; so do we.
GLAPI void APIENTRY glFrustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
                              GLdouble zFar) {
  if (api::compiled(&glFrustum, left, right, bottom, top, zNear, zFar)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (zNear <= 0 || zFar <= 0 || left == right || bottom == top || zNear == zFar) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  float l = static_cast<float>(left), r = static_cast<float>(right), b = static_cast<float>(bottom),
        t = static_cast<float>(top), n = static_cast<float>(zNear), f = static_cast<float>(zFar);
  glm::mat4 m(0.0f);  // m[col][row]
  m[0][0] = (2.0f * n) / (r - l);
  m[1][1] = (2.0f * n) / (t - b);
  m[2][0] = (r + l) / (r - l);
  m[2][1] = (t + b) / (t - b);
  m[2][2] = -(f + n) / (f - n);
  m[2][3] = -1.0f;
  m[3][2] = -(2.0f * f * n) / (f - n);
  multiplyCurrent(*ctx, m);
}

GLAPI void APIENTRY glOrtho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
                            GLdouble zFar) {
  if (api::compiled(&glOrtho, left, right, bottom, top, zNear, zFar)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (left == right || bottom == top || zNear == zFar) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  float l = static_cast<float>(left), r = static_cast<float>(right), b = static_cast<float>(bottom),
        t = static_cast<float>(top), n = static_cast<float>(zNear), f = static_cast<float>(zFar);
  glm::mat4 m(1.0f);
  m[0][0] = 2.0f / (r - l);
  m[1][1] = 2.0f / (t - b);
  m[2][2] = -2.0f / (f - n);
  m[3][0] = -(r + l) / (r - l);
  m[3][1] = -(t + b) / (t - b);
  m[3][2] = -(f + n) / (f - n);
  multiplyCurrent(*ctx, m);
}

}  // extern "C"
