// The attribute groups of glPushAttrib (GL 2.1 §6.1.14, tables 6.5-6.37) that the
// core uses, one struct each, so that push and pop are a copy.
#pragma once

#include <GL/gl.h>

#ifndef GL_PACK_INVERT_MESA  // GL_MESA_pack_invert, which the system gl.h may lack
#define GL_PACK_INVERT_MESA 0x8758
#endif

#include <array>
#include <glm/glm.hpp>

namespace glfixed {

// GL_CURRENT_BIT: the current vertex attributes.
struct CurrentAttrib {
  glm::vec4 color{1, 1, 1, 1};
  glm::vec3 normal{0, 0, 1};
  glm::vec4 texCoord[8] = {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1),
                           glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1),
                           glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1)};
  glm::vec4 secondaryColor{0, 0, 0, 1};
  float fogCoord = 0;
  float colorIndex = 1;
  bool edgeFlag = true;
};

// GL_MAX_CLIP_PLANES: Mesa's is 8 (REFERENCE.md, "Depth and limits").
constexpr int kMaxClipPlanes = 8;

// GL_TRANSFORM_BIT.
struct TransformAttrib {
  GLenum matrixMode = GL_MODELVIEW;
  bool normalize = false;
  bool rescaleNormal = false;
  // ARB_depth_clamp (GL 3.2 §2.17): no near and far clipping; fragment depth
  // clamped to the depth range. In GL_TRANSFORM_BIT and GL_ENABLE_BIT.
  bool depthClamp = false;
  // Client clip planes (§2.12), in eye space as glClipPlane stored them
  // (float, as Mesa's EyeUserPlane; api/gl_clip_api.cpp).
  std::array<glm::vec4, kMaxClipPlanes> clipPlane{};
  std::array<bool, kMaxClipPlanes> clipPlaneEnabled{};
};

// GL_VIEWPORT_BIT.
struct ViewportAttrib {
  GLint x = 0, y = 0;
  GLsizei width = 0, height = 0;
  GLclampd depthNear = 0, depthFar = 1;
  bool operator==(const ViewportAttrib& o) const {
    return x == o.x && y == o.y && width == o.width && height == o.height && depthNear == o.depthNear &&
           depthFar == o.depthFar;
  }
};

// GL_DEPTH_BUFFER_BIT.
struct DepthBufferAttrib {
  bool test = false;
  GLenum func = GL_LESS;
  bool writeMask = true;
  GLclampd clearDepth = 1;
};

// GL_COLOR_BUFFER_BIT.
struct ColorBufferAttrib {
  glm::vec4 clearColor{0, 0, 0, 0};
  // As glClearColor got it: OSMesa's float buffers are cleared to it unclamped.
  glm::vec4 clearColorUnclamped{0, 0, 0, 0};
  // OSMesaColorClamp(GL_TRUE): fragment colours are clamped on float buffers
  // too (Mesa's GL_CLAMP_FRAGMENT_COLOR GL_TRUE; its default, GL_FIXED_ONLY,
  // leaves them unclamped there).
  bool clampFragmentColor = false;
  bool dither = true;
  std::array<bool, 4> writeMask{true, true, true, true};
  bool alphaTest = false;  // the alpha test (fragment/alpha_test.inc)
  GLenum alphaFunc = GL_ALWAYS;
  float alphaRef = 0;  // clamped to [0, 1]
  // Held, not used yet (table 6.18-6.19): the per-fragment stages that read
  // them come later.
  bool blend = false;
  GLenum blendSrcRGB = GL_ONE, blendSrcAlpha = GL_ONE, blendDstRGB = GL_ZERO, blendDstAlpha = GL_ZERO;
  GLenum blendEquationRGB = GL_FUNC_ADD, blendEquationAlpha = GL_FUNC_ADD;
  glm::vec4 blendColor{0, 0, 0, 0};
  bool colorLogicOp = false, indexLogicOp = false;
  GLenum logicOpMode = GL_COPY;
  GLenum drawBuffer = GL_FRONT;  // single-buffered OSMesa
  float clearIndex = 0;
  GLuint indexWriteMask = ~0u;
};

// GL_POLYGON_BIT.
struct PolygonAttrib {
  bool cullFace = false;
  GLenum cullFaceMode = GL_BACK;
  GLenum frontFace = GL_CCW;
  // Held, not used yet (table 6.17): polygon modes, offset, smoothing, stipple.
  GLenum frontMode = GL_FILL, backMode = GL_FILL;
  float offsetFactor = 0, offsetUnits = 0;
  bool smooth = false, stipple = false;
  bool offsetPoint = false, offsetLine = false, offsetFill = false;
};

// GL_HINT_BIT (GL 2.1 §5.6).
struct HintAttrib {
  GLenum perspectiveCorrection = GL_DONT_CARE;
  GLenum pointSmooth = GL_DONT_CARE;
  GLenum lineSmooth = GL_DONT_CARE;
  GLenum polygonSmooth = GL_DONT_CARE;
  GLenum fog = GL_DONT_CARE;
  GLenum generateMipmap = GL_DONT_CARE;
  GLenum textureCompression = GL_DONT_CARE;
  GLenum fragmentShaderDerivative = GL_DONT_CARE;
};

}  // namespace glfixed

namespace glfixed {

// GL_CLIENT_PIXEL_STORE_BIT (glPixelStore, GL 2.1 §3.6.1, §4.3.2).
struct PixelStoreAttrib {
  GLint packAlignment = 4, packRowLength = 0, packSkipPixels = 0, packSkipRows = 0;
  GLint unpackAlignment = 4, unpackRowLength = 0, unpackSkipPixels = 0, unpackSkipRows = 0;
  // GL 2.1 puts the pixel buffer bindings (§4.3.5, table 6.34) in this group.
  GLuint pixelPackBufferBinding = 0, pixelUnpackBufferBinding = 0;
  // Textures (3D images, byte order; texture/unpack.h reads them).
  GLint unpackImageHeight = 0, unpackSkipImages = 0, packImageHeight = 0, packSkipImages = 0;
  bool unpackSwapBytes = false;
  // GL_MESA_pack_invert: packed images are written top row first. Mesa keeps
  // the GLboolean as given (5 reads back 5).
  GLboolean packInvert = GL_FALSE;
};

}  // namespace glfixed
