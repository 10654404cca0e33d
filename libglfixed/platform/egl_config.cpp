// EGL configurations: their attributes (eglGetConfigAttrib) and the
// matching and sorting rules of eglChooseConfig (EGL 1.5 §3.4, §3.4.1,
// Table 3.4).
#include <X11/Xutil.h>

#include <algorithm>

#include "platform/egl_objects.h"
#include "platform/x11_present.h"
#include "state/context.h"

namespace glfixed::platform::egl {

std::vector<const FramebufferConfig*> eglConfigs() {
  std::vector<const FramebufferConfig*> out;
  for (const FramebufferConfig& c : framebufferConfigs())
    if (c.doubleBuffered) out.push_back(&c);
  return out;
}

EGLint surfaceTypes(const EglDisplay& d, const FramebufferConfig& c) {
  EGLint types = EGL_PBUFFER_BIT;
  if (d.platform == Platform::kX11 && d.nativeVisual(c)) types |= EGL_WINDOW_BIT | EGL_PIXMAP_BIT;
  return types;
}

bool configAttrib(const EglDisplay& d, const FramebufferConfig& c, EGLint attribute, EGLint* value) {
  const Visual* visual = d.platform == Platform::kX11 ? d.nativeVisual(c) : nullptr;
  switch (attribute) {
    case EGL_BUFFER_SIZE: *value = c.bufferBits(); return true;
    case EGL_RED_SIZE:
    case EGL_GREEN_SIZE:
    case EGL_BLUE_SIZE: *value = 8; return true;
    case EGL_ALPHA_SIZE: *value = c.alphaBits; return true;
    case EGL_LUMINANCE_SIZE: *value = 0; return true;
    case EGL_ALPHA_MASK_SIZE: *value = 0; return true;
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA: *value = EGL_FALSE; return true;
    case EGL_COLOR_BUFFER_TYPE: *value = EGL_RGB_BUFFER; return true;
    case EGL_CONFIG_CAVEAT: *value = EGL_NONE; return true;
    case EGL_CONFIG_ID: *value = c.id; return true;
    case EGL_CONFORMANT: *value = EGL_OPENGL_BIT; return true;
    // Debian's xscreensaver hacks (jwz's jwzgles code) choose a configuration
    // renderable with OpenGL ES 1, then bind EGL_OPENGL_API and draw with
    // GL 1.x calls; Mesa's configurations carry every API's bit, so they
    // start there. They carry the ES 1 bit here too, for that reason only:
    // EGL_CLIENT_APIS is "OpenGL", eglBindAPI(EGL_OPENGL_ES_API) fails, and
    // no ES context can be made; ES 2 and 3 requests match nothing.
    case EGL_RENDERABLE_TYPE: *value = EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT; return true;
    case EGL_DEPTH_SIZE: *value = c.depthBits; return true;
    case EGL_STENCIL_SIZE: *value = c.stencilBits; return true;
    case EGL_LEVEL: *value = 0; return true;
    case EGL_MAX_PBUFFER_WIDTH:
    case EGL_MAX_PBUFFER_HEIGHT: *value = kMaxViewportSize; return true;
    case EGL_MAX_PBUFFER_PIXELS: *value = kMaxViewportSize * kMaxViewportSize; return true;
    // Swaps do not wait for the display: every interval is the same one.
    case EGL_MIN_SWAP_INTERVAL: *value = 0; return true;
    case EGL_MAX_SWAP_INTERVAL: *value = 1; return true;
    case EGL_NATIVE_RENDERABLE: *value = visual ? EGL_TRUE : EGL_FALSE; return true;
    case EGL_NATIVE_VISUAL_ID:
      *value = visual ? static_cast<EGLint>(XVisualIDFromVisual(const_cast<Visual*>(visual))) : 0;
      return true;
    case EGL_NATIVE_VISUAL_TYPE: *value = visual ? TrueColor : EGL_NONE; return true;
    case EGL_SAMPLE_BUFFERS:
    case EGL_SAMPLES: *value = 0; return true;
    case EGL_SURFACE_TYPE: *value = surfaceTypes(d, c); return true;
    case EGL_TRANSPARENT_TYPE: *value = EGL_NONE; return true;
    case EGL_TRANSPARENT_RED_VALUE:
    case EGL_TRANSPARENT_GREEN_VALUE:
    case EGL_TRANSPARENT_BLUE_VALUE: *value = 0; return true;
    default: return false;
  }
}

namespace {

enum class Criterion { kAtLeast, kExact, kMask, kIgnored };

struct Rule {
  EGLint attribute;
  Criterion criterion;
  EGLint defaultValue;
};

// Table 3.4, less EGL_MATCH_NATIVE_PIXMAP (handled on its own). The default
// of EGL_RENDERABLE_TYPE is EGL_OPENGL_ES_BIT there, which no configuration
// of this OpenGL-only library has; a request that does not name the API
// matches on the one API there is (as it does on Mesa, whose configurations
// serve every API), so the default here asks for nothing.
constexpr Rule kRules[] = {
    {EGL_BUFFER_SIZE, Criterion::kAtLeast, 0},
    {EGL_RED_SIZE, Criterion::kAtLeast, 0},
    {EGL_GREEN_SIZE, Criterion::kAtLeast, 0},
    {EGL_BLUE_SIZE, Criterion::kAtLeast, 0},
    {EGL_LUMINANCE_SIZE, Criterion::kAtLeast, 0},
    {EGL_ALPHA_SIZE, Criterion::kAtLeast, 0},
    {EGL_ALPHA_MASK_SIZE, Criterion::kAtLeast, 0},
    {EGL_BIND_TO_TEXTURE_RGB, Criterion::kExact, EGL_DONT_CARE},
    {EGL_BIND_TO_TEXTURE_RGBA, Criterion::kExact, EGL_DONT_CARE},
    {EGL_COLOR_BUFFER_TYPE, Criterion::kExact, EGL_RGB_BUFFER},
    {EGL_CONFIG_CAVEAT, Criterion::kExact, EGL_DONT_CARE},
    {EGL_CONFIG_ID, Criterion::kExact, EGL_DONT_CARE},
    {EGL_CONFORMANT, Criterion::kMask, 0},
    {EGL_DEPTH_SIZE, Criterion::kAtLeast, 0},
    {EGL_LEVEL, Criterion::kExact, 0},
    {EGL_MAX_PBUFFER_WIDTH, Criterion::kIgnored, 0},
    {EGL_MAX_PBUFFER_HEIGHT, Criterion::kIgnored, 0},
    {EGL_MAX_PBUFFER_PIXELS, Criterion::kIgnored, 0},
    {EGL_MAX_SWAP_INTERVAL, Criterion::kExact, EGL_DONT_CARE},
    {EGL_MIN_SWAP_INTERVAL, Criterion::kExact, EGL_DONT_CARE},
    {EGL_NATIVE_RENDERABLE, Criterion::kExact, EGL_DONT_CARE},
    {EGL_NATIVE_VISUAL_ID, Criterion::kIgnored, 0},
    {EGL_NATIVE_VISUAL_TYPE, Criterion::kExact, EGL_DONT_CARE},
    {EGL_RENDERABLE_TYPE, Criterion::kMask, 0},
    {EGL_SAMPLE_BUFFERS, Criterion::kAtLeast, 0},
    {EGL_SAMPLES, Criterion::kAtLeast, 0},
    {EGL_STENCIL_SIZE, Criterion::kAtLeast, 0},
    {EGL_SURFACE_TYPE, Criterion::kMask, EGL_WINDOW_BIT},
    {EGL_TRANSPARENT_TYPE, Criterion::kExact, EGL_NONE},
    {EGL_TRANSPARENT_RED_VALUE, Criterion::kExact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_GREEN_VALUE, Criterion::kExact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_BLUE_VALUE, Criterion::kExact, EGL_DONT_CARE},
};

const Rule* ruleFor(EGLint attribute) {
  for (const Rule& r : kRules)
    if (r.attribute == attribute) return &r;
  return nullptr;
}

// The values a request may give (Mesa refuses the others with
// EGL_BAD_ATTRIBUTE, as §3.4.1 lets it).
bool valueIsValid(EGLint attribute, EGLint value) {
  if (value == EGL_DONT_CARE) return attribute != EGL_LEVEL;
  switch (attribute) {
    case EGL_COLOR_BUFFER_TYPE: return value == EGL_RGB_BUFFER || value == EGL_LUMINANCE_BUFFER;
    case EGL_CONFIG_CAVEAT:
      return value == EGL_NONE || value == EGL_SLOW_CONFIG || value == EGL_NON_CONFORMANT_CONFIG;
    case EGL_TRANSPARENT_TYPE: return value == EGL_NONE || value == EGL_TRANSPARENT_RGB;
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA:
    case EGL_NATIVE_RENDERABLE: return value == EGL_TRUE || value == EGL_FALSE;
    case EGL_CONFORMANT:
    case EGL_RENDERABLE_TYPE:
      return (value & ~(EGL_OPENGL_ES_BIT | EGL_OPENVG_BIT | EGL_OPENGL_ES2_BIT | EGL_OPENGL_BIT |
                        EGL_OPENGL_ES3_BIT)) == 0;
    case EGL_SURFACE_TYPE:
    case EGL_NATIVE_VISUAL_TYPE:
    case EGL_LEVEL: return true;
    default: return value >= 0;
  }
}

struct Request {
  EGLint value[std::size(kRules)];
  bool given[std::size(kRules)] = {};
  EGLint matchPixmapDepth = 0;  // EGL_MATCH_NATIVE_PIXMAP's depth, 0: none asked
  EGLint& operator[](EGLint attribute) { return value[ruleFor(attribute) - kRules]; }
  EGLint get(EGLint attribute) const { return value[ruleFor(attribute) - kRules]; }
};

bool matches(const EglDisplay& d, const FramebufferConfig& c, const Request& r) {
  if (r.get(EGL_CONFIG_ID) != EGL_DONT_CARE) return r.get(EGL_CONFIG_ID) == c.id;  // the others are ignored
  if (r.matchPixmapDepth &&
      (!d.drawableVisual(c, r.matchPixmapDepth) || !(surfaceTypes(d, c) & EGL_PIXMAP_BIT)))
    return false;
  for (size_t i = 0; i < std::size(kRules); ++i) {
    const Rule& rule = kRules[i];
    const EGLint want = r.value[i];
    if (rule.criterion == Criterion::kIgnored || want == EGL_DONT_CARE) continue;
    EGLint have = 0;
    configAttrib(d, c, rule.attribute, &have);
    switch (rule.criterion) {
      case Criterion::kAtLeast:
        if (have < want) return false;
        break;
      case Criterion::kExact:
        if (have != want) return false;
        break;
      case Criterion::kMask:
        if ((have & want) != want) return false;
        break;
      case Criterion::kIgnored: break;
    }
  }
  return true;
}

// §3.4.1's sort: caveat, colour buffer type, then the larger sum of the
// colour components the request asked for, then smaller buffer size,
// samples, depth, stencil, alpha mask, then visual type and config id.
bool better(const EglDisplay& d, const Request& r, const FramebufferConfig* a, const FramebufferConfig* b) {
  auto attr = [&d](const FramebufferConfig* c, EGLint name) {
    EGLint v = 0;
    configAttrib(d, *c, name, &v);
    return v;
  };
  auto colorBits = [&](const FramebufferConfig* c) {
    int sum = 0;
    for (EGLint name : {EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE, EGL_LUMINANCE_SIZE}) {
      const EGLint want = r.get(name);
      if (want != 0 && want != EGL_DONT_CARE) sum += attr(c, name);
    }
    return sum;
  };
  if (colorBits(a) != colorBits(b)) return colorBits(a) > colorBits(b);
  for (EGLint name : {EGL_BUFFER_SIZE, EGL_SAMPLE_BUFFERS, EGL_SAMPLES, EGL_DEPTH_SIZE, EGL_STENCIL_SIZE,
                      EGL_ALPHA_MASK_SIZE, EGL_NATIVE_VISUAL_TYPE, EGL_CONFIG_ID})
    if (attr(a, name) != attr(b, name)) return attr(a, name) < attr(b, name);
  return false;
}

}  // namespace

bool chooseConfigs(const EglDisplay& d, const EGLint* attribs, std::vector<const FramebufferConfig*>* out,
                   EGLint* error) {
  Request r;
  for (size_t i = 0; i < std::size(kRules); ++i) r.value[i] = kRules[i].defaultValue;
  for (int i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    const EGLint name = attribs[i], value = attribs[i + 1];
    if (name == EGL_MATCH_NATIVE_PIXMAP) {
      if (value == EGL_NONE) continue;
      int w, h, depth;
      if (d.platform != Platform::kX11 ||
          !x11DrawableSize(d.x11, static_cast<Drawable>(static_cast<unsigned>(value)), &w, &h, &depth)) {
        *error = EGL_BAD_NATIVE_PIXMAP;
        return false;
      }
      r.matchPixmapDepth = depth;
      continue;
    }
    if (!ruleFor(name) || !valueIsValid(name, value)) {
      *error = EGL_BAD_ATTRIBUTE;
      return false;
    }
    r[name] = value;
  }
  out->clear();
  for (const FramebufferConfig* c : eglConfigs())
    if (matches(d, *c, r)) out->push_back(c);
  std::stable_sort(out->begin(), out->end(), [&](const FramebufferConfig* a, const FramebufferConfig* b) {
    return better(d, r, a, b);
  });
  return true;
}

}  // namespace glfixed::platform::egl
