// The current vertex attributes besides colour and normal (GL 2.1 §2.7):
// texture coordinates, secondary colour, fog coordinate, colour index and edge
// flag. They are state now; the stages that use them come with texturing, fog
// and polygon modes.
#include "api/api.h"
#include "api/list_record.h"
#include "api/list_record.h"
#include "api/normalized.h"
#include "pipeline/immediate_mode.h"

using namespace glfixed;

namespace {

constexpr int kMaxTextureCoords = 8;

using api::normalized;

void texCoord(GLenum unit, float s, float t, float r, float q) {
  const bool validUnit = unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + kMaxTextureCoords;
  if (validUnit &&
      api::compiledVertexData(
          [&](pipeline::ListCompiler& l) { l.texCoord(int(unit - GL_TEXTURE0), glm::vec4(s, t, r, q)); },
          &glMultiTexCoord4f, unit, s, t, r, q))
    return;
  if (!validUnit && api::compiledAttribute(&glMultiTexCoord4f, unit, s, t, r, q)) return;
  Context* ctx = currentContext();
  if (!ctx) return;
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kMaxTextureCoords) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  ctx->current.texCoord[unit - GL_TEXTURE0] = glm::vec4(s, t, r, q);
}

void secondaryColor(float r, float g, float b) {
  Context* ctx = currentContext();
  if (ctx && ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.secondaryColor(glm::vec4(r, g, b, 1.0f)); },
                              &glSecondaryColor3f, r, g, b))
    return;
  if (!ctx) return;
  // A vbo attribute of Mesa's like glFogCoord: it grows the vertex format.
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::secondaryColorBecomesVertexData(*ctx);
  ctx->current.secondaryColor = glm::vec4(r, g, b, 1.0f);
}

// Fog: a vertex attribute of Mesa's vbo (it grows the vertex format like
// glEdgeFlag), and vertex data of a list's node inside its glBegin/glEnd.
void fogCoord(float f) {
  Context* ctx = currentContext();
  if (ctx && ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.fogCoord(f); }, &glFogCoordf, f))
    return;
  if (!ctx) return;
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::fogCoordBecomesVertexData(*ctx);
  ctx->current.fogCoord = f;
}

void colorIndex(float i) {
  if (api::compiledAttribute(&glIndexf, i)) return;
  Context* ctx = currentContext();
  if (ctx) ctx->current.colorIndex = i;
}

}  // namespace

extern "C" {
GLAPI void APIENTRY glTexCoord1s(GLshort s) { texCoord(GL_TEXTURE0, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1sv(const GLshort* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1s(GLenum target, GLshort s) { texCoord(target, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1sv(GLenum target, const GLshort* v) { if (v) texCoord(target, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1i(GLint s) { texCoord(GL_TEXTURE0, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1iv(const GLint* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1i(GLenum target, GLint s) { texCoord(target, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1iv(GLenum target, const GLint* v) { if (v) texCoord(target, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1f(GLfloat s) { texCoord(GL_TEXTURE0, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1fv(const GLfloat* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1f(GLenum target, GLfloat s) { texCoord(target, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1fv(GLenum target, const GLfloat* v) { if (v) texCoord(target, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1d(GLdouble s) { texCoord(GL_TEXTURE0, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord1dv(const GLdouble* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1d(GLenum target, GLdouble s) { texCoord(target, static_cast<float>(s), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord1dv(GLenum target, const GLdouble* v) { if (v) texCoord(target, static_cast<float>(v[0]), 0.0f, 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2s(GLshort s, GLshort t) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2sv(const GLshort* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2s(GLenum target, GLshort s, GLshort t) { texCoord(target, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2sv(GLenum target, const GLshort* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2i(GLint s, GLint t) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2iv(const GLint* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2i(GLenum target, GLint s, GLint t) { texCoord(target, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2iv(GLenum target, const GLint* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2f(GLfloat s, GLfloat t) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2fv(const GLfloat* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2f(GLenum target, GLfloat s, GLfloat t) { texCoord(target, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2fv(GLenum target, const GLfloat* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2d(GLdouble s, GLdouble t) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord2dv(const GLdouble* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2d(GLenum target, GLdouble s, GLdouble t) { texCoord(target, static_cast<float>(s), static_cast<float>(t), 0.0f, 1.0f); }
GLAPI void APIENTRY glMultiTexCoord2dv(GLenum target, const GLdouble* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f); }
GLAPI void APIENTRY glTexCoord3s(GLshort s, GLshort t, GLshort r) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glTexCoord3sv(const GLshort* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3s(GLenum target, GLshort s, GLshort t, GLshort r) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3sv(GLenum target, const GLshort* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glTexCoord3i(GLint s, GLint t, GLint r) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glTexCoord3iv(const GLint* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3i(GLenum target, GLint s, GLint t, GLint r) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3iv(GLenum target, const GLint* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glTexCoord3f(GLfloat s, GLfloat t, GLfloat r) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glTexCoord3fv(const GLfloat* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3f(GLenum target, GLfloat s, GLfloat t, GLfloat r) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3fv(GLenum target, const GLfloat* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glTexCoord3d(GLdouble s, GLdouble t, GLdouble r) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glTexCoord3dv(const GLdouble* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3d(GLenum target, GLdouble s, GLdouble t, GLdouble r) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), 1.0f); }
GLAPI void APIENTRY glMultiTexCoord3dv(GLenum target, const GLdouble* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f); }
GLAPI void APIENTRY glTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glTexCoord4sv(const GLshort* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glMultiTexCoord4s(GLenum target, GLshort s, GLshort t, GLshort r, GLshort q) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glMultiTexCoord4sv(GLenum target, const GLshort* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glTexCoord4i(GLint s, GLint t, GLint r, GLint q) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glTexCoord4iv(const GLint* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glMultiTexCoord4i(GLenum target, GLint s, GLint t, GLint r, GLint q) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glMultiTexCoord4iv(GLenum target, const GLint* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glTexCoord4fv(const GLfloat* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glMultiTexCoord4f(GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glMultiTexCoord4fv(GLenum target, const GLfloat* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q) { texCoord(GL_TEXTURE0, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glTexCoord4dv(const GLdouble* v) { if (v) texCoord(GL_TEXTURE0, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glMultiTexCoord4d(GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q) { texCoord(target, static_cast<float>(s), static_cast<float>(t), static_cast<float>(r), static_cast<float>(q)); }
GLAPI void APIENTRY glMultiTexCoord4dv(GLenum target, const GLdouble* v) { if (v) texCoord(target, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])); }
GLAPI void APIENTRY glSecondaryColor3b(GLbyte r, GLbyte g, GLbyte b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3bv(const GLbyte* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3s(GLshort r, GLshort g, GLshort b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3sv(const GLshort* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3i(GLint r, GLint g, GLint b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3iv(const GLint* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3f(GLfloat r, GLfloat g, GLfloat b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3fv(const GLfloat* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3d(GLdouble r, GLdouble g, GLdouble b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3dv(const GLdouble* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3ub(GLubyte r, GLubyte g, GLubyte b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3ubv(const GLubyte* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3us(GLushort r, GLushort g, GLushort b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3usv(const GLushort* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glSecondaryColor3ui(GLuint r, GLuint g, GLuint b) { secondaryColor(normalized(r), normalized(g), normalized(b)); }
GLAPI void APIENTRY glSecondaryColor3uiv(const GLuint* v) { if (v) secondaryColor(normalized(v[0]), normalized(v[1]), normalized(v[2])); }
GLAPI void APIENTRY glFogCoordf(GLfloat f) { fogCoord(static_cast<float>(f)); }
GLAPI void APIENTRY glFogCoordfv(const GLfloat* f) { if (f) fogCoord(static_cast<float>(*f)); }
GLAPI void APIENTRY glFogCoordd(GLdouble f) { fogCoord(static_cast<float>(f)); }
GLAPI void APIENTRY glFogCoorddv(const GLdouble* f) { if (f) fogCoord(static_cast<float>(*f)); }
GLAPI void APIENTRY glIndexs(GLshort c) { colorIndex(static_cast<float>(c)); }
GLAPI void APIENTRY glIndexsv(const GLshort* c) { if (c) colorIndex(static_cast<float>(*c)); }
GLAPI void APIENTRY glIndexi(GLint c) { colorIndex(static_cast<float>(c)); }
GLAPI void APIENTRY glIndexiv(const GLint* c) { if (c) colorIndex(static_cast<float>(*c)); }
GLAPI void APIENTRY glIndexf(GLfloat c) { colorIndex(static_cast<float>(c)); }
GLAPI void APIENTRY glIndexfv(const GLfloat* c) { if (c) colorIndex(static_cast<float>(*c)); }
GLAPI void APIENTRY glIndexd(GLdouble c) { colorIndex(static_cast<float>(c)); }
GLAPI void APIENTRY glIndexdv(const GLdouble* c) { if (c) colorIndex(static_cast<float>(*c)); }
GLAPI void APIENTRY glIndexub(GLubyte c) { colorIndex(static_cast<float>(c)); }
GLAPI void APIENTRY glIndexubv(const GLubyte* c) { if (c) colorIndex(static_cast<float>(*c)); }

// Polygon area: between a list's glBegin and glEnd the edge flag is vertex
// data of the list's node (Mesa's save module keeps it per vertex).
GLAPI void APIENTRY glEdgeFlag(GLboolean flag) {
  Context* ctx = currentContext();
  if (ctx && ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.edgeFlag(flag != GL_FALSE); }, &glEdgeFlag,
                              flag))
    return;
  if (!ctx) return;
  // A vertex attribute of Mesa's vbo: it grows the vertex format like glNormal.
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::edgeFlagBecomesVertexData(*ctx);
  ctx->current.edgeFlag = flag != GL_FALSE;
}
GLAPI void APIENTRY glEdgeFlagv(const GLboolean* flag) {
  if (flag) glEdgeFlag(*flag);
}

}  // extern "C"
