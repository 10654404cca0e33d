// GLX FBConfigs and visuals: the configurations of platform/configs.h, each
// given a TrueColor visual of the screen (depth 24 without alpha, depth 32
// with), and glXChooseVisual / glXChooseFBConfig, which select and sort them
// by GLX 1.4's rules (§3.3.3, table 3.4) as Mesa's GLX client does.
//
// GLX entry points used by the programs the library serves (nm -D
// --undefined-only, Debian 12; those resolved by glXGetProcAddress in
// brackets):
//   glxgears   ChooseVisual CreateContext DestroyContext GetProcAddressARB
//              MakeCurrent QueryDrawable QueryExtensionsString SwapBuffers
//              [SwapIntervalEXT/MESA/SGI, GetSwapIntervalMESA: only if
//              advertised]
//   glxinfo    ChooseFBConfig ChooseVisual CreateContext CreateNewContext
//              DestroyContext GetClientString GetConfig GetFBConfigAttrib
//              GetFBConfigs GetProcAddress GetProcAddressARB
//              GetVisualFromFBConfig IsDirect MakeCurrent
//              QueryExtensionsString QueryServerString QueryVersion
//              [CreateContextAttribsARB, QueryCurrentRenderer*MESA]
//   glxdemo, glxheads  ChooseVisual CreateContext MakeCurrent SwapBuffers
//   freeglut (libglut.so.3.12)  ChooseFBConfig CreateNewContext
//              DestroyContext GetCurrentContext GetFBConfigAttrib
//              GetProcAddressARB GetVisualFromFBConfig IsDirect
//              MakeContextCurrent QueryExtension QueryExtensionsString
//              SwapBuffers [CreateContextAttribsARB]
//   GLU        none
//   waffle (libwaffle-1.so.0, dlopen/dlsym) ChooseFBConfig CreateNewContext
//              DestroyContext GetFBConfigAttrib GetProcAddress
//              GetVisualFromFBConfig MakeCurrent QueryExtensionsString
//              SwapBuffers [CreateContextAttribsARB]
#include <X11/Xutil.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "platform/glx_internal.h"
#include "state/context.h"

namespace glfixed::platform::glx {

namespace {

bool rgb888(const XVisualInfo& v) {
  return v.c_class == TrueColor && v.red_mask == 0xff0000 && v.green_mask == 0xff00 && v.blue_mask == 0xff &&
         v.bits_per_rgb >= 8;
}

// The screen's TrueColor visuals of `depth` with 8-bit red, green and blue,
// the screen's default visual first.
std::vector<VisualID> visualsOf(Display* display, int screen, int depth) {
  XVisualInfo tmpl{};
  tmpl.screen = screen;
  tmpl.depth = depth;
  tmpl.c_class = TrueColor;
  int n = 0;
  XVisualInfo* list =
      XGetVisualInfo(display, VisualScreenMask | VisualDepthMask | VisualClassMask, &tmpl, &n);
  std::vector<VisualID> ids;
  const VisualID defaultId = XVisualIDFromVisual(DefaultVisual(display, screen));
  for (int i = 0; i < n; ++i)
    if (rgb888(list[i])) ids.push_back(list[i].visualid);
  if (list) XFree(list);
  std::stable_partition(ids.begin(), ids.end(), [&](VisualID id) { return id == defaultId; });
  return ids;
}

// The fullest configuration of a visual depth (double-buffered, 24-bit
// depth, 8 stencil bits) gets the first visual (the default one, for depth
// 24): what a program that takes the default visual most likely wants.
// Where the screen has as many visuals as configurations each gets its own;
// otherwise they share the first.
void assignVisuals(Display* display, int screen, std::vector<std::unique_ptr<FBConfig>>& configs, int depth) {
  std::vector<FBConfig*> ofDepth;
  for (auto& c : configs)
    if (c->visualDepth == depth) ofDepth.push_back(c.get());
  std::stable_partition(ofDepth.begin(), ofDepth.end(), [](const FBConfig* c) {
    return c->config->doubleBuffered && c->config->depthBits == 24 && c->config->stencilBits == 8 &&
           !c->accumBits;
  });
  const std::vector<VisualID> visuals = visualsOf(display, screen, depth);
  if (visuals.empty()) return;
  for (size_t i = 0; i < ofDepth.size(); ++i)
    ofDepth[i]->visualId = visuals.size() >= ofDepth.size() ? visuals[i] : visuals[0];
}

}  // namespace

void makeConfigs(DisplayState& ds) {
  const int screens = ScreenCount(ds.display);
  ds.screens.resize(screens);
  for (int s = 0; s < screens; ++s) {
    auto& list = ds.screens[s];
    for (int accum : {0, 16})
      for (const FramebufferConfig& c : framebufferConfigs())
        list.push_back(std::make_unique<FBConfig>(FBConfig{&c, s, 0, c.visualDepth(), accum}));
    assignVisuals(ds.display, s, list, 24);
    assignVisuals(ds.display, s, list, 32);
  }
}

bool isConfigOf(DisplayState& ds, const FBConfig* config) {
  if (!config) return false;
  for (auto& list : ds.screens)
    for (auto& c : list)
      if (c.get() == config) return true;
  return false;
}

const FBConfig* configForVisual(DisplayState& ds, const XVisualInfo* visual) {
  if (!visual || visual->screen < 0 || visual->screen >= static_cast<int>(ds.screens.size())) return nullptr;
  auto chosen = ds.visualChoice.find(visual->visualid);
  if (chosen != ds.visualChoice.end()) return chosen->second;
  for (auto& c : ds.screens[visual->screen])  // the first is the fullest (assignVisuals)
    if (c->visualId == visual->visualid && c->config->doubleBuffered && c->config->depthBits == 24 &&
        c->config->stencilBits == 8 && !c->accumBits)
      return c.get();
  for (auto& c : ds.screens[visual->screen])
    if (c->visualId == visual->visualid) return c.get();
  return nullptr;
}

XVisualInfo* visualInfoFor(Display* display, const FBConfig& config) {
  if (!config.visualId) return nullptr;
  XVisualInfo tmpl{};
  tmpl.visualid = config.visualId;
  tmpl.screen = config.screen;
  int n = 0;
  return XGetVisualInfo(display, VisualIDMask | VisualScreenMask, &tmpl, &n);
}

int configAttrib(const FBConfig& fb, int attribute, int* value) {
  const FramebufferConfig& c = *fb.config;
  const bool hasVisual = fb.visualId != 0;
  int v = 0;
  switch (attribute) {
    case GLX_USE_GL: v = True; break;
    case GLX_BUFFER_SIZE: v = c.bufferBits(); break;
    case GLX_LEVEL: v = 0; break;
    case GLX_RGBA: v = True; break;
    case GLX_DOUBLEBUFFER: v = c.doubleBuffered; break;
    case GLX_STEREO: v = False; break;
    case GLX_AUX_BUFFERS: v = 0; break;
    case GLX_RED_SIZE:
    case GLX_GREEN_SIZE:
    case GLX_BLUE_SIZE: v = 8; break;
    case GLX_ALPHA_SIZE: v = c.alphaBits; break;
    case GLX_DEPTH_SIZE: v = c.depthBits; break;
    case GLX_STENCIL_SIZE: v = c.stencilBits; break;
    case GLX_ACCUM_RED_SIZE:
    case GLX_ACCUM_GREEN_SIZE:
    case GLX_ACCUM_BLUE_SIZE:
    case GLX_ACCUM_ALPHA_SIZE: v = fb.accumBits; break;
    case GLX_SAMPLE_BUFFERS:
    case GLX_SAMPLES: v = 0; break;
    case GLX_X_VISUAL_TYPE: v = hasVisual ? GLX_TRUE_COLOR : GLX_NONE; break;
    case GLX_CONFIG_CAVEAT: v = fb.accumBits ? GLX_SLOW_CONFIG : GLX_NONE; break;
    case GLX_TRANSPARENT_TYPE: v = GLX_NONE; break;
    case GLX_TRANSPARENT_INDEX_VALUE:
    case GLX_TRANSPARENT_RED_VALUE:
    case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE:
    case GLX_TRANSPARENT_ALPHA_VALUE: v = 0; break;
    case GLX_VISUAL_ID: v = static_cast<int>(fb.visualId); break;
    case GLX_SCREEN: v = fb.screen; break;
    case GLX_DRAWABLE_TYPE:
      // GLX pixmaps are single-buffered (as Mesa's double-buffered configs
      // leave out GLX_PIXMAP_BIT); without a visual, only pbuffers.
      v = GLX_PBUFFER_BIT;
      if (hasVisual) v |= GLX_WINDOW_BIT | (c.doubleBuffered ? 0 : GLX_PIXMAP_BIT);
      break;
    case GLX_RENDER_TYPE: v = GLX_RGBA_BIT; break;
    case GLX_X_RENDERABLE: v = hasVisual; break;
    case GLX_FBCONFIG_ID: v = fb.id(); break;
    case GLX_MAX_PBUFFER_WIDTH:
    case GLX_MAX_PBUFFER_HEIGHT: v = kMaxViewportSize; break;
    case GLX_MAX_PBUFFER_PIXELS: v = kMaxViewportSize * kMaxViewportSize; break;
    default: return GLX_BAD_ATTRIBUTE;
  }
  *value = v;
  return Success;
}

namespace {

// GLX_DONT_CARE (0xFFFFFFFF) as the ints of an attribute list hold it.
constexpr int kDontCare = static_cast<int>(GLX_DONT_CARE);

// What a glXChooseVisual or glXChooseFBConfig attribute list asks for.
struct Request {
  int bufferSize = 0, level = 0, doubleBuffer = kDontCare, stereo = False, auxBuffers = 0;
  int red = 0, green = 0, blue = 0, alpha = 0, depth = 0, stencil = 0;
  int accumRed = 0, accumGreen = 0, accumBlue = 0, accumAlpha = 0;
  int sampleBuffers = 0, samples = 0;
  int renderType = GLX_RGBA_BIT, drawableType = GLX_WINDOW_BIT, xRenderable = kDontCare;
  int visualType = kDontCare, caveat = kDontCare, transparentType = GLX_NONE;
  int fbconfigId = kDontCare;
};

int* field(Request& r, int attribute) {
  switch (attribute) {
    case GLX_BUFFER_SIZE: return &r.bufferSize;
    case GLX_LEVEL: return &r.level;
    case GLX_AUX_BUFFERS: return &r.auxBuffers;
    case GLX_RED_SIZE: return &r.red;
    case GLX_GREEN_SIZE: return &r.green;
    case GLX_BLUE_SIZE: return &r.blue;
    case GLX_ALPHA_SIZE: return &r.alpha;
    case GLX_DEPTH_SIZE: return &r.depth;
    case GLX_STENCIL_SIZE: return &r.stencil;
    case GLX_ACCUM_RED_SIZE: return &r.accumRed;
    case GLX_ACCUM_GREEN_SIZE: return &r.accumGreen;
    case GLX_ACCUM_BLUE_SIZE: return &r.accumBlue;
    case GLX_ACCUM_ALPHA_SIZE: return &r.accumAlpha;
    case GLX_SAMPLE_BUFFERS: return &r.sampleBuffers;
    case GLX_SAMPLES: return &r.samples;
    case GLX_X_VISUAL_TYPE: return &r.visualType;
    case GLX_CONFIG_CAVEAT: return &r.caveat;  // = GLX_VISUAL_CAVEAT_EXT
    case GLX_TRANSPARENT_TYPE: return &r.transparentType;
    default: return nullptr;
  }
}

// glXChooseVisual's list: GLX_RGBA, GLX_DOUBLEBUFFER and GLX_STEREO stand
// alone; without GLX_DOUBLEBUFFER only single-buffered visuals match (GLX
// 1.4 §3.3.10). As Mesa answers (reference/MESA_FACTS.md, "GLX"): a list
// without GLX_RGBA still gets an RGBA visual (there are no colour-index
// ones), and an unknown attribute is skipped with its value.
void parseVisualList(const int* list, Request* r) {
  r->doubleBuffer = False;
  for (int i = 0; list && list[i] != None; ++i) {
    const int a = list[i];
    if (a == GLX_USE_GL || a == GLX_RGBA) continue;
    if (a == GLX_DOUBLEBUFFER) {
      r->doubleBuffer = True;
      continue;
    }
    if (a == GLX_STEREO) {
      r->stereo = True;
      continue;
    }
    const int v = list[++i];
    if (v == None) break;
    if (int* f = field(*r, a)) *f = v;
  }
}

// glXChooseFBConfig's list: pairs; GLX_DONT_CARE leaves an attribute out;
// an unknown attribute is skipped (as Mesa does).
void parseFBConfigList(const int* list, Request* r) {
  for (int i = 0; list && list[i] != None; i += 2) {
    const int a = list[i], v = list[i + 1];
    switch (a) {
      case GLX_DOUBLEBUFFER: r->doubleBuffer = v; break;
      case GLX_STEREO: r->stereo = v; break;
      case GLX_RENDER_TYPE: r->renderType = v; break;
      case GLX_DRAWABLE_TYPE: r->drawableType = v; break;
      case GLX_X_RENDERABLE: r->xRenderable = v; break;
      case GLX_FBCONFIG_ID: r->fbconfigId = v; break;
      default:
        // Attributes ignored in selection (GLX_MAX_PBUFFER_*, GLX_VISUAL_ID,
        // the transparent values, table 3.4) and unknown ones fall here.
        if (int* f = field(*r, a)) *f = v;
    }
  }
}

bool atLeast(int have, int want) { return want == kDontCare || have >= want; }
bool exactly(int have, int want) { return want == kDontCare || have == want; }
bool mask(int have, int want) { return want == kDontCare || (have & want) == want; }

bool matches(const FBConfig& fb, const Request& r) {
  auto get = [&](int attribute) {
    int v = 0;
    configAttrib(fb, attribute, &v);
    return v;
  };
  if (r.fbconfigId != kDontCare) return fb.id() == r.fbconfigId;  // all else ignored
  return atLeast(get(GLX_BUFFER_SIZE), r.bufferSize) && exactly(0, r.level) &&
         exactly(get(GLX_DOUBLEBUFFER), r.doubleBuffer) && exactly(False, r.stereo) &&
         atLeast(0, r.auxBuffers) && atLeast(8, r.red) && atLeast(8, r.green) && atLeast(8, r.blue) &&
         atLeast(fb.config->alphaBits, r.alpha) && atLeast(fb.config->depthBits, r.depth) &&
         atLeast(fb.config->stencilBits, r.stencil) && atLeast(fb.accumBits, r.accumRed) &&
         atLeast(fb.accumBits, r.accumGreen) && atLeast(fb.accumBits, r.accumBlue) &&
         atLeast(fb.accumBits, r.accumAlpha) && atLeast(0, r.sampleBuffers) &&
         atLeast(0, r.samples) && (r.renderType != kDontCare && (r.renderType & GLX_RGBA_BIT)) &&
         mask(get(GLX_DRAWABLE_TYPE), r.drawableType) && exactly(get(GLX_X_RENDERABLE), r.xRenderable) &&
         exactly(get(GLX_X_VISUAL_TYPE), r.visualType) && exactly(get(GLX_CONFIG_CAVEAT), r.caveat) &&
         exactly(GLX_NONE, r.transparentType);
}

// Mesa's order (glxcmds.c fbconfig_compare, after GLX 1.4 table 3.4): for
// colour, depth and accumulation sizes "larger" puts a size of 0 first (it
// stands in for "the components asked for"); the caveat before them all
// (GLX_NONE before GLX_SLOW_CONFIG); then single before double buffering,
// the smaller stencil, the accumulation buffer, the configuration id.
int preferLargerOrZero(int a, int b) {
  if (a == b) return 0;
  if (a == 0) return -1;
  if (b == 0) return 1;
  return a > b ? -1 : 1;
}

bool before(const FBConfig* x, const FBConfig* y) {
  const FramebufferConfig &a = *x->config, &b = *y->config;
  if (x->accumBits != y->accumBits && (!x->accumBits || !y->accumBits)) return !x->accumBits;  // caveat
  if (int c = preferLargerOrZero(a.alphaBits, b.alphaBits)) return c < 0;
  if (a.bufferBits() != b.bufferBits()) return a.bufferBits() < b.bufferBits();
  if (a.doubleBuffered != b.doubleBuffered) return !a.doubleBuffered;
  if (int c = preferLargerOrZero(a.depthBits, b.depthBits)) return c < 0;
  if (a.stencilBits != b.stencilBits) return a.stencilBits < b.stencilBits;
  if (int c = preferLargerOrZero(x->accumBits, y->accumBits)) return c < 0;
  if ((x->visualId != 0) != (y->visualId != 0)) return x->visualId != 0;  // GLX_TRUE_COLOR before none
  return x->id() < y->id();
}

std::vector<const FBConfig*> choose(DisplayState& ds, int screen, const Request& r, bool needVisual) {
  std::vector<const FBConfig*> out;
  if (screen < 0 || screen >= static_cast<int>(ds.screens.size())) return out;
  for (auto& c : ds.screens[screen])
    if (matches(*c, r) && (!needVisual || c->visualId)) out.push_back(c.get());
  std::stable_sort(out.begin(), out.end(), before);
  return out;
}

GLXFBConfig* copyOut(const std::vector<const FBConfig*>& configs, int* count) {
  *count = static_cast<int>(configs.size());
  if (configs.empty()) return nullptr;
  // malloc: the program frees it with XFree.
  auto* out = static_cast<GLXFBConfig*>(std::malloc(configs.size() * sizeof(GLXFBConfig)));
  if (!out) return *count = 0, nullptr;
  for (size_t i = 0; i < configs.size(); ++i) out[i] = const_cast<GLXFBConfig>(configs[i]);
  return out;
}

}  // namespace

}  // namespace glfixed::platform::glx

int __GLXFBConfigRec::id() const {
  return config->id + (accumBits ? static_cast<int>(glfixed::platform::framebufferConfigs().size()) : 0);
}

using namespace glfixed::platform::glx;

extern "C" {

GLAPI XVisualInfo* APIENTRY glXChooseVisual(Display* dpy, int screen, int* attribList) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  Request r;
  if (!ds) return nullptr;
  parseVisualList(attribList, &r);
  const auto configs = choose(*ds, screen, r, true);
  if (configs.empty()) return nullptr;
  ds->visualChoice[configs[0]->visualId] = configs[0];
  return visualInfoFor(dpy, *configs[0]);
}

GLAPI int APIENTRY glXGetConfig(Display* dpy, XVisualInfo* visual, int attrib, int* value) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !visual || !value) return GLX_BAD_VISUAL;
  if (visual->screen < 0 || visual->screen >= static_cast<int>(ds->screens.size())) return GLX_BAD_SCREEN;
  const FBConfig* c = configForVisual(*ds, visual);
  if (!c) {
    // A visual GL does not render to (GLX 1.4 §3.3.10).
    if (attrib == GLX_USE_GL) return *value = False, Success;
    return GLX_BAD_VISUAL;
  }
  return configAttrib(*c, attrib, value);
}

GLAPI GLXFBConfig* APIENTRY glXGetFBConfigs(Display* dpy, int screen, int* nelements) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  int unused;
  if (!nelements) nelements = &unused;
  *nelements = 0;
  DisplayState* ds = displayState(dpy);
  if (!ds || screen < 0 || screen >= static_cast<int>(ds->screens.size())) return nullptr;
  std::vector<const FBConfig*> all;
  for (auto& c : ds->screens[screen]) all.push_back(c.get());
  return copyOut(all, nelements);
}

GLAPI GLXFBConfig* APIENTRY glXChooseFBConfig(Display* dpy, int screen, const int* attribList, int* nitems) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  int unused;
  if (!nitems) nitems = &unused;
  *nitems = 0;
  DisplayState* ds = displayState(dpy);
  Request r;
  if (!ds) return nullptr;
  parseFBConfigList(attribList, &r);
  return copyOut(choose(*ds, screen, r, false), nitems);
}

GLAPI int APIENTRY glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !isConfigOf(*ds, config)) return GLX_BAD_VISUAL;  // GLXBadFBConfig in 1.4's words
  if (!value) return GLX_BAD_VALUE;
  return configAttrib(*config, attribute, value);
}

GLAPI XVisualInfo* APIENTRY glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config) {
  std::lock_guard<std::recursive_mutex> lock(glxMutex());
  DisplayState* ds = displayState(dpy);
  if (!ds || !isConfigOf(*ds, config) || !config->visualId) return nullptr;
  ds->visualChoice[config->visualId] = config;
  return visualInfoFor(dpy, *config);
}

}  // extern "C"
