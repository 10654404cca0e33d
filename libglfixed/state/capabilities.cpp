#include "state/capabilities.h"

#include <iterator>

#include "state/context.h"

namespace glfixed {

namespace {

// Where a flag lives: member Flag of Context member Group.
template <auto Group, auto Flag>
bool& field(Context& c) {
  return (c.*Group).*Flag;
}
template <int I>
bool& light(Context& c) {
  return c.lighting.light[I].enabled;
}
template <int I>
bool& clipPlane(Context& c) {
  return c.transform.clipPlaneEnabled[I];
}
template <int Slot>
bool& map1(Context& c) {
  return c.eval.map1Enabled[Slot];
}
template <int Slot>
bool& map2(Context& c) {
  return c.eval.map2Enabled[Slot];
}
template <auto Flag>
bool& textureUnit(Context& c) {
  return c.texture.activeEnables().*Flag;
}

constexpr bool kSettable = true, kHeld = false;

// One row per GL 2.1 capability.
constexpr Capability entry(GLenum cap, bool& (*flag)(Context&), GLbitfield groups, uint32_t dirty,
                           bool settable, bool perUnit = false) {
  return Capability{cap, flag, groups, dirty, settable, perUnit};
}

constexpr Capability kTable[] = {
    entry(GL_DEPTH_TEST, field<&Context::depth, &DepthBufferAttrib::test>, GL_DEPTH_BUFFER_BIT, 0, kSettable),
    entry(GL_CULL_FACE, field<&Context::polygon, &PolygonAttrib::cullFace>, GL_POLYGON_BIT, 0, kSettable),
    entry(GL_DITHER, field<&Context::colorBuffer, &ColorBufferAttrib::dither>, GL_COLOR_BUFFER_BIT, 0,
          kSettable),
    entry(GL_LIGHTING, field<&Context::lighting, &LightingAttrib::lighting>, GL_LIGHTING_BIT, kDirtyLighting,
          kSettable),
    entry(GL_LIGHT0, light<0>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT1, light<1>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT2, light<2>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT3, light<3>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT4, light<4>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT5, light<5>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT6, light<6>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_LIGHT7, light<7>, GL_LIGHTING_BIT, kDirtyLighting, kSettable),
    entry(GL_COLOR_MATERIAL, field<&Context::lighting, &LightingAttrib::colorMaterial>, GL_LIGHTING_BIT,
          kDirtyLighting, kSettable),
    // The lighting constants hold whether normals are normalized or rescaled.
    entry(GL_NORMALIZE, field<&Context::transform, &TransformAttrib::normalize>, GL_TRANSFORM_BIT,
          kDirtyLighting, kSettable),
    entry(GL_RESCALE_NORMAL, field<&Context::transform, &TransformAttrib::rescaleNormal>, GL_TRANSFORM_BIT,
          kDirtyLighting, kSettable),
    entry(GL_DEPTH_CLAMP, field<&Context::transform, &TransformAttrib::depthClamp>, GL_TRANSFORM_BIT, 0,
          kSettable),
    // The evaluators (§5.1): GL_EVAL_BIT and GL_ENABLE_BIT both hold them.
    entry(GL_AUTO_NORMAL, field<&Context::eval, &EvalAttrib::autoNormal>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_COLOR_4, map1<0>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_INDEX, map1<1>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_NORMAL, map1<2>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_TEXTURE_COORD_1, map1<3>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_TEXTURE_COORD_2, map1<4>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_TEXTURE_COORD_3, map1<5>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_TEXTURE_COORD_4, map1<6>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_VERTEX_3, map1<7>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP1_VERTEX_4, map1<8>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_COLOR_4, map2<0>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_INDEX, map2<1>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_NORMAL, map2<2>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_TEXTURE_COORD_1, map2<3>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_TEXTURE_COORD_2, map2<4>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_TEXTURE_COORD_3, map2<5>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_TEXTURE_COORD_4, map2<6>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_VERTEX_3, map2<7>, GL_EVAL_BIT, 0, kSettable),
    entry(GL_MAP2_VERTEX_4, map2<8>, GL_EVAL_BIT, 0, kSettable),
    // Clip planes and scissor (§2.12, §4.1.2): the user clip planes and the
    // scissor test.
    entry(GL_CLIP_PLANE0, clipPlane<0>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE1, clipPlane<1>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE2, clipPlane<2>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE3, clipPlane<3>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE4, clipPlane<4>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE5, clipPlane<5>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE0 + 6, clipPlane<6>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_CLIP_PLANE0 + 7, clipPlane<7>, GL_TRANSFORM_BIT, 0, kSettable),
    entry(GL_SCISSOR_TEST, field<&Context::scissor, &ScissorAttrib::test>, GL_SCISSOR_BIT, 0, kSettable),
    // The alpha test (fragment/alpha_test.inc).
    entry(GL_ALPHA_TEST, field<&Context::colorBuffer, &ColorBufferAttrib::alphaTest>, GL_COLOR_BUFFER_BIT, 0,
          kSettable),
    // Blending and the logic op (fragment/blend.inc). GL_INDEX_LOGIC_OP (GL
    // 1.0's GL_LOGIC_OP) is held and queried but, as in Mesa, changes nothing
    // in RGBA mode.
    entry(GL_BLEND, field<&Context::colorBuffer, &ColorBufferAttrib::blend>, GL_COLOR_BUFFER_BIT, 0,
          kSettable),
    entry(GL_COLOR_LOGIC_OP, field<&Context::colorBuffer, &ColorBufferAttrib::colorLogicOp>,
          GL_COLOR_BUFFER_BIT, 0, kSettable),
    entry(GL_INDEX_LOGIC_OP, field<&Context::colorBuffer, &ColorBufferAttrib::indexLogicOp>,
          GL_COLOR_BUFFER_BIT, 0, kSettable),
    // Fog (fragment/fog.inc).
    entry(GL_FOG, field<&Context::fog, &FogAttrib::enabled>, GL_FOG_BIT, 0, kSettable),
    // The colour sum without lighting (GL 2.1 §3.9; pipeline/draw.cpp).
    entry(GL_COLOR_SUM, field<&Context::fog, &FogAttrib::colorSum>, GL_FOG_BIT, 0, kSettable),
    // Lines (primitive/lines.cpp) and points (primitive/points.cpp): drawn.
    entry(GL_LINE_SMOOTH, field<&Context::line, &LineAttrib::smooth>, GL_LINE_BIT, 0, kSettable),
    entry(GL_LINE_STIPPLE, field<&Context::line, &LineAttrib::stipple>, GL_LINE_BIT, 0, kSettable),
    entry(GL_POINT_SMOOTH, field<&Context::point, &PointAttrib::smooth>, GL_POINT_BIT, 0, kSettable),
    entry(GL_POINT_SPRITE, field<&Context::point, &PointAttrib::sprite>, GL_POINT_BIT, 0, kSettable),
    entry(GL_POLYGON_SMOOTH, field<&Context::polygon, &PolygonAttrib::smooth>, GL_POLYGON_BIT, 0, kHeld),
    // Polygon area: stipple and offset are drawn (primitive/unfilled.cpp, raster/).
    entry(GL_POLYGON_STIPPLE, field<&Context::polygon, &PolygonAttrib::stipple>, GL_POLYGON_BIT, 0,
          kSettable),
    entry(GL_POLYGON_OFFSET_POINT, field<&Context::polygon, &PolygonAttrib::offsetPoint>, GL_POLYGON_BIT, 0,
          kSettable),
    entry(GL_POLYGON_OFFSET_LINE, field<&Context::polygon, &PolygonAttrib::offsetLine>, GL_POLYGON_BIT, 0,
          kSettable),
    entry(GL_POLYGON_OFFSET_FILL, field<&Context::polygon, &PolygonAttrib::offsetFill>, GL_POLYGON_BIT, 0,
          kSettable),
    entry(GL_STENCIL_TEST, field<&Context::stencil, &StencilAttrib::test>, GL_STENCIL_BUFFER_BIT, 0, kSettable),
    entry(StencilAttrib::kTestTwoSideEXT, field<&Context::stencil, &StencilAttrib::testTwoSide>,
          GL_STENCIL_BUFFER_BIT, 0, kSettable),
    // Multisample (GL 2.1 §3.2.1, §4.1.3): every surface has GL_SAMPLE_BUFFERS
    // 0, where these change nothing that is drawn; they are state all the same.
    entry(GL_MULTISAMPLE, field<&Context::multisample, &MultisampleAttrib::multisample>, GL_MULTISAMPLE_BIT,
          0, kSettable),
    entry(GL_SAMPLE_ALPHA_TO_COVERAGE,
          field<&Context::multisample, &MultisampleAttrib::sampleAlphaToCoverage>, GL_MULTISAMPLE_BIT, 0,
          kSettable),
    entry(GL_SAMPLE_ALPHA_TO_ONE, field<&Context::multisample, &MultisampleAttrib::sampleAlphaToOne>,
          GL_MULTISAMPLE_BIT, 0, kSettable),
    entry(GL_SAMPLE_COVERAGE, field<&Context::multisample, &MultisampleAttrib::sampleCoverage>,
          GL_MULTISAMPLE_BIT, 0, kSettable),
    // Texture coordinates (issue 14): an enabled target makes the vertex
    // stage output the unit's coordinates (vertex/texcoord.h); texgen is
    // computed there. Sampling them is the texture stage's.
    entry(GL_TEXTURE_1D, textureUnit<&TextureUnitEnables::texture1D>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_2D, textureUnit<&TextureUnitEnables::texture2D>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_3D, textureUnit<&TextureUnitEnables::texture3D>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_CUBE_MAP, textureUnit<&TextureUnitEnables::textureCubeMap>, GL_TEXTURE_BIT, 0, kSettable,
          true),
    entry(GL_TEXTURE_GEN_S, textureUnit<&TextureUnitEnables::genS>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_GEN_T, textureUnit<&TextureUnitEnables::genT>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_GEN_R, textureUnit<&TextureUnitEnables::genR>, GL_TEXTURE_BIT, 0, kSettable, true),
    entry(GL_TEXTURE_GEN_Q, textureUnit<&TextureUnitEnables::genQ>, GL_TEXTURE_BIT, 0, kSettable, true),
};
// kCapabilityCount (capabilities.h) sizes EnableAttrib: it must be the table's size.
static_assert(std::size(kTable) == kCapabilityCount, "kCapabilityCount must count kTable's entries");

constexpr std::array<Capability, kCapabilityCount> makeArray() {
  std::array<Capability, kCapabilityCount> a{};
  for (int i = 0; i < kCapabilityCount; ++i) a[i] = kTable[i];
  return a;
}
constexpr std::array<Capability, kCapabilityCount> kCapabilities = makeArray();

}  // namespace

const std::array<Capability, kCapabilityCount>& capabilities() { return kCapabilities; }

const Capability* findCapability(GLenum cap) {
  for (const Capability& c : kCapabilities)
    if (c.cap == cap) return &c;
  return nullptr;
}

void storeCapability(Context& ctx, const Capability& c, bool enabled) {
  ctx.markChanged(GL_ENABLE_BIT | c.groups, c.dirty);
  c.flag(ctx) = enabled;
}

EnableAttrib saveEnables(Context& ctx) {
  EnableAttrib e;
  for (int i = 0; i < kCapabilityCount; ++i)
    if (!kCapabilities[i].perTextureUnit) e.flag[i] = kCapabilities[i].flag(ctx);
  e.texture = ctx.texture.enables;
  return e;
}

void restoreEnables(Context& ctx, const EnableAttrib& saved) {
  for (int i = 0; i < kCapabilityCount; ++i) {
    const Capability& c = kCapabilities[i];
    if (!c.perTextureUnit && c.flag(ctx) != saved.flag[i]) storeCapability(ctx, c, saved.flag[i]);
  }
  if (!(ctx.texture.enables == saved.texture)) {
    ctx.markChanged(GL_ENABLE_BIT | GL_TEXTURE_BIT, 0);
    ctx.texture.enables = saved.texture;
  }
}

}  // namespace glfixed
