/*
 * feedback_batches: how immediate mode's draws reach the feedback buffer.
 * Consecutive glBegin/glEnd pairs that Mesa merges into one draw, a glColor
 * that grows the vertex format in the middle of a glBegin (one glBegin cut
 * into two draws), glMaterial between glBegin and glEnd, and primitives long
 * enough for Mesa's draw module to run them in segments (a 1100-vertex fan,
 * a 4200-vertex strip), partly outside the view volume.
 */
#include <math.h>

#include "fb_common.h"

enum { W = 64, H = 48 };
static GLfloat buf[1 << 17];

static void scene(void) {
    glColor3f(0.5f, 0.25f, 0.75f);
    for (int k = 0; k < 3; ++k) { /* merged: one draw */
        glBegin(GL_TRIANGLES);
        glVertex2f(-0.9f + 0.3f * k, -0.9f); glVertex2f(-0.7f + 0.3f * k, -0.9f); glVertex2f(-0.8f + 0.3f * k, -0.6f);
        glEnd();
    }
    glPassThrough(1.0f);
    glBegin(GL_QUADS); /* the colour grows the vertex format mid-glBegin */
    glVertex2f(0.1f, 0.1f); glVertex2f(0.4f, 0.1f); glVertex2f(0.4f, 0.4f); glVertex2f(0.1f, 0.4f);
    glVertex2f(0.5f, 0.1f); glVertex2f(0.8f, 0.1f);
    glColor3f(0.9f, 0.1f, 0.1f);
    glVertex2f(0.8f, 0.4f); glVertex2f(1.3f, 0.4f);
    glEnd();
    glPassThrough(2.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBegin(GL_TRIANGLE_STRIP); /* glMaterial inside glBegin/glEnd */
    for (int i = 0; i < 6; ++i) {
        GLfloat d[4] = {0.1f * i, 0.9f - 0.1f * i, 0.5f, 1.0f};
        glMaterialfv(GL_FRONT, GL_DIFFUSE, d);
        glNormal3f(0.1f * i, 0.2f, 1.0f);
        glVertex2f(-0.9f + 0.2f * (i / 2), 0.2f + 0.3f * (i % 2));
    }
    glEnd();
    glDisable(GL_LIGHTING);
    glPassThrough(3.0f);
    glBegin(GL_TRIANGLE_FAN); /* segments of 1024 vertices */
    glColor3f(0.2f, 0.8f, 0.4f);
    glVertex2f(0.0f, 0.0f);
    for (int i = 0; i < 1099; ++i) {
        float a = 6.2831853f * (float)i / 1098.0f;
        glColor3f(0.5f + 0.5f * cosf(a), 0.5f, 0.5f + 0.5f * sinf(3.0f * a));
        glVertex2f(1.3f * cosf(a), 1.1f * sinf(a));
    }
    glEnd();
    glPassThrough(4.0f);
    glBegin(GL_TRIANGLE_STRIP); /* segments of 4096 vertices */
    for (int i = 0; i < 4200; ++i) {
        float x = -1.2f + 2.4f * (float)(i / 2) / 2100.0f;
        glColor3f((float)(i % 7) / 7.0f, (float)(i % 5) / 5.0f, 0.5f);
        glVertex2f(x, -0.2f + 0.1f * (float)(i % 2) + 0.3f * sinf(9.0f * x));
    }
    glEnd();
    glPassThrough(5.0f);
}

int main(void) {
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glFeedbackBuffer(1 << 17, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    scene();
    fb_print_feedback("batches", GL_3D_COLOR, glRenderMode(GL_RENDER), buf, 1 << 17);
    glShadeModel(GL_FLAT);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glFeedbackBuffer(1 << 17, GL_2D, buf);
    glRenderMode(GL_FEEDBACK);
    scene();
    fb_print_feedback("batches, flat, first vertex, 2D", GL_2D, glRenderMode(GL_RENDER), buf, 1 << 17);
    return fb_end();
}
