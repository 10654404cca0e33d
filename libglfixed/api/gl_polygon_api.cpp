// Polygon rasterization state (GL 2.1 §3.6): glPolygonMode, glPolygonOffset,
// glPolygonStipple, glGetPolygonStipple. Culling and the front face are in
// gl_state_api.cpp; the enables in state/capabilities.cpp.
#include <array>
#include <cstdint>

#include "api/api.h"
#include "api/list_record.h"
#include "api/pixel_buffer.h"
#include "state/buffer_objects.h"

using namespace glfixed;

GLAPI void APIENTRY glPolygonMode(GLenum face, GLenum mode) {
  if (api::compiled(&glPolygonMode, face, mode)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
      (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  PolygonAttrib& p = ctx->polygon;
  const GLenum front = face == GL_BACK ? p.frontMode : mode;
  const GLenum back = face == GL_FRONT ? p.backMode : mode;
  if (front == p.frontMode && back == p.backMode) return;  // unchanged: no flush (main/polygon.c)
  api::beginStateChange(*ctx, GL_POLYGON_BIT);
  p.frontMode = front;
  p.backMode = back;
}

// §3.6.5: any values, NaN and infinities included, are stored as given
// (Mesa: the same; a NaN never equals the stored value, so it always flushes).
GLAPI void APIENTRY glPolygonOffset(GLfloat factor, GLfloat units) {
  if (api::compiled(&glPolygonOffset, factor, units)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  PolygonAttrib& p = ctx->polygon;
  if (p.offsetFactor == factor && p.offsetUnits == units) return;
  api::beginStateChange(*ctx, GL_POLYGON_BIT);
  p.offsetFactor = factor;
  p.offsetUnits = units;
}

// ---- Polygon stipple (GL 2.1 §3.6.2) ------------------------------------------

namespace {

// The bytes and bit of pixel (column, row) of a 32x32 bitmap laid out by the
// pixel store (§3.6.4, §4.3.2: GL_COLOR_INDEX/GL_BITMAP, most significant bit
// first; GL_*_SWAP_BYTES has no effect on bitmaps; LSB_FIRST cannot be set in
// libglfixed yet).
struct BitmapLayout {
  size_t rowBytes = 4, skipBits = 0, skipRows = 0;
  static BitmapLayout of(GLint alignment, GLint rowLength, GLint skipPixels, GLint skipRows) {
    BitmapLayout l;
    const size_t length = rowLength > 0 ? size_t(rowLength) : 32;
    const size_t a = size_t(alignment);
    l.rowBytes = (length + 8 * a - 1) / (8 * a) * a;
    l.skipBits = size_t(skipPixels);
    l.skipRows = size_t(skipRows);
    return l;
  }
  size_t byteOf(int column, int row) const { return (skipRows + row) * rowBytes + (skipBits + column) / 8; }
  uint8_t maskOf(int column) const { return static_cast<uint8_t>(0x80u >> ((skipBits + column) % 8)); }
  size_t bytes() const { return byteOf(31, 31) + 1; }  // the extent the 32 rows use
};

// Reads the pattern through the unpack state; false when nothing is read.
bool unpackStipple(Context& ctx, const GLubyte* mask, std::array<uint32_t, 32>& words) {
  const PixelStoreAttrib& p = ctx.pixelStore;
  const BitmapLayout layout =
      BitmapLayout::of(p.unpackAlignment, p.unpackRowLength, p.unpackSkipPixels, p.unpackSkipRows);
  GLenum error;
  const GLubyte* bytes = api::pixelBufferMemory(ctx, p.pixelUnpackBufferBinding, mask, layout.bytes(), error);
  if (error != GL_NO_ERROR) ctx.recordError(error);
  if (!bytes) return false;
  for (int row = 0; row < 32; ++row) {
    uint32_t w = 0;
    for (int column = 0; column < 32; ++column)
      if (bytes[layout.byteOf(column, row)] & layout.maskOf(column)) w |= 0x80000000u >> column;
    words[row] = w;
  }
  return true;
}

// The command a list replays: the pattern as unpacked at compile time (§5.4).
void setPolygonStipple(const GLuint* words) {
  Context* ctx = api::contextForSetter();
  if (!ctx || !words) return;
  api::beginStateChange(*ctx, GL_POLYGON_STIPPLE_BIT);  // Mesa flushes even when unchanged
  for (int row = 0; row < 32; ++row) ctx->polygonStipple.pattern[row] = words[row];
}

}  // namespace

GLAPI void APIENTRY glPolygonStipple(const GLubyte* mask) {
  Context* ctx = currentContext();
  if (!ctx) return;
  if (api::listCompiler(ctx) && !api::listCompiler(ctx)->insideBeginEnd()) {
    std::array<uint32_t, 32> words;
    if (!unpackStipple(*ctx, mask, words)) return;
    if (api::compiled(&setPolygonStipple, api::copied(words.data(), 32))) return;
    return setPolygonStipple(words.data());
  }
  if (api::compiled(&setPolygonStipple, api::copied<GLuint>(nullptr, 0))) return;  // inside a list's glBegin
  ctx = api::contextForSetter();
  if (!ctx) return;
  std::array<uint32_t, 32> words;
  if (unpackStipple(*ctx, mask, words)) setPolygonStipple(words.data());
}

// Written through the pack state, or into the pixel pack buffer (§6.1.6).
GLAPI void APIENTRY glGetPolygonStipple(GLubyte* mask) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const PixelStoreAttrib& p = ctx->pixelStore;
  const BitmapLayout layout =
      BitmapLayout::of(p.packAlignment, p.packRowLength, p.packSkipPixels, p.packSkipRows);
  GLenum error;
  GLubyte* bytes = api::pixelBufferMemory(*ctx, p.pixelPackBufferBinding, mask, layout.bytes(), error);
  if (error != GL_NO_ERROR) return ctx->recordError(error);
  if (!bytes) return;
  for (int row = 0; row < 32; ++row) {
    // Mesa clears the bits a row's bytes hold besides the pattern's.
    for (size_t i = layout.byteOf(0, row); i <= layout.byteOf(31, row); ++i) bytes[i] = 0;
    const uint32_t w = ctx->polygonStipple.pattern[row];
    for (int column = 0; column < 32; ++column)
      if (w & (0x80000000u >> column)) bytes[layout.byteOf(column, row)] |= layout.maskOf(column);
  }
}
