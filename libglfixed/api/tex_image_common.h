// What the texture image commands share (api/gl_tex_image_api.cpp,
// api/gl_tex_copy_api.cpp): the image targets, the level and size limits,
// the object a target addresses, GL_GENERATE_MIPMAP.
#pragma once

#include "state/context.h"
#include "texture/texture_image.h"
#include "texture/texture_objects.h"

// EXT_packed_depth_stencil (not in GL 2.1's gl.h).
#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8
#define GL_UNSIGNED_INT_24_8 0x84FA
#endif

namespace glfixed::api::teximage {

// What an image target names: the object's target index, the cube face,
// whether it is a proxy.
struct ImageTarget {
  int index = -1;
  int face = 0;
  bool proxy = false;
};

// The image targets of a command of `dims` dimensions; false: GL_INVALID_ENUM.
inline bool imageTarget(GLenum target, int dims, bool allowProxy, ImageTarget& out) {
  switch (target) {
    case GL_TEXTURE_1D: out = {0, 0, false}; return dims == 1;
    case GL_PROXY_TEXTURE_1D: out = {0, 0, true}; return dims == 1 && allowProxy;
    case GL_TEXTURE_2D: out = {1, 0, false}; return dims == 2;
    case GL_PROXY_TEXTURE_2D: out = {1, 0, true}; return dims == 2 && allowProxy;
    case GL_TEXTURE_3D: out = {2, 0, false}; return dims == 3;
    case GL_PROXY_TEXTURE_3D: out = {2, 0, true}; return dims == 3 && allowProxy;
    case GL_PROXY_TEXTURE_CUBE_MAP: out = {3, 0, true}; return dims == 2 && allowProxy;
    default:
      if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) {
        out = {3, static_cast<int>(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X), false};
        return dims == 2;
      }
      return false;
  }
}

inline int maxLevels(int index) { return index == 2 ? 12 : texture::kMaxTextureLevels; }
inline int maxSize(int index) { return index == 2 ? texture::kMax3DTextureSize : texture::kMaxTextureSize; }

inline texture::TextureObject& targetObject(Context& ctx, const ImageTarget& t) {
  if (t.proxy) return ctx.textures->proxy(t.index);
  return texture::boundObject(*ctx.textures, ctx.texture.binding[ctx.texture.activeUnit()], t.index);
}

inline void maybeGenerateMipmaps(Context& ctx, texture::TextureObject& object, const ImageTarget& t,
                                 int level) {
  if (!object.generateMipmap || t.proxy || level != object.params.baseLevel) return;
  if (!texture::generateMipmaps(object, t.face, level, maxLevels(t.index))) ctx.recordError(GL_OUT_OF_MEMORY);
}

}  // namespace glfixed::api::teximage
