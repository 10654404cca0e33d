#include "texture/internal_format.h"

#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9  // EXT_packed_depth_stencil (not in GL 2.1's gl.h)
#endif
#ifndef GL_DEPTH24_STENCIL8
#define GL_DEPTH24_STENCIL8 0x88F0
#endif

namespace glfixed::texture {

GLenum baseInternalFormat(GLint internalFormat) {
  switch (internalFormat) {
    case 1:
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16:
    case GL_COMPRESSED_LUMINANCE:
    case GL_SLUMINANCE:
    case GL_SLUMINANCE8:
    case GL_COMPRESSED_SLUMINANCE:
    case GL_LUMINANCE32F_ARB:
    case GL_LUMINANCE16F_ARB: return GL_LUMINANCE;
    case 2:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
    case GL_COMPRESSED_LUMINANCE_ALPHA:
    case GL_SLUMINANCE_ALPHA:
    case GL_SLUMINANCE8_ALPHA8:
    case GL_COMPRESSED_SLUMINANCE_ALPHA:
    case GL_LUMINANCE_ALPHA32F_ARB:
    case GL_LUMINANCE_ALPHA16F_ARB: return GL_LUMINANCE_ALPHA;
    case GL_ALPHA32F_ARB:
    case GL_ALPHA16F_ARB:
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16:
    case GL_COMPRESSED_ALPHA: return GL_ALPHA;
    case GL_INTENSITY32F_ARB:
    case GL_INTENSITY16F_ARB:
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16:
    case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
    case 3:
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16:
    case GL_COMPRESSED_RGB:
    case GL_SRGB:
    case GL_SRGB8:
    case GL_COMPRESSED_SRGB:
    case GL_RGB32F_ARB:
    case GL_RGB16F_ARB: return GL_RGB;
    case 4:
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16:
    case GL_COMPRESSED_RGBA:
    case GL_SRGB_ALPHA:
    case GL_SRGB8_ALPHA8:
    case GL_COMPRESSED_SRGB_ALPHA:
    case GL_RGBA32F_ARB:
    case GL_RGBA16F_ARB: return GL_RGBA;
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32: return GL_DEPTH_COMPONENT;
    case GL_DEPTH_STENCIL:
    case GL_DEPTH24_STENCIL8: return GL_DEPTH_STENCIL;
    default: return 0;
  }
}

bool isGenericCompressed(GLint internalFormat) {
  switch (internalFormat) {
    case GL_COMPRESSED_ALPHA:
    case GL_COMPRESSED_LUMINANCE:
    case GL_COMPRESSED_LUMINANCE_ALPHA:
    case GL_COMPRESSED_INTENSITY:
    case GL_COMPRESSED_RGB:
    case GL_COMPRESSED_RGBA:
    case GL_COMPRESSED_SRGB:
    case GL_COMPRESSED_SRGB_ALPHA:
    case GL_COMPRESSED_SLUMINANCE:
    case GL_COMPRESSED_SLUMINANCE_ALPHA: return true;
    default: return false;
  }
}

GLint reportedInternalFormat(GLint internalFormat) {
  switch (internalFormat) {
    case GL_COMPRESSED_SRGB: return GL_SRGB;
    case GL_COMPRESSED_SRGB_ALPHA: return GL_SRGB_ALPHA;
    case GL_COMPRESSED_SLUMINANCE: return GL_LUMINANCE;  // as Mesa reports it
    case GL_COMPRESSED_SLUMINANCE_ALPHA: return GL_LUMINANCE_ALPHA;
    default:
      return isGenericCompressed(internalFormat) ? static_cast<GLint>(baseInternalFormat(internalFormat))
                                                 : internalFormat;
  }
}

TexelFormat chooseTexelFormat(GLint internalFormat, GLenum format, GLenum type) {
  (void)format;
  switch (internalFormat) {
    // Unsized GL_RGB/GL_RGBA: the packed types choose the matching precision.
    case GL_RGB:
      switch (type) {
        case GL_UNSIGNED_SHORT_5_6_5:
        case GL_UNSIGNED_SHORT_5_6_5_REV: return TexelFormat::R5G6B5;
        case GL_UNSIGNED_SHORT_5_5_5_1:
        case GL_UNSIGNED_SHORT_1_5_5_5_REV: return TexelFormat::RGB5X1;
        case GL_UNSIGNED_INT_10_10_10_2:
        case GL_UNSIGNED_INT_2_10_10_10_REV: return TexelFormat::RGB10X2;
        case GL_UNSIGNED_BYTE_3_3_2:
        case GL_UNSIGNED_BYTE_2_3_3_REV: return TexelFormat::R3G3B2;
        default: return TexelFormat::RGBX8;
      }
    case GL_RGBA:
      switch (type) {
        case GL_UNSIGNED_SHORT: return TexelFormat::RGBA16;
        case GL_UNSIGNED_SHORT_4_4_4_4:
        case GL_UNSIGNED_SHORT_4_4_4_4_REV: return TexelFormat::RGBA4;
        case GL_UNSIGNED_SHORT_5_5_5_1:
        case GL_UNSIGNED_SHORT_1_5_5_5_REV: return TexelFormat::RGB5A1;
        case GL_UNSIGNED_INT_10_10_10_2:
        case GL_UNSIGNED_INT_2_10_10_10_REV: return TexelFormat::RGB10A2;
        default: return TexelFormat::RGBA8;
      }
    case GL_DEPTH_COMPONENT:
      return type == GL_UNSIGNED_SHORT ? TexelFormat::Z16
             : type == GL_UNSIGNED_INT ? TexelFormat::Z32
                                       : TexelFormat::Z24;
    case GL_DEPTH_COMPONENT16: return TexelFormat::Z16;
    case GL_DEPTH_COMPONENT24: return TexelFormat::Z24;
    case GL_DEPTH_COMPONENT32: return TexelFormat::Z32;
    case GL_DEPTH_STENCIL:
    case GL_DEPTH24_STENCIL8: return TexelFormat::Z24S8;
    case GL_LUMINANCE12:
    case GL_LUMINANCE16: return TexelFormat::L16;
    case GL_ALPHA12:
    case GL_ALPHA16: return TexelFormat::A16;
    case GL_INTENSITY12:
    case GL_INTENSITY16: return TexelFormat::I16;
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16: return TexelFormat::L16A16;
    case GL_LUMINANCE4_ALPHA4: return TexelFormat::L4A4;
    case GL_R3_G3_B2: return TexelFormat::R3G3B2;
    case GL_RGB4: return TexelFormat::RGBX4;
    case GL_RGB5: return TexelFormat::RGB5X1;
    case GL_RGB10: return TexelFormat::RGB10X2;
    case GL_RGB12:
    case GL_RGB16: return TexelFormat::RGBX16;
    case GL_RGBA2:
    case GL_RGBA4: return TexelFormat::RGBA4;
    case GL_RGB5_A1: return TexelFormat::RGB5A1;
    case GL_SRGB:
    case GL_SRGB8: return TexelFormat::SRGBX8;
    case GL_SRGB_ALPHA:
    case GL_SRGB8_ALPHA8: return TexelFormat::SRGBA8;
    case GL_SLUMINANCE:
    case GL_SLUMINANCE8: return TexelFormat::SL8;
    case GL_SLUMINANCE_ALPHA:
    case GL_SLUMINANCE8_ALPHA8: return TexelFormat::SL8A8;
    case GL_RGB10_A2: return TexelFormat::RGB10A2;
    // ARB_texture_float: llvmpipe has every one of them (sizes probed).
    case GL_RGBA32F_ARB: return TexelFormat::RGBA32F;
    case GL_RGB32F_ARB: return TexelFormat::RGBX32F;
    case GL_ALPHA32F_ARB: return TexelFormat::A32F;
    case GL_INTENSITY32F_ARB: return TexelFormat::I32F;
    case GL_LUMINANCE32F_ARB: return TexelFormat::L32F;
    case GL_LUMINANCE_ALPHA32F_ARB: return TexelFormat::L32A32F;
    case GL_RGBA16F_ARB: return TexelFormat::RGBA16F;
    case GL_RGB16F_ARB: return TexelFormat::RGBX16F;
    case GL_ALPHA16F_ARB: return TexelFormat::A16F;
    case GL_INTENSITY16F_ARB: return TexelFormat::I16F;
    case GL_LUMINANCE16F_ARB: return TexelFormat::L16F;
    case GL_LUMINANCE_ALPHA16F_ARB: return TexelFormat::L16A16F;
    case GL_RGBA12:
    case GL_RGBA16: return TexelFormat::RGBA16;
    default: break;
  }
  // The rest are stored at 8 bits per component (the sRGB ones and the
  // generic compressed ones too: see MESA_FACTS "Textures: storage").
  switch (baseInternalFormat(internalFormat)) {
    case GL_LUMINANCE: return TexelFormat::L8;
    case GL_LUMINANCE_ALPHA: return TexelFormat::L8A8;
    case GL_ALPHA: return TexelFormat::A8;
    case GL_INTENSITY: return TexelFormat::I8;
    case GL_RGB: return TexelFormat::RGBX8;
    default: return TexelFormat::RGBA8;
  }
}

}  // namespace glfixed::texture
