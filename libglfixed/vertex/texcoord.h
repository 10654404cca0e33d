// Texture coordinates in the vertex stage (GL 2.1 §2.11.4, §2.11.2): per
// unit, texgen then the texture matrix, as Mesa's fixed-function vertex
// shader computes them (ffvertex_prog.c, build_texture_transform) and
// llvmpipe runs it: dot products summed from the last component down,
// unfused; the matrix as a multiply and three multiply-adds down the
// columns, unfused; the sphere and reflection maps from the normal and the
// normalised eye position (vertex/lighting_math.h has the shader's ops).
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "pipeline/vertex_batch.h"
#include "state/attrib_groups.h"

namespace glfixed {
class Context;
}

namespace glfixed::vertex {

// One unit's part of the shader (Mesa's state key: texgen modes, texmat_enabled).
struct TexCoordUnit {
  std::array<GLenum, 4> gen{};  // per coordinate: 0 (not generated) or the mode
  bool texgen = false;          // some coordinate is generated
  bool matrix = false;          // the texture matrix is not the identity
  glm::mat4 textureMatrix{1};
  std::array<glm::vec4, 4> objectPlane{}, eyePlane{};
  glm::vec4 current{0, 0, 0, 1};  // the current coordinates, for a batch without the unit's array
};

struct TexCoordState {
  uint32_t units = 0;  // bit u: the shader outputs unit u's coordinates
  std::array<TexCoordUnit, kMaxTextureUnits> unit;
  // Mesa's TEXGEN_NEED_EYE_COORD: an eye-linear, sphere, reflection or
  // normal map on an output unit makes the whole shader work in eye space
  // (_NeedEyeCoords): lighting too.
  bool needEyeCoords = false;
  bool needNormal = false;  // sphere, reflection or normal map
  // The normal transform (get_transformed_normal) for eye coordinates.
  glm::mat3 normalFromObject{1};  // rows of the inverse transpose
  bool normalize = false, rescale = false;
  float normalRescale = 1;
};

// Whether unit u's texture is enabled for the fixed-function pipeline (Mesa's
// _EnabledCoordUnits). Any enabled target counts here; a target whose texture
// is incomplete should not (GL 2.1 §3.8.10): the texture stage may refine it.
bool textureUnitEnabled(const Context& ctx, int u);

// The units whose per-vertex texture coordinates a batch must carry: the
// enabled ones, and unit 0 in GL_FEEDBACK (Mesa's shader then always outputs
// it: ffvertex_prog.c, make_state_key).
uint32_t texCoordInputUnits(const Context& ctx);

// The shader's texture coordinate state from the context (every draw).
void buildTexCoordState(const Context& ctx, TexCoordState& out);

// The coordinates of every vertex of the batch for the units in state.units:
// out.texCoordUnits and out.texCoord[u].
void computeTexCoords(const TexCoordState& state, const glm::mat4& eyeFromObject, const VertexBatch& batch,
                      ShadedVertices& out);

// One vertex's coordinates of unit u (the raster position, §2.13).
glm::vec4 texCoordOfVertex(const TexCoordState& state, int u, const glm::mat4& eyeFromObject,
                           const glm::vec4& position, const glm::vec3& normal, const glm::vec4& texCoord);

// glGet: GL_TEXTURE_MATRIX, GL_TEXTURE_STACK_DEPTH, the transposed matrices.
bool getTexCoordState(const Context& ctx, GLenum pname, GLdouble* out, int* count);

}  // namespace glfixed::vertex
