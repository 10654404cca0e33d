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
struct SamplerView {
  const TextureObject* texture = nullptr;
  GLenum target = GL_TEXTURE_2D;
  float unitLodBias = 0;
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
