// Sampling as llvmpipe samples (GL 2.1 §3.8.8-3.8.11): a block of eight
// fragments (fragment/lanes.h) in, one RGBA colour per fragment out. The
// level of detail comes from the coordinate differences inside each 2x2 quad
// of the block, as llvmpipe computes them.
#pragma once

#include <GL/gl.h>

#include "fragment/lanes.h"
#include "texture/texture_object.h"

namespace glfixed::texture {

// One texture unit's texture as one draw samples it: the object, the target
// the unit has enabled, and the unit's own bias (glTexEnv
// GL_TEXTURE_LOD_BIAS), with whatever the sampler derives once per draw.
// One mipmap level as the sampler reads it (face[f] for cube maps).
struct SamplerLevel {
  const TextureImage* face[kMaxCubeFaces] = {};
  int size[3] = {1, 1, 1};
  float sizeF[3] = {1, 1, 1};
  bool pot[3] = {true, true, true};
};

struct SamplerView {
  const TextureObject* texture = nullptr;
  GLenum target = GL_TEXTURE_2D;
  float unitLodBias = 0;

  // Derived once per draw (sampler.cpp says what each decides in llvmpipe).
  int dims = 2;  // coordinates that address texels: 1, 2 or 3 (cube: 2 per face)
  bool cube = false;
  bool unorm8 = false;  // llvmpipe's AoS 8-bit fixed-point path, else its SoA float path
  GLenum minImage = GL_NEAREST, magImage = GL_NEAREST;  // GL_NEAREST or GL_LINEAR
  GLenum mipFilter = GL_NONE;                           // GL_NONE, GL_NEAREST or GL_LINEAR
  GLenum wrap[3] = {GL_REPEAT, GL_REPEAT, GL_REPEAT};
  bool border[3] = {};        // the wrap mode of that coordinate reads the border colour
  float borderColor[4] = {};  // clamped to [0, 1], as llvmpipe clamps it for unorm formats
  bool samplesZero = false;   // complete, yet llvmpipe reads (0, 0, 0, 0) (sampler.cpp)
  bool needLod = false;
  bool minMaxLodEqual = false, applyMinLod = false, applyMaxLod = false;
  float lodBias = 0, minLod = 0, maxLod = 1000;  // the gallium sampler's values
  int firstLevel = 0, lastLevel = 0;
  TexelFormat format = TexelFormat::RGBA8;
  // A depth texture (ARB_depth_texture, ARB_shadow): its value, or with
  // GL_COMPARE_R_TO_TEXTURE the comparison of r with it, through the mode.
  bool depth = false, compare = false;
  GLenum compareFunc = GL_LEQUAL, depthTextureMode = GL_LUMINANCE;
  SamplerLevel levels[kMaxTextureLevels];
};

// Builds the view of `texture` as `target`; false when the texture is not
// complete for its filters (§3.8.10), which disables the unit (§3.8.15).
bool makeSamplerView(const TextureObject& texture, GLenum target, float unitLodBias, SamplerView& out);

// The colours of the eight fragments whose texture coordinates are (s, t, r,
// q), as interpolated (the projective division by q is the sampler's, done
// as Mesa's fixed-function fragment shader does it on llvmpipe).
void sampleBlock(const SamplerView& view, const fragment::Lanes& s, const fragment::Lanes& t,
                 const fragment::Lanes& r, const fragment::Lanes& q, fragment::ColorLanes& out);

}  // namespace glfixed::texture
