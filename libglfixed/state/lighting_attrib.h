// The GL_LIGHTING_BIT attribute group (GL 2.1 §2.14, table 6.11-6.13): lights,
// light model, materials, colour material, shade model. Raw API values; the
// lighting stage reads the derived form in vertex/light_constants.h.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace glfixed {

constexpr int kMaxLights = 8;

struct Light {
  glm::vec4 ambient{0, 0, 0, 1};
  glm::vec4 diffuse{0, 0, 0, 1};         // LIGHT0: (1,1,1,1)
  glm::vec4 specular{0, 0, 0, 1};        // LIGHT0: (1,1,1,1)
  glm::vec4 eyePosition{0, 0, 1, 0};     // stored in eye space (§2.14.2)
  glm::vec3 eyeSpotDirection{0, 0, -1};  // stored in eye space
  float spotExponent = 0;
  float spotCutoff = 180;
  float constantAttenuation = 1;
  float linearAttenuation = 0;
  float quadraticAttenuation = 0;
  bool enabled = false;
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1};
  glm::vec4 specular{0, 0, 0, 1};
  glm::vec4 emission{0, 0, 0, 1};
  float shininess = 0;
  glm::vec3 colorIndexes{0, 1, 1};  // GL_COLOR_INDEXES: stored and returned, never used in RGBA
};

struct LightModel {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1};
  bool localViewer = false;
  bool twoSide = false;
  GLenum colorControl = GL_SINGLE_COLOR;
};

enum Face { kFront = 0, kBack = 1 };

struct LightingAttrib {
  GLenum shadeModel = GL_SMOOTH;
  bool lighting = false;
  bool colorMaterial = false;
  GLenum colorMaterialFace = GL_FRONT_AND_BACK;
  GLenum colorMaterialParameter = GL_AMBIENT_AND_DIFFUSE;
  LightModel model;
  std::array<Light, kMaxLights> light;
  std::array<Material, 2> material;  // [kFront], [kBack]
  GLenum provokingVertex = GL_LAST_VERTEX_CONVENTION;
  // Not GL state: which material components (vertex::MaterialBit, front and
  // back) glMaterial set between the current glBegin and glEnd. Mesa treats
  // those as per-vertex attributes, which changes its shader (see
  // vertex/lighting.cpp). Meaningful only while the batch holds more than one
  // material snapshot; reset by the first glMaterial of each glBegin/glEnd.
  uint32_t beginEndMaterialMask = 0;

  LightingAttrib() {
    light[0].diffuse = glm::vec4(1);
    light[0].specular = glm::vec4(1);
  }
};

}  // namespace glfixed
