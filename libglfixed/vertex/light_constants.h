// Per-light constants derived from the lighting state when it changes (not per
// vertex): rebuilt by Context::validate() when kDirtyLighting is set.
#pragma once

#include <glm/glm.hpp>

#include "state/attribs.h"
#include "state/lighting_attrib.h"

namespace glfixed::vertex {

struct LightingConstants {
  // Filled in by the lighting stage.
  bool twoSide = false;
  bool separateSpecular = false;
};

void buildLightingConstants(const LightingAttrib& lighting, const TransformAttrib& transform,
                            LightingConstants& out);

}  // namespace glfixed::vertex
