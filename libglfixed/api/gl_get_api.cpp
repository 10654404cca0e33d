// State queries (GL 2.1 §6.1): glGetError, glGetString and glGet{Boolean,
// Integer,Float,Double}v with the conversions of §6.1.2.
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "api/api.h"
#include "vertex/lighting_queries.h"

using namespace glfixed;

namespace {

// How a value converts for glGetIntegerv (§6.1.2): colours, normals, depth
// range and depth clear value map [-1,1] linearly onto the integer range;
// every other float rounds to the nearest integer.
enum class Kind { kPlain, kNormalized };

struct StateValue {
  Kind kind = Kind::kPlain;
  int count = 0;
  GLdouble v[16] = {};
  void set(std::initializer_list<double> values, Kind k = Kind::kPlain) {
    kind = k;
    count = 0;
    for (double d : values) v[count++] = d;
  }
  void setMatrix(const glm::mat4& m) {
    kind = Kind::kPlain;
    count = 16;
    for (int i = 0; i < 16; ++i) v[i] = glm::value_ptr(m)[i];
  }
};

bool isNormalizedLightingQuery(GLenum pname) { return pname == GL_LIGHT_MODEL_AMBIENT; }

// False: not a pname this library knows (GL_INVALID_ENUM).
bool queryState(Context& ctx, GLenum pname, StateValue& out) {
  const Framebuffer& fb = ctx.framebuffer;
  const bool hasAlpha = fb.color.alpha >= 0;
  switch (pname) {
    case GL_MATRIX_MODE: out.set({double(ctx.transform.matrixMode)}); return true;
    case GL_MODELVIEW_MATRIX: out.setMatrix(ctx.modelview.top()); return true;
    case GL_PROJECTION_MATRIX: out.setMatrix(ctx.projection.top()); return true;
    case GL_MODELVIEW_STACK_DEPTH: out.set({double(ctx.modelview.depth())}); return true;
    case GL_PROJECTION_STACK_DEPTH: out.set({double(ctx.projection.depth())}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out.set({double(kMaxModelviewStackDepth)}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out.set({double(kMaxProjectionStackDepth)}); return true;
    case GL_VIEWPORT:
      out.set({double(ctx.viewport.x), double(ctx.viewport.y), double(ctx.viewport.width),
               double(ctx.viewport.height)});
      return true;
    case GL_MAX_VIEWPORT_DIMS: out.set({double(kMaxViewportSize), double(kMaxViewportSize)}); return true;
    case GL_DEPTH_RANGE:
      out.set({ctx.viewport.depthNear, ctx.viewport.depthFar}, Kind::kNormalized);
      return true;
    case GL_COLOR_CLEAR_VALUE: {
      const glm::vec4& c = ctx.colorBuffer.clearColor;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_COLOR_WRITEMASK: {
      const auto& m = ctx.colorBuffer.writeMask;
      out.set({double(m[0]), double(m[1]), double(m[2]), double(m[3])});
      return true;
    }
    case GL_DEPTH_CLEAR_VALUE: out.set({ctx.depth.clearDepth}, Kind::kNormalized); return true;
    case GL_DEPTH_FUNC: out.set({double(ctx.depth.func)}); return true;
    case GL_DEPTH_WRITEMASK: out.set({double(ctx.depth.writeMask)}); return true;
    case GL_DEPTH_TEST: out.set({double(ctx.depth.test)}); return true;
    case GL_CULL_FACE: out.set({double(ctx.polygon.cullFace)}); return true;
    case GL_CULL_FACE_MODE: out.set({double(ctx.polygon.cullFaceMode)}); return true;
    case GL_FRONT_FACE: out.set({double(ctx.polygon.frontFace)}); return true;
    case GL_DITHER: out.set({double(ctx.colorBuffer.dither)}); return true;
    case GL_PERSPECTIVE_CORRECTION_HINT: out.set({double(ctx.hint.perspectiveCorrection)}); return true;
    case GL_POINT_SMOOTH_HINT: out.set({double(ctx.hint.pointSmooth)}); return true;
    case GL_LINE_SMOOTH_HINT: out.set({double(ctx.hint.lineSmooth)}); return true;
    case GL_POLYGON_SMOOTH_HINT: out.set({double(ctx.hint.polygonSmooth)}); return true;
    case GL_FOG_HINT: out.set({double(ctx.hint.fog)}); return true;
    case GL_GENERATE_MIPMAP_HINT: out.set({double(ctx.hint.generateMipmap)}); return true;
    case GL_TEXTURE_COMPRESSION_HINT: out.set({double(ctx.hint.textureCompression)}); return true;
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: out.set({double(ctx.hint.fragmentShaderDerivative)}); return true;
    case GL_PROVOKING_VERTEX: out.set({double(ctx.lighting.provokingVertex)}); return true;
    case GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION: out.set({0.0}); return true;
    case GL_CURRENT_COLOR: {
      const glm::vec4& c = ctx.current.color;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_NORMAL: {
      const glm::vec3& n = ctx.current.normal;
      out.set({n.x, n.y, n.z}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_TEXTURE_COORDS: {
      const glm::vec4& t = ctx.current.texCoord[0];
      out.set({t.x, t.y, t.z, t.w});
      return true;
    }
    case GL_CURRENT_SECONDARY_COLOR: {
      const glm::vec4& c = ctx.current.secondaryColor;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_FOG_COORD: out.set({ctx.current.fogCoord}); return true;
    case GL_CURRENT_INDEX: out.set({ctx.current.colorIndex}); return true;
    case GL_EDGE_FLAG: out.set({double(ctx.current.edgeFlag)}); return true;
    case GL_LIST_BASE: out.set({double(ctx.list.base)}); return true;
    case GL_LIST_INDEX: {  // the list being compiled, or 0
      const auto& c = ctx.displayLists.compiler;
      out.set({c ? double(c->name()) : 0.0});
      return true;
    }
    case GL_LIST_MODE: {
      const auto& c = ctx.displayLists.compiler;
      out.set({c ? double(c->mode()) : 0.0});
      return true;
    }
    case GL_MAX_LIST_NESTING: out.set({double(kMaxListNesting)}); return true;
    case GL_SUBPIXEL_BITS: out.set({double(kSubpixelBits)}); return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: out.set({8.0}); return true;
    case GL_ALPHA_BITS: out.set({hasAlpha ? 8.0 : 0.0}); return true;
    case GL_DEPTH_BITS: out.set({double(fb.depth.bits())}); return true;
    case GL_STENCIL_BITS: case GL_INDEX_BITS: case GL_AUX_BUFFERS:
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
      out.set({0.0});
      return true;
    case GL_RGBA_MODE: out.set({1.0}); return true;
    case GL_INDEX_MODE: case GL_DOUBLEBUFFER: case GL_STEREO: out.set({0.0}); return true;
    case GL_PACK_ALIGNMENT: out.set({double(ctx.pixelStore.packAlignment)}); return true;
    case GL_PACK_ROW_LENGTH: out.set({double(ctx.pixelStore.packRowLength)}); return true;
    case GL_PACK_SKIP_PIXELS: out.set({double(ctx.pixelStore.packSkipPixels)}); return true;
    case GL_PACK_SKIP_ROWS: out.set({double(ctx.pixelStore.packSkipRows)}); return true;
    case GL_UNPACK_ALIGNMENT: out.set({double(ctx.pixelStore.unpackAlignment)}); return true;
    case GL_UNPACK_ROW_LENGTH: out.set({double(ctx.pixelStore.unpackRowLength)}); return true;
    case GL_UNPACK_SKIP_PIXELS: out.set({double(ctx.pixelStore.unpackSkipPixels)}); return true;
    case GL_UNPACK_SKIP_ROWS: out.set({double(ctx.pixelStore.unpackSkipRows)}); return true;
    default:
      break;
  }
  int count = 0;
  if (getLightingState(ctx, pname, out.v, &count)) {
    out.count = count;
    out.kind = isNormalizedLightingQuery(pname) ? Kind::kNormalized : Kind::kPlain;
    return true;
  }
  return false;
}

// Looks the value up, or records the error the query raises.
bool lookUp(GLenum pname, const void* params, StateValue& value) {
  Context* ctx = api::contextForQuery();
  if (!ctx || !params) return false;
  if (!queryState(*ctx, pname, value)) {
    ctx->recordError(GL_INVALID_ENUM);
    return false;
  }
  return true;
}

GLint toInteger(double v, Kind kind) {
  if (kind == Kind::kNormalized) {
    // §6.1.2: 1.0 to the most positive integer, -1.0 to the most negative.
    double scaled = v * 2147483647.0;
    if (scaled >= 2147483647.0) return 2147483647;
    if (scaled <= -2147483648.0) return -2147483647 - 1;
    return static_cast<GLint>(std::floor(scaled + 0.5));  // rounded, not truncated
  }
  double r = std::floor(v + 0.5);
  if (r >= 2147483647.0) return 2147483647;
  if (r <= -2147483648.0) return -2147483647 - 1;
  return static_cast<GLint>(r);
}

}  // namespace

extern "C" {

GLAPI GLenum APIENTRY glGetError(void) {
  Context* ctx = currentContext();
  if (!ctx) return GL_NO_ERROR;
  if (ctx->insideBeginEnd) {
    // GL 2.1 §2.6.3: glGetError is not allowed between Begin and End; it
    // records INVALID_OPERATION and returns 0.
    ctx->recordError(GL_INVALID_OPERATION);
    return 0;
  }
  return ctx->takeError();
}

GLAPI const GLubyte* APIENTRY glGetString(GLenum name) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return nullptr;
  const char* s = nullptr;
  switch (name) {
    case GL_VENDOR: s = "libglfixed"; break;
    case GL_RENDERER: s = "libglfixed fixed-function software renderer"; break;
    case GL_VERSION: s = "2.1 libglfixed 0.1"; break;
    case GL_EXTENSIONS: s = "GL_ARB_provoking_vertex GL_EXT_provoking_vertex"; break;
    case GL_SHADING_LANGUAGE_VERSION: s = nullptr; break;  // no GLSL: GL 2.1 without shaders yet
    default: break;
  }
  if (!s) ctx->recordError(GL_INVALID_ENUM);
  return reinterpret_cast<const GLubyte*>(s);
}

GLAPI void APIENTRY glGetBooleanv(GLenum pname, GLboolean* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = v.v[i] != 0 ? GL_TRUE : GL_FALSE;
}

GLAPI void APIENTRY glGetIntegerv(GLenum pname, GLint* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = toInteger(v.v[i], v.kind);
}

GLAPI void APIENTRY glGetFloatv(GLenum pname, GLfloat* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = static_cast<GLfloat>(v.v[i]);
}

GLAPI void APIENTRY glGetDoublev(GLenum pname, GLdouble* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = v.v[i];
}

}  // extern "C"
