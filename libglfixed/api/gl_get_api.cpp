// State queries (GL 2.1 §6.1): glGetError, glGetString and glGet{Boolean,
// Integer,Float,Double}v with the conversions of §6.1.2.
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "api/api.h"
#include "state/framebuffer_binding.h"
#include "api/gl_version.h"
#include "state/vertex_array_queries.h"
#include "state/capabilities.h"
#include "api/eval_commands.h"
#include "texture/texture_object.h"
#include "vertex/lighting_queries.h"
#include "vertex/texcoord.h"  // texture coordinates (issue 14)

using namespace glfixed;

namespace {

// How a value converts for glGetIntegerv (§6.1.2): colours, normals, depth
// range and depth clear value map [-1,1] linearly onto the integer range;
// every other float rounds to the nearest integer.
enum class Kind { kPlain, kNormalized };

struct StateValue {
  Kind kind = Kind::kPlain;
  int count = 0;
  GLdouble v[16] = {};
  void set(std::initializer_list<double> values, Kind k = Kind::kPlain) {
    kind = k;
    count = 0;
    for (double d : values) v[count++] = d;
  }
  void setMatrix(const glm::mat4& m) {
    kind = Kind::kPlain;
    count = 16;
    for (int i = 0; i < 16; ++i) v[i] = glm::value_ptr(m)[i];
  }
};

bool isNormalizedLightingQuery(GLenum pname) { return pname == GL_LIGHT_MODEL_AMBIENT; }

// The state of the groups whose stages come later (state/attrib_groups.h and
// the held parts of attribs.h): their initial values, or what glPopAttrib
// gave back.
bool queryHeldState(Context& ctx, GLenum pname, StateValue& out) {
  const ColorBufferAttrib& cb = ctx.colorBuffer;
  const StencilAttrib::Face& front = ctx.stencil.face[ctx.stencil.activeFace];
  const StencilAttrib::Face& back = ctx.stencil.face[1];
  const int stencilMax = (1 << ctx.framebuffer.depth.stencilBits()) - 1;
  const auto stencilRef = [stencilMax](GLint ref) { return ref < 0 ? 0 : (ref > stencilMax ? stencilMax : ref); };
  switch (pname) {
    case GL_FOG_MODE: out.set({double(ctx.fog.mode)}); return true;
    case GL_FOG_DENSITY: out.set({ctx.fog.density}); return true;
    case GL_FOG_START: out.set({ctx.fog.start}); return true;
    case GL_FOG_END: out.set({ctx.fog.end}); return true;
    case GL_FOG_INDEX: out.set({ctx.fog.index}); return true;
    case GL_FOG_COLOR: {  // clamped, as Mesa reports it for fixed-point buffers
      const glm::vec4& c = ctx.fog.color;
      out.set({api::clamp01(c.r), api::clamp01(c.g), api::clamp01(c.b), api::clamp01(c.a)}, Kind::kNormalized);
      return true;
    }
    case GL_FOG_COORD_SRC: out.set({double(ctx.fog.coordSrc)}); return true;
    case 0x855A: out.set({double(ctx.fog.distanceMode)}); return true;  // GL_FOG_DISTANCE_MODE_NV
    case GL_LINE_WIDTH: out.set({ctx.line.width}); return true;
    case GL_LINE_STIPPLE_PATTERN: out.set({double(ctx.line.stipplePattern)}); return true;
    case GL_LINE_STIPPLE_REPEAT: out.set({double(ctx.line.stippleRepeat)}); return true;
    case GL_POINT_SIZE: out.set({ctx.point.size}); return true;
    case GL_POINT_SIZE_MIN: out.set({ctx.point.sizeMin}); return true;
    case GL_POINT_FADE_THRESHOLD_SIZE: out.set({ctx.point.fadeThresholdSize}); return true;
    case GL_POINT_DISTANCE_ATTENUATION: {
      const glm::vec3& a = ctx.point.distanceAttenuation;
      out.set({a.x, a.y, a.z});
      return true;
    }
    case GL_POINT_SPRITE_COORD_ORIGIN: out.set({double(ctx.point.spriteCoordOrigin)}); return true;
    // Points: GL_POINT_SIZE_MAX and Mesa 22.3's llvmpipe limits (probed):
    // aliased and smooth sizes 1 to 255, granularity 0.1f.
    case GL_POINT_SIZE_MAX: out.set({ctx.point.sizeMax}); return true;
    case GL_POINT_SIZE_RANGE:  // = GL_SMOOTH_POINT_SIZE_RANGE
    case GL_ALIASED_POINT_SIZE_RANGE: out.set({1.0, 255.0}); return true;
    case GL_POINT_SIZE_GRANULARITY: out.set({double(0.1f)}); return true;  // = GL_SMOOTH_POINT_SIZE_GRANULARITY
    case GL_SCISSOR_BOX:
      out.set({double(ctx.scissor.x), double(ctx.scissor.y), double(ctx.scissor.width),
               double(ctx.scissor.height)});
      return true;
    case GL_STENCIL_FUNC: out.set({double(front.func)}); return true;
    // The reference as the test uses it: clamped to the buffer's range
    // (0 without a stencil buffer; Mesa's _mesa_get_stencil_ref).
    case GL_STENCIL_REF: out.set({double(stencilRef(front.ref))}); return true;
    case GL_STENCIL_VALUE_MASK: out.set({double(front.valueMask)}); return true;
    case GL_STENCIL_WRITEMASK: out.set({double(front.writeMask)}); return true;
    case GL_STENCIL_BACK_VALUE_MASK: out.set({double(back.valueMask)}); return true;
    case GL_STENCIL_BACK_WRITEMASK: out.set({double(back.writeMask)}); return true;
    case GL_STENCIL_FAIL: out.set({double(front.fail)}); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: out.set({double(front.depthFail)}); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: out.set({double(front.depthPass)}); return true;
    case StencilAttrib::kActiveFaceEXT:
      out.set({double(ctx.stencil.activeFace ? GL_BACK : GL_FRONT)});
      return true;
    case GL_STENCIL_BACK_FUNC: out.set({double(back.func)}); return true;
    case GL_STENCIL_BACK_REF: out.set({double(stencilRef(back.ref))}); return true;
    case GL_STENCIL_BACK_FAIL: out.set({double(back.fail)}); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_FAIL: out.set({double(back.depthFail)}); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_PASS: out.set({double(back.depthPass)}); return true;
    case GL_STENCIL_CLEAR_VALUE: out.set({double(ctx.stencil.clearValue)}); return true;
    case GL_ACCUM_CLEAR_VALUE: {
      const glm::vec4& c = ctx.accum.clearValue;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_ALPHA_TEST_FUNC: out.set({double(cb.alphaFunc)}); return true;
    case GL_ALPHA_TEST_REF: out.set({cb.alphaRef}, Kind::kNormalized); return true;
    case GL_BLEND_SRC_RGB: out.set({double(cb.blendSrcRGB)}); return true;
    case GL_BLEND_DST_RGB: out.set({double(cb.blendDstRGB)}); return true;
    case GL_BLEND_SRC_ALPHA: out.set({double(cb.blendSrcAlpha)}); return true;
    case GL_BLEND_DST_ALPHA: out.set({double(cb.blendDstAlpha)}); return true;
    case GL_BLEND_EQUATION_RGB: out.set({double(cb.blendEquationRGB)}); return true;
    case GL_BLEND_EQUATION_ALPHA: out.set({double(cb.blendEquationAlpha)}); return true;
    case GL_BLEND_SRC: out.set({double(cb.blendSrcRGB)}); return true;
    case GL_BLEND_DST: out.set({double(cb.blendDstRGB)}); return true;
    case GL_BLEND_COLOR: {  // clamped, as Mesa reports it for fixed-point buffers
      const glm::vec4& c = cb.blendColor;
      out.set({api::clamp01(c.r), api::clamp01(c.g), api::clamp01(c.b), api::clamp01(c.a)}, Kind::kNormalized);
      return true;
    }
    case GL_LOGIC_OP_MODE: out.set({double(cb.logicOpMode)}); return true;
    case GL_DRAW_BUFFER: out.set({double(cb.drawBuffer)}); return true;
    case GL_INDEX_CLEAR_VALUE: out.set({cb.clearIndex}); return true;
    case GL_POLYGON_MODE: out.set({double(ctx.polygon.frontMode), double(ctx.polygon.backMode)}); return true;
    case GL_POLYGON_OFFSET_FACTOR: out.set({ctx.polygon.offsetFactor}); return true;
    case GL_POLYGON_OFFSET_UNITS: out.set({ctx.polygon.offsetUnits}); return true;
    case GL_READ_BUFFER: out.set({double(ctx.pixelMode.readBuffer)}); return true;
    case GL_MAP_COLOR: out.set({double(ctx.pixelMode.mapColor)}); return true;
    case GL_PIXEL_MAP_I_TO_I_SIZE:
    case GL_PIXEL_MAP_S_TO_S_SIZE:
    case GL_PIXEL_MAP_I_TO_R_SIZE:
    case GL_PIXEL_MAP_I_TO_G_SIZE:
    case GL_PIXEL_MAP_I_TO_B_SIZE:
    case GL_PIXEL_MAP_I_TO_A_SIZE:
    case GL_PIXEL_MAP_R_TO_R_SIZE:
    case GL_PIXEL_MAP_G_TO_G_SIZE:
    case GL_PIXEL_MAP_B_TO_B_SIZE:
    case GL_PIXEL_MAP_A_TO_A_SIZE:
      out.set({double(ctx.pixelMaps.map[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size)});
      return true;
    case GL_MAX_PIXEL_MAP_TABLE: out.set({double(kMaxPixelMapTable)}); return true;
    case GL_MAP_STENCIL: out.set({double(ctx.pixelMode.mapStencil)}); return true;
    case GL_INDEX_SHIFT: out.set({double(ctx.pixelMode.indexShift)}); return true;
    case GL_INDEX_OFFSET: out.set({double(ctx.pixelMode.indexOffset)}); return true;
    case GL_RED_SCALE: out.set({ctx.pixelMode.scale.r}); return true;
    case GL_GREEN_SCALE: out.set({ctx.pixelMode.scale.g}); return true;
    case GL_BLUE_SCALE: out.set({ctx.pixelMode.scale.b}); return true;
    case GL_ALPHA_SCALE: out.set({ctx.pixelMode.scale.a}); return true;
    case GL_RED_BIAS: out.set({ctx.pixelMode.bias.r}); return true;
    case GL_GREEN_BIAS: out.set({ctx.pixelMode.bias.g}); return true;
    case GL_BLUE_BIAS: out.set({ctx.pixelMode.bias.b}); return true;
    case GL_ALPHA_BIAS: out.set({ctx.pixelMode.bias.a}); return true;
    case GL_DEPTH_SCALE: out.set({ctx.pixelMode.depthScale}); return true;
    case GL_DEPTH_BIAS: out.set({ctx.pixelMode.depthBias}); return true;
    case GL_ZOOM_X: out.set({ctx.pixelMode.zoomX}); return true;
    case GL_ZOOM_Y: out.set({ctx.pixelMode.zoomY}); return true;
    case GL_ACTIVE_TEXTURE: out.set({double(ctx.texture.activeTexture)}); return true;
    case GL_MAX_TEXTURE_UNITS: out.set({double(kMaxTextureUnits)}); return true;
    // Texture objects: the active unit's bindings, and llvmpipe's limits.
    case GL_TEXTURE_BINDING_1D: out.set({double(ctx.texture.binding[ctx.texture.activeUnit()].texture1D)}); return true;
    case GL_TEXTURE_BINDING_2D: out.set({double(ctx.texture.binding[ctx.texture.activeUnit()].texture2D)}); return true;
    case GL_TEXTURE_BINDING_3D: out.set({double(ctx.texture.binding[ctx.texture.activeUnit()].texture3D)}); return true;
    case GL_TEXTURE_BINDING_CUBE_MAP:
      out.set({double(ctx.texture.binding[ctx.texture.activeUnit()].textureCubeMap)});
      return true;
    case GL_MAX_TEXTURE_SIZE: out.set({double(texture::kMaxTextureSize)}); return true;
    case GL_MAX_3D_TEXTURE_SIZE: out.set({double(texture::kMax3DTextureSize)}); return true;
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE: out.set({double(texture::kMaxTextureSize)}); return true;
    // Issue 14, texture environment: Mesa's limit of GL_TEXTURE_LOD_BIAS (not enforced).
    case GL_MAX_TEXTURE_LOD_BIAS: out.set({16.0}); return true;
    // No surface or framebuffer object has sample buffers (§3.2.1).
    case GL_SAMPLE_BUFFERS: out.set({0}); return true;
    case GL_SAMPLES: out.set({0}); return true;
    case GL_SAMPLE_COVERAGE_VALUE: out.set({ctx.multisample.sampleCoverageValue}); return true;
    case GL_SAMPLE_COVERAGE_INVERT: out.set({double(ctx.multisample.sampleCoverageInvert)}); return true;
    default: return false;
  }
}

// The core's own state. False: not one of its pnames.
// Framebuffer objects (GL 3.0 table 6.31, 6.32; Mesa's limits).
bool queryFramebufferObjects(Context& ctx, GLenum pname, StateValue& out) {
  if (pname >= 0x8825 && pname < 0x8825 + kMaxColorAttachments) {  // GL_DRAW_BUFFERi
    const int i = static_cast<int>(pname - 0x8825);
    GLenum b = i == 0 ? ctx.colorBuffer.drawBuffer : GL_NONE;
    if (const FramebufferObject* fb = drawFramebufferObject(ctx)) b = fb->drawBuffers[i];
    out.set({double(b)});
    return true;
  }
  switch (pname) {
    case 0x8CA6: out.set({double(ctx.fbo.draw)}); return true;          // GL_(DRAW_)FRAMEBUFFER_BINDING
    case 0x8CAA: out.set({double(ctx.fbo.read)}); return true;          // GL_READ_FRAMEBUFFER_BINDING
    case 0x8CA7: out.set({double(ctx.fbo.renderbuffer)}); return true;  // GL_RENDERBUFFER_BINDING
    case 0x84E8: out.set({double(kMaxRenderbufferSize)}); return true;  // GL_MAX_RENDERBUFFER_SIZE
    case 0x8CDF: out.set({double(kMaxColorAttachments)}); return true;  // GL_MAX_COLOR_ATTACHMENTS
    case 0x8824: out.set({double(kMaxColorAttachments)}); return true;  // GL_MAX_DRAW_BUFFERS
    case 0x8D57: out.set({double(kMaxSamples)}); return true;           // GL_MAX_SAMPLES
    default: return false;
  }
}

bool queryCoreState(Context& ctx, GLenum pname, StateValue& out) {
  if (ctx.objectBound()) refreshFramebuffer(ctx);
  if (queryFramebufferObjects(ctx, pname, out)) return true;
  const Framebuffer& fb = ctx.framebuffer;
  // A framebuffer object's colour bits are those of its draw buffer 0 (none: 0).
  const double colorBits = ctx.fbo.draw && !fb.color.pixels ? 0.0 : 8.0;
  const ColorBuffer& sized = ctx.fbo.draw ? fb.color : fb.front;
  switch (pname) {
    case GL_MATRIX_MODE: out.set({double(ctx.transform.matrixMode)}); return true;
    case GL_MODELVIEW_MATRIX: out.setMatrix(ctx.modelview.top()); return true;
    case GL_PROJECTION_MATRIX: out.setMatrix(ctx.projection.top()); return true;
    case GL_MODELVIEW_STACK_DEPTH: out.set({double(ctx.modelview.depth())}); return true;
    case GL_PROJECTION_STACK_DEPTH: out.set({double(ctx.projection.depth())}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out.set({double(kMaxModelviewStackDepth)}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out.set({double(kMaxProjectionStackDepth)}); return true;
    case GL_VIEWPORT:
      out.set({double(ctx.viewport.x), double(ctx.viewport.y), double(ctx.viewport.width),
               double(ctx.viewport.height)});
      return true;
    case GL_MAX_VIEWPORT_DIMS: out.set({double(kMaxViewportSize), double(kMaxViewportSize)}); return true;
    case GL_DEPTH_RANGE:
      out.set({ctx.viewport.depthNear, ctx.viewport.depthFar}, Kind::kNormalized);
      return true;
    case GL_COLOR_CLEAR_VALUE: {
      const glm::vec4& c = ctx.colorBuffer.clearColor;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_INDEX_WRITEMASK: out.set({double(static_cast<int32_t>(ctx.colorBuffer.indexWriteMask))}); return true;
    case GL_COLOR_WRITEMASK: {
      const auto& m = ctx.colorBuffer.writeMask;
      out.set({double(m[0]), double(m[1]), double(m[2]), double(m[3])});
      return true;
    }
    case GL_DEPTH_CLEAR_VALUE: out.set({ctx.depth.clearDepth}, Kind::kNormalized); return true;
    case GL_DEPTH_FUNC: out.set({double(ctx.depth.func)}); return true;
    case GL_DEPTH_WRITEMASK: out.set({double(ctx.depth.writeMask)}); return true;
    case GL_DEPTH_TEST: out.set({double(ctx.depth.test)}); return true;
    case GL_CULL_FACE: out.set({double(ctx.polygon.cullFace)}); return true;
    case GL_CULL_FACE_MODE: out.set({double(ctx.polygon.cullFaceMode)}); return true;
    case GL_FRONT_FACE: out.set({double(ctx.polygon.frontFace)}); return true;
    case GL_DITHER: out.set({double(ctx.colorBuffer.dither)}); return true;
    case GL_PERSPECTIVE_CORRECTION_HINT: out.set({double(ctx.hint.perspectiveCorrection)}); return true;
    case GL_POINT_SMOOTH_HINT: out.set({double(ctx.hint.pointSmooth)}); return true;
    case GL_LINE_SMOOTH_HINT: out.set({double(ctx.hint.lineSmooth)}); return true;
    case GL_POLYGON_SMOOTH_HINT: out.set({double(ctx.hint.polygonSmooth)}); return true;
    case GL_FOG_HINT: out.set({double(ctx.hint.fog)}); return true;
    case GL_GENERATE_MIPMAP_HINT: out.set({double(ctx.hint.generateMipmap)}); return true;
    case GL_TEXTURE_COMPRESSION_HINT: out.set({double(ctx.hint.textureCompression)}); return true;
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: out.set({double(ctx.hint.fragmentShaderDerivative)}); return true;
    case GL_PROVOKING_VERTEX: out.set({double(ctx.lighting.provokingVertex)}); return true;
    case GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION: out.set({0.0}); return true;
    case GL_CURRENT_COLOR: {
      const glm::vec4& c = ctx.current.color;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_NORMAL: {
      const glm::vec3& n = ctx.current.normal;
      out.set({n.x, n.y, n.z}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_TEXTURE_COORDS: {
      const glm::vec4& t = ctx.current.texCoord[ctx.texture.activeUnit()];  // of the active unit (table 6.5)
      out.set({t.x, t.y, t.z, t.w});
      return true;
    }
    case GL_CURRENT_SECONDARY_COLOR: {
      const glm::vec4& c = ctx.current.secondaryColor;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_FOG_COORD: out.set({ctx.current.fogCoord}); return true;
    case GL_CURRENT_INDEX: out.set({ctx.current.colorIndex}); return true;
    case GL_EDGE_FLAG: out.set({double(ctx.current.edgeFlag)}); return true;
    case GL_LIST_BASE: out.set({double(ctx.list.base)}); return true;
    case GL_LIST_INDEX: {  // the list being compiled, or 0
      const auto& c = ctx.displayLists.compiler;
      out.set({c ? double(c->name()) : 0.0});
      return true;
    }
    case GL_LIST_MODE: {
      const auto& c = ctx.displayLists.compiler;
      out.set({c ? double(c->mode()) : 0.0});
      return true;
    }
    case GL_MAX_LIST_NESTING: out.set({double(kMaxListNesting)}); return true;
    case GL_SUBPIXEL_BITS: out.set({double(kSubpixelBits)}); return true;
    // Lines: llvmpipe's limits as Mesa 22.3 reports them (probed; Mesa keeps
    // them as floats). GL_LINE_WIDTH_RANGE is GL_SMOOTH_LINE_WIDTH_RANGE.
    case GL_LINE_WIDTH_RANGE:
    case GL_ALIASED_LINE_WIDTH_RANGE: out.set({1.0, 255.0}); return true;
    case GL_LINE_WIDTH_GRANULARITY: out.set({double(0.1f)}); return true;
    // OSMesa's 5-6-5, 16-bit and float buffers report their own sizes; a
    // framebuffer object those of its draw buffer 0 (none: 0).
    case GL_RED_BITS: out.set({colorBits > 0 ? double(sized.channelBits(0)) : 0.0}); return true;
    case GL_GREEN_BITS: out.set({colorBits > 0 ? double(sized.channelBits(1)) : 0.0}); return true;
    case GL_BLUE_BITS: out.set({colorBits > 0 ? double(sized.channelBits(2)) : 0.0}); return true;
    case GL_ALPHA_BITS: out.set({colorBits > 0 ? double(sized.channelBits(3)) : 0.0}); return true;
    // ARB_color_buffer_float: Mesa's framebuffer is in float mode with a
    // framebuffer object's float colour buffer bound, not with OSMesa's
    // float buffers (probed).
    case 0x8820: out.set({ctx.fbo.draw && sized.floatMode ? 1.0 : 0.0}); return true;  // GL_RGBA_FLOAT_MODE_ARB
    case GL_DEPTH_BITS: out.set({double(fb.depth.bits())}); return true;
    case GL_STENCIL_BITS: out.set({double(fb.depth.stencilBits())}); return true;
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
      out.set({fb.accum.present() ? 16.0 : 0.0});
      return true;
    case GL_INDEX_BITS: case GL_AUX_BUFFERS:
      out.set({0.0});
      return true;
    case GL_RGBA_MODE: out.set({1.0}); return true;
    case GL_DOUBLEBUFFER: out.set({fb.doubleBuffered() ? 1.0 : 0.0}); return true;
    case GL_INDEX_MODE: case GL_STEREO: out.set({0.0}); return true;
    case GL_PACK_ALIGNMENT: out.set({double(ctx.pixelStore.packAlignment)}); return true;
    case GL_PACK_ROW_LENGTH: out.set({double(ctx.pixelStore.packRowLength)}); return true;
    case GL_PACK_SKIP_PIXELS: out.set({double(ctx.pixelStore.packSkipPixels)}); return true;
    case GL_PACK_SKIP_ROWS: out.set({double(ctx.pixelStore.packSkipRows)}); return true;
    case GL_UNPACK_ALIGNMENT: out.set({double(ctx.pixelStore.unpackAlignment)}); return true;
    case GL_UNPACK_ROW_LENGTH: out.set({double(ctx.pixelStore.unpackRowLength)}); return true;
    case GL_UNPACK_SKIP_PIXELS: out.set({double(ctx.pixelStore.unpackSkipPixels)}); return true;
    case GL_UNPACK_SKIP_ROWS: out.set({double(ctx.pixelStore.unpackSkipRows)}); return true;
    // Textures: the pixel store state of texture images (texture/unpack.h).
    case GL_UNPACK_IMAGE_HEIGHT: out.set({double(ctx.pixelStore.unpackImageHeight)}); return true;
    case GL_UNPACK_SKIP_IMAGES: out.set({double(ctx.pixelStore.unpackSkipImages)}); return true;
    case GL_PACK_IMAGE_HEIGHT: out.set({double(ctx.pixelStore.packImageHeight)}); return true;
    case GL_PACK_SKIP_IMAGES: out.set({double(ctx.pixelStore.packSkipImages)}); return true;
    case GL_UNPACK_SWAP_BYTES: out.set({double(ctx.pixelStore.unpackSwapBytes)}); return true;
    case GL_PACK_INVERT_MESA: out.set({double(ctx.pixelStore.packInvert)}); return true;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_UNPACK_LSB_FIRST: out.set({0.0}); return true;
    case GL_ATTRIB_STACK_DEPTH: out.set({double(ctx.attribStack.depth())}); return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: out.set({double(kMaxAttribStackDepth)}); return true;
    case GL_CURRENT_RASTER_POSITION: {
      const glm::vec4& p = ctx.rasterPos.position;
      out.set({p.x, p.y, p.z, p.w});
      return true;
    }
    case GL_CURRENT_RASTER_POSITION_VALID: out.set({double(ctx.rasterPos.valid)}); return true;
    case GL_CURRENT_RASTER_DISTANCE: out.set({ctx.rasterPos.distance}); return true;
    case GL_CURRENT_RASTER_COLOR: {
      const glm::vec4& c = ctx.rasterPos.color;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_RASTER_SECONDARY_COLOR: {
      const glm::vec4& c = ctx.rasterPos.secondaryColor;
      out.set({c.r, c.g, c.b, c.a}, Kind::kNormalized);
      return true;
    }
    case GL_CURRENT_RASTER_TEXTURE_COORDS: {
      const glm::vec4& t = ctx.rasterPos.unitTexCoord[ctx.texture.activeUnit()];  // the active unit's (issue 14)
      out.set({t.x, t.y, t.z, t.w});
      return true;
    }
    case GL_CURRENT_RASTER_INDEX: out.set({1.0}); return true;
    // §5.2, §5.3 (tables 6.57, 6.58)
    case GL_RENDER_MODE: out.set({double(ctx.renderMode.mode)}); return true;
    case GL_NAME_STACK_DEPTH: out.set({double(ctx.renderMode.select.nameStackDepth)}); return true;
    case GL_MAX_NAME_STACK_DEPTH: out.set({double(kMaxNameStackDepth)}); return true;
    case GL_SELECTION_BUFFER_SIZE: out.set({double(ctx.renderMode.select.bufferSize)}); return true;
    case GL_FEEDBACK_BUFFER_SIZE: out.set({double(ctx.renderMode.feedback.bufferSize)}); return true;
    case GL_FEEDBACK_BUFFER_TYPE: out.set({double(ctx.renderMode.feedback.type)}); return true;
    // Clip planes and scissor (§2.12; the box is answered with the held state above).
    case GL_MAX_CLIP_PLANES: out.set({double(kMaxClipPlanes)}); return true;
    default:
      break;
  }
  return false;
}

// Every capability's flag is a boolean query of the same name (§6.1.1).
bool queryCapability(Context& ctx, GLenum pname, StateValue& out) {
  const Capability* c = findCapability(pname);
  if (c) out.set({double(c->flag(ctx))});
  return c != nullptr;
}

// The stages that answer in GLdouble arrays of their own.
template <bool (*Get)(const Context&, GLenum, GLdouble*, int*)>
bool queryStage(Context& ctx, GLenum pname, StateValue& out) {
  int count = 0;
  if (!Get(ctx, pname, out.v, &count)) return false;
  out.count = count;
  out.kind = Kind::kPlain;
  return true;
}

bool queryLighting(Context& ctx, GLenum pname, StateValue& out) {
  int count = 0;
  if (!getLightingState(ctx, pname, out.v, &count)) return false;
  out.count = count;
  out.kind = isNormalizedLightingQuery(pname) ? Kind::kNormalized : Kind::kPlain;
  return true;
}

// Who answers glGet (§6.1): each part answers the pnames of the state it
// owns; a pname none of them knows is GL_INVALID_ENUM. Adding state that
// glGet reads is a case in its owner's answer, or one row here.
using Answer = bool (*)(Context&, GLenum, StateValue&);
const Answer kAnswers[] = {
    queryCoreState,                        // this file: transform, viewport, buffers, current, pixel store, ...
    queryHeldState,                        // the groups whose stages come later
    queryCapability,                       // state/capabilities.h
    queryStage<getVertexArrayState>,       // state/vertex_array_queries.h
    queryStage<api::getEvalState>,         // api/eval_commands.h
    queryLighting,                         // vertex/lighting_queries.h
    queryStage<vertex::getTexCoordState>,  // texture coordinates (issue 14): vertex/texcoord.h
};

bool queryState(Context& ctx, GLenum pname, StateValue& out) {
  for (Answer answer : kAnswers)
    if (answer(ctx, pname, out)) return true;
  return false;
}

// Looks the value up, or records the error the query raises.
bool lookUp(GLenum pname, const void* params, StateValue& value) {
  Context* ctx = api::contextForQuery();
  if (!ctx || !params) return false;
  if (!queryState(*ctx, pname, value)) {
    ctx->recordError(GL_INVALID_ENUM);
    return false;
  }
  return true;
}

GLint toInteger(double v, Kind kind) {
  // NaN (a NaN colour, fog end or grid domain is stored as given) would be
  // an undefined conversion: Mesa's answers, its (GLint) cast of the scaled
  // colour (INT_MIN) and its lroundf truncated to 32 bits (0).
  if (std::isnan(v)) return kind == Kind::kNormalized ? -2147483647 - 1 : 0;
  if (kind == Kind::kNormalized) {
    // §6.1.2: 1.0 to the most positive integer, -1.0 to the most negative.
    double scaled = v * 2147483647.0;
    if (scaled >= 2147483647.0) return 2147483647;
    if (scaled <= -2147483648.0) return -2147483647 - 1;
    return static_cast<GLint>(std::floor(scaled + 0.5));  // rounded, not truncated
  }
  double r = std::floor(v + 0.5);
  if (r >= 2147483647.0) return 2147483647;
  if (r <= -2147483648.0) return -2147483647 - 1;
  return static_cast<GLint>(r);
}

}  // namespace

extern "C" {

GLAPI GLenum APIENTRY glGetError(void) {
  Context* ctx = currentContext();
  if (!ctx) return GL_NO_ERROR;
  if (ctx->insideBeginEnd) {
    // GL 2.1 §2.6.3: glGetError is not allowed between Begin and End; it
    // records INVALID_OPERATION and returns 0.
    ctx->recordError(GL_INVALID_OPERATION);
    return 0;
  }
  return ctx->takeError();
}

GLAPI const GLubyte* APIENTRY glGetString(GLenum name) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return nullptr;
  const char* s = nullptr;
  switch (name) {
    case GL_VENDOR: s = kGLVendorString; break;
    case GL_RENDERER: s = kGLRendererString; break;
    case GL_VERSION: s = kGLVersionString; break;
    case GL_EXTENSIONS: s = kGLExtensionsString; break;
    default: break;  // GL_SHADING_LANGUAGE_VERSION too: no GLSL, a GL 1.5 context (api/gl_version.h)
  }
  if (!s) ctx->recordError(GL_INVALID_ENUM);
  return reinterpret_cast<const GLubyte*>(s);
}

GLAPI void APIENTRY glGetBooleanv(GLenum pname, GLboolean* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = v.v[i] != 0 ? GL_TRUE : GL_FALSE;
}

GLAPI void APIENTRY glGetIntegerv(GLenum pname, GLint* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = toInteger(v.v[i], v.kind);
}

GLAPI void APIENTRY glGetFloatv(GLenum pname, GLfloat* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = static_cast<GLfloat>(v.v[i]);
}

GLAPI void APIENTRY glGetDoublev(GLenum pname, GLdouble* params) {
  StateValue v;
  if (!lookUp(pname, params, v)) return;
  for (int i = 0; i < v.count; ++i) params[i] = v.v[i];
}

}  // extern "C"
