// The GL context: every piece of GL state, grouped as glPushAttrib groups it,
// plus the derived state the stages read. One per OSMesa context; the current
// context is per thread.
#pragma once

#include <GL/gl.h>

#include <memory>
#include <vector>

#include "framebuffer/framebuffer.h"
#include "pipeline/vbo_store.h"
#include "pipeline/display_list.h"
#include "pipeline/vertex_batch.h"
#include "state/attrib_groups.h"
#include "state/attrib_stack.h"
#include "state/attribs.h"
#include "state/bitmap_cache.h"
#include "state/buffer_objects.h"
#include "state/diagnostics.h"
#include "state/dirty.h"
#include "state/eval_attrib.h"
#include "state/framebuffer_objects.h"
#include "state/lighting_attrib.h"
#include "state/list_attrib.h"
#include "state/matrix_stack.h"
#include "state/pixel_maps.h"
#include "state/query_objects.h"
#include "state/vertex_array_attrib.h"
#include "state/vertex_array_objects.h"
#include "state/raster_pos.h"
#include "state/render_mode.h"
#include "texture/texture_objects.h"
#include "vertex/light_constants.h"
#include "vertex/vertex_stage.h"

namespace glfixed {

constexpr int kMaxModelviewStackDepth = 32;
constexpr int kMaxProjectionStackDepth = 32;
constexpr int kMaxViewportSize = 16384;
constexpr int kViewportBoundsMin = -2 * kMaxViewportSize;  // Mesa's GL_VIEWPORT_BOUNDS_RANGE
constexpr int kViewportBoundsMax = 2 * kMaxViewportSize - 1;
constexpr int kSubpixelBits = 8;
constexpr int kMaxClientAttribStackDepth = 16;  // GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, as Mesa
// Texture coordinates (issue 14): GL_MAX_TEXTURE_STACK_DEPTH, as Mesa.
constexpr int kMaxTextureStackDepth = 10;

// One entry of the glPushClientAttrib stack (GL 2.1 §6.1.14).
struct ClientAttribEntry {
  GLbitfield mask = 0;
  PixelStoreAttrib pixelStore;
  VertexArrayAttrib vertexArray;
};

class Context {
 public:
  explicit Context(int depthBits, int stencilBits = 0);

  // API state, by attribute group.
  CurrentAttrib current;
  TransformAttrib transform;
  ViewportAttrib viewport;
  DepthBufferAttrib depth;
  ColorBufferAttrib colorBuffer;
  PolygonAttrib polygon;
  HintAttrib hint;
  PixelStoreAttrib pixelStore;
  LightingAttrib lighting;
  VertexArrayAttrib vertexArray;
  VertexArrayObjects vertexArrayObjects;  // the objects not bound (ARB_vertex_array_object)
  BufferObjects buffers;
  // GL_COPY_READ_BUFFER and GL_COPY_WRITE_BUFFER (ARB_copy_buffer): binding
  // points for glCopyBufferSubData, in no attribute group: glPopClientAttrib
  // leaves them as they are, as Mesa does.
  struct CopyBufferBindings {
    GLuint read = 0, write = 0;
  } copyBuffer;
  QueryObjects queries;  // occlusion queries, in no attribute group
  std::vector<ClientAttribEntry> clientAttribStack;
  // The groups whose stages come later (state/attrib_groups.h).
  FogAttrib fog;
  StencilAttrib stencil;
  ScissorAttrib scissor;
  LineAttrib line;
  PointAttrib point;
  PolygonStippleAttrib polygonStipple;
  PixelModeAttrib pixelMode;
  AccumAttrib accum;
  MultisampleAttrib multisample;
  TextureAttrib texture;
  AttribStack attribStack;  // glPushAttrib/glPopAttrib
  EvalAttrib eval;
  EvalMaps evalMaps;  // in no attribute group (table 6.39)
  PixelMaps pixelMaps;  // glPixelMap, in no attribute group (table 6.27)
  ListAttrib list;
  MatrixStack modelview{kMaxModelviewStackDepth};
  MatrixStack projection{kMaxProjectionStackDepth};
  // Texture coordinates (issue 14): the texture matrix stack of every unit
  // (GL 2.1 §2.11.2); glMatrixMode(GL_TEXTURE) addresses the active unit's.
  std::vector<MatrixStack> textureMatrix{static_cast<size_t>(kMaxTextureUnits),
                                         MatrixStack(kMaxTextureStackDepth)};
  RasterPosState rasterPos;    // glRasterPos (§2.13); belongs to GL_CURRENT_BIT
  RenderModeState renderMode;  // glRenderMode, selection, feedback (§5.2, §5.3)

  // What the stages draw into and read from: the window system's
  // framebuffer, or, while a framebuffer object is bound (draw or read),
  // views of the objects' attachments (and of the window's buffers for the
  // other binding if it is 0), rebuilt before every use by
  // refreshFramebuffer (state/framebuffer_binding.h). The window's own
  // buffers are then parked in parkedWindow; the platform layer reaches them
  // through windowFramebuffer() either way.
  Framebuffer framebuffer;
  Framebuffer parkedWindow;
  // Framebuffer and renderbuffer objects: shared as textures are.
  std::shared_ptr<FramebufferObjects> framebufferObjects = std::make_shared<FramebufferObjects>();
  struct FramebufferBindings {
    GLuint draw = 0, read = 0, renderbuffer = 0;
    // The window's draw and read buffers while an object holds the binding
    // (the object's own are in ctx.colorBuffer.drawBuffer / pixelMode.readBuffer).
    GLenum windowDrawBuffer = GL_FRONT, windowReadBuffer = GL_FRONT;
    // The bound objects' status at the last refreshFramebuffer.
    GLenum drawStatus = 0x8CD5, readStatus = 0x8CD5;
  } fbo;
  bool objectBound() const { return fbo.draw != 0 || fbo.read != 0; }
  Framebuffer& windowFramebuffer() { return objectBound() ? parkedWindow : framebuffer; }
  GLenum windowDrawBuffer() const { return fbo.draw ? fbo.windowDrawBuffer : colorBuffer.drawBuffer; }
  GLenum windowReadBuffer() const { return fbo.read ? fbo.windowReadBuffer : pixelMode.readBuffer; }
  // Points the window framebuffer's draw and read views at the buffers GL state names.
  void selectWindowBuffers() { windowFramebuffer().selectBuffers(windowDrawBuffer(), windowReadBuffer()); }
  int requestedDepthBits;
  int requestedStencilBits;  // 0 or 8: the stencil buffer (framebuffer/framebuffer.h)
  // An accumulation buffer (OSMesaCreateContextExt's accumBits > 0); Mesa's
  // always has 16 bits a channel.
  bool requestedAccum = false;
  bool viewportInitialized = false;  // the first MakeCurrent sets the viewport
  // At the context's first surface (unless glViewport came first): the
  // viewport and scissor box take its size (GL 2.1 §2.11.1, §4.1.2), and the
  // draw and read buffers start as GL_BACK on a double-buffered one (§4.2.1).
  void sizeToFirstSurface(int width, int height, bool doubleBuffered) {
    if (viewportInitialized) return;
    viewport.width = scissor.width = width;
    viewport.height = scissor.height = height;
    viewportInitialized = true;
    const GLenum initial = doubleBuffered ? GL_BACK : GL_FRONT;
    (fbo.draw ? fbo.windowDrawBuffer : colorBuffer.drawBuffer) = initial;
    (fbo.read ? fbo.windowReadBuffer : pixelMode.readBuffer) = initial;
  }

  // Between glBegin and glEnd (GL 2.1 §2.6.3).
  bool insideBeginEnd = false;
  GLenum beginEndMode = 0;  // glBegin's mode, for glPrimitiveRestartNV
  VertexBatch batch;

  // What Mesa's vbo module would hold (REFERENCE: "constant colours"): the
  // vertices of consecutive glBegin/glEnd pairs stay buffered until a state
  // change flushes them, and a colour becomes per-vertex data once glColor is
  // called between glBegin and glEnd, or outside while vertices are buffered.
  // Until then the colour reaches Mesa's fragment shader as a constant, which
  // is never interpolated. Only which of the two rounds the pixels differs.
  struct VboFormat {
    bool verticesBuffered = false;
    int positionSize = 0;  // the most components a glVertex gave since the reset: 2, 3, 4
    int colorSize = 0;     // 0: a constant; 3 or 4: glColor3 or glColor4 made it vertex data
    bool normalIsVertexData = false;  // the same for glNormal
    bool edgeFlagIsVertexData = false;  // and for glEdgeFlag (one float in Mesa's vertex)
    bool fogCoordIsVertexData = false;  // and for glFogCoord (one float)
    bool secondaryColorIsVertexData = false;  // and for glSecondaryColor (three floats)
    uint32_t materialAttributes = 0;  // glMaterial components made vertex data (materialfv)
    int materialFloats = 0;
    bool colorIsVertexData() const { return colorSize != 0; }
    // Mesa's vertex_size.
    uint32_t vertexFloats() const {
      return static_cast<uint32_t>(positionSize + colorSize + (normalIsVertexData ? 3 : 0) +
                                   (edgeFlagIsVertexData ? 1 : 0) + (fogCoordIsVertexData ? 1 : 0) + (secondaryColorIsVertexData ? 3 : 0) +
                                   materialFloats);
    }
  } vbo;
  // Where Mesa's vertex buffer stands (pipeline/vbo_store.h); kept across flushes.
  pipeline::VboStore vboStore;
  // glBitmap calls not drawn yet (state/bitmap_cache.h, pipeline/pixel_rect.cpp).
  BitmapCache bitmapCache;
  // The texture units whose coordinates the last draw carried per vertex
  // (Mesa's VertexProgram._VaryingInputs, which glBitmap's fragment program
  // reads: state/bitmap_cache.h, BitmapShading).
  uint32_t lastDrawTexCoordUnits = 0;
  bool lastDrawSecondaryColorVaries = false;  // and whether it carried secondary colours
  // Lines (primitive/lines.cpp): the draw module's stipple counter, which Mesa
  // keeps from draw to draw (draw_pipe_stipple.c), and whether the next batch
  // continues the previous one's strip (a long array draw drawn in chunks,
  // pipeline/array_draw.cpp), so that it does not restart the pattern.
  struct LineStippleCarry {
    uint32_t counter = 0;
    bool continues = false;
  } lineStipple;
  // The primitives of consecutive glBegin/glEnd pairs Mesa would draw as one
  // (pipeline/immediate_mode.h); drawn when a state change flushes them.
  VertexBatch pending;

  // Display lists (GL 2.1 §5.4): per context for now.
  pipeline::DisplayLists displayLists;

  // Textures (texture objects): the name space and the objects, shared with
  // the contexts this one shares display lists with (shareObjectsWith).
  std::shared_ptr<texture::TextureObjects> textures = std::make_shared<texture::TextureObjects>();
  // Called where a context is created sharing another's lists (OSMesa, GLX, EGL).
  void shareObjectsWith(Context& other) {
    displayLists.shareWith(other.displayLists);
    textures = other.textures;
    framebufferObjects = other.framebufferObjects;
  }

  // Errors (GL 2.1 §2.5): the first error is kept until glGetError reads it.
  // With GLFIXED_DEBUG set, every error is also printed (state/diagnostics.h).
  void recordError(GLenum error) {
    if (error_ == GL_NO_ERROR) error_ = error;
    if (reportErrors_) reportError(error);
  }
  GLenum takeError() {
    GLenum e = error_;
    error_ = GL_NO_ERROR;
    return e;
  }

  MatrixStack& currentMatrixStack() {
    if (transform.matrixMode == GL_TEXTURE) return textureMatrix[texture.activeUnit()];  // texture coordinates
    return transform.matrixMode == GL_PROJECTION ? projection : modelview;
  }
  void markDirty(uint32_t bits) { dirty_ |= bits; }
  // A setter changed state of glPushAttrib group(s) `attribGroups` (GL_*_BIT)
  // and derived state `dirty` must be rebuilt before the next draw.
  void markChanged(GLbitfield attribGroups, uint32_t dirty) {
    attribGroupsChanged |= attribGroups;
    dirty_ |= dirty;
  }
  // The groups changed since the last glPushAttrib (Mesa's PopAttribState):
  // glPopAttrib restores, and so flushes for, only these.
  GLbitfield attribGroupsChanged = 0;
  // Rebuilds the derived state from the dirty bits; called before every draw.
  const vertex::VertexState& validate();

 private:
  GLenum error_ = GL_NO_ERROR;
  const bool reportErrors_ = debugOutputEnabled();
  uint32_t dirty_ = kDirtyAll;
  vertex::VertexState vertexState_;
  vertex::LightingConstants lightingConstants_;
};

Context* currentContext();
void setCurrentContext(Context* ctx);

}  // namespace glfixed
