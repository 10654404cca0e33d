#include "state/attrib_stack.h"

#include "state/context.h"
#include "vertex/color_material.h"

namespace glfixed {

namespace {

// A group: which bit, how it is saved and restored.
struct Group {
  GLbitfield bit;
  void (*save)(Context&, AttribNode&);
  void (*restore)(Context&, const AttribNode&);
};

// Most groups are one struct of the Context: saved and restored by copy;
// restoring marks the derived state `Dirty` reads.
template <auto ContextField, auto NodeField>
void saveCopy(Context& c, AttribNode& n) {
  n.*NodeField = c.*ContextField;
}
template <auto ContextField, auto NodeField, uint32_t Dirty>
void restoreCopy(Context& c, const AttribNode& n) {
  c.*ContextField = n.*NodeField;
  c.markDirty(Dirty);
}
template <auto ContextField, auto NodeField, uint32_t Dirty = 0>
constexpr Group copied(GLbitfield bit) {
  return Group{bit, saveCopy<ContextField, NodeField>, restoreCopy<ContextField, NodeField, Dirty>};
}

// GL_ENABLE_BIT gathers flags of several groups (state/capabilities.h).
void saveEnable(Context& c, AttribNode& n) { n.enable = saveEnables(c); }
void restoreEnable(Context& c, const AttribNode& n) { restoreEnables(c, n.enable); }

// GL_LIGHTING_BIT: the provoking vertex is in no group (GL 3.2 table 6.11;
// Mesa does not restore it), and the glMaterial-inside-glBegin mask is not GL
// state: both keep their current value.
void restoreLighting(Context& c, const AttribNode& n) {
  const GLenum provokingVertex = c.lighting.provokingVertex;
  const uint32_t beginEndMaterialMask = c.lighting.beginEndMaterialMask;
  c.lighting = n.lighting;
  c.lighting.provokingVertex = provokingVertex;
  c.lighting.beginEndMaterialMask = beginEndMaterialMask;
  c.markDirty(kDirtyLighting);  // light positions restore as stored, in eye space
}

// GL_FOG_BIT: Mesa's glPopAttrib restores the fog through glFog calls for
// the enable, colour, density, start, end, index and mode only: the fog
// coordinate source and NV_fog_distance's mode keep their current values
// (probed: FogTest.FogBitAndEnableBitPushAndPop).
void restoreFog(Context& c, const AttribNode& n) {
  const GLenum coordSrc = c.fog.coordSrc, distanceMode = c.fog.distanceMode;
  c.fog = n.fog;
  c.fog.coordSrc = coordSrc;
  c.fog.distanceMode = distanceMode;
}

// Textures: the parameters of the bound texture objects (GL_TEXTURE_BIT),
// restored into the objects of the names bound at the push, where they
// still exist, after the bindings themselves.
void saveTextureParams(Context& c, AttribNode& n) {
  for (int unit = 0; unit < kMaxTextureUnits; ++unit)
    for (int index = 0; index < texture::kTargetCount; ++index) {
      const texture::TextureObject& o = texture::boundObject(*c.textures, c.texture.binding[unit], index);
      n.textureParams[unit][index] = {texture::bindingOf(c.texture.binding[unit], index), o.params, o.generateMipmap,
                                      o.priority};
    }
}
void restoreTextureParams(Context& c, const AttribNode& n) {
  for (int unit = 0; unit < kMaxTextureUnits; ++unit)
    for (int index = 0; index < texture::kTargetCount; ++index) {
      const AttribNode::BoundTextureParams& saved = n.textureParams[unit][index];
      texture::TextureObject* o =
          saved.name ? c.textures->find(saved.name) : &c.textures->defaultTexture(index);
      if (!o) continue;
      o->params = saved.params;
      o->generateMipmap = saved.generateMipmap;
      o->priority = saved.priority;
    }
}

// The table, in Mesa's order of restoration (main/attrib.c). GL_LIST_BIT
// comes with the display lists: a member in AttribNode and, after
// GL_LIGHTING_BIT, copied<&Context::list, &AttribNode::list>(GL_LIST_BIT).
const Group kGroups[] = {
    copied<&Context::accum, &AttribNode::accum>(GL_ACCUM_BUFFER_BIT),
    copied<&Context::colorBuffer, &AttribNode::colorBuffer>(GL_COLOR_BUFFER_BIT),
    copied<&Context::current, &AttribNode::current>(GL_CURRENT_BIT),
    copied<&Context::rasterPos, &AttribNode::rasterPos>(GL_CURRENT_BIT),
    copied<&Context::depth, &AttribNode::depth>(GL_DEPTH_BUFFER_BIT),
    Group{GL_ENABLE_BIT, saveEnable, restoreEnable},
    copied<&Context::eval, &AttribNode::eval>(GL_EVAL_BIT),
    Group{GL_FOG_BIT, saveCopy<&Context::fog, &AttribNode::fog>, restoreFog},
    copied<&Context::hint, &AttribNode::hint>(GL_HINT_BIT),
    Group{GL_LIGHTING_BIT, saveCopy<&Context::lighting, &AttribNode::lighting>, restoreLighting},
    copied<&Context::line, &AttribNode::line>(GL_LINE_BIT),
    copied<&Context::pixelMode, &AttribNode::pixelMode>(GL_PIXEL_MODE_BIT),
    copied<&Context::point, &AttribNode::point>(GL_POINT_BIT),
    // Two-sided lighting picks faces by GL_FRONT_FACE.
    copied<&Context::polygon, &AttribNode::polygon, kDirtyLighting>(GL_POLYGON_BIT),
    copied<&Context::polygonStipple, &AttribNode::polygonStipple>(GL_POLYGON_STIPPLE_BIT),
    copied<&Context::scissor, &AttribNode::scissor>(GL_SCISSOR_BIT),
    copied<&Context::stencil, &AttribNode::stencil>(GL_STENCIL_BUFFER_BIT),
    copied<&Context::texture, &AttribNode::texture>(GL_TEXTURE_BIT),
    Group{GL_TEXTURE_BIT, saveTextureParams, restoreTextureParams},  // textures: the bound objects' parameters
    // GL_NORMALIZE and GL_RESCALE_NORMAL are read by the lighting constants.
    copied<&Context::transform, &AttribNode::transform, kDirtyLighting>(GL_TRANSFORM_BIT),
    copied<&Context::viewport, &AttribNode::viewport>(GL_VIEWPORT_BIT),
    copied<&Context::multisample, &AttribNode::multisample>(GL_MULTISAMPLE_BIT),
};

}  // namespace

bool AttribStack::push(Context& ctx, GLbitfield mask) {
  if (depth_ >= kMaxAttribStackDepth) return false;
  if (static_cast<int>(nodes_.size()) <= depth_) nodes_.emplace_back();
  AttribNode& n = nodes_[depth_];
  n.mask = mask;
  n.changedBeforePush = ctx.attribGroupsChanged;
  for (const Group& g : kGroups)
    if (mask & g.bit) g.save(ctx, n);
  ++depth_;
  ctx.attribGroupsChanged = 0;
  return true;
}

bool AttribStack::pop(Context& ctx) {
  if (depth_ == 0) return false;
  const AttribNode& n = nodes_[--depth_];
  // The current attributes' setters (glColor, glNormal, ...) do not record a
  // change: the group is always restored, a copy of the same values if
  // nothing changed.
  const GLbitfield restore = n.mask & (ctx.attribGroupsChanged | GL_CURRENT_BIT);
  // A flag restored through its own group (the depth test by
  // GL_DEPTH_BUFFER_BIT, ...) changes GL_ENABLE_BIT's state too.
  const EnableAttrib before = saveEnables(ctx);
  for (const Group& g : kGroups)
    if (restore & g.bit) g.restore(ctx, n);
  for (int i = 0; i < kCapabilityCount; ++i) {
    const Capability& c = capabilities()[i];
    if (!c.perTextureUnit && c.flag(ctx) != before.flag[i])
      ctx.markChanged(GL_ENABLE_BIT | c.groups, c.dirty);
  }
  // With GL_COLOR_MATERIAL on, the tracked material is the current colour
  // (Mesa's shader reads the colour itself), whatever was restored.
  if ((restore & (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT)) && ctx.lighting.colorMaterial)
    trackColorMaterial(ctx);
  // Mesa: the groups changed before the push, and those changed since that
  // this pop did not restore.
  ctx.attribGroupsChanged = n.changedBeforePush | (ctx.attribGroupsChanged & ~n.mask);
  return true;
}

void copyAttribGroups(Context& src, Context& dst, GLbitfield mask) {
  AttribNode n;
  n.mask = mask;
  for (const Group& g : kGroups)
    if (mask & g.bit) {
      g.save(src, n);
      g.restore(dst, n);
    }
  dst.markChanged(mask, kDirtyAll);
  if ((mask & (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT)) && dst.lighting.colorMaterial)
    trackColorMaterial(dst);
}

}  // namespace glfixed
