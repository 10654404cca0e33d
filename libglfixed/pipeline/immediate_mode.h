// glBegin/glEnd as Mesa's vbo module runs it: the primitives of consecutive
// glBegin/glEnd pairs are kept and merged into one draw until a state change
// flushes them (primitive/merge.h). Which primitives share a draw decides
// how llvmpipe splits quads and culls, so the draws must be the same.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// glBegin: a new primitive in ctx.batch.
void beginPrimitive(Context& ctx, GLenum mode);

// glEnd: the primitive in ctx.batch joins the pending draw, or the pending
// draw is drawn and this one waits in its place.
void endPrimitive(Context& ctx);

// glVertex has appended a vertex to ctx.batch: when Mesa's vertex buffer is
// full (vbo_store.h), what is buffered is drawn and the primitive goes on.
void vertexAdded(Context& ctx);

// Draws what is pending (the vertices Mesa would still have buffered).
void drawPending(Context& ctx);

// A state change, a query that reads the framebuffer, or a context switch:
// draw what is pending, and the vertex format is reset (nothing is per-vertex data).
void flushVertices(Context& ctx);

// glColor3 (size 3) or glColor4 (size 4) is about to make the colour
// per-vertex data, or give it more components (Context::vbo): Mesa draws the
// buffered vertices with the old vertex format first.
void colorBecomesVertexData(Context& ctx, int size);
// The same for the normal (glNormal): it grows the vbo's vertex format too.
void normalBecomesVertexData(Context& ctx);
void edgeFlagBecomesVertexData(Context& ctx);
// And for glFogCoord (Mesa's VBO_ATTRIB_FOG).
void fogCoordBecomesVertexData(Context& ctx);
void secondaryColorBecomesVertexData(Context& ctx);
// And for the position: a glVertex3 after glVertex2 calls grows it.
void positionGrows(Context& ctx, int size);
// And for glMaterial: `attributes` are the material components the call sets
// (MaterialBits of both faces; colour indexes as bits 10 and 11).
void materialBecomesVertexData(Context& ctx, uint32_t attributes);

}  // namespace glfixed::pipeline
