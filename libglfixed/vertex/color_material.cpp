// glColorMaterial tracking (GL 2.1 §2.14.3): while GL_COLOR_MATERIAL is on, the
// selected material components take the current colour.
#include "vertex/color_material.h"

#include "state/context.h"
#include "vertex/light_constants.h"

namespace glfixed {

void trackColorMaterial(Context& ctx) {
  LightingAttrib& l = ctx.lighting;
  if (!l.colorMaterial) return;
  const uint32_t bits = vertex::colorMaterialBits(l.colorMaterialFace, l.colorMaterialParameter);
  const glm::vec4& c = ctx.current.color;
  bool changed = false;
  for (int face = 0; face < 2; ++face) {
    const uint32_t b = bits >> (face * vertex::kTrackBackShift);
    Material& m = l.material[face];
    auto set = [&](uint32_t bit, glm::vec4& component) {
      if ((b & bit) && component != c) {
        component = c;
        changed = true;
      }
    };
    set(vertex::kTrackEmission, m.emission);
    set(vertex::kTrackAmbient, m.ambient);
    set(vertex::kTrackDiffuse, m.diffuse);
    set(vertex::kTrackSpecular, m.specular);
  }
  if (changed) ctx.markDirty(kDirtyLighting);
}

}  // namespace glfixed
