// Defining texture images (GL 2.1 §3.8.1-3.8.3): the storage of one level,
// llvmpipe's memory limit, and mipmap generation (§3.8.8, GL_GENERATE_MIPMAP
// and glGenerateMipmap).
#pragma once

#include <GL/gl.h>

#include <cstddef>

#include "texture/texture_object.h"

namespace glfixed::texture {

// llvmpipe refuses a texture larger than 1 GiB (LP_MAX_TEXTURE_SIZE): Mesa
// then reports GL_OUT_OF_MEMORY, or an empty proxy.
constexpr size_t kMaxImageBytes = size_t(1) << 30;

// The bytes llvmpipe's pipe format would take for the image (its texel
// size, not this library's, which keeps a byte or two per channel).
size_t llvmpipeImageBytes(TexelFormat format, int width, int height, int depth);

// Gives `image` a format and size, texels zero (an undefined image, or one
// to be filled). False if the memory cannot be had (the image is then
// left undefined). A zero size makes the level undefined.
bool defineImage(TextureImage& image, GLint internalFormat, TexelFormat format, int width, int height,
                 int depth);

// Records a proxy image's size and format, without texels.
void defineProxyImage(TextureImage& image, GLint internalFormat, TexelFormat format, int width, int height,
                      int depth);

// Levels base+1 ... down to 1x1 of one face, each from the one above, as
// llvmpipe's blit makes them (util_gen_mipmap: a linear sample at each
// texel's centre; for even sizes the average of 2x2 texels). False if
// memory ran out.
bool generateMipmaps(TextureObject& object, int face, int baseLevel, int maxLevels);

}  // namespace glfixed::texture
