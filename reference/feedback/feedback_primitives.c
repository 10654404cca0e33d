/*
 * feedback_primitives: every primitive type in GL_FEEDBACK mode, for each of
 * the five feedback types, under a perspective projection (w != 1), with
 * smooth and flat colours, primitives inside and across the view volume,
 * glPassThrough markers, and back-face culling.
 */
#include <math.h>

#include "fb_common.h"

enum { W = 100, H = 80 };
static GLfloat buf[4096];

static void colour(int i) {
    glColor4f(0.1f + 0.07f * (i % 9), 0.9f - 0.11f * (i % 7), 0.3f + 0.05f * (i % 5), 0.25f + 0.125f * (i % 4));
}

/* n vertices on a slanted ellipse around (cx, cy) at depth z, coloured. */
static void ring(GLenum mode, int n, float cx, float cy, float r, float z) {
    glBegin(mode);
    for (int i = 0; i < n; ++i) {
        float a = 6.2831853f * (float)i / (float)n + 0.3f;
        colour(i);
        glVertex3f(cx + r * cosf(a), cy + 0.8f * r * sinf(a), z + 0.1f * (float)i);
    }
    glEnd();
}

static void strip(GLenum mode, int n, float x0, float y0, float z) {
    glBegin(mode);
    for (int i = 0; i < n; ++i) {
        colour(i + 3);
        glVertex3f(x0 + 0.45f * (float)(i / 2), y0 + 0.5f * (float)(i % 2) + 0.03f * (float)i, z - 0.05f * (float)i);
    }
    glEnd();
}

/* clipped = 0: nothing the clipper cuts but lines. Under GL_FLAT Mesa leaves
 * the colours of the vertices it makes when clipping a polygon uninitialised
 * (MESA_FACTS.md), so flat runs draw only the rest. */
static void scene(int clipped) {
    glPassThrough(1.0f);
    ring(GL_TRIANGLES, 6, -0.5f, 0.4f, 0.5f, -3.0f);
    glPassThrough(2.0f);
    ring(GL_QUADS, 8, 0.6f, 0.2f, 0.6f, -3.5f);
    glPassThrough(3.0f);
    ring(GL_POLYGON, 7, 0.0f, -0.6f, 0.7f, -4.0f);
    glPassThrough(4.0f);
    strip(GL_TRIANGLE_STRIP, 6, -1.0f, -1.0f, -3.2f);
    glPassThrough(5.0f);
    if (clipped) ring(GL_TRIANGLE_FAN, 6, -0.9f, 0.9f, 0.4f, -3.0f);
    ring(GL_TRIANGLE_FAN, 6, -0.4f, 0.3f, 0.3f, -3.0f);
    glPassThrough(6.0f);
    ring(GL_TRIANGLE_FAN, 3, 0.9f, 0.9f, 0.4f, -3.0f);
    ring(GL_TRIANGLE_STRIP, 3, 0.9f, -0.9f, 0.4f, -3.0f);
    glPassThrough(7.0f);
    strip(GL_QUAD_STRIP, 8, 0.2f, 0.6f, -3.3f);
    glPassThrough(8.0f);
    /* across the left, top and near planes */
    if (clipped) {
        ring(GL_TRIANGLES, 3, -1.9f, 1.2f, 1.2f, -2.0f);
        ring(GL_QUADS, 4, 1.8f, -0.2f, 1.0f, -3.0f);
        ring(GL_POLYGON, 6, 0.0f, 0.0f, 1.6f, -1.1f);
    }
    glPassThrough(9.0f);
    /* wholly outside */
    ring(GL_TRIANGLES, 3, 9.0f, 0.0f, 0.5f, -3.0f);
    glPassThrough(10.0f);
    glBegin(GL_LINES);
    colour(1); glVertex3f(-1.0f, -0.5f, -3.0f);
    colour(2); glVertex3f(0.7f, 0.6f, -3.5f);
    colour(3); glVertex3f(-3.0f, 0.0f, -3.0f);   /* crosses the left plane */
    colour(4); glVertex3f(0.2f, 0.1f, -2.5f);
    colour(5); glVertex3f(-9.0f, 0.0f, -3.0f);   /* wholly outside */
    colour(6); glVertex3f(-8.0f, 1.0f, -3.0f);
    colour(7); glVertex3f(0.3f, -0.3f, -3.0f);
    colour(8); glVertex3f(0.5f, 3.0f, -3.0f);    /* crosses the top plane */
    glEnd();
    glPassThrough(11.0f);
    ring(GL_LINE_STRIP, 5, 0.0f, 0.0f, 1.3f, -3.0f);
    glPassThrough(12.0f);
    ring(GL_LINE_LOOP, 4, 0.3f, 0.2f, 0.8f, -3.0f);
    ring(GL_LINE_LOOP, 2, 0.3f, 0.2f, 0.8f, -3.0f);
    ring(GL_LINE_STRIP, 2, -0.3f, 0.2f, 0.8f, -3.0f);
    glPassThrough(13.0f);
    ring(GL_POINTS, 5, 0.0f, 0.0f, 1.5f, -3.0f);
    glPassThrough(14.0f);
}

static void run_scene(GLenum type, const char *title, int clipped) {
    for (int i = 0; i < 4096; ++i) buf[i] = -777.0f;
    glFeedbackBuffer(4096, type, buf);
    fb_error("glFeedbackBuffer");
    glRenderMode(GL_FEEDBACK);
    fb_error("glRenderMode(GL_FEEDBACK)");
    scene(clipped);
    GLint n = glRenderMode(GL_RENDER);
    fb_error("glRenderMode(GL_RENDER)");
    fb_print_feedback(title, type, n, buf, 4096);
}

static void run(GLenum type, const char *title) { run_scene(type, title, 1); }

int main(void) {
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 6.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(7.0f, 0.2f, 1.0f, 0.1f);

    run(GL_2D, "2D smooth");
    run(GL_3D, "3D smooth");
    run(GL_3D_COLOR, "3D_COLOR smooth");
    run(GL_3D_COLOR_TEXTURE, "3D_COLOR_TEXTURE smooth");
    run(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE smooth");

    glShadeModel(GL_FLAT);
    run_scene(GL_3D_COLOR, "3D_COLOR flat", 0);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    run_scene(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE flat, first vertex", 0);
    glShadeModel(GL_SMOOTH);
    run(GL_3D_COLOR, "3D_COLOR smooth, first vertex");
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glShadeModel(GL_SMOOTH);

    glEnable(GL_CULL_FACE);
    run(GL_3D_COLOR, "3D_COLOR cull back");
    glCullFace(GL_FRONT);
    run(GL_3D_COLOR, "3D_COLOR cull front");
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);

    /* lit, two-sided: back faces report the back material's colour */
    static const GLfloat front[4] = {0.8f, 0.3f, 0.2f, 1.0f}, back[4] = {0.1f, 0.4f, 0.9f, 0.5f};
    static const GLfloat light[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back);
    glNormal3f(0.2f, 0.3f, 0.9f);
    run(GL_3D_COLOR, "3D_COLOR lit");
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    run(GL_3D_COLOR, "3D_COLOR lit two-sided");
    glEnable(GL_CULL_FACE);
    run(GL_3D_COLOR, "3D_COLOR lit two-sided, cull back");
    glDisable(GL_CULL_FACE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glDisable(GL_LIGHTING);

    glDepthRange(0.25, 0.75);
    glTexCoord4f(0.5f, 0.25f, -2.0f, 2.0f);
    run(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE depth range, texcoord");
    return fb_end();
}
