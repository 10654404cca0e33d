// glBegin/glEnd and the current vertex attributes: glVertex, glColor, glNormal
// (GL 2.1 §2.6-§2.7), every variant.
#include <type_traits>

#include "api/api.h"
#include "state/framebuffer_binding.h"
#include "api/list_record.h"
#include "api/normalized.h"
#include "pipeline/immediate_mode.h"
#include "vertex/color_material.h"

using namespace glfixed;

namespace {

using api::normalized;

// `size`: the components the call gave (glVertex2, 3 or 4), which Mesa's
// vertex format follows.
void addVertex(int size, float x, float y, float z, float w) {
  Context* ctx = currentContext();
  if (!ctx) return;
  if (ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.vertex(glm::vec4(x, y, z, w)); },
                              &glVertex4f, x, y, z, w))
    return;
  if (!ctx->insideBeginEnd) return;  // GL 2.1 §2.6.3: undefined outside Begin/End; ignored
  pipeline::positionGrows(*ctx, size);
  VertexBatch& b = ctx->batch;
  b.position.emplace_back(x, y, z, w);
  b.normal.push_back(ctx->current.normal);
  b.color.push_back(ctx->current.color);
  b.materialIndex.push_back(static_cast<uint32_t>(b.materials.size() - 1));
  b.edgeFlag.push_back(ctx->current.edgeFlag);  // polygon area: the edge flag
  for (uint32_t m = b.texCoordUnits; m != 0; m &= m - 1)  // texture coordinates (issue 14)
    b.texCoord[__builtin_ctz(m)].push_back(ctx->current.texCoord[__builtin_ctz(m)]);
  if (b.hasFogCoord) b.fogCoord.push_back(ctx->current.fogCoord);  // fog
  if (b.hasSecondaryColor) b.secondaryColor.push_back(ctx->current.secondaryColor);  // the colour sum
  pipeline::vertexAdded(*ctx);
}

void color(int size, float r, float g, float b, float a) {
  Context* ctx = currentContext();
  if (!ctx) return;
  if (ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.color(glm::vec4(r, g, b, a)); },
                              &glColor4f, r, g, b, a))
    return;
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::colorBecomesVertexData(*ctx, size);
  ctx->current.color = glm::vec4(r, g, b, a);
  if (!ctx->insideBeginEnd && ctx->lighting.colorMaterial) {
    pipeline::drawPending(*ctx);  // the material changes: what is pending was lit with the old one
    trackColorMaterial(*ctx);
  }
}

// Only glColor3f and glColor3fv give Mesa's vbo a 3-component colour; the
// other glColor3 variants go through its glColor4f(r, g, b, 1) (api_loopback.c).
template <typename T>
void color3(T r, T g, T b) {
  color(std::is_same_v<T, GLfloat> ? 3 : 4, normalized(r), normalized(g), normalized(b), 1.0f);
}
template <typename T>
void color4(T r, T g, T b, T a) {
  color(4, normalized(r), normalized(g), normalized(b), normalized(a));
}

void normal(float x, float y, float z) {
  Context* ctx = currentContext();
  if (!ctx) return;
  if (ctx->displayLists.compiler &&
      api::compiledVertexData([&](pipeline::ListCompiler& l) { l.normal(glm::vec3(x, y, z)); },
                              &glNormal3f, x, y, z))
    return;
  if (ctx->insideBeginEnd || ctx->vbo.verticesBuffered) pipeline::normalBecomesVertexData(*ctx);
  ctx->current.normal = glm::vec3(x, y, z);
}
template <typename T>
void normal3(T x, T y, T z) {
  normal(normalized(x), normalized(y), normalized(z));
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glBegin(GLenum mode) {
  // In a list: the glBegin/glEnd pairs become a vertex node; the errors are
  // compiled (§5.4), as Mesa's save_Begin compiles them.
  if (pipeline::ListCompiler* list = api::listCompiler(currentContext())) {
    if (mode > GL_POLYGON)
      list->recordError(*currentContext(), GL_INVALID_ENUM);
    else if (list->insideBeginEnd())
      list->recordError(*currentContext(), GL_INVALID_OPERATION);
    else
      list->begin(mode);
    return;
  }
  // Not a state change: Mesa keeps buffering vertices across glBegin.
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (mode > GL_POLYGON) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  // An incomplete framebuffer object: Mesa refuses the glBegin (its
  // _mesa_valid_prim_mode) with GL_INVALID_FRAMEBUFFER_OPERATION (probed).
  if (ctx->objectBound() && !drawFramebufferComplete(*ctx)) return;
  ctx->insideBeginEnd = true;
  ctx->beginEndMode = mode;
  pipeline::beginPrimitive(*ctx, mode);
}

GLAPI void APIENTRY glEnd(void) {
  if (api::compiledVertexData([](pipeline::ListCompiler& l) { l.end(); }, &glEnd)) return;
  Context* ctx = currentContext();
  if (!ctx) return;
  if (!ctx->insideBeginEnd) {
    ctx->recordError(GL_INVALID_OPERATION);
    return;
  }
  ctx->insideBeginEnd = false;
  pipeline::endPrimitive(*ctx);
  if (ctx->lighting.colorMaterial) trackColorMaterial(*ctx);
}

// glVertex: positions, as (x, y, 0, 1), (x, y, z, 1) or (x, y, z, w).
GLAPI void APIENTRY glVertex2s(GLshort x, GLshort y) { addVertex(2, x, y, 0, 1); }
GLAPI void APIENTRY glVertex2i(GLint x, GLint y) { addVertex(2, x, y, 0, 1); }
GLAPI void APIENTRY glVertex2f(GLfloat x, GLfloat y) { addVertex(2, x, y, 0, 1); }
GLAPI void APIENTRY glVertex2d(GLdouble x, GLdouble y) { addVertex(2, x, y, 0, 1); }
GLAPI void APIENTRY glVertex3s(GLshort x, GLshort y, GLshort z) { addVertex(3, x, y, z, 1); }
GLAPI void APIENTRY glVertex3i(GLint x, GLint y, GLint z) { addVertex(3, x, y, z, 1); }
GLAPI void APIENTRY glVertex3f(GLfloat x, GLfloat y, GLfloat z) { addVertex(3, x, y, z, 1); }
GLAPI void APIENTRY glVertex3d(GLdouble x, GLdouble y, GLdouble z) { addVertex(3, x, y, z, 1); }
GLAPI void APIENTRY glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w) { addVertex(4, x, y, z, w); }
GLAPI void APIENTRY glVertex4i(GLint x, GLint y, GLint z, GLint w) { addVertex(4, x, y, z, w); }
GLAPI void APIENTRY glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { addVertex(4, x, y, z, w); }
GLAPI void APIENTRY glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { addVertex(4, x, y, z, w); }
GLAPI void APIENTRY glVertex2sv(const GLshort* v) { if (v) addVertex(2, v[0], v[1], 0, 1); }
GLAPI void APIENTRY glVertex2iv(const GLint* v) { if (v) addVertex(2, v[0], v[1], 0, 1); }
GLAPI void APIENTRY glVertex2fv(const GLfloat* v) { if (v) addVertex(2, v[0], v[1], 0, 1); }
GLAPI void APIENTRY glVertex2dv(const GLdouble* v) { if (v) addVertex(2, v[0], v[1], 0, 1); }
GLAPI void APIENTRY glVertex3sv(const GLshort* v) { if (v) addVertex(3, v[0], v[1], v[2], 1); }
GLAPI void APIENTRY glVertex3iv(const GLint* v) { if (v) addVertex(3, v[0], v[1], v[2], 1); }
GLAPI void APIENTRY glVertex3fv(const GLfloat* v) { if (v) addVertex(3, v[0], v[1], v[2], 1); }
GLAPI void APIENTRY glVertex3dv(const GLdouble* v) { if (v) addVertex(3, v[0], v[1], v[2], 1); }
GLAPI void APIENTRY glVertex4sv(const GLshort* v) { if (v) addVertex(4, v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glVertex4iv(const GLint* v) { if (v) addVertex(4, v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glVertex4fv(const GLfloat* v) { if (v) addVertex(4, v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glVertex4dv(const GLdouble* v) { if (v) addVertex(4, v[0], v[1], v[2], v[3]); }

// glColor: integer components are normalised (table 2.9); alpha 1 for glColor3.
GLAPI void APIENTRY glColor3b(GLbyte r, GLbyte g, GLbyte b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3s(GLshort r, GLshort g, GLshort b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3i(GLint r, GLint g, GLint b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3f(GLfloat r, GLfloat g, GLfloat b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3d(GLdouble r, GLdouble g, GLdouble b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3ub(GLubyte r, GLubyte g, GLubyte b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3us(GLushort r, GLushort g, GLushort b) { color3(r, g, b); }
GLAPI void APIENTRY glColor3ui(GLuint r, GLuint g, GLuint b) { color3(r, g, b); }
GLAPI void APIENTRY glColor4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4s(GLshort r, GLshort g, GLshort b, GLshort a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4i(GLint r, GLint g, GLint b, GLint a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4us(GLushort r, GLushort g, GLushort b, GLushort a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor4ui(GLuint r, GLuint g, GLuint b, GLuint a) { color4(r, g, b, a); }
GLAPI void APIENTRY glColor3bv(const GLbyte* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3sv(const GLshort* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3iv(const GLint* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3fv(const GLfloat* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3dv(const GLdouble* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3ubv(const GLubyte* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3usv(const GLushort* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor3uiv(const GLuint* v) { if (v) color3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glColor4bv(const GLbyte* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4sv(const GLshort* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4iv(const GLint* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4fv(const GLfloat* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4dv(const GLdouble* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4ubv(const GLubyte* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4usv(const GLushort* v) { if (v) color4(v[0], v[1], v[2], v[3]); }
GLAPI void APIENTRY glColor4uiv(const GLuint* v) { if (v) color4(v[0], v[1], v[2], v[3]); }

// glNormal: signed integer components are normalised like colours.
GLAPI void APIENTRY glNormal3b(GLbyte x, GLbyte y, GLbyte z) { normal3(x, y, z); }
GLAPI void APIENTRY glNormal3s(GLshort x, GLshort y, GLshort z) { normal3(x, y, z); }
GLAPI void APIENTRY glNormal3i(GLint x, GLint y, GLint z) { normal3(x, y, z); }
GLAPI void APIENTRY glNormal3f(GLfloat x, GLfloat y, GLfloat z) { normal3(x, y, z); }
GLAPI void APIENTRY glNormal3d(GLdouble x, GLdouble y, GLdouble z) { normal3(x, y, z); }
GLAPI void APIENTRY glNormal3bv(const GLbyte* v) { if (v) normal3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glNormal3sv(const GLshort* v) { if (v) normal3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glNormal3iv(const GLint* v) { if (v) normal3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glNormal3fv(const GLfloat* v) { if (v) normal3(v[0], v[1], v[2]); }
GLAPI void APIENTRY glNormal3dv(const GLdouble* v) { if (v) normal3(v[0], v[1], v[2]); }

}  // extern "C"
