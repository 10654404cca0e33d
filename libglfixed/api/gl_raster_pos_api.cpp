// The current raster position (GL 2.1 §2.13), glWindowPos (GL 1.4 §2.13),
// and the pixel rectangle commands that draw at it: glBitmap (§3.7),
// glDrawPixels (§3.6.4) and glCopyPixels (§4.3.3); in GL_FEEDBACK and
// GL_SELECT what §5.2, §5.3 say. The drawing itself is pipeline/pixel_rect.
//
// For fixed-function vertex processing Mesa computes the raster position in
// plain C (main/rastpos.c, reached from st_RasterPos): float matrix products
// summed left to right, a clip test against the six planes, ndc * scale +
// translate unfused, w the clip w; an invalid position leaves the old values.
#include <cmath>
#include <vector>

#include "api/api.h"
#include "api/list_record.h"
#include "api/pixel_buffer.h"
#include "pipeline/pixel_rect.h"
#include "state/lighting_attrib.h"
#include "texture/unpack.h"
#include "vertex/lighting_matrix.h"
#include "vertex/vertex_stage.h"

using namespace glfixed;

namespace {

// Mesa's TRANSFORM_POINT: each row summed left to right, rounded each step.
glm::vec4 transformPoint(const glm::mat4& m, const glm::vec4& p) {
  glm::vec4 q;
  for (int r = 0; r < 4; ++r) {
    float s = m[0][r] * p[0];
    s = s + m[1][r] * p[1];
    s = s + m[2][r] * p[2];
    q[r] = s + m[3][r] * p[3];
  }
  return q;
}

// Texture coordinates (issue 14): rastpos.c computes every unit's in C, for
// every unit whatever its texture enables: texgen where a coordinate's
// generation is on (compute_texgen, the sphere-map terms always), then the
// texture matrix (TRANSFORM_POINT), whether or not it is the identity. The
// normal is the current one, through the inverse modelview (TRANSFORM_NORMAL)
// only when Mesa works in eye coordinates (_NeedEyeCoords), and never
// normalised or rescaled (measured: GL_NORMALIZE and GL_RESCALE_NORMAL change
// nothing; feedback_texcoords).
void rasterTexCoords(const Context& ctx, const vertex::VertexState& vs, const glm::vec4& object,
                     const glm::vec4& eye, RasterPosState& rp) {
  const vertex::ModelviewAnalysis mv = vertex::analyseModelview(ctx.modelview.top());
  // _mesa_update_tnl_spaces: texgen that needs eye coordinates on a unit
  // whose texture is enabled, point attenuation, lighting that needs them or
  // a modelview that does not keep lengths.
  const bool lit = ctx.lighting.lighting;
  const bool eyeCoords = vs.texCoord.needEyeCoords || vs.pointAttenuated ||
                         (lit && vs.lightingConstants && !vs.lightingConstants->lightsAllowObjectSpace) ||
                         (lit && !mv.lengthPreserving);
  const glm::vec3 n =
      eyeCoords ? vertex::transformNormalLikeMesa(mv.inverse, ctx.current.normal) : ctx.current.normal;
  // The sphere-map terms (NORMALIZE_3FV of the eye position).
  glm::vec3 u(eye);
  {
    float len = u.x * u.x + u.y * u.y + u.z * u.z;
    if (len != 0.0f) {
      len = 1.0f / std::sqrt(len);
      u = glm::vec3(u.x * len, u.y * len, u.z * len);
    }
  }
  const float twoNu = 2.0f * (n.x * u.x + n.y * u.y + n.z * u.z);
  const glm::vec3 r(u.x - n.x * twoNu, u.y - n.y * twoNu, u.z - n.z * twoNu);
  const float m = r.x * r.x + r.y * r.y + (r.z + 1.0f) * (r.z + 1.0f);
  const float mInv = m > 0.0f ? 0.5f * (1.0f / std::sqrt(m)) : 0.0f;
  auto dot4 = [](const glm::vec4& a, const glm::vec4& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  };
  for (int unit = 0; unit < kMaxTextureUnits; ++unit) {
    glm::vec4 tc = ctx.current.texCoord[unit];
    const TextureUnitEnables& e = ctx.texture.enables[unit];
    const bool on[4] = {e.genS, e.genT, e.genR, e.genQ};
    const TexGenAttrib& g = ctx.texture.texgen[unit];
    for (int j = 0; j < 4; ++j) {
      if (!on[j]) continue;
      switch (g.coord[j].mode) {
        case GL_OBJECT_LINEAR: tc[j] = dot4(object, g.coord[j].objectPlane); break;
        case GL_EYE_LINEAR: tc[j] = dot4(eye, g.coord[j].eyePlane); break;
        case GL_SPHERE_MAP: tc[j] = r[j] * mInv + 0.5f; break;
        case GL_REFLECTION_MAP: tc[j] = r[j]; break;
        case GL_NORMAL_MAP: tc[j] = n[j]; break;
        default: break;
      }
    }
    rp.unitTexCoord[unit] = transformPoint(ctx.textureMatrix[unit].top(), tc);
  }
  rp.texCoord = rp.unitTexCoord[0];
}

// Every form is compiled as this one call (Mesa's save_RasterPos4f).
void rasterPos(float x, float y, float z, float w) {
  if (api::compiled(&rasterPos, x, y, z, w)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  RasterPosState& rp = ctx->rasterPos;
  const glm::vec4 object(x, y, z, w);
  const glm::vec4 eye = transformPoint(ctx->modelview.top(), object);
  const glm::vec4 clip = transformPoint(ctx->projection.top(), eye);
  // GL_DEPTH_CLAMP: no near and far test; the window z stays unclamped (Mesa).
  const bool depthOutside = !ctx->transform.depthClamp && (clip.z > clip.w || clip.z < -clip.w);
  if (depthOutside || clip.x > clip.w || clip.x < -clip.w || clip.y > clip.w || clip.y < -clip.w) {
    rp.valid = false;
    return;
  }
  const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
  const ViewportAttrib& v = ctx->viewport;
  const float halfWidth = 0.5f * static_cast<float>(v.width),
              halfHeight = 0.5f * static_cast<float>(v.height);
  const float n = static_cast<float>(api::clamp01(v.depthNear)),
              f = static_cast<float>(api::clamp01(v.depthFar));
  const float scale[3] = {halfWidth, halfHeight, static_cast<float>(0.5 * (double(f) - double(n)))};
  const float translate[3] = {halfWidth + static_cast<float>(v.x), halfHeight + static_cast<float>(v.y),
                              static_cast<float>(0.5 * (double(n) + double(f)))};
  for (int i = 0; i < 3; ++i) {
    const float ndc = clip[i] * d;
    const float scaled = ndc * scale[i];
    rp.position[i] = scaled + translate[i];
  }
  rp.position[3] = clip.w;
  // GL_CURRENT_RASTER_DISTANCE (§2.13, EXT_fog_coord): the current fog
  // coordinate as it is (no fabs) when it is the fog source, else the eye
  // distance (rastpos.c; fog enabled or not).
  rp.distance = ctx->fog.coordSrc == GL_FOG_COORD ? ctx->current.fogCoord
                                                 : std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  const vertex::VertexState& vs = ctx->validate();
  rasterTexCoords(*ctx, vs, object, eye, rp);  // texture coordinates (issue 14)
  if (vs.lighting) {
    // Lit by the lighting stage (Mesa lights it in C: not bit-identical).
    VertexBatch batch;
    batch.reset(GL_POINTS, ctx->lighting.material);
    batch.resizeVertices(1);
    batch.position[0] = object;
    batch.normal[0] = ctx->current.normal;
    batch.color[0] = ctx->current.color;
    ShadedVertices shaded;
    vertex::shadeBatch(vs, batch, shaded);
    rp.color = shaded.primary[kFront][0];
    rp.secondaryColor = shaded.hasSecondary ? shaded.secondary[kFront][0] : glm::vec4(0, 0, 0, 1);
    rp.secondaryColor.a = 1.0f;  // rastpos.c: the specular colour's alpha is 1
  } else {
    rp.color = ctx->current.color;
    rp.secondaryColor = ctx->current.secondaryColor;
  }
  rp.valid = true;
  if (ctx->renderMode.mode == GL_SELECT) ctx->renderMode.select.updateHitFlag(rp.position.z);
}

// GL_FEEDBACK: the token and the raster position as a vertex (§5.3).
void feedbackRasterPos(Context& ctx, GLenum token) {
  FeedbackState& f = ctx.renderMode.feedback;
  const RasterPosState& rp = ctx.rasterPos;
  f.token(static_cast<GLfloat>(token));
  f.token(rp.position.x);
  f.token(rp.position.y);
  const GLenum type = f.type;
  if (type != GL_2D) f.token(rp.position.z);
  if (type == GL_4D_COLOR_TEXTURE) f.token(rp.position.w);
  if (type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE)
    for (int k = 0; k < 4; ++k) f.token(rp.color[k]);
  if (type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE)
    for (int k = 0; k < 4; ++k) f.token(rp.texCoord[k]);
}

bool isDrawPixelsFormat(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_RGB:
    case GL_RGBA:
    case GL_BGR:
    case GL_BGRA:
    case GL_LUMINANCE:
    case GL_LUMINANCE_ALPHA:
    case GL_DEPTH_STENCIL: return true;
    default: return false;
  }
}

bool isPackedPixelType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV: return true;
    default: return false;
  }
}

// GL 2.1 §3.6.4 and table 3.8: the error a format/type pair raises, if any.
GLenum drawPixelsTypeError(const Context& ctx, GLenum format, GLenum type) {
  // GL_RG (ARB_texture_rg) is no format here, but with a packed type it is
  // the invalid operation Mesa records (piglit draw-pixels checks it).
  constexpr GLenum kRG = 0x8227;
  if (format == kRG) return isPackedPixelType(type) ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
  if (!isDrawPixelsFormat(format)) return GL_INVALID_ENUM;
  // EXT_packed_depth_stencil: GL_DEPTH_STENCIL only with its type (else an
  // invalid enum), the type only with it (else an invalid operation).
  if (format == GL_DEPTH_STENCIL && type != GL_UNSIGNED_INT_24_8) return GL_INVALID_ENUM;
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: break;
    case GL_BITMAP:
      if (format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX) return GL_INVALID_ENUM;
      break;
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
      if (format != GL_RGB) return GL_INVALID_OPERATION;
      break;
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
      if (format != GL_RGBA && format != GL_BGRA) return GL_INVALID_OPERATION;
      break;
    case GL_UNSIGNED_INT_24_8:
      if (format != GL_DEPTH_STENCIL) return GL_INVALID_OPERATION;
      break;
    default: return GL_INVALID_ENUM;
  }
  // §3.6.4: stencil only with a stencil buffer, depth only with a depth buffer.
  const DepthBuffer& db = ctx.framebuffer.depth;
  if ((format == GL_STENCIL_INDEX || format == GL_DEPTH_STENCIL) && db.stencilBits() == 0)
    return GL_INVALID_OPERATION;
  if ((format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL) && db.bits() == 0)
    return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

// After validation, outside GL_RENDER: GL_FEEDBACK writes the token,
// GL_SELECT does nothing (GL 2.1 appendix B, corollary 6; Mesa alike).
void pixelsInFeedbackOrSelect(Context& ctx, GLenum token) {
  if (ctx.renderMode.mode == GL_FEEDBACK) feedbackRasterPos(ctx, token);
}

// glBitmap's bits through the unpack state (§3.6.4 with GL_COLOR_INDEX,
// GL_BITMAP; most significant bit first) into Mesa's tight rows
// (pipeline::bitmapRowBytes). False (error recorded if any) when nothing
// can be read.
bool unpackBitmap(Context& ctx, int width, int height, const GLubyte* bitmap, std::vector<GLubyte>& bits) {
  PixelStoreAttrib store = ctx.pixelStore;
  store.unpackSkipImages = 0;  // a 2D image
  const texture::ClientLayout layout = texture::unpackLayout(store, width, height, GL_COLOR_INDEX, GL_BITMAP);
  GLenum error;
  const uint8_t* src = api::pixelBufferMemory(ctx, ctx.pixelStore.pixelUnpackBufferBinding, bitmap,
                                              layout.extent(width, height, 1), error);
  if (error) ctx.recordError(error);
  if (!src) return false;
  const int rowBytes = pipeline::bitmapRowBytes(width);
  bits.assign(static_cast<size_t>(rowBytes) * height, 0);
  for (int j = 0; j < height; ++j) {
    const uint8_t* row = src + layout.start + static_cast<size_t>(j) * layout.rowStride;
    for (int i = 0; i < width; ++i) {
      const int bit = layout.skipBits + i;
      if (row[bit >> 3] & (0x80u >> (bit & 7))) bits[size_t(j) * rowBytes + (i >> 3)] |= 0x80u >> (i & 7);
    }
  }
  return true;
}

// glBitmap with its bits unpacked: what a display list stores and replays
// (Mesa's save_Bitmap unpacks at compile time, §5.4).
void bitmapUnpacked(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                    const GLubyte* bits) {
  if (api::compiled(&bitmapUnpacked, width, height, xorig, yorig, xmove, ymove,
                    api::copied(bits, bits ? size_t(pipeline::bitmapRowBytes(width)) * size_t(height) : 0)))
    return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!ctx->rasterPos.valid) return;
  if (ctx->renderMode.mode == GL_RENDER)
    pipeline::drawBitmap(*ctx, width, height, xorig, yorig, bits, ctx->displayLists.executing);
  else
    pixelsInFeedbackOrSelect(*ctx, GL_BITMAP_TOKEN);
  ctx->rasterPos.position.x += xmove;
  ctx->rasterPos.position.y += ymove;
}

// glDrawPixels with its image read: `bytes` is the client memory (or the
// display list's copy of its first `extent` bytes), laid out as `layout`.
void drawPixelsUnpacked(GLsizei width, GLsizei height, GLenum format, GLenum type,
                        texture::ClientLayout layout, const uint8_t* bytes, size_t extent) {
  if (api::compiled(&drawPixelsUnpacked, width, height, format, type, layout, api::copied(bytes, extent),
                    extent))
    return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (GLenum e = drawPixelsTypeError(*ctx, format, type)) return ctx->recordError(e);
  if (!ctx->rasterPos.valid) return;
  if (ctx->renderMode.mode != GL_RENDER) return pixelsInFeedbackOrSelect(*ctx, GL_DRAW_PIXEL_TOKEN);
  if (width == 0 || height == 0) return;
  pipeline::PixelImage image;
  image.width = width;
  image.height = height;
  image.format = format;
  image.type = type;
  image.layout = layout;
  image.pixels = bytes;
  if (format == GL_DEPTH_COMPONENT) return pipeline::drawDepthPixels(*ctx, image);
  if (format == GL_STENCIL_INDEX || format == GL_DEPTH_STENCIL)
    return pipeline::drawStencilPixels(*ctx, image);
  pipeline::drawColorPixels(*ctx, image);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                             GLfloat ymove, const GLubyte* bitmap) {
  Context* ctx = api::context();
  if (!ctx) return;
  std::vector<GLubyte> bits;
  const bool compiling = api::listCompiler(ctx) && !api::listCompiler(ctx)->insideBeginEnd();
  // The bits are read while compiling (§5.4), or when something is drawn.
  const bool read = width > 0 && height > 0 && !ctx->insideBeginEnd &&
                    (compiling || (ctx->rasterPos.valid && ctx->renderMode.mode == GL_RENDER));
  if (read && !unpackBitmap(*ctx, width, height, bitmap, bits) && ctx->pixelStore.pixelUnpackBufferBinding &&
      !compiling)
    return;  // a bad pixel unpack buffer: the error, and no draw, no move
  bitmapUnpacked(width, height, xorig, yorig, xmove, ymove, bits.empty() ? nullptr : bits.data());
}

GLAPI void APIENTRY glDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                                 const void* pixels) {
  Context* ctx = api::context();
  if (!ctx) return;
  // The pixels are read now, while compiling too (Mesa's save_DrawPixels
  // unpacks the image at compile time, §5.4), and replayed from the copy.
  const bool compiling = api::listCompiler(ctx) && !api::listCompiler(ctx)->insideBeginEnd();
  // GL_DEPTH_STENCIL's GL_UNSIGNED_INT_24_8 is laid out as one 32-bit index
  // a pixel; GL_STENCIL_INDEX and GL_COLOR_INDEX take GL_BITMAP.
  const bool depthStencil = format == GL_DEPTH_STENCIL && type == GL_UNSIGNED_INT_24_8;
  const bool readable = depthStencil || (texture::checkFormatAndType(format, type) == GL_NO_ERROR &&
                                         (type != GL_BITMAP || format == GL_STENCIL_INDEX ||
                                           format == GL_COLOR_INDEX));
  if (!ctx->insideBeginEnd && width > 0 && height > 0 && readable) {
    PixelStoreAttrib store = ctx->pixelStore;
    store.unpackSkipImages = 0;  // a 2D image
    const texture::ClientLayout layout =
        texture::unpackLayout(store, width, height, depthStencil ? GL_STENCIL_INDEX : format,
                              depthStencil ? GL_UNSIGNED_INT : type);
    const bool read = compiling || (ctx->rasterPos.valid && ctx->renderMode.mode == GL_RENDER &&
                                    drawPixelsTypeError(*ctx, format, type) == GL_NO_ERROR);
    if (read) {
      GLenum error;
      const uint8_t* src =
          api::pixelBufferMemory(*ctx, ctx->pixelStore.pixelUnpackBufferBinding,
                                 static_cast<const uint8_t*>(pixels), layout.extent(width, height, 1), error);
      if (error) return ctx->recordError(error);  // a bad pixel unpack buffer
      return drawPixelsUnpacked(width, height, format, type, layout, src,
                                src ? layout.extent(width, height, 1) : 0);
    }
  }
  drawPixelsUnpacked(width, height, format, type, texture::ClientLayout{}, nullptr, 0);
}

GLAPI void APIENTRY glCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (api::compiled(&glCopyPixels, x, y, width, height, type)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (width < 0 || height < 0) return ctx->recordError(GL_INVALID_VALUE);
  // GL_DEPTH_STENCIL: EXT_packed_depth_stencil.
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL && type != GL_DEPTH_STENCIL)
    return ctx->recordError(GL_INVALID_ENUM);
  const DepthBuffer& db = ctx->framebuffer.depth;
  if ((type == GL_DEPTH || type == GL_DEPTH_STENCIL) && db.bits() == 0)
    return ctx->recordError(GL_INVALID_OPERATION);
  if ((type == GL_STENCIL || type == GL_DEPTH_STENCIL) && db.stencilBits() == 0)
    return ctx->recordError(GL_INVALID_OPERATION);
  // No read buffer (glReadBuffer(GL_NONE)): Mesa's _mesa_source_buffer_exists.
  if (type == GL_COLOR && ctx->framebuffer.bound() && !ctx->framebuffer.read.pixels)
    return ctx->recordError(GL_INVALID_OPERATION);
  if (!ctx->rasterPos.valid) return;
  if (ctx->renderMode.mode == GL_RENDER) {
    if (width == 0 || height == 0) return;
    if (type == GL_COLOR) return pipeline::copyColorPixels(*ctx, x, y, width, height);
    return pipeline::copyDepthStencilPixels(*ctx, x, y, width, height, type);
  }
  pixelsInFeedbackOrSelect(*ctx, GL_COPY_PIXEL_TOKEN);
}

}  // extern "C"

// glRasterPos{234}{sifd}[v] (§2.13): missing z is 0, missing w is 1.
extern "C" {

GLAPI void APIENTRY glRasterPos2s(GLshort x, GLshort y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
GLAPI void APIENTRY glRasterPos3s(GLshort x, GLshort y, GLshort z) {
  rasterPos(float(x), float(y), float(z), 1.0f);
}
GLAPI void APIENTRY glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
GLAPI void APIENTRY glRasterPos2sv(const GLshort* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), 0.0f, 1.0f);
}
GLAPI void APIENTRY glRasterPos3sv(const GLshort* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), 1.0f);
}
GLAPI void APIENTRY glRasterPos4sv(const GLshort* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
}
GLAPI void APIENTRY glRasterPos2i(GLint x, GLint y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
GLAPI void APIENTRY glRasterPos3i(GLint x, GLint y, GLint z) {
  rasterPos(float(x), float(y), float(z), 1.0f);
}
GLAPI void APIENTRY glRasterPos4i(GLint x, GLint y, GLint z, GLint w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
GLAPI void APIENTRY glRasterPos2iv(const GLint* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), 0.0f, 1.0f);
}
GLAPI void APIENTRY glRasterPos3iv(const GLint* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), 1.0f);
}
GLAPI void APIENTRY glRasterPos4iv(const GLint* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
}
GLAPI void APIENTRY glRasterPos2f(GLfloat x, GLfloat y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
GLAPI void APIENTRY glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) {
  rasterPos(float(x), float(y), float(z), 1.0f);
}
GLAPI void APIENTRY glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
GLAPI void APIENTRY glRasterPos2fv(const GLfloat* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), 0.0f, 1.0f);
}
GLAPI void APIENTRY glRasterPos3fv(const GLfloat* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), 1.0f);
}
GLAPI void APIENTRY glRasterPos4fv(const GLfloat* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
}
GLAPI void APIENTRY glRasterPos2d(GLdouble x, GLdouble y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
GLAPI void APIENTRY glRasterPos3d(GLdouble x, GLdouble y, GLdouble z) {
  rasterPos(float(x), float(y), float(z), 1.0f);
}
GLAPI void APIENTRY glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
GLAPI void APIENTRY glRasterPos2dv(const GLdouble* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), 0.0f, 1.0f);
}
GLAPI void APIENTRY glRasterPos3dv(const GLdouble* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), 1.0f);
}
GLAPI void APIENTRY glRasterPos4dv(const GLdouble* v) {
  if (v) rasterPos(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
}

}  // extern "C"

// glWindowPos (GL 1.4 §2.13): the raster position set in window coordinates,
// without transformation or clipping, always valid; z mapped through
// glDepthRange; the colour, secondary colour and texture coordinates the
// current ones (Mesa's window_pos3f clamps the colours to [0, 1]).
namespace {

float clamp01f(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN -> 0

void windowPos(float x, float y, float z) {
  if (api::compiled(&windowPos, x, y, z)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  RasterPosState& rp = ctx->rasterPos;
  const float n = static_cast<float>(api::clamp01(ctx->viewport.depthNear)),
              f = static_cast<float>(api::clamp01(ctx->viewport.depthFar));
  rp.position = glm::vec4(x, y, clamp01f(z) * (f - n) + n, 1.0f);
  // ARB_window_pos: the current fog coordinate when it is the fog source, else 0.
  rp.distance = ctx->fog.coordSrc == GL_FOG_COORD ? ctx->current.fogCoord : 0.0f;
  for (int k = 0; k < 4; ++k) {
    rp.color[k] = clamp01f(ctx->current.color[k]);
    rp.secondaryColor[k] = clamp01f(ctx->current.secondaryColor[k]);
  }
  for (int unit = 0; unit < kMaxTextureUnits; ++unit) rp.unitTexCoord[unit] = ctx->current.texCoord[unit];
  rp.texCoord = rp.unitTexCoord[0];
  rp.valid = true;
  if (ctx->renderMode.mode == GL_SELECT) ctx->renderMode.select.updateHitFlag(rp.position.z);
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glWindowPos2s(GLshort x, GLshort y) { windowPos(float(x), float(y), 0.0f); }
GLAPI void APIENTRY glWindowPos2i(GLint x, GLint y) { windowPos(float(x), float(y), 0.0f); }
GLAPI void APIENTRY glWindowPos2f(GLfloat x, GLfloat y) { windowPos(x, y, 0.0f); }
GLAPI void APIENTRY glWindowPos2d(GLdouble x, GLdouble y) { windowPos(float(x), float(y), 0.0f); }
GLAPI void APIENTRY glWindowPos3s(GLshort x, GLshort y, GLshort z) {
  windowPos(float(x), float(y), float(z));
}
GLAPI void APIENTRY glWindowPos3i(GLint x, GLint y, GLint z) { windowPos(float(x), float(y), float(z)); }
GLAPI void APIENTRY glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { windowPos(x, y, z); }
GLAPI void APIENTRY glWindowPos3d(GLdouble x, GLdouble y, GLdouble z) {
  windowPos(float(x), float(y), float(z));
}
GLAPI void APIENTRY glWindowPos2sv(const GLshort* v) {
  if (v) windowPos(float(v[0]), float(v[1]), 0.0f);
}
GLAPI void APIENTRY glWindowPos2iv(const GLint* v) {
  if (v) windowPos(float(v[0]), float(v[1]), 0.0f);
}
GLAPI void APIENTRY glWindowPos2fv(const GLfloat* v) {
  if (v) windowPos(v[0], v[1], 0.0f);
}
GLAPI void APIENTRY glWindowPos2dv(const GLdouble* v) {
  if (v) windowPos(float(v[0]), float(v[1]), 0.0f);
}
GLAPI void APIENTRY glWindowPos3sv(const GLshort* v) {
  if (v) windowPos(float(v[0]), float(v[1]), float(v[2]));
}
GLAPI void APIENTRY glWindowPos3iv(const GLint* v) {
  if (v) windowPos(float(v[0]), float(v[1]), float(v[2]));
}
GLAPI void APIENTRY glWindowPos3fv(const GLfloat* v) {
  if (v) windowPos(v[0], v[1], v[2]);
}
GLAPI void APIENTRY glWindowPos3dv(const GLdouble* v) {
  if (v) windowPos(float(v[0]), float(v[1]), float(v[2]));
}

}  // extern "C"
