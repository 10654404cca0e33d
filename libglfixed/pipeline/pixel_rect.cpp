#include "pipeline/pixel_rect.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <vector>

#include "fragment/texture_stage.h"
#include "pipeline/draw.h"
#include "raster/pixel_rect.h"
#include "state/context.h"
#include "texture/internal_format.h"
#include "texture/texture_image.h"
#include "state/framebuffer_binding.h"

namespace glfixed::pipeline {

namespace {

// Runs `draw` into the draw buffer, or into the back then the front buffer
// from the same depth values for GL_FRONT_AND_BACK (§4.2.1; as drawBatch).
template <typename Draw>
void intoDrawBuffers(Context& ctx, Draw draw) {
  if (ctx.objectBound()) refreshFramebuffer(ctx);  // the attachments as they are now
  Framebuffer& fb = ctx.framebuffer;
  if (!fb.drawsIntoBoth(ctx.colorBuffer.drawBuffer)) return draw(fb);
  const DepthBuffer depthBefore = fb.depth;
  draw(fb);
  fb.depth = depthBefore;
  const ColorBuffer back = fb.color;
  fb.color = fb.front;
  draw(fb);
  fb.color = back;
}

// Mesa's IFLOOR of a float, saturated so that far-off positions stay ints.
int floorToInt(float v) {
  if (!(v > -1e9f)) return -1000000000;  // NaN too
  if (v > 1e9f) return 1000000000;
  return static_cast<int>(std::floor(v));
}

bool isIdentity(const glm::mat4& m) { return m == glm::mat4(1.0f); }

// The shading a glBitmap call validates (BitmapShading): Mesa's
// filter_fp_input_mask says which inputs the fixed-function program reads as
// constants (a unit varies with texgen, a texture matrix, point sprites, or
// coordinates per vertex in the last draw).
BitmapShading bitmapShading(const Context& ctx) {
  BitmapShading b;
  b.textured = anyTextureEnabled(ctx.texture);
  if (b.textured) {
    b.texture = ctx.texture;
    for (int u = 0; u < kMaxTextureUnits; ++u) {
      b.texCoord[u] = ctx.current.texCoord[u];
      const TextureUnitEnables& e = ctx.texture.enables[u];
      const bool enabled = e.texture1D || e.texture2D || e.texture3D || e.textureCubeMap;
      const bool texgen = e.genS || e.genT || e.genR || e.genQ;
      if (ctx.point.sprite || (ctx.lastDrawTexCoordUnits >> u & 1u) ||
          (enabled && (texgen || !isIdentity(ctx.textureMatrix[u].top()))))
        b.varyingUnits |= 1u << u;
    }
  }
  // texenv_doing_secondary_color; under lighting the program reads the
  // varying, which the bitmap's vertices do not carry (0).
  b.colorSum = ctx.fog.colorSum;
  // So it is after a draw with per-vertex secondary colours.
  if (b.colorSum && !ctx.lighting.lighting && !ctx.lastDrawSecondaryColorVaries)
    b.secondary = clampedCurrentSecondaryColor(ctx);
  return b;
}

// Draws rows of `on` bytes (1: a fragment) or bits (`packed`), `width` wide,
// at window (x, y), as runs of pixels cut to the region, shaded as `shading` says.
void drawBits(Context& ctx, raster::RasterState state, long long x, long long y, int width, int height,
              const uint8_t* rows, size_t rowBytes, bool packed, float z, const float color[4],
              bool scissorEnabled, const BitmapShading& shading) {
  std::optional<fragment::TextureStage> stage;
  std::optional<raster::QuadTexCoords> quadCoords;
  if (shading.textured) {
    buildTextureStage(shading.texture, *ctx.textures, shading.texCoord, stage.emplace());
    state.texCoordUnits = 0;
    for (int i = 0; i < stage->unitCount; ++i) {
      fragment::TextureStage::Unit& unit = stage->units[i];
      if (!(shading.varyingUnits >> unit.unit & 1u)) continue;
      if (unit.unit == 0) {
        // Unit 0's varying is the bitmap texture's coordinates: 0 to 1
        // over Mesa's quad (the 512 x 32 cache, or the bitmap itself).
        quadCoords.emplace();
        quadCoords->x = static_cast<float>(x);
        quadCoords->y = static_cast<float>(y);
        quadCoords->width = static_cast<float>(width);
        quadCoords->height = static_cast<float>(height);
        state.texCoordUnits = 1;
      } else {
        for (float& c : unit.currentCoord) c = 0.0f;  // a varying the quad does not carry
      }
    }
    state.textures = &*stage;
  }
  const float secondary[4] = {shading.secondary.r, shading.secondary.g, shading.secondary.b, 0.0f};
  if (shading.colorSum) state.varyingCount = 8;
  if (!scissorEnabled) {  // the cache's scissor enable, not the current one
    state.scissorX0 = state.scissorY0 = 0;
    state.scissorX1 = ctx.framebuffer.width();
    state.scissorY1 = ctx.framebuffer.height();
  }
  auto isOn = [&](const uint8_t* row, int i) {
    return packed ? (row[i >> 3] & (0x80u >> (i & 7))) != 0 : row[i] != 0;
  };
  // Rows wholly outside the region draw nothing: skip them.
  const long long rowFirst = std::max<long long>(0, state.scissorY0 - y);
  const long long rowEnd = std::min<long long>(height, state.scissorY1 - y);
  intoDrawBuffers(ctx, [&](Framebuffer& fb) {
    for (long long j = rowFirst; j < rowEnd; ++j) {
      const uint8_t* row = rows + static_cast<size_t>(j) * rowBytes;
      int i = 0;
      while (i < width) {
        if (!isOn(row, i)) {
          ++i;
          continue;
        }
        int end = i + 1;
        while (end < width && isOn(row, end)) ++end;
        const long long x0 = x + i, x1 = x + end;
        if (x1 > state.scissorX0 && x0 < state.scissorX1)
          raster::drawPixelRun(state, fb, static_cast<int>(std::max<long long>(x0, state.scissorX0)),
                               static_cast<int>(y + j),
                               static_cast<int>(std::min<long long>(x1, state.scissorX1)),
                               static_cast<int>(y + j + 1), z, color, secondary,
                               quadCoords ? &*quadCoords : nullptr);
        i = end;
      }
    }
  });
}

}  // namespace

void flushBitmapCache(Context& ctx) {
  BitmapCache& c = ctx.bitmapCache;
  if (c.empty) return;
  c.empty = true;
  if (ctx.framebuffer.bound())
    drawBits(ctx, c.validated, c.xpos, c.ypos, BitmapCache::kWidth, BitmapCache::kHeight, c.on.data(),
             BitmapCache::kWidth, false, c.zpos, c.color, c.scissorEnabled, c.shading);
}

void drawBitmap(Context& ctx, int width, int height, float xorig, float yorig, const uint8_t* bits,
                bool fromList) {
  if (!ctx.framebuffer.bound() || width <= 0 || height <= 0 || !bits) return;
  const RasterPosState& rp = ctx.rasterPos;
  const float epsilon = 0.0001f;
  const long long x = floorToInt(rp.position.x + epsilon - xorig);
  const long long y = floorToInt(rp.position.y + epsilon - yorig);
  const float z = rp.position.z;
  const float color[4] = {rp.color.r, rp.color.g, rp.color.b, rp.color.a};
  const bool scissorEnabled = ctx.scissor.test;
  const size_t rowBytes = static_cast<size_t>(bitmapRowBytes(width));
  BitmapCache& c = ctx.bitmapCache;
  if (fromList) flushBitmapCache(ctx);
  const raster::RasterState state = pixelRectRasterState(ctx);
  c.validated = state;  // st_Bitmap validates before it accumulates
  c.shading = bitmapShading(ctx);
  if (fromList || width > BitmapCache::kWidth || height > BitmapCache::kHeight)
    return drawBits(ctx, state, x, y, width, height, bits, rowBytes, true, z, color, scissorEnabled, c.shading);
  // accum_bitmap: does it fit in the cache with the same colour and depth?
  long long px = 0, py = 0;
  if (!c.empty) {
    px = x - c.xpos;
    py = y - c.ypos;
    const bool sameColor =
        c.color[0] == color[0] && c.color[1] == color[1] && c.color[2] == color[2] && c.color[3] == color[3];
    if (px < 0 || px + width > BitmapCache::kWidth || py < 0 || py + height > BitmapCache::kHeight ||
        !sameColor || scissorEnabled != c.scissorEnabled || std::fabs(z - c.zpos) > 1e-06f)
      flushBitmapCache(ctx);
  }
  if (c.empty) {  // a new cache, the bitmap centred vertically in it
    px = 0;
    py = (BitmapCache::kHeight - height) / 2;
    c.xpos = x;
    c.ypos = y - py;
    c.zpos = z;
    for (int k = 0; k < 4; ++k) c.color[k] = color[k];
    c.scissorEnabled = scissorEnabled;
    c.on.assign(size_t(BitmapCache::kWidth) * BitmapCache::kHeight, 0);
    c.empty = false;
  }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      if (bits[j * rowBytes + (i >> 3)] & (0x80u >> (i & 7)))
        c.on[size_t(py + j) * BitmapCache::kWidth + size_t(px + i)] = 1;
}

namespace {

// The internal format st_DrawPixels gives its temporary texture for a colour
// image of `type` (st_cb_drawpixels.c, internal_format). Mesa applies the
// scale and bias in its fragment shader, on the sampled value; here they are
// applied while unpacking, into 16 bits a channel so that the value keeps
// its precision until the colour is written (a float texture in Mesa).
GLint drawPixelsInternalFormat(GLenum type, bool scaleBias) {
  if (scaleBias) return GL_RGBA16;
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV: return GL_R3_G3_B2;
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return GL_RGBA4;
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV: return GL_RGB;  // RGB565: B5G6R5 matches exactly
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return GL_RGB5_A1;
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV: return GL_RGB10_A2;
    case GL_UNSIGNED_SHORT:
    case GL_UNSIGNED_INT:
    case GL_SHORT:
    case GL_INT:
    case GL_FLOAT: return GL_RGBA16;  // Mesa: RGBA16, RGBA16_SNORM, RGBA32F
    default: return GL_RGBA8;
  }
}

// Mesa's lroundf of the raster position, saturated so that far-off
// positions stay ints.
long long roundToInt(float v) {
  if (!(v > -1e9f)) return -1000000000;  // NaN too
  if (v > 1e9f) return 1000000000;
  return std::lround(v);
}

// What the fragments of a stencil image do (draw_textured_quad with
// write_stencil, measured on llvmpipe): the stencil test, depth test, alpha
// test, blending and colour writes of the GL state do not apply.
void writeStencilImageState(const Context& ctx, bool writeDepth, raster::RasterState& r) {
  for (bool& c : r.colorWrite) c = false;
  r.alphaTest = fragment::AlphaTestState();
  r.blend = fragment::BlendState();
  r.depthTest = writeDepth;
  r.depthFunc = GL_ALWAYS;
  r.depthWrite = ctx.depth.writeMask;
  r.stencil.enabled = ctx.framebuffer.depth.stencilBits() > 0;
  fragment::StencilFaceState f;
  f.func = GL_ALWAYS;
  f.writeMask = static_cast<int32_t>(ctx.stencil.face[0].writeMask & 0xffu);
  f.fail = f.depthFail = GL_KEEP;
  f.depthPass = GL_REPLACE;
  r.stencil.face[0] = r.stencil.face[1] = f;
}

// The temporary texture and its quad: the image drawn at window (x, y)
// zoomed by the pixel zoom (draw_textured_quad). `topDown`: texture row 0 is
// the image's top row (glCopyPixels reads the buffer that way), else its
// bottom row (glDrawPixels).
// `color`: the fragments' colour (null: the raster colour). A `depth`
// image with stencil values writes them as st_DrawPixels sets the state for
// a stencil write: stencil test GL_ALWAYS, GL_REPLACE under the front write
// mask; no colour, alpha test or blending; the depth test only to write an
// image's depth (GL_ALWAYS, under the depth mask). The scissor (when on)
// still cuts (draw_textured_quad's rasterizer state).
void drawTexturedQuad(Context& ctx, const texture::TextureObject* object,
                      const fragment::DepthImageState* depth, long long x, long long y, int width, int height,
                      bool topDown, const float* color = nullptr) {
  const PixelModeAttrib& pm = ctx.pixelMode;
  const float zoomX = pm.zoomX, zoomY = pm.zoomY;
  raster::PixelQuad q;
  q.x0 = static_cast<float>(x);
  q.y0 = static_cast<float>(y);
  q.x1 = static_cast<float>(x) + static_cast<float>(width) * zoomX;
  q.y1 = static_cast<float>(y) + static_cast<float>(height) * zoomY;
  q.z = ctx.rasterPos.position.z;
  q.s0 = 0.0f;
  q.s1 = 1.0f;
  // st_draw_quad puts t0 at y1 (the top): the bottom row of the image is
  // t = 0 for glDrawPixels, the top row for glCopyPixels (invertTex).
  q.t0 = topDown ? 0.0f : 1.0f;
  q.t1 = topDown ? 1.0f : 0.0f;
  q.texCoords = true;
  const RasterPosState& rp = ctx.rasterPos;
  const float rasterColor[4] = {rp.color.r, rp.color.g, rp.color.b, rp.color.a};
  for (int k = 0; k < 4; ++k) q.color[k] = color ? color[k] : rasterColor[k];
  if (std::isnan(q.x1) || std::isnan(q.y1) || q.x0 == q.x1 || q.y0 == q.y1) return;
  const float w = static_cast<float>(ctx.framebuffer.width()),
              h = static_cast<float>(ctx.framebuffer.height());
  // A quad wholly off the buffer draws nothing.
  if (std::max(q.x0, q.x1) <= 0 || std::min(q.x0, q.x1) >= w || std::max(q.y0, q.y1) <= 0 ||
      std::min(q.y0, q.y1) >= h)
    return;
  fragment::TextureStage stage;
  if (object) {
    fragment::TextureStage::Unit& image = stage.image;
    if (!texture::makeSamplerView(*object, GL_TEXTURE_2D, 0.0f, image.view)) return;
    image.unit = 0;
    image.env.env.mode = GL_REPLACE;  // the fragment colour is the texel (gl_Color replaced)
    image.env.baseFormat = GL_RGBA;
    stage.hasImage = true;
    // The user's texturing: Mesa runs the current fixed-function fragment
    // program with the image in place of gl_Color. glDrawPixels overrides
    // the vertex program (drawpix.c, _mesa_set_vp_override), so the program
    // reads every texture coordinate as a varying: unit 0's becomes the
    // current coordinates, untransformed (nir_lower_drawpixels'
    // gl_MultiTexCoord0), the others are varyings the quad does not carry,
    // (0, 0, 0, 0); so is the secondary colour (no colour sum), and the
    // variant has no fog (MESA_FACTS.md "Pixel rectangles").
    if (anyTextureEnabled(ctx.texture)) {
      glm::vec4 coords[kMaxTextureUnits];
      for (glm::vec4& c : coords) c = glm::vec4(0.0f);
      coords[0] = ctx.current.texCoord[0];
      buildTextureStage(ctx.texture, *ctx.textures, coords, stage);
      for (int i = 0; i < stage.unitCount; ++i) stage.units[i].constantCoord = true;
    }
  }
  // The quad goes down the draw module like any fan (st_draw_quad): in clip
  // space x / width * 2 - 1, clipped against the view volume when it
  // reaches past the buffer (which moves its texture coordinates), the
  // viewport the whole buffer.
  primitive::PrimitiveState ps;
  ps.mode = GL_TRIANGLE_FAN;
  ps.viewportWidth = ctx.framebuffer.width();
  ps.viewportHeight = ctx.framebuffer.height();
  ps.constantPrimary = true;
  ps.raster = pixelRectRasterState(ctx);
  ps.raster.textures = object ? &stage : nullptr;
  // GL_DEPTH_CLAMP: the quad is not clipped at the near and far planes, and
  // its depth is clamped to the viewport the state tracker sets for it,
  // whose depth range is [0, 1] (st_cb_drawpixels.c, cso_set_viewport_dims).
  ps.userClipPlanes.depthClamp = ctx.transform.depthClamp;
  ps.raster.depthClampMin = 0.0f;
  ps.raster.depthClampMax = 1.0f;
  ps.raster.texCoordUnits = 1;
  if (depth) ps.raster.depthImage = *depth;
  if (depth && depth->stencil) writeStencilImageState(ctx, depth->depth != nullptr, ps.raster);
  ps.raster.firstVertexConvention = false;  // the state tracker's rasterizer state
  // Into a framebuffer object the viewport still flips y, so the state
  // tracker places the quad upside down: y = height - (int)(y + h * zoom),
  // and flips the texture (draw_textured_quad, Y_0_BOTTOM).
  if (ctx.framebuffer.rowsUp()) {
    const float top = static_cast<float>(y) + static_cast<float>(height) * zoomY;
    const long long flippedY = ctx.framebuffer.height() - static_cast<long long>(top);
    q.y0 = static_cast<float>(flippedY);
    q.y1 = static_cast<float>(flippedY) + static_cast<float>(height) * zoomY;
    std::swap(q.t0, q.t1);
  }
  ShadedVertices v;
  const float cz = q.z * 2.0f - 1.0f;
  auto clipX = [&](float x) { return x / w * 2.0f - 1.0f; };
  auto clipY = [&](float y) { return y / h * 2.0f - 1.0f; };
  // st_draw_quad's vertices: (x0, y1), (x1, y1), (x1, y0), (x0, y0).
  const float xs[4] = {q.x0, q.x1, q.x1, q.x0}, ys[4] = {q.y1, q.y1, q.y0, q.y0};
  const float ss[4] = {q.s0, q.s1, q.s1, q.s0}, ts[4] = {q.t0, q.t0, q.t1, q.t1};
  v.texCoordUnits = 1;
  for (int i = 0; i < 4; ++i) {
    v.clip.emplace_back(clipX(xs[i]), clipY(ys[i]), cz, 1.0f);
    v.primary[0].emplace_back(q.color[0], q.color[1], q.color[2], q.color[3]);
    v.texCoord[0].emplace_back(ss[i], ts[i], 0.0f, 1.0f);
  }
  intoDrawBuffers(ctx, [&](Framebuffer& fb) { primitive::drawPrimitives(ps, v, fb); });
}

uint8_t* texelAt(texture::TextureImage& image, int i, int j) {
  return image.texels.data() + size_t(j) * image.rowStride +
         size_t(i) * texture::texelFormatInfo(image.format).bytesPerTexel;
}

// GL_MAP_COLOR as Mesa's glDrawPixels and glCopyPixels apply it, in the
// fragment shader after the scale and bias (nir_lower_drawpixels on llvmpipe;
// measured, reference/MESA_FACTS.md "Pixel maps"): the colour c looks red and
// green up in a 256 x 256 RGBA8 texture of the maps, NEAREST and clamped:
// column floor(c * 256) holds entry floor(column * size / 256). Blue and
// alpha come from the second lookup, which samples the image texture itself
// instead of the maps, at (b, a): that texel's red and green. Every texel of
// `image` (the unscaled image, row 0 where t = 0) is replaced by what the
// shader computes from it, in RGBA16, which holds those values exactly.
void mapColorAsMesa(const PixelModeAttrib& pm, const PixelMaps& maps, texture::TextureImage& image) {
  const int width = image.width, height = image.height;
  std::vector<float> raw(size_t(width) * height * 4);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      texture::decodeTexelFloat(image.format, image.texel(i, j, 0), &raw[(size_t(j) * width + i) * 4]);
  auto column = [](float c, int size) {  // NEAREST, CLAMP_TO_EDGE; NaN: 0
    const float x = std::floor(c * static_cast<float>(size));
    return x >= static_cast<float>(size) ? size - 1 : x > 0.0f ? static_cast<int>(x) : 0;
  };
  auto entry = [&](GLenum map, float c) {
    const PixelMap& m = maps[map];
    const float v = m.values[size_t(column(c, 256) * m.size / 256)];
    return std::nearbyint(v * 255.0f) / 255.0f;  // the RGBA8 texel
  };
  if (!texture::defineImage(image, GL_RGBA16, texture::TexelFormat::RGBA16, width, height, 1)) return;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const float* r = &raw[(size_t(j) * width + i) * 4];
      float c[4];
      for (int k = 0; k < 4; ++k) c[k] = r[k] * pm.scale[k] + pm.bias[k];
      const float* second = &raw[(size_t(column(c[3], height)) * width + column(c[2], width)) * 4];
      const float out[4] = {entry(GL_PIXEL_MAP_R_TO_R, c[0]), entry(GL_PIXEL_MAP_G_TO_G, c[1]), second[0],
                            second[1]};
      texture::storeTexel(texture::TexelFormat::RGBA16, out, texelAt(image, i, j));
    }
}

// glDrawPixels(GL_COLOR_INDEX) in RGBA mode as Mesa draws it (measured): each
// index (texture::clientColorIndex) through GL_PIXEL_MAP_I_TO_R .. I_TO_A,
// masked by their sizes (§3.6.5). Mesa's st_DrawPixels unpacks the image
// with the pixel transfer switched off, so GL_INDEX_SHIFT and GL_INDEX_OFFSET
// are not applied, nor the colour scale, bias or maps its shader would add.
void unpackColorIndices(const texture::ClientLayout& layout, const uint8_t* pixels, GLenum type,
                        const PixelMaps& maps, texture::TextureImage& image) {
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const uint32_t index = texture::clientColorIndex(layout, pixels, type, i, j);
      const float rgba[4] = {maps[GL_PIXEL_MAP_I_TO_R].atIndex(index), maps[GL_PIXEL_MAP_I_TO_G].atIndex(index),
                             maps[GL_PIXEL_MAP_I_TO_B].atIndex(index), maps[GL_PIXEL_MAP_I_TO_A].atIndex(index)};
      texture::storeTexel(image.format, rgba, texelAt(image, i, j));
    }
}

std::unique_ptr<texture::TextureObject> temporaryTexture() {
  auto object = std::make_unique<texture::TextureObject>();
  object->target = GL_TEXTURE_2D;
  texture::SamplerParams& p = object->params;
  p.minFilter = p.magFilter = GL_NEAREST;
  p.wrapS = p.wrapT = p.wrapR = GL_CLAMP_TO_EDGE;
  p.maxLevel = 0;
  return object;
}

// blit_copy_pixels (st_cb_drawpixels.c): without zoom, pixel transfer or
// a fragment operation that reads or changes what is written, and without
// an active occlusion query (measured: its fragments are counted), Mesa copies
// with a blit when the rectangles do not overlap in the same buffer. A blit
// writes every channel: the colour write mask is not applied (measured:
// scene pixel_copy). The rectangles are cut to the read buffer, then the
// destination to the draw buffer and the scissor box. True when done so.
bool copyAsBlit(Context& ctx, int srcX, int srcY, int width, int height, long long dstX, long long dstY) {
  const PixelModeAttrib& pm = ctx.pixelMode;
  const ColorBufferAttrib& cb = ctx.colorBuffer;
  const DepthBufferAttrib& d = ctx.depth;
  const StencilAttrib::Face& sf = ctx.stencil.face[0];
  Framebuffer& fb = ctx.framebuffer;
  if (pm.zoomX != 1.0f || pm.zoomY != 1.0f || pm.scale != glm::vec4(1) || pm.bias != glm::vec4(0) ||
      pm.mapColor || cb.blend || cb.alphaTest || (cb.colorLogicOp && cb.logicOpMode != GL_COPY) ||
      (d.test && (d.func != GL_ALWAYS || d.writeMask)) || ctx.fog.enabled ||
      (ctx.stencil.test && (sf.fail != GL_KEEP || sf.depthFail != GL_KEEP || sf.depthPass != GL_KEEP)) ||
      fb.drawsIntoBoth(cb.drawBuffer) || ctx.queries.active() != 0)  // a blit is not counted
    return false;
  const ColorBuffer& read = fb.read;
  // _mesa_clip_readpixels, then _mesa_clip_drawpixels of the rest.
  long long sx0 = srcX, sy0 = srcY, sx1 = static_cast<long long>(srcX) + width,
            sy1 = static_cast<long long>(srcY) + height;
  long long dx0 = dstX, dy0 = dstY;
  auto cutLow = [](long long& a0, long long& b0, long long lo) {
    if (a0 < lo) {
      b0 += lo - a0;
      a0 = lo;
    }
  };
  cutLow(sx0, dx0, 0);
  cutLow(sy0, dy0, 0);
  sx1 = std::min<long long>(sx1, read.width);
  sy1 = std::min<long long>(sy1, read.height);
  if (sx0 >= sx1 || sy0 >= sy1) return true;
  long long bx0 = 0, by0 = 0, bx1 = fb.width(), by1 = fb.height();
  if (ctx.scissor.test) {
    const ScissorAttrib& sc = ctx.scissor;
    bx0 = std::max<long long>(bx0, sc.x);
    by0 = std::max<long long>(by0, sc.y);
    bx1 = std::min<long long>(bx1, static_cast<long long>(sc.x) + sc.width);
    by1 = std::min<long long>(by1, static_cast<long long>(sc.y) + sc.height);
  }
  cutLow(dx0, sx0, bx0);
  cutLow(dy0, sy0, by0);
  const long long w = std::min(sx1 - sx0, bx1 - dx0), h = std::min(sy1 - sy0, by1 - dy0);
  if (w <= 0 || h <= 0) return true;
  // The same buffer and overlapping rectangles: the textured quad instead.
  if (read.pixels == fb.color.pixels && sx0 < dx0 + w && dx0 < sx0 + w && sy0 < dy0 + h && dy0 < sy0 + h)
    return false;
  for (long long j = 0; j < h; ++j)
    for (long long i = 0; i < w; ++i) {
      uint8_t rgba[4];
      read.read(static_cast<int>(sx0 + i), static_cast<int>(sy0 + j), rgba);
      fb.color.write(static_cast<int>(dx0 + i), static_cast<int>(dy0 + j), rgba);
    }
  return true;
}

}  // namespace

void drawColorPixels(Context& ctx, const PixelImage& image) {
  flushBitmapCache(ctx);
  if (!ctx.framebuffer.bound() || image.width <= 0 || image.height <= 0) return;
  const RasterPosState& rp = ctx.rasterPos;
  long long x = roundToInt(rp.position.x), y = roundToInt(rp.position.y);
  int width = image.width, height = image.height;
  texture::ClientLayout layout = image.layout;
  const PixelModeAttrib& pm = ctx.pixelMode;
  // Without zoom Mesa first cuts the rectangle to the buffer and the scissor
  // box (_mesa_clip_drawpixels); the pixels drawn are the same, the texture
  // smaller.
  if (pm.zoomX == 1.0f && pm.zoomY == 1.0f) {
    int x0 = 0, y0 = 0, x1 = ctx.framebuffer.width(), y1 = ctx.framebuffer.height();
    if (ctx.scissor.test) {
      const ScissorAttrib& sc = ctx.scissor;
      x0 = std::max(x0, sc.x);
      y0 = std::max(y0, sc.y);
      x1 = static_cast<int>(std::min<long long>(x1, static_cast<long long>(sc.x) + sc.width));
      y1 = static_cast<int>(std::min<long long>(y1, static_cast<long long>(sc.y) + sc.height));
    }
    const long long skipX = std::max<long long>(0, x0 - x), skipY = std::max<long long>(0, y0 - y);
    const long long endX = std::min<long long>(width, x1 - x), endY = std::min<long long>(height, y1 - y);
    if (skipX >= endX || skipY >= endY) return;
    layout.start +=
        static_cast<size_t>(skipX) * layout.groupBytes + static_cast<size_t>(skipY) * layout.rowStride;
    if (layout.bitmap) {  // GL_BITMAP: skipped columns are bits
      layout.skipBits += static_cast<int>(skipX);
      layout.start += static_cast<size_t>(layout.skipBits / 8);
      layout.skipBits %= 8;
    }
    width = static_cast<int>(endX - skipX);
    height = static_cast<int>(endY - skipY);
    x += skipX;
    y += skipY;
  }
  // clamp_size: at most the largest texture.
  width = std::min(width, texture::kMaxTextureSize);
  height = std::min(height, texture::kMaxTextureSize);
  if (!image.pixels) return ctx.recordError(GL_OUT_OF_MEMORY);  // make_texture fails on a null image
  const bool colorIndex = image.format == GL_COLOR_INDEX;
  const bool mapColor = pm.mapColor && !colorIndex;
  const bool scaleBias = (pm.scale != glm::vec4(1) || pm.bias != glm::vec4(0)) && !pm.mapColor && !colorIndex;
  const GLint internalFormat = colorIndex ? GL_RGBA8 : drawPixelsInternalFormat(image.type, scaleBias);
  auto object = temporaryTexture();
  texture::TextureImage& texImage = object->face[0][0];
  if (!texture::defineImage(texImage, internalFormat,
                            texture::chooseTexelFormat(internalFormat, image.format, image.type), width,
                            height, 1))
    return ctx.recordError(GL_OUT_OF_MEMORY);
  PixelModeAttrib transfer;  // only the scale and bias, or nothing when the maps apply them
  if (scaleBias) {
    transfer.scale = pm.scale;
    transfer.bias = pm.bias;
  }
  if (colorIndex)
    unpackColorIndices(layout, image.pixels, image.type, ctx.pixelMaps, texImage);
  else
    texture::unpackImage(layout, image.pixels, image.format, image.type, transfer, width, height, 1, texImage,
                         0, 0, 0);
  if (mapColor) mapColorAsMesa(pm, ctx.pixelMaps, texImage);
  drawTexturedQuad(ctx, object.get(), nullptr, x, y, width, height, false);
}

// glCopyPixels' source rectangle cut to the buffer read (_mesa_clip_readpixels).
struct CopySource {
  long long srcX, srcY, x0, y0, x1, y1;
  CopySource(int x, int y, int width, int height, int bufferWidth, int bufferHeight)
      : srcX(x), srcY(y), x0(std::max<long long>(0, x)), y0(std::max<long long>(0, y)),
        x1(std::min<long long>(bufferWidth, static_cast<long long>(x) + width)),
        y1(std::min<long long>(bufferHeight, static_cast<long long>(y) + height)) {}
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  // visit(sx, sy, row, col) for every source pixel inside the buffer and the
  // width x height image it is read into, row 0 the image's top row: the
  // whole source is read before anything is drawn (overlapping copies).
  template <typename Visit>
  void forEachPixel(int width, int height, Visit visit) const {
    for (long long sy = y0; sy < y1; ++sy) {
      const int row = static_cast<int>(srcY + height - 1 - sy);
      if (row < 0 || row >= height) continue;
      for (long long sx = x0; sx < x1; ++sx) {
        const int col = static_cast<int>(sx - srcX);
        if (col >= width) break;
        visit(static_cast<int>(sx), static_cast<int>(sy), row, col);
      }
    }
  }
};

void copyColorPixels(Context& ctx, int srcX, int srcY, int width, int height) {
  flushBitmapCache(ctx);
  Framebuffer& fb = ctx.framebuffer;
  if (!fb.bound() || !fb.read.pixels || width <= 0 || height <= 0) return;
  const RasterPosState& rp = ctx.rasterPos;
  const long long x = roundToInt(rp.position.x), y = roundToInt(rp.position.y);
  const ColorBuffer& read = fb.read;
  // Wholly outside the read buffer: nothing is drawn.
  const CopySource source(srcX, srcY, width, height, read.width, read.height);
  if (source.empty()) return;
  if (copyAsBlit(ctx, srcX, srcY, width, height, x, y)) return;
  width = std::min(width, texture::kMaxTextureSize);
  height = std::min(height, texture::kMaxTextureSize);
  const PixelModeAttrib& pm = ctx.pixelMode;
  const bool scaleBias = (pm.scale != glm::vec4(1) || pm.bias != glm::vec4(0)) && !pm.mapColor;
  auto object = temporaryTexture();
  texture::TextureImage& texImage = object->face[0][0];
  const GLint internalFormat = scaleBias ? GL_RGBA16 : GL_RGBA8;
  const texture::TexelFormat format = scaleBias ? texture::TexelFormat::RGBA16 : texture::TexelFormat::RGBA8;
  if (!texture::defineImage(texImage, internalFormat, format, width, height, 1))
    return ctx.recordError(GL_OUT_OF_MEMORY);
  // The whole source is read before anything is drawn (overlapping copies),
  // texture row 0 the top row; what lies outside the read buffer stays 0.
  source.forEachPixel(width, height, [&](int sx, int sy, int row, int col) {
    uint8_t rgba[4];
    read.read(sx, sy, rgba);
    uint8_t* t = texImage.texels.data() + size_t(row) * texImage.rowStride +
                 size_t(col) * texture::texelFormatInfo(format).bytesPerTexel;
    if (!scaleBias) {
      for (int k = 0; k < 4; ++k) t[k] = rgba[k];
    } else {
      float c[4];
      for (int k = 0; k < 4; ++k)
        c[k] = static_cast<float>(rgba[k]) * (1.0f / 255.0f) * pm.scale[k] + pm.bias[k];
      texture::storeTexel(format, c, t);
    }
  });
  if (pm.mapColor) mapColorAsMesa(pm, ctx.pixelMaps, texImage);
  drawTexturedQuad(ctx, object.get(), nullptr, x, y, width, height, true);
}

void drawDepthPixels(Context& ctx, const PixelImage& image) {
  flushBitmapCache(ctx);
  if (!ctx.framebuffer.bound() || image.width <= 0 || image.height <= 0) return;
  const RasterPosState& rp = ctx.rasterPos;
  const long long x = roundToInt(rp.position.x), y = roundToInt(rp.position.y);
  const int width = std::min(image.width, texture::kMaxTextureSize);
  const int height = std::min(image.height, texture::kMaxTextureSize);
  const PixelModeAttrib& pm = ctx.pixelMode;
  if (pm.zoomX == 1.0f && pm.zoomY == 1.0f) {  // _mesa_clip_drawpixels: wholly outside reads nothing
    const ScissorAttrib& sc = ctx.scissor;
    long long x0 = 0, y0 = 0, x1 = ctx.framebuffer.width(), y1 = ctx.framebuffer.height();
    if (sc.test) {
      x0 = std::max<long long>(x0, sc.x);
      y0 = std::max<long long>(y0, sc.y);
      x1 = std::min<long long>(x1, static_cast<long long>(sc.x) + sc.width);
      y1 = std::min<long long>(y1, static_cast<long long>(sc.y) + sc.height);
    }
    if (x + width <= x0 || x >= x1 || y + height <= y0 || y >= y1) return;
  }
  if (!image.pixels) return ctx.recordError(GL_OUT_OF_MEMORY);
  // The depth the shader samples: the image unpacked (depth scale and bias
  // applied, §3.6.5) into the texture format st_DrawPixels picks, read back
  // as llvmpipe's sampler converts it to float.
  std::vector<float> depth(static_cast<size_t>(width) * height);
  if (image.type == GL_FLOAT) {  // GL_DEPTH_COMPONENT32F: the values as they are, clamped
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        float v;
        std::memcpy(
            &v, image.pixels + image.layout.start + size_t(j) * image.layout.rowStride + size_t(i) * 4, 4);
        if (image.layout.swapBytes) {
          uint32_t u;
          std::memcpy(&u, &v, 4);
          u = __builtin_bswap32(u);
          std::memcpy(&v, &u, 4);
        }
        v = v * pm.depthScale + pm.depthBias;
        depth[size_t(j) * width + i] = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN: 0
      }
  } else {
    const GLint internalFormat = image.type == GL_UNSIGNED_SHORT ? GL_DEPTH_COMPONENT16
                                 : image.type == GL_UNSIGNED_INT ? GL_DEPTH_COMPONENT32
                                                                 : GL_DEPTH_COMPONENT24;
    const texture::TexelFormat format = image.type == GL_UNSIGNED_SHORT ? texture::TexelFormat::Z16
                                        : image.type == GL_UNSIGNED_INT ? texture::TexelFormat::Z32
                                                                        : texture::TexelFormat::Z24;
    texture::TextureImage texImage;
    if (!texture::defineImage(texImage, internalFormat, format, width, height, 1))
      return ctx.recordError(GL_OUT_OF_MEMORY);
    texture::unpackImage(image.layout, image.pixels, image.format, image.type, pm, width, height, 1, texImage,
                         0, 0, 0);
    const float scale = format == texture::TexelFormat::Z16   ? 1.0f / 65535.0f
                        : format == texture::TexelFormat::Z24 ? 1.0f / 16777215.0f
                                                              : 1.0f / 4294967295.0f;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i)
        depth[size_t(j) * width + i] =
            static_cast<float>(texture::storedChannel(format, texImage.texel(i, j, 0), 0)) * scale;
  }
  fragment::DepthImageState d;
  d.depth = depth.data();
  d.width = width;
  d.height = height;
  drawTexturedQuad(ctx, nullptr, &d, x, y, width, height, false);
}

namespace {

// A stencil index of a client image as Mesa unpacks it (extract_uint_indexes,
// then the low 8 bits): integers as they are (signed ones sign-extended),
// floats truncated as x86's 64-bit conversion does (NaN and the far-off
// ones: 0), bits 0 or 1. Measured: 300.0 draws 44, -1 draws 255.
uint8_t unpackedStencilIndex(const PixelImage& image, int i, int j) {
  const texture::ClientLayout& l = image.layout;
  const uint8_t* row = image.pixels + l.start + static_cast<size_t>(j) * l.rowStride;
  if (l.bitmap) {  // most significant bit first
    const int bit = l.skipBits + i;
    return (row[bit >> 3] >> (7 - (bit & 7))) & 1u;
  }
  const uint8_t* p = row + static_cast<size_t>(i) * l.groupBytes;
  const int bytes = image.type == GL_UNSIGNED_BYTE || image.type == GL_BYTE     ? 1
                    : image.type == GL_UNSIGNED_SHORT || image.type == GL_SHORT ? 2
                                                                                : 4;
  uint8_t b[4];
  for (int k = 0; k < bytes; ++k) b[k] = p[l.swapBytes ? bytes - 1 - k : k];
  if (bytes < 4) return b[0];  // the low byte (little-endian)
  uint32_t v;
  std::memcpy(&v, b, 4);
  if (image.type == GL_FLOAT) {
    float f;
    std::memcpy(&f, &v, 4);
    if (!(std::fabs(f) < 9.2e18f)) return 0;  // cvttss2si's 0x8000000000000000, NaN too
    return static_cast<uint8_t>(static_cast<uint64_t>(static_cast<int64_t>(f)));
  }
  return static_cast<uint8_t>(v);  // GL_UNSIGNED_INT_24_8: the stencil is the low byte
}

// _mesa_clip_drawpixels without zoom: an image wholly outside the buffer and
// the scissor box reads no pixel.
bool drawnAtAll(const Context& ctx, long long x, long long y, int width, int height) {
  const PixelModeAttrib& pm = ctx.pixelMode;
  if (pm.zoomX != 1.0f || pm.zoomY != 1.0f) return true;
  const ScissorAttrib& sc = ctx.scissor;
  long long x0 = 0, y0 = 0, x1 = ctx.framebuffer.width(), y1 = ctx.framebuffer.height();
  if (sc.test) {
    x0 = std::max<long long>(x0, sc.x);
    y0 = std::max<long long>(y0, sc.y);
    x1 = std::min<long long>(x1, static_cast<long long>(sc.x) + sc.width);
    y1 = std::min<long long>(y1, static_cast<long long>(sc.y) + sc.height);
  }
  return !(x + width <= x0 || x >= x1 || y + height <= y0 || y >= y1);
}

// A depth value of the depth buffer as llvmpipe's sampler reads the
// temporary depth texture (its format the buffer's).
float storedDepthAsFloat(const DepthBuffer& db, uint32_t d) {
  return static_cast<float>(d) * (db.bits() == 16 ? 1.0f / 65535.0f : 1.0f / 16777215.0f);
}

}  // namespace

void drawStencilPixels(Context& ctx, const PixelImage& image) {
  flushBitmapCache(ctx);
  if (!ctx.framebuffer.bound() || image.width <= 0 || image.height <= 0) return;
  const RasterPosState& rp = ctx.rasterPos;
  const long long x = roundToInt(rp.position.x), y = roundToInt(rp.position.y);
  const int width = std::min(image.width, texture::kMaxTextureSize);
  const int height = std::min(image.height, texture::kMaxTextureSize);
  if (!drawnAtAll(ctx, x, y, width, height)) return;
  if (!image.pixels) return ctx.recordError(GL_OUT_OF_MEMORY);
  // The stencil values (and depths) the shader samples, row 0 the bottom
  // row. No index shift, offset or S_TO_S map: Mesa stores the image with
  // the pixel transfer state cleared (measured; framebuffer/stencil_index.h).
  const bool withDepth = image.format == GL_DEPTH_STENCIL;
  std::vector<uint8_t> stencil;
  std::vector<float> depth;
  try {
    stencil.resize(static_cast<size_t>(width) * height);
    depth.resize(withDepth ? stencil.size() : 0);
  } catch (const std::bad_alloc&) {
    return ctx.recordError(GL_OUT_OF_MEMORY);  // as make_texture failing
  }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const size_t at = static_cast<size_t>(j) * width + i;
      stencil[at] = unpackedStencilIndex(image, i, j);
      if (withDepth) {  // GL_UNSIGNED_INT_24_8: the depth in the top 24 bits, no scale or bias (measured)
        const uint8_t* p = image.pixels + image.layout.start +
                           static_cast<size_t>(j) * image.layout.rowStride + static_cast<size_t>(i) * 4;
        uint32_t v;
        std::memcpy(&v, p, 4);
        if (image.layout.swapBytes) v = __builtin_bswap32(v);
        depth[at] = static_cast<float>(v >> 8) * (1.0f / 16777215.0f);
      }
    }
  fragment::DepthImageState d;
  d.depth = withDepth ? depth.data() : nullptr;
  d.stencil = stencil.data();
  d.width = width;
  d.height = height;
  drawTexturedQuad(ctx, nullptr, &d, x, y, width, height, false);
}

void copyDepthStencilPixels(Context& ctx, int srcX, int srcY, int width, int height, GLenum type) {
  flushBitmapCache(ctx);
  Framebuffer& fb = ctx.framebuffer;
  if (!fb.bound() || width <= 0 || height <= 0) return;
  const DepthBuffer& db = fb.depth;
  const RasterPosState& rp = ctx.rasterPos;
  const long long x = roundToInt(rp.position.x), y = roundToInt(rp.position.y);
  // The source cut to the buffer; wholly outside: nothing is drawn.
  const CopySource source(srcX, srcY, width, height, db.width(), db.height());
  if (source.empty()) return;
  width = std::min(width, texture::kMaxTextureSize);
  height = std::min(height, texture::kMaxTextureSize);
  // llvmpipe cannot render to a depth format, so Mesa never blits these: the
  // source is read whole first (overlapping copies), texture row 0 the top
  // row, 0 outside the buffer; values as stored: no depth scale or bias, no
  // index shift, offset or map (measured).
  const bool copyDepth = type != GL_STENCIL, copyStencil = type != GL_DEPTH;
  const size_t texels = static_cast<size_t>(width) * height;
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  try {
    depth.assign(copyDepth ? texels : 0, 0.0f);
    stencil.assign(copyStencil ? texels : 0, 0);
  } catch (const std::bad_alloc&) {
    return ctx.recordError(GL_OUT_OF_MEMORY);
  }
  source.forEachPixel(width, height, [&](int sx, int sy, int row, int col) {
    const size_t at = static_cast<size_t>(row) * width + col;
    if (copyDepth) depth[at] = storedDepthAsFloat(db, db.get(sx, sy));
    if (copyStencil) stencil[at] = static_cast<uint8_t>(db.getStencil(sx, sy));
  });
  fragment::DepthImageState d;
  d.depth = copyDepth ? depth.data() : nullptr;
  d.stencil = copyStencil ? stencil.data() : nullptr;
  d.width = width;
  d.height = height;
  // A depth copy's fragments are coloured with the current colour (st_CopyPixels),
  // not the raster colour, and go through the fragment operations.
  const glm::vec4& c = ctx.current.color;
  const float color[4] = {c.r, c.g, c.b, c.a};
  drawTexturedQuad(ctx, nullptr, &d, x, y, width, height, true, color);
}

}  // namespace glfixed::pipeline
