// The six 8-bit formats of the skeleton (texel_format.h). The sampler's
// helper wrote only these, to test sampling; the texture-objects part lists
// every format here (a merge keeps that version and its decoders).
#include "texture/texel_format.h"

namespace glfixed::texture {

const TexelFormatInfo& texelFormatInfo(TexelFormat format) {
  static const TexelFormatInfo kInfo[] = {
      {4, true, GL_RGBA},             // RGBA8
      {4, true, GL_RGB},              // RGBX8
      {1, true, GL_LUMINANCE},        // L8
      {1, true, GL_ALPHA},            // A8
      {1, true, GL_INTENSITY},        // I8
      {2, true, GL_LUMINANCE_ALPHA},  // L8A8
  };
  return kInfo[static_cast<int>(format) < 6 ? static_cast<int>(format) : 0];
}

void decodeTexelUnorm8(TexelFormat format, const uint8_t* texel, uint8_t rgba[4]) {
  switch (format) {
    case TexelFormat::RGBA8:
      rgba[0] = texel[0], rgba[1] = texel[1], rgba[2] = texel[2], rgba[3] = texel[3];
      break;
    case TexelFormat::RGBX8: rgba[0] = texel[0], rgba[1] = texel[1], rgba[2] = texel[2], rgba[3] = 255; break;
    case TexelFormat::L8: rgba[0] = rgba[1] = rgba[2] = texel[0], rgba[3] = 255; break;
    case TexelFormat::A8: rgba[0] = rgba[1] = rgba[2] = 0, rgba[3] = texel[0]; break;
    case TexelFormat::I8: rgba[0] = rgba[1] = rgba[2] = rgba[3] = texel[0]; break;
    case TexelFormat::L8A8: rgba[0] = rgba[1] = rgba[2] = texel[0], rgba[3] = texel[1]; break;
    default: rgba[0] = rgba[1] = rgba[2] = 0, rgba[3] = 255; break;
  }
}

void decodeTexelFloat(TexelFormat format, const uint8_t* texel, float rgba[4]) {
  uint8_t v[4];
  decodeTexelUnorm8(format, texel, v);
  for (int i = 0; i < 4; ++i) rgba[i] = unormToFloat(v[i], 8);
}

}  // namespace glfixed::texture
