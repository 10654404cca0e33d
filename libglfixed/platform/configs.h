// The framebuffer configurations the library offers, as GLX FBConfigs and
// visuals and as EGL configs: 8-bit red, green and blue, with or without
// 8 alpha bits (alpha needs a depth-32 visual on X11), single- or
// double-buffered, with a depth buffer of 0, 16 or 24 bits, and the 24-bit
// one with or without 8 stencil bits (Mesa pairs stencil with 24-bit depth).
// The stencil buffer is the top byte of the depth words, as Mesa's
// Z24_UNORM_S8_UINT (framebuffer/framebuffer.h).
#pragma once

#include <array>

namespace glfixed::platform {

struct FramebufferConfig {
  int id;  // GLX_FBCONFIG_ID, EGL_CONFIG_ID: 1, 2, ...
  bool doubleBuffered;
  int alphaBits;  // 0 or 8
  int depthBits;  // 0, 16, 24
  int stencilBits;  // 0 or 8
  int bufferBits() const { return 24 + alphaBits; }
  int visualDepth() const { return alphaBits ? 32 : 24; }
};

// Best first, in the order GLX and EGL sort a "choose" that asks for little:
// RGB before RGBA, double before single buffering... each platform sorts its
// answers by its own rules; this is only the list.
inline const std::array<FramebufferConfig, 16>& framebufferConfigs() {
  static const std::array<FramebufferConfig, 16> kConfigs = [] {
    std::array<FramebufferConfig, 16> c{};
    int i = 0;
    for (int alpha : {0, 8})
      for (bool db : {true, false})
        for (int ds : {0, 1, 2, 3}) {
          const int depth[] = {0, 16, 24, 24}, stencil[] = {0, 0, 0, 8};
          c[i] = FramebufferConfig{i + 1, db, alpha, depth[ds], stencil[ds]};
          ++i;
        }
    return c;
  }();
  return kConfigs;
}

inline const FramebufferConfig* findFramebufferConfig(int id) {
  for (const FramebufferConfig& c : framebufferConfigs())
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace glfixed::platform
