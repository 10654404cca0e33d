// glBegin/glEnd as Mesa's vbo module runs it: the primitives of consecutive
// glBegin/glEnd pairs are kept and merged into one draw until a state change
// flushes them (primitive/merge.h). Which primitives share a draw decides
// how llvmpipe splits quads and culls, so the draws must be the same.
#pragma once

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// glEnd: the primitive in ctx.batch joins the pending draw, or the pending
// draw is drawn and this one waits in its place.
void endPrimitive(Context& ctx);

// Draws what is pending (the vertices Mesa would still have buffered).
void drawPending(Context& ctx);

// A state change, a query that reads the framebuffer, or a context switch:
// draw what is pending, and the colour stops being per-vertex data.
void flushVertices(Context& ctx);

// glColor is about to make the colour per-vertex data (Context::vbo): Mesa
// draws the buffered vertices with the old vertex format first.
void colorBecomesVertexData(Context& ctx);
// The same for the normal (glNormal): it grows the vbo's vertex format too.
void normalBecomesVertexData(Context& ctx);

}  // namespace glfixed::pipeline
