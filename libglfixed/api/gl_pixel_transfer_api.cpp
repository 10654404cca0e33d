// glPixelTransfer (GL 2.1 §3.6.3, table 6.26 group GL_PIXEL_MODE_BIT): the
// scale, bias, shift and map switches the pixel transfer operations read.
// glPixelMap and glGetPixelMap (§3.6.3, §6.1.3): the maps of
// state/pixel_maps.h, through the pixel unpack and pack buffers.
#include <cstring>
#include <vector>

#include "api/api.h"
#include "api/list_record.h"
#include "api/pixel_buffer.h"

using namespace glfixed;

namespace {

// The error glPixelMap gives before reading any value (§3.6.3): the size
// first, then the map; the power-of-two rule as Mesa applies it, to S_TO_S
// and I_TO_R .. I_TO_A but not to I_TO_I (measured).
GLenum pixelMapError(GLenum map, GLsizei mapsize) {
  if (mapsize < 1 || mapsize > kMaxPixelMapTable) return GL_INVALID_VALUE;
  if (!PixelMaps::isMap(map)) return GL_INVALID_ENUM;
  if (map >= GL_PIXEL_MAP_S_TO_S && map <= GL_PIXEL_MAP_I_TO_A && (mapsize & (mapsize - 1)))
    return GL_INVALID_VALUE;
  return GL_NO_ERROR;
}

bool isColorMap(GLenum map) { return map != GL_PIXEL_MAP_I_TO_I && map != GL_PIXEL_MAP_S_TO_S; }

// The command a list replays, and the store of all three glPixelMap: the
// values already converted to float. Colour maps keep them clamped to [0, 1],
// S_TO_S rounded to integers, I_TO_I as they are (Mesa).
void setPixelMap(GLenum map, GLsizei mapsize, const GLfloat* values) {
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (const GLenum e = pixelMapError(map, mapsize)) return ctx->recordError(e);
  if (!values) return;
  api::beginStateChange(*ctx, 0);
  PixelMap& m = ctx->pixelMaps[map];
  m.size = mapsize;
  for (GLsizei i = 0; i < mapsize; ++i) {
    const float v = values[i];
    m.values[i] = map == GL_PIXEL_MAP_S_TO_S ? static_cast<float>(std::round(v))
                  : isColorMap(map)          ? api::clamp01(v)
                                             : v;
  }
}

// A client value as glPixelMap reads it (§3.6.3): unsigned int and short
// colour entries normalized to [0, 1] (Mesa's UINT_TO_FLOAT and
// USHORT_TO_FLOAT), index entries as they are.
float fromClient(GLenum, GLfloat v) { return v; }
float fromClient(GLenum map, GLuint v) {
  return isColorMap(map) ? static_cast<float>(v) * (1.0f / 4294967295.0f) : static_cast<float>(v);
}
float fromClient(GLenum map, GLushort v) {
  return isColorMap(map) ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
}

// The values from client memory or the pixel unpack buffer: the offset a
// multiple of the type's size and the values inside the buffer
// (GL_INVALID_OPERATION otherwise). False when nothing is to be read.
template <typename T>
bool readPixelMap(Context& ctx, GLenum map, GLsizei mapsize, const T* values, std::vector<GLfloat>& out) {
  const GLuint buffer = ctx.pixelStore.pixelUnpackBufferBinding;
  if (buffer && reinterpret_cast<uintptr_t>(values) % sizeof(T)) {
    ctx.recordError(GL_INVALID_OPERATION);
    return false;
  }
  GLenum error;
  const T* p = api::pixelBufferMemory(ctx, buffer, values, size_t(mapsize) * sizeof(T), error);
  if (error != GL_NO_ERROR) ctx.recordError(error);
  if (!p) return false;
  out.resize(size_t(mapsize));
  for (GLsizei i = 0; i < mapsize; ++i) {
    T v;
    std::memcpy(&v, p + i, sizeof v);
    out[size_t(i)] = fromClient(map, v);
  }
  return true;
}

// glPixelMap{fv,uiv,usv}: executed, or compiled (§5.4) with the values read
// at compile time; a list checks the size and map when it runs, as Mesa's.
template <typename T>
void pixelMap(GLenum map, GLsizei mapsize, const T* values) {
  Context* ctx = currentContext();
  if (!ctx) return;
  std::vector<GLfloat> converted;
  if (api::listCompiler(ctx) && !api::listCompiler(ctx)->insideBeginEnd()) {
    if (pixelMapError(map, mapsize) == GL_NO_ERROR && !readPixelMap(*ctx, map, mapsize, values, converted))
      return;
    if (api::compiled(&setPixelMap, map, mapsize, api::copied(converted.data(), converted.size()))) return;
    return setPixelMap(map, mapsize, converted.data());
  }
  if (api::compiled(&setPixelMap, map, mapsize, api::copied<GLfloat>(nullptr, 0))) return;  // in a list's glBegin
  ctx = api::contextForSetter();
  if (!ctx) return;
  if (const GLenum e = pixelMapError(map, mapsize)) return ctx->recordError(e);
  if (readPixelMap(*ctx, map, mapsize, values, converted)) setPixelMap(map, mapsize, converted.data());
}

// A stored value as glGetPixelMap returns it (§6.1.3), as Mesa converts it
// (measured): FLOAT_TO_UINT for every map but S_TO_S, whose float is copied
// bit for bit; unsigned shorts rounded from colour entries, clamped and
// truncated from index entries.
GLfloat toClient(GLenum, float v, GLfloat*) { return v; }
GLuint toClient(GLenum map, float v, GLuint*) {
  if (map == GL_PIXEL_MAP_S_TO_S) {
    GLuint bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
  }
  // (GLuint)(v * 4294967295.0) as x86-64 converts it: through a 64-bit
  // integer, the overflow value when out of its range.
  const double d = static_cast<double>(v) * 4294967295.0;
  if (!(d > -9223372036854775808.0 && d < 9223372036854775808.0)) return 0;
  return static_cast<GLuint>(static_cast<uint64_t>(static_cast<int64_t>(d)));
}
GLushort toClient(GLenum map, float v, GLushort*) {
  if (isColorMap(map)) return static_cast<GLushort>(std::nearbyint(v * 65535.0f));  // float, half to even
  return static_cast<GLushort>(v > 0.0f ? (v < 65535.0f ? v : 65535.0f) : 0.0f);
}

template <typename T>
void getPixelMap(GLenum map, T* values) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (!PixelMaps::isMap(map)) return ctx->recordError(GL_INVALID_ENUM);
  const PixelMap& m = ctx->pixelMaps[map];
  const GLuint buffer = ctx->pixelStore.pixelPackBufferBinding;
  if (buffer && reinterpret_cast<uintptr_t>(values) % sizeof(T)) return ctx->recordError(GL_INVALID_OPERATION);
  GLenum error;
  T* p = api::pixelBufferMemory(*ctx, buffer, values, size_t(m.size) * sizeof(T), error);
  if (error != GL_NO_ERROR) return ctx->recordError(error);
  if (!p) return;
  for (int i = 0; i < m.size; ++i) {
    const T v = toClient(map, m.values[size_t(i)], static_cast<T*>(nullptr));
    std::memcpy(p + i, &v, sizeof v);
  }
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values) {
  pixelMap(map, mapsize, values);
}
GLAPI void APIENTRY glPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values) {
  pixelMap(map, mapsize, values);
}
GLAPI void APIENTRY glPixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values) {
  pixelMap(map, mapsize, values);
}
GLAPI void APIENTRY glGetPixelMapfv(GLenum map, GLfloat* values) { getPixelMap(map, values); }
GLAPI void APIENTRY glGetPixelMapuiv(GLenum map, GLuint* values) { getPixelMap(map, values); }
GLAPI void APIENTRY glGetPixelMapusv(GLenum map, GLushort* values) { getPixelMap(map, values); }

GLAPI void APIENTRY glPixelTransferf(GLenum pname, GLfloat param) {
  if (api::compiled(&glPixelTransferf, pname, param)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PixelModeAttrib& p = ctx->pixelMode;
  switch (pname) {
    case GL_MAP_COLOR: api::setState(*ctx, p.mapColor, param != 0, GL_PIXEL_MODE_BIT); return;
    case GL_MAP_STENCIL: api::setState(*ctx, p.mapStencil, param != 0, GL_PIXEL_MODE_BIT); return;
    case GL_INDEX_SHIFT:
      api::setState(*ctx, p.indexShift, static_cast<GLint>(param), GL_PIXEL_MODE_BIT);
      return;
    case GL_INDEX_OFFSET:
      api::setState(*ctx, p.indexOffset, static_cast<GLint>(param), GL_PIXEL_MODE_BIT);
      return;
    case GL_RED_SCALE: api::setState(*ctx, p.scale.r, param, GL_PIXEL_MODE_BIT); return;
    case GL_GREEN_SCALE: api::setState(*ctx, p.scale.g, param, GL_PIXEL_MODE_BIT); return;
    case GL_BLUE_SCALE: api::setState(*ctx, p.scale.b, param, GL_PIXEL_MODE_BIT); return;
    case GL_ALPHA_SCALE: api::setState(*ctx, p.scale.a, param, GL_PIXEL_MODE_BIT); return;
    case GL_RED_BIAS: api::setState(*ctx, p.bias.r, param, GL_PIXEL_MODE_BIT); return;
    case GL_GREEN_BIAS: api::setState(*ctx, p.bias.g, param, GL_PIXEL_MODE_BIT); return;
    case GL_BLUE_BIAS: api::setState(*ctx, p.bias.b, param, GL_PIXEL_MODE_BIT); return;
    case GL_ALPHA_BIAS: api::setState(*ctx, p.bias.a, param, GL_PIXEL_MODE_BIT); return;
    case GL_DEPTH_SCALE: api::setState(*ctx, p.depthScale, param, GL_PIXEL_MODE_BIT); return;
    case GL_DEPTH_BIAS: api::setState(*ctx, p.depthBias, param, GL_PIXEL_MODE_BIT); return;
    default: ctx->recordError(GL_INVALID_ENUM); return;
  }
}

// glPixelZoom (§3.6.4): stored as given, any value (0, negative, NaN);
// glDrawPixels and glCopyPixels read it.
GLAPI void APIENTRY glPixelZoom(GLfloat xfactor, GLfloat yfactor) {
  if (api::compiled(&glPixelZoom, xfactor, yfactor)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PixelModeAttrib& p = ctx->pixelMode;
  if (p.zoomX == xfactor && p.zoomY == yfactor) return;
  api::beginStateChange(*ctx, GL_PIXEL_MODE_BIT);
  p.zoomX = xfactor;
  p.zoomY = yfactor;
}

GLAPI void APIENTRY glPixelTransferi(GLenum pname, GLint param) {
  glPixelTransferf(pname, static_cast<GLfloat>(param));
}

}  // extern "C"
