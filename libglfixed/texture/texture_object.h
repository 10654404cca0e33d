// Texture objects (GL 2.1 §3.8.12): the images of every level (and cube
// face) and the sampler state of one texture. The names are shared between
// contexts that share display lists.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "state/buffer_objects.h"  // DataStore: calloc, so a huge image fails as GL_OUT_OF_MEMORY
#include "texture/texel_format.h"

namespace glfixed::texture {

constexpr int kMaxTextureLevels = 15;  // GL_MAX_TEXTURE_SIZE 16384, as llvmpipe
constexpr int kMaxTextureSize = 16384;  // GL_MAX_TEXTURE_SIZE, GL_MAX_CUBE_MAP_TEXTURE_SIZE (Mesa)
constexpr int kMax3DTextureSize = 2048;  // GL_MAX_3D_TEXTURE_SIZE (Mesa): 12 levels
constexpr int kMaxCubeFaces = 6;       // +X, -X, +Y, -Y, +Z, -Z (GL's face order)

// One mipmap level of one face, stored as llvmpipe stores it: no border
// (Mesa strips texture borders before the driver sees them), texels in
// `format`, rows of `rowStride` bytes from the bottom row (t = 0) up, images
// (r slices) `imageStride` bytes apart.
struct TextureImage {
  int width = 0, height = 0, depth = 0;  // 0: the level is not defined
  GLint internalFormat = 0;              // as the application gave it (glGetTexLevelParameter)
  TexelFormat format = TexelFormat::RGBA8;
  size_t rowStride = 0, imageStride = 0;
  DataStore texels;
  bool defined() const { return width > 0; }
  const uint8_t* texel(int x, int y, int z) const {
    return texels.data() + size_t(z) * imageStride + size_t(y) * rowStride +
           size_t(x) * texelFormatInfo(format).bytesPerTexel;
  }
};

// The texture parameters of table 6.23 that sampling reads (glTexParameter).
struct SamplerParams {
  GLenum minFilter = GL_NEAREST_MIPMAP_LINEAR, magFilter = GL_LINEAR;
  GLenum wrapS = GL_REPEAT, wrapT = GL_REPEAT, wrapR = GL_REPEAT;
  glm::vec4 borderColor{0, 0, 0, 0};
  float minLod = -1000, maxLod = 1000, lodBias = 0;
  int baseLevel = 0, maxLevel = 1000;
  GLenum compareMode = GL_NONE, compareFunc = GL_LEQUAL, depthTextureMode = GL_LUMINANCE;
};

struct TextureObject {
  GLuint name = 0;
  GLenum target = 0;  // 0 until first bound (§3.8.12)
  SamplerParams params;
  bool generateMipmap = false;
  float priority = 1;
  // face[0] for every target but GL_TEXTURE_CUBE_MAP, which uses all six.
  std::array<std::array<TextureImage, kMaxTextureLevels>, kMaxCubeFaces> face;
  const TextureImage& level(int face, int level) const { return this->face[face][level]; }
};

}  // namespace glfixed::texture
