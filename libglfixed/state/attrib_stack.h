// The server attribute stack (GL 2.1 §6.1.14): glPushAttrib saves the groups
// of its mask, one struct per group, and glPopAttrib restores them.
#pragma once

#include <GL/gl.h>

#include <vector>

#include "state/attrib_groups.h"
#include "state/attribs.h"
#include "state/capabilities.h"
#include "state/eval_attrib.h"
#include "state/lighting_attrib.h"
#include "state/raster_pos.h"
#include "texture/texture_object.h"

namespace glfixed {

class Context;

constexpr int kMaxAttribStackDepth = 16;  // GL_MAX_ATTRIB_STACK_DEPTH, Mesa's too

// One glPushAttrib: the mask and a copy of each group (only those in the mask
// are meaningful). Adding a group (GL_LIST_BIT) is one member
// here and one entry in attrib_stack.cpp's table.
struct AttribNode {
  GLbitfield mask = 0;
  // Context::attribGroupsChanged at the push, given back at the pop.
  GLbitfield changedBeforePush = 0;

  AccumAttrib accum;
  ColorBufferAttrib colorBuffer;
  CurrentAttrib current;
  RasterPosState rasterPos;  // GL_CURRENT_BIT too (table 6.5)
  DepthBufferAttrib depth;
  EnableAttrib enable;
  EvalAttrib eval;
  FogAttrib fog;
  HintAttrib hint;
  LightingAttrib lighting;
  LineAttrib line;
  PixelModeAttrib pixelMode;
  PointAttrib point;
  PolygonAttrib polygon;
  PolygonStippleAttrib polygonStipple;
  ScissorAttrib scissor;
  StencilAttrib stencil;
  TextureAttrib texture;
  TransformAttrib transform;
  ViewportAttrib viewport;
  MultisampleAttrib multisample;
  // Textures: GL_TEXTURE_BIT also holds the parameters of the objects bound
  // to every target of every unit (table 6.23; Mesa's attrib.c saves them).
  struct BoundTextureParams {
    GLuint name = 0;
    texture::SamplerParams params;
    bool generateMipmap = false;
    float priority = 1;
  };
  std::array<std::array<BoundTextureParams, 4>, kMaxTextureUnits> textureParams;
};

class AttribStack {
 public:
  int depth() const { return depth_; }
  // False: the stack is full (GL_STACK_OVERFLOW), nothing is pushed.
  bool push(Context& ctx, GLbitfield mask);
  // False: the stack is empty (GL_STACK_UNDERFLOW). Restores only the groups
  // changed since the push (Mesa's PopAttribState): the others hold the
  // pushed values already. The caller has drawn the buffered vertices.
  bool pop(Context& ctx);

 private:
  std::vector<AttribNode> nodes_;  // grown on first use, never shrunk
  int depth_ = 0;
};

// glXCopyContext: the groups of `mask` (GL_ALL_ATTRIB_BITS: all) go from
// `src` to `dst` as glPushAttrib would save them and glPopAttrib restore them.
// The caller has drawn both contexts' buffered vertices.
void copyAttribGroups(Context& src, Context& dst, GLbitfield mask);

}  // namespace glfixed
