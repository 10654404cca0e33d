#include "pipeline/draw.h"

#include <algorithm>
#include <optional>

#include "fragment/texture_stage.h"
#include "pipeline/pixel_rect.h"
#include "primitive/clip.h"
#include "primitive/primitive.h"
#include "primitive/select_feedback.h"
#include "state/context.h"
#include "state/framebuffer_binding.h"
#include "vertex/lighting_math.h"
#include "vertex/lighting_matrix.h"
#include "vertex/vertex_stage.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::pipeline {

namespace {

// Clip planes and scissor: the enabled user clip planes in clip space, as
// Mesa keeps them (_ClipUserPlane: the eye-space plane times its inverse of
// the current projection, recomputed whenever the projection changes).
primitive::UserClipPlanes userClipPlanes(const Context& ctx) {
  primitive::UserClipPlanes u;
  u.depthClamp = ctx.transform.depthClamp;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if (ctx.transform.clipPlaneEnabled[i]) u.enabled |= 1u << i;
  if (u.enabled == 0) return u;
  const glm::mat4 eyeFromClip = vertex::analyseModelview(ctx.projection.top()).inverse;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if (u.enabled & (1u << i))
      u.plane[i] = primitive::transformPlane(ctx.transform.clipPlane[i], eyeFromClip);
  return u;
}

// Texturing (GL 2.1 §3.8.15): each unit textures with the first of its
// enabled targets, from the highest priority down (cube map, 3D, 2D, 1D),
// whose texture is complete; a unit with none does not texture. (Mesa goes on
// to a lower enabled target when a higher one is incomplete, where GL 2.1
// disables the unit: texstate.c, update_ff_texture_state.)
}  // namespace

void buildTextureStage(const TextureAttrib& texture, const texture::TextureObjects& objects,
                       const glm::vec4 (&current)[kMaxTextureUnits], fragment::TextureStage& stage) {
  struct Target {
    bool TextureUnitEnables::*enabled;
    GLenum target;
  };
  static constexpr Target kPriority[] = {{&TextureUnitEnables::textureCubeMap, GL_TEXTURE_CUBE_MAP},
                                         {&TextureUnitEnables::texture3D, GL_TEXTURE_3D},
                                         {&TextureUnitEnables::texture2D, GL_TEXTURE_2D},
                                         {&TextureUnitEnables::texture1D, GL_TEXTURE_1D}};
  stage.unitCount = 0;
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    for (const Target& target : kPriority) {
      if (!(texture.enables[u].*target.enabled)) continue;
      const texture::TextureObject& object =
          texture::boundObject(objects, texture.binding[u], texture::targetIndex(target.target));
      fragment::TextureStage::Unit& unit = stage.units[stage.unitCount];
      if (!texture::makeSamplerView(object, target.target, texture.env[u].lodBias, unit.view)) continue;
      unit.unit = u;
      unit.env.env = texture.env[u];
      const texture::TextureImage& base = object.level(0, unit.view.firstLevel);
      unit.env.baseFormat = texture::texelFormatInfo(base.format).baseFormat;
      unit.env.depthTextureMode = object.params.depthTextureMode;
      for (int j = 0; j < 4; ++j) unit.currentCoord[j] = current[u][j];
      ++stage.unitCount;
      break;
    }
  }
}

bool anyTextureEnabled(const TextureAttrib& texture) {
  for (const TextureUnitEnables& e : texture.enables)
    if (e.texture1D || e.texture2D || e.texture3D || e.textureCubeMap) return true;
  return false;
}

namespace {

primitive::PrimitiveState primitiveState(const Context& ctx, GLenum mode, bool separateSpecular) {
  primitive::PrimitiveState s;
  s.mode = mode;
  s.flat = ctx.lighting.shadeModel == GL_FLAT;
  s.firstVertexConvention = ctx.lighting.provokingVertex == GL_FIRST_VERTEX_CONVENTION;
  s.cullFace = ctx.polygon.cullFace;
  s.cullFaceMode = ctx.polygon.cullFaceMode;
  // Into a framebuffer object Mesa does not flip y, and flips the notion of
  // front instead (st_atom_rasterizer.c: front_ccw ^= 1 for Y_0_BOTTOM), so
  // llvmpipe's front face is the other winding there.
  const bool rowsUp = ctx.framebuffer.rowsUp();
  const GLenum glFront = ctx.polygon.frontFace;
  const GLenum llvmpipeFront = rowsUp ? (glFront == GL_CCW ? GL_CW : GL_CCW) : glFront;
  s.frontFace = llvmpipeFront;
  s.flipViewportY = !rowsUp;
  s.viewportX = ctx.viewport.x;
  s.viewportY = ctx.viewport.y;
  s.viewportWidth = ctx.viewport.width;
  s.viewportHeight = ctx.viewport.height;
  s.depthNear = ctx.viewport.depthNear;
  s.depthFar = ctx.viewport.depthFar;

  raster::RasterState& r = s.raster;
  // Without a depth buffer the depth test always passes (GL 2.1 §4.1.6).
  r.depthTest = ctx.depth.test && ctx.framebuffer.depth.bits() > 0;
  r.depthFunc = ctx.depth.func;
  // GL_DEPTH_CLAMP: fragment depth clamped to the depth range, as floats
  // (llvmpipe clamps to the viewport's min and max depth).
  r.depthClamp = ctx.transform.depthClamp;
  r.depthClampMin = static_cast<float>(std::min(ctx.viewport.depthNear, ctx.viewport.depthFar));
  r.depthClampMax = static_cast<float>(std::max(ctx.viewport.depthNear, ctx.viewport.depthFar));
  r.depthWrite = ctx.depth.writeMask;
  for (int i = 0; i < 4; ++i) r.colorWrite[i] = ctx.colorBuffer.writeMask[i];
  {
    const ColorBufferAttrib& cb = ctx.colorBuffer;
    const float color[4] = {cb.blendColor.r, cb.blendColor.g, cb.blendColor.b, cb.blendColor.a};
    r.blend = fragment::makeBlendState(cb.blend, cb.blendSrcRGB, cb.blendDstRGB, cb.blendSrcAlpha, cb.blendDstAlpha,
                                       cb.blendEquationRGB, cb.blendEquationAlpha, color, cb.colorLogicOp,
                                       cb.logicOpMode);
  }
  // Without a stencil buffer the stencil test always passes (GL 2.1 §4.1.5).
  r.stencil.enabled = ctx.stencil.test && ctx.framebuffer.depth.stencilBits() > 0;
  if (r.stencil.enabled)
    for (int i = 0; i < 2; ++i) {
      const int back = ctx.stencil.testTwoSide ? 2 : 1;
      const StencilAttrib::Face& from = ctx.stencil.face[i == 0 ? 0 : back];
      fragment::StencilFaceState& to = r.stencil.face[i];
      to.func = from.func;
      to.ref = from.ref < 0 ? 0 : (from.ref > 255 ? 255 : from.ref);
      to.valueMask = static_cast<int32_t>(from.valueMask & 0xffu);
      to.writeMask = static_cast<int32_t>(from.writeMask & 0xffu);
      to.fail = from.fail;
      to.depthFail = from.depthFail;
      to.depthPass = from.depthPass;
    }
  r.frontFace = llvmpipeFront;
  r.bottomEdgeRule = !rowsUp;  // st_atom_rasterizer.c: only for Y_0_TOP
  r.varyingCount = separateSpecular ? 8 : 4;
  // Fog (GL 2.1 §3.10; fragment/fog.inc).
  r.fog = fragment::makeFogState(ctx.fog.enabled, ctx.fog.mode, ctx.fog.density, ctx.fog.start, ctx.fog.end,
                                 ctx.fog.color);
  r.alphaTest =
      fragment::makeAlphaTest(ctx.colorBuffer.alphaTest, ctx.colorBuffer.alphaFunc, ctx.colorBuffer.alphaRef);
  r.clampFragmentColor = ctx.colorBuffer.clampFragmentColor;
  r.scissorX0 = std::max(0, ctx.viewport.x);
  r.scissorY0 = std::max(0, ctx.viewport.y);
  r.scissorX1 = std::min(ctx.framebuffer.width(), ctx.viewport.x + ctx.viewport.width);
  r.scissorY1 = std::min(ctx.framebuffer.height(), ctx.viewport.y + ctx.viewport.height);
  // Polygon area (GL 2.1 §3.6.5): Mesa's state tracker hands llvmpipe the
  // factor and units whenever any of the three offset enables is on, and
  // llvmpipe's triangle setup then offsets every filled triangle, even with
  // only GL_POLYGON_OFFSET_LINE or _POINT on (st_atom_rasterizer.c,
  // lp_state_setup.c; a Mesa departure, matched: MESA_FACTS.md "Polygons").
  r.polygonOffset = ctx.polygon.offsetFill || ctx.polygon.offsetLine || ctx.polygon.offsetPoint;
  r.offsetFactor = ctx.polygon.offsetFactor;
  r.offsetUnits = ctx.polygon.offsetUnits;
  s.polygonModeFront = ctx.polygon.frontMode;
  s.polygonModeBack = ctx.polygon.backMode;
  s.offsetFill = ctx.polygon.offsetFill;
  s.offsetLine = ctx.polygon.offsetLine;
  s.offsetPoint = ctx.polygon.offsetPoint;
  s.polygonStipple = ctx.polygon.stipple;
  r.polygonStipple = ctx.polygon.stipple ? ctx.polygonStipple.pattern.data() : nullptr;
  // lp_state_rasterizer.c: smooth points or lines, or a line stipple that is
  // not all ones (st_atom_rasterizer.c), also make llvmpipe leave offset and
  // two-sided colours to the draw module.
  s.lineOrPointPipeline =
      ctx.point.smooth || ctx.line.smooth || (ctx.line.stipple && ctx.line.stipplePattern != 0xffff);
  // Points (primitive.h): the size as the state tracker clamps it, CLAMP(x,
  // min, max) = x > min ? (x > max ? max : x) : min; per-vertex sizes under
  // distance attenuation (the vertex stage computes them).
  {
    const PointAttrib& p = ctx.point;
    s.pointSize = p.size > p.sizeMin ? (p.size > p.sizeMax ? p.sizeMax : p.size) : p.sizeMin;
    const glm::vec3& a = p.distanceAttenuation;
    s.pointSizePerVertex = a.x != 1.0f || a.y != 0.0f || a.z != 0.0f;
    s.pointSmooth = p.smooth && !p.sprite;
    // Point sprites (raster/point.cpp): st/mesa's point_quad_rasterization
    // and sprite_coord_enable (st_atom_rasterizer.c).
    r.pointSprite = p.sprite;
    // The origin in llvmpipe's rows: GL's upper left is llvmpipe's lower
    // left in a framebuffer object (st_atom_rasterizer.c).
    r.spriteCoordOrigin =
        rowsUp ? (p.spriteCoordOrigin == GL_UPPER_LEFT ? GL_LOWER_LEFT : GL_UPPER_LEFT) : p.spriteCoordOrigin;
    r.spriteCoordReplace = 0;
    if (p.sprite)
      for (size_t u = 0; u < p.coordReplace.size() && u < size_t(raster::kMaxTexCoordUnits); ++u)
        if (p.coordReplace[u]) r.spriteCoordReplace |= 1u << u;
  }

  // Lines (primitive/lines.cpp): Mesa's rasterizer state (st_atom_rasterizer.c).
  // CLAMP turns NaN into the minimum.
  s.lineWidth = ctx.line.width > 1.0f ? (ctx.line.width > 255.0f ? 255.0f : ctx.line.width) : 1.0f;
  s.lineSmooth = ctx.line.smooth;
  s.lineStipple = ctx.line.stipple && ctx.line.stipplePattern != 0xffff;
  s.lineStippleFactor = ctx.line.stippleRepeat;
  s.lineStipplePattern = ctx.line.stipplePattern;
  s.lineStippleContinues = ctx.lineStipple.continues;

  // Clip planes and scissor: with GL_SCISSOR_TEST the drawable box of
  // triangles, and the regions of points and lines (the buffer), are cut to
  // the scissor box too (§4.1.2; llvmpipe's draw regions, st_atom_scissor.c).
  if (ctx.scissor.test) {
    const ScissorAttrib& sc = ctx.scissor;
    const int sx1 = static_cast<int>(std::min<long long>(1 << 30, static_cast<long long>(sc.x) + sc.width));
    const int sy1 = static_cast<int>(std::min<long long>(1 << 30, static_cast<long long>(sc.y) + sc.height));
    auto cut = [&](int& x0, int& y0, int& x1, int& y1) {
      x0 = std::max(x0, sc.x);
      y0 = std::max(y0, sc.y);
      x1 = std::min(x1, sx1);
      y1 = std::min(y1, sy1);
    };
    cut(r.scissorX0, r.scissorY0, r.scissorX1, r.scissorY1);
    cut(r.pointLineRegion.x0, r.pointLineRegion.y0, r.pointLineRegion.x1, r.pointLineRegion.y1);
  }
  s.userClipPlanes = userClipPlanes(ctx);
  r.samplesPassed = ctx.queries.samplesPassedCounter();
  return s;
}

}  // namespace

glm::vec4 clampedCurrentSecondaryColor(const Context& ctx) {
  glm::vec4 c = ctx.current.secondaryColor;
  for (int k = 0; k < 3; ++k) c[k] = c[k] > 1.0f ? 1.0f : (c[k] < 0.0f ? 0.0f : c[k]);  // SATURATE: NaN stays
  c[3] = 0.0f;  // the sum adds rgb only
  return c;
}

void addCurrentSecondaryColor(const Context& ctx, ShadedVertices& shaded) {
  shaded.hasSecondary = true;
  shaded.secondary[kFront].assign(shaded.size(), clampedCurrentSecondaryColor(ctx));
}

raster::RasterState pixelRectRasterState(const Context& ctx) {
  raster::RasterState r = primitiveState(ctx, GL_TRIANGLES, false).raster;
  // The state tracker's bitmap and drawpixels rasterizer state: the whole
  // buffer as the viewport, the scissor only if enabled; no stipple, no
  // offset (st_cb_bitmap.c, st_cb_drawpixels.c).
  r.scissorX0 = 0;
  r.scissorY0 = 0;
  r.scissorX1 = ctx.framebuffer.width();
  r.scissorY1 = ctx.framebuffer.height();
  if (ctx.scissor.test) {
    const ScissorAttrib& sc = ctx.scissor;
    r.scissorX0 = std::max(r.scissorX0, sc.x);
    r.scissorY0 = std::max(r.scissorY0, sc.y);
    r.scissorX1 = static_cast<int>(std::min<long long>(r.scissorX1, static_cast<long long>(sc.x) + sc.width));
    r.scissorY1 = static_cast<int>(std::min<long long>(r.scissorY1, static_cast<long long>(sc.y) + sc.height));
  }
  r.polygonStipple = nullptr;
  r.stippleEveryPrimitive = false;
  r.bottomEdgeRule = true;  // the state tracker's own rasterizer state, in any framebuffer
  r.polygonOffset = false;
  r.textures = nullptr;
  r.texCoordUnits = 0;
  r.varyingCount = 4;
  r.pointSprite = false;
  r.fog = fragment::FogState();  // Mesa's pixel rectangles are not fogged (MESA_FACTS.md)
  return r;
}

void drawBatch(Context& ctx, const VertexBatch& batch) {
  drawBatch(ctx, batch, primitive::PrimitiveState::Submission::kBeginEnd, ctx.vbo.colorIsVertexData(), false,
            ctx.vbo.secondaryColorIsVertexData);
}

void drawBatch(Context& ctx, const VertexBatch& batch, primitive::PrimitiveState::Submission submission,
               bool colorIsVertexData, bool fetchedVertexOutside, bool secondaryIsVertexData) {
  flushBitmapCache(ctx);  // Mesa's st_prepare_draw
  // A framebuffer object: its attachments as they are now; an incomplete one
  // draws nothing (GL 3.0 §4.4.4).
  if (ctx.objectBound() && batch.size() != 0 && !drawFramebufferComplete(ctx)) return;
  if (!ctx.framebuffer.bound() || batch.size() == 0) return;
  ctx.lastDrawTexCoordUnits = batch.texCoordUnits;
  ctx.lastDrawSecondaryColorVaries = secondaryIsVertexData;
  const vertex::VertexState& vs = ctx.validate();
  struct SiteShaded {};
  ShadedVertices& shaded = threadScratch<ShadedVertices, SiteShaded>();  // reused: no allocation per batch
  vertex::shadeBatch(vs, batch, shaded);
  const bool unlitColorSum = !vs.lighting && ctx.fog.colorSum;
  // Per-vertex secondary colours (glSecondaryColor as vertex data, or an
  // array) are varyings, clamped at the vertex; else the current one is a
  // constant.
  const bool secondaryVaries =
      unlitColorSum && secondaryIsVertexData && batch.hasSecondaryColor && batch.secondaryColor.size() == batch.size();
  if (secondaryVaries) {
    shaded.hasSecondary = true;
    shaded.secondary[kFront].resize(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) {
      const glm::vec4 c = vertex::lp::clampColor(batch.secondaryColor[i]);
      shaded.secondary[kFront][i] = glm::vec4(c.r, c.g, c.b, 0.0f);
    }
  } else if (unlitColorSum) {
    addCurrentSecondaryColor(ctx, shaded);
  }
  primitive::PrimitiveState ps = primitiveState(ctx, batch.mode, shaded.hasSecondary);
  ps.submission = submission;
  ps.constantPrimary = !vs.lighting && !colorIsVertexData;
  ps.constantSecondary = unlitColorSum && !secondaryVaries;
  ps.fetchedVertexOutside = fetchedVertexOutside;
  ps.lineStippleCounter = &ctx.lineStipple.counter;  // lines: Mesa keeps it from draw to draw
  // Polygon area: the batch's edge flags (GL 2.1 §2.6.2), when it has them.
  ps.edgeFlags = batch.edgeFlag.size() == batch.size() ? batch.edgeFlag.data() : nullptr;
  // GL_SELECT and GL_FEEDBACK: transformed and clipped, never rasterized (§5.2, §5.3).
  if (ctx.renderMode.mode == GL_SELECT)
    return primitive::selectPrimitives(ps, shaded, ctx.framebuffer.height(), ctx.renderMode.select);
  if (ctx.renderMode.mode == GL_FEEDBACK)
    return primitive::feedbackPrimitives(ps, shaded, ctx.framebuffer.height(), ctx.current.texCoord[0],
                                         ctx.renderMode.feedback);
  // Built only when a unit enables a target: the stage is large.
  std::optional<fragment::TextureStage> textures;
  if (anyTextureEnabled(ctx.texture)) {
    buildTextureStage(ctx.texture, *ctx.textures, ctx.current.texCoord, textures.emplace());
    ps.raster.textures = &*textures;
  }
  Framebuffer& fb = ctx.framebuffer;
  if (fb.moreColorCount > 0) {
    // glDrawBuffers: the same primitives into each draw buffer, from the
    // same depth and stencil values and stipple phase; the last pass's
    // depth and stencil stay.
    const ColorBuffer first = fb.color;
    const uint32_t stippleStart = ctx.lineStipple.counter;
    const std::vector<uint8_t> depthStart = fb.depth.saveValues();
    for (int i = 0; i <= fb.moreColorCount; ++i) {
      if (i > 0) {
        fb.depth.restoreValues(depthStart);
        ctx.lineStipple.counter = stippleStart;
        fb.color = fb.moreColor[i - 1];
      }
      primitive::drawPrimitives(ps, shaded, fb);
    }
    fb.color = first;
    return;
  }
  if (!fb.drawsIntoBoth(ctx.colorBuffer.drawBuffer)) return primitive::drawPrimitives(ps, shaded, fb);
  // GL_FRONT_AND_BACK (and GL_LEFT) on a double-buffered surface: the same
  // primitives into the back buffer, then into the front one from the same
  // depth values and stipple phase, so both get the same pixels (§4.2.1).
  const DepthBuffer depthBefore = fb.depth;
  const uint32_t stippleBefore = ctx.lineStipple.counter;
  primitive::drawPrimitives(ps, shaded, fb);
  fb.depth = depthBefore;
  ctx.lineStipple.counter = stippleBefore;
  const ColorBuffer back = fb.color;
  fb.color = fb.front;
  primitive::drawPrimitives(ps, shaded, fb);
  fb.color = back;
}

bool anyVertexOutside(Context& ctx, const VertexBatch& batch) {
  if (batch.size() == 0) return false;
  const vertex::VertexState& vs = ctx.validate();
  struct SiteShaded {};
  ShadedVertices& shaded = threadScratch<ShadedVertices, SiteShaded>();
  vertex::shadeBatch(vs, batch, shaded);
  const primitive::UserClipPlanes user = userClipPlanes(ctx);  // clip planes: outside one counts
  for (const glm::vec4& c : shaded.clip)
    if (primitive::clipMask(c, user) != 0) return true;
  return false;
}

}  // namespace glfixed::pipeline
