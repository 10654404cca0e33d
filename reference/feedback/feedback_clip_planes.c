/*
 * feedback_clip_planes: triangles, quads, lines and points cut by user clip
 * planes (set under different modelview matrices, after the projection) in
 * GL_FEEDBACK, smooth and flat, and the same primitives in GL_SELECT; the
 * draw module clips against the user planes after the six frustum planes.
 */
#include "fb_common.h"

enum { W = 96, H = 72 };
static GLfloat buf[8192];
static GLuint sel[512];

static void colour(int i) {
    glColor4f(0.15f + 0.08f * (i % 9), 0.85f - 0.1f * (i % 7), 0.2f + 0.07f * (i % 5), 1.0f);
}

/* Under GL_FLAT Mesa leaves the colours of the vertices the clipper makes
 * for a polygon uninitialised (MESA_FACTS.md): flat runs draw only lines
 * and points. */
static void scene(int flat) {
    int i;
    glPassThrough(1.0f);
    if (!flat) {
        glBegin(GL_TRIANGLES);
        colour(0); glVertex3f(-0.9f, -0.7f, -3.0f);
        colour(1); glVertex3f(0.8f, -0.6f, -3.4f);
        colour(2); glVertex3f(0.1f, 0.8f, -2.8f);
        glEnd();
        glPassThrough(2.0f);
        glBegin(GL_QUADS);
        colour(3); glVertex3f(-0.6f, -0.2f, -3.0f);
        colour(4); glVertex3f(0.5f, -0.3f, -3.0f);
        colour(5); glVertex3f(0.6f, 0.5f, -3.2f);
        colour(6); glVertex3f(-0.5f, 0.4f, -3.1f);
        glEnd();
        glPassThrough(3.0f);
        glBegin(GL_TRIANGLE_FAN);
        for (i = 0; i < 7; ++i) {
            colour(i + 2);
            glVertex3f(0.9f * (float)(i % 3) - 0.9f, 0.6f * (float)(i / 3) - 0.6f, -3.0f - 0.1f * (float)i);
        }
        glEnd();
    }
    glPassThrough(4.0f);
    glBegin(GL_LINES);
    colour(1); glVertex3f(-1.0f, 0.0f, -3.0f);
    colour(2); glVertex3f(1.0f, 0.1f, -3.0f);
    colour(3); glVertex3f(-0.2f, -0.9f, -3.0f);
    colour(4); glVertex3f(0.3f, 0.9f, -3.0f);
    glEnd();
    glPassThrough(5.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 9; ++i) {
        colour(i);
        glVertex3f(0.22f * (float)i - 0.9f, 0.15f * (float)(i % 4) - 0.2f, -3.0f);
    }
    glEnd();
    glPassThrough(6.0f);
}

static void run_feedback(GLenum type, const char *title, int flat) {
    int i;
    for (i = 0; i < 8192; ++i) buf[i] = -777.0f;
    glFeedbackBuffer(8192, type, buf);
    glRenderMode(GL_FEEDBACK);
    scene(flat);
    GLint n = glRenderMode(GL_RENDER);
    fb_error("glRenderMode(GL_RENDER)");
    fb_print_feedback(title, type, n, buf, 8192);
}

static void run_select(const char *title) {
    glSelectBuffer(512, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    scene(0);
    glLoadName(2);
    glBegin(GL_TRIANGLES); /* wholly outside plane 0: no hit */
    glVertex3f(-0.9f, -0.1f, -3.0f);
    glVertex3f(-0.8f, 0.1f, -3.0f);
    glVertex3f(-0.95f, 0.1f, -3.0f);
    glEnd();
    GLint hits = glRenderMode(GL_RENDER);
    fb_print_select(title, hits, sel, 512);
}

int main(void) {
    const GLdouble right_of[4] = {1.0, 0.0, 0.0, 0.35};
    const GLdouble tilted[4] = {0.3, -1.0, 0.0, 0.3};
    const GLdouble depth_cut[4] = {0.0, 0.0, -1.0, -3.05};
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.4, 0.4, 1.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glClipPlane(GL_CLIP_PLANE0, right_of);
    glLoadIdentity();
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glClipPlane(GL_CLIP_PLANE0 + 6, tilted);
    glLoadIdentity();
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE0 + 6);

    run_feedback(GL_3D_COLOR, "3D_COLOR two planes", 0);
    run_feedback(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE two planes", 0);
    glClipPlane(GL_CLIP_PLANE3, depth_cut);
    glEnable(GL_CLIP_PLANE3);
    run_feedback(GL_3D_COLOR, "3D_COLOR three planes", 0);
    glShadeModel(GL_FLAT);
    run_feedback(GL_3D_COLOR, "3D_COLOR flat, lines and points", 1);
    glShadeModel(GL_SMOOTH);
    run_select("three planes");
    /* A new projection moves the clip-space planes with it. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.7, 0.6, -0.5, 0.45, 1.5, 7.0);
    glMatrixMode(GL_MODELVIEW);
    run_feedback(GL_3D_COLOR, "3D_COLOR after a projection change", 0);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE3);
    glDisable(GL_CLIP_PLANE0 + 6);
    run_feedback(GL_3D, "3D no planes", 0);
    return fb_end();
}
