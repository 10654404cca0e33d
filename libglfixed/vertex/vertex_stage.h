// The vertex stage: object coordinates to clip coordinates, and the colour of
// each vertex (the current colour, or lit per GL 2.1 §2.14), for a whole batch.
#pragma once

#include <glm/glm.hpp>

#include "pipeline/vertex_batch.h"
#include "vertex/light_constants.h"
#include "vertex/texcoord.h"

namespace glfixed {
class Context;
}

namespace glfixed::vertex {

// Fog (GL 2.1 §3.10): what Mesa's fixed-function vertex program computes as
// the fog coordinate it hands the fragment shader (ffvertex_prog.c,
// build_fog), when GL_FOG is on.
struct FogVertexState {
  bool enabled = false;
  bool fromFogCoord = false;  // GL_FOG_COORD_SRC = GL_FOG_COORD: |coordinate|
  GLenum distanceMode = 0x855C;  // else NV_fog_distance's mode (GL_EYE_PLANE_ABSOLUTE_NV)
  float currentCoord = 0;        // for a batch without per-vertex fog coordinates
};

// Whether a batch must carry each vertex's fog coordinate (fog on, with
// GL_FOG_COORD as the source).
bool fogCoordInput(const Context& ctx);

struct VertexState {
  glm::mat4 eyeFromObject{1};   // modelview
  glm::mat4 clipFromObject{1};  // projection * modelview
  bool lighting = false;
  const LightingConstants* lightingConstants = nullptr;
  const LightingAttrib* lightingAttrib = nullptr;
  const TransformAttrib* transformAttrib = nullptr;
  // Points: distance attenuation (GL 2.1 §3.4), computed per vertex as Mesa's
  // fixed-function vertex program does (ffvertex_prog.c, build_atten_pointsize)
  // when the attenuation is not (1, 0, 0). pointSizeClamp: the size, then the
  // min and max sizes already clamped to the implementation's [1, 255]
  // (prog_statevars.c, STATE_POINT_SIZE_CLAMPED).
  bool pointAttenuated = false;
  glm::vec3 pointAttenuation{1, 0, 0};
  float pointSizeClamp[3] = {1, 1, 255};
  // Texture coordinates (issue 14, vertex/texcoord.h): the units the shader
  // outputs and how it computes them; texCoord.units == 0: none.
  TexCoordState texCoord;
  FogVertexState fog;
};

// The attenuated size of one vertex (see pointAttenuated).
float attenuatedPointSize(const VertexState& state, const glm::vec4& objectPosition);

void shadeBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out);

// The lighting stage proper (vertex/lighting.cpp): fills out.primary (and back,
// secondary as the light model asks) for every vertex of the batch.
void lightBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out);

}  // namespace glfixed::vertex
