// One vertex batch for every way of submitting vertices: glBegin/glEnd fills it
// now; vertex arrays and display lists will fill the same structure. Stages
// read it as arrays (structure of arrays), never a call at a time.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "state/lighting_attrib.h"

namespace glfixed {
// Texture coordinates (issue 14): the units a batch can carry.
constexpr int kBatchTexCoordUnits = 8;
}  // namespace glfixed

namespace glfixed {

using MaterialPair = std::array<Material, 2>;  // [kFront], [kBack]

struct VertexBatch {
  GLenum mode = GL_TRIANGLES;
  std::vector<glm::vec4> position;  // object coordinates
  std::vector<glm::vec3> normal;    // object coordinates, as given
  std::vector<glm::vec4> color;     // the current colour at each vertex
  // glMaterial between glBegin and glEnd (GL 2.1 §2.14.3): vertex i is lit with
  // materials[materialIndex[i]]. materials[0] is the material at glBegin.
  std::vector<uint32_t> materialIndex;
  std::vector<MaterialPair> materials;
  // Polygon area: each vertex's edge flag (GL 2.1 §2.6.2), 1 or 0; kept in
  // step with the other arrays.
  std::vector<uint8_t> edgeFlag;
  // Texture coordinates (issue 14): s, t, r, q of each vertex for the units
  // in texCoordUnits (bit u), kept in step with the other arrays; the other
  // units' arrays are empty (the vertex stage uses the current coordinates).
  // None are carried while no unit needs them.
  uint32_t texCoordUnits = 0;
  std::array<std::vector<glm::vec4>, kBatchTexCoordUnits> texCoord;
  void setTexCoordUnits(uint32_t units) {
    texCoordUnits = units;
    for (int u = 0; u < kBatchTexCoordUnits; ++u)
      texCoord[u].resize((units >> u & 1u) ? size() : 0, glm::vec4(0, 0, 0, 1));
  }
  // Fog (GL 2.1 §3.10): each vertex's fog coordinate, carried only while
  // the draw reads it (fog on, GL_FOG_COORD its source); else empty and the
  // vertex stage uses the current one.
  bool hasFogCoord = false;
  std::vector<float> fogCoord;
  void setHasFogCoord(bool on) {
    hasFogCoord = on;
    fogCoord.resize(on ? size() : 0, 0.0f);
  }
  // The colour sum without lighting (GL_COLOR_SUM): each vertex's secondary
  // colour, carried only while the draw reads it; else empty.
  bool hasSecondaryColor = false;
  std::vector<glm::vec4> secondaryColor;
  void setHasSecondaryColor(bool on) {
    hasSecondaryColor = on;
    secondaryColor.resize(on ? size() : 0, glm::vec4(0, 0, 0, 1));
  }
  size_t size() const { return position.size(); }
  void reset(GLenum primitiveMode, const MaterialPair& current) {
    mode = primitiveMode;
    clearVertices();
    materials.assign(1, current);
  }

  // The per-vertex arrays, kept in step: the one place that lists them.
  void clearVertices() { resizeVertices(0); }
  void resizeVertices(size_t n) {
    position.resize(n);
    normal.resize(n);
    color.resize(n);
    materialIndex.resize(n);
    edgeFlag.resize(n, 1);
    for (uint32_t m = texCoordUnits; m != 0; m &= m - 1) texCoord[__builtin_ctz(m)].resize(n, glm::vec4(0, 0, 0, 1));
    if (hasFogCoord) fogCoord.resize(n, 0.0f);
    if (hasSecondaryColor) secondaryColor.resize(n, glm::vec4(0, 0, 0, 1));
  }
  // Appends vertices [first, last) of `from` (their material indexes as they are).
  void appendVertices(const VertexBatch& from, size_t first, size_t last) {
    // Texture coordinates: an empty batch takes the units of the one it copies.
    if (position.empty() && texCoordUnits != from.texCoordUnits) setTexCoordUnits(from.texCoordUnits);
    if (position.empty() && hasFogCoord != from.hasFogCoord) setHasFogCoord(from.hasFogCoord);
    if (position.empty() && hasSecondaryColor != from.hasSecondaryColor) setHasSecondaryColor(from.hasSecondaryColor);
    position.insert(position.end(), from.position.begin() + first, from.position.begin() + last);
    normal.insert(normal.end(), from.normal.begin() + first, from.normal.begin() + last);
    color.insert(color.end(), from.color.begin() + first, from.color.begin() + last);
    materialIndex.insert(materialIndex.end(), from.materialIndex.begin() + first,
                         from.materialIndex.begin() + last);
    edgeFlag.insert(edgeFlag.end(), from.edgeFlag.begin() + first, from.edgeFlag.begin() + last);
    for (uint32_t m = texCoordUnits; m != 0; m &= m - 1) {
      const int u = __builtin_ctz(m);
      std::vector<glm::vec4>& t = texCoord[u];
      if (from.texCoordUnits >> u & 1u)
        t.insert(t.end(), from.texCoord[u].begin() + first, from.texCoord[u].begin() + last);
      else
        t.resize(position.size(), glm::vec4(0, 0, 0, 1));
    }
    if (hasFogCoord) {
      if (from.hasFogCoord)
        fogCoord.insert(fogCoord.end(), from.fogCoord.begin() + first, from.fogCoord.begin() + last);
      else
        fogCoord.resize(position.size(), 0.0f);
    }
    if (hasSecondaryColor) {
      if (from.hasSecondaryColor)
        secondaryColor.insert(secondaryColor.end(), from.secondaryColor.begin() + first,
                              from.secondaryColor.begin() + last);
      else
        secondaryColor.resize(position.size(), glm::vec4(0, 0, 0, 1));
    }
  }
  void eraseFirstVertices(size_t n) { eraseVertices(0, n); }
  // Erases vertices [first, last) (their material indexes as they are).
  void eraseVertices(size_t first, size_t last) {
    position.erase(position.begin() + first, position.begin() + last);
    normal.erase(normal.begin() + first, normal.begin() + last);
    color.erase(color.begin() + first, color.begin() + last);
    materialIndex.erase(materialIndex.begin() + first, materialIndex.begin() + last);
    edgeFlag.erase(edgeFlag.begin() + first, edgeFlag.begin() + last);
    for (uint32_t m = texCoordUnits; m != 0; m &= m - 1)
      texCoord[__builtin_ctz(m)].erase(texCoord[__builtin_ctz(m)].begin() + first,
                                       texCoord[__builtin_ctz(m)].begin() + last);
    if (hasFogCoord) fogCoord.erase(fogCoord.begin() + first, fogCoord.begin() + last);
    if (hasSecondaryColor) secondaryColor.erase(secondaryColor.begin() + first, secondaryColor.begin() + last);
  }
};

// What the vertex stage hands to primitive assembly: clip coordinates and
// colours clamped to [0,1] (llvmpipe clamps at the vertex, REFERENCE.md).
struct ShadedVertices {
  std::vector<glm::vec4> clip;
  std::array<std::vector<glm::vec4>, 2> primary;    // [kFront], [kBack]
  std::array<std::vector<glm::vec4>, 2> secondary;  // specular, GL_SEPARATE_SPECULAR_COLOR only
  bool hasBack = false;       // two-sided lighting: back colours are filled
  bool hasSecondary = false;  // separate specular: secondary colours are filled
  // Points (GL 2.1 §3.4): the size of each vertex, filled only when point
  // distance attenuation is on (hasPointSize); else the state's size is used.
  std::vector<float> pointSize;
  bool hasPointSize = false;
  // Texture coordinates (issue 14, vertex/texcoord.h): s, t, r, q of each
  // vertex for the units in texCoordUnits, after texgen and the texture matrix.
  uint32_t texCoordUnits = 0;
  std::array<std::vector<glm::vec4>, kBatchTexCoordUnits> texCoord;
  // Fog (GL 2.1 §3.10): each vertex's fog distance (the shader's
  // gl_FogFragCoord), filled only while hasFog.
  std::vector<float> fog;
  bool hasFog = false;
  size_t size() const { return clip.size(); }
};

}  // namespace glfixed
