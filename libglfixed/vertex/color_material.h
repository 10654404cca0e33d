// glColorMaterial (GL 2.1 §2.14.3): with GL_COLOR_MATERIAL enabled, the chosen
// material components track the current colour.
#pragma once

namespace glfixed {

class Context;

// Copies the current colour into the tracked material components of
// ctx.lighting.material. Called after the current colour changes outside
// glBegin/glEnd, at glEnd, and when GL_COLOR_MATERIAL is enabled.
void trackColorMaterial(Context& ctx);

}  // namespace glfixed
