// The texture environment of each unit (GL 2.1 §3.8.13, table 3.22-3.24):
// how a unit's texel combines with the colour from the unit before it, done
// with the float operations, in the order, that Mesa's fixed-function
// fragment shader gives llvmpipe.
#pragma once

#include <GL/gl.h>

#include "fragment/lanes.h"
#include "state/texture_env_attrib.h"

namespace glfixed::fragment {

constexpr int kMaxTextureEnvUnits = 8;

// One unit's environment as one draw uses it: glTexEnv's state and the base
// internal format of the unit's texture (which decides REPLACE, MODULATE,
// DECAL, BLEND and ADD, table 3.22).
struct TexEnvUnit {
  TexEnvAttrib env;
  GLenum baseFormat = GL_RGBA;
  // For a GL_DEPTH_COMPONENT texture: the base format its GL_DEPTH_TEXTURE_MODE
  // gives it (GL_LUMINANCE, GL_INTENSITY or GL_ALPHA).
  GLenum depthTextureMode = GL_LUMINANCE;
};

// The colours a unit may read: the fragment's primary colour, and the texel
// of every enabled unit (crossbar sources GL_TEXTUREn of
// ARB_texture_env_crossbar); null where a unit is not enabled.
struct TexEnvSources {
  const ColorLanes* primary = nullptr;
  const ColorLanes* texel[kMaxTextureEnvUnits] = {};
};

// Applies unit `unit`'s environment: `previous` holds the colour of the unit
// before (the primary colour for the first enabled unit) and receives the result.
void applyTexEnv(const TexEnvUnit& env, int unit, const TexEnvSources& sources, ColorLanes& previous);

}  // namespace glfixed::fragment
