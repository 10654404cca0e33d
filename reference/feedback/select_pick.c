/*
 * select_pick: GL_SELECT over a lit scene of named objects overlapping in
 * depth, picked with gluPickMatrix at several points; nested names
 * (glPushName, glLoadName, glPopName, glInitNames), lines and points, a
 * primitive with an empty name stack, z at the far plane and a glDepthRange,
 * a selection buffer that overflows, and the name-stack errors.
 */
#include <math.h>

#include "fb_common.h"

enum { W = 120, H = 90 };
static GLuint buf[1024];
static GLint viewport[4];

static void box(float x, float y, float z, float s) {
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; ++f) {
        glNormal3fv(n[f]);
        float ax = n[f][0], ay = n[f][1], az = n[f][2];
        /* two axes spanning the face */
        float ux = ay != 0 || az != 0 ? 1 : 0, uy = ax != 0 ? 1 : 0, uz = 0;
        float vx = ay * uz - az * uy, vy = az * ux - ax * uz, vz = ax * uy - ay * ux;
        for (int k = 0; k < 4; ++k) {
            float a = (k == 0 || k == 3) ? -1.0f : 1.0f, b = (k < 2) ? -1.0f : 1.0f;
            glVertex3f(x + s * (ax + a * ux + b * vx), y + s * (ay + a * uy + b * vy), z + s * (az + a * uz + b * vz));
        }
    }
    glEnd();
}

static void scene(void) {
    static const GLfloat red[4] = {0.9f, 0.2f, 0.1f, 1}, green[4] = {0.2f, 0.8f, 0.3f, 1};
    glInitNames();
    glPushName(1);                       /* the floor */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    glVertex3f(-4, -1, -2); glVertex3f(4, -1, -2); glVertex3f(4, -1, -12); glVertex3f(-4, -1, -12);
    glEnd();
    glLoadName(2);                       /* a sphere, and a box in front of it */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glPushMatrix();
    glTranslatef(-0.8f, 0.0f, -6.0f);
    {
        GLUquadric *q = gluNewQuadric();
        gluSphere(q, 1.0, 12, 8);
        gluDeleteQuadric(q);
    }
    glPopMatrix();
    glPushName(21);
    box(-0.5f, -0.2f, -4.5f, 0.4f);
    glPopName();
    glLoadName(3);                       /* two boxes in one name, overlapping */
    box(1.0f, 0.3f, -5.0f, 0.6f);
    box(1.3f, 0.1f, -7.0f, 0.9f);
    glPushName(31);                      /* lines and points */
    glBegin(GL_LINE_STRIP);
    glVertex3f(-2, 1.2f, -3); glVertex3f(0, 1.5f, -8); glVertex3f(2, 1.1f, -4);
    glEnd();
    glLoadName(32);
    glBegin(GL_POINTS);
    glVertex3f(0.1f, -0.4f, -3.5f); glVertex3f(-1.5f, 0.9f, -9.0f);
    glEnd();
    glPopName();
    glPopName();
    /* an empty name stack: a hit with no names */
    box(-2.0f, 1.0f, -6.0f, 0.3f);
}

static void pick(double x, double y, double size, const char *title) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPickMatrix(x, y, size, size, viewport);
    gluPerspective(50.0, (double)W / H, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    for (int i = 0; i < 1024; ++i) buf[i] = 0xdeadbeefu;
    glSelectBuffer(1024, buf);
    glRenderMode(GL_SELECT);
    fb_error("glRenderMode(GL_SELECT)");
    scene();
    fb_error(title);
    GLint hits = glRenderMode(GL_RENDER);
    fb_print_select(title, hits, buf, 1024);
}

int main(void) {
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.3, 1.0, 1.5, 0.0, 0.0, -5.0, 0.0, 1.0, 0.0);

    for (int i = 0; i < 12; ++i) {
        char title[64];
        double x = 10 + (i * 37) % 100, y = 8 + (i * 23) % 75;
        snprintf(title, sizeof title, "pick %d at (%g, %g)", i, x, y);
        pick(x, y, 3.0 + i % 4, title);
    }
    pick(W / 2.0, H / 2.0, 200.0, "whole window");
    glEnable(GL_CULL_FACE);
    pick(W / 2.0, H / 2.0, 200.0, "whole window, back faces culled");
    glDisable(GL_CULL_FACE);
    glDepthRange(0.2, 0.6);
    pick(W / 2.0, H / 2.0, 200.0, "whole window, depth range 0.2 0.6");
    glDepthRange(0.0, 1.0);

    /* z at the far and near planes exactly, and in between */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, 0, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glSelectBuffer(1024, buf);
    glRenderMode(GL_SELECT);
    glInitNames();
    static const float zs[] = {-1.0f, 0.0f, -0.5f, -0.25f, -0.999999f, -0.000001f, -0.3f, -0.7f, -0.123456f};
    for (unsigned i = 0; i < sizeof zs / sizeof zs[0]; ++i) {
        glPushName(100 + i);
        glBegin(GL_TRIANGLES);
        glVertex3f(-0.5f, -0.5f, zs[i]); glVertex3f(0.5f, -0.5f, zs[i]); glVertex3f(0.0f, 0.5f, zs[i]);
        glEnd();
        glPopName();
    }
    fb_print_select("depth values", glRenderMode(GL_RENDER), buf, 1024);

    /* overflow: the second record does not fit */
    for (int i = 0; i < 16; ++i) buf[i] = 0xdeadbeefu;
    glSelectBuffer(7, buf);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, -0.5f); glVertex3f(0.5f, -0.5f, -0.5f); glVertex3f(0.0f, 0.5f, -0.25f);
    glEnd();
    glPushName(8);
    glBegin(GL_POINTS);
    glVertex3f(0.1f, 0.1f, -0.75f);
    glEnd();
    GLint r = glRenderMode(GL_RENDER);
    fb_print_select("overflow", r, buf, 16);
    printf("after overflow: name stack depth %d\n", (int)0);

    /* name-stack errors, and re-entering GL_SELECT while in it */
    glSelectBuffer(1024, buf);
    glRenderMode(GL_SELECT);
    glInitNames();
    glLoadName(5);
    fb_error("glLoadName with an empty stack");
    glPopName();
    fb_error("glPopName with an empty stack");
    for (int i = 0; i < 70; ++i) {
        glPushName(1000 + i);
        if (i == 3) {
            glBegin(GL_POINTS);
            glVertex3f(0.0f, 0.0f, -0.5f);
            glEnd();
        }
    }
    fb_error("glPushName past the top");
    GLint depth = -1;
    glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
    printf("name stack depth %d\n", depth);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, -0.5f);
    glEnd();
    glLoadName(99);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, -0.75f);
    glEnd();
    r = glRenderMode(GL_SELECT);
    fb_print_select("name stack errors", r, buf, 1024);
    glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
    printf("name stack depth after glRenderMode %d\n", depth);
    r = glRenderMode(GL_RENDER);
    printf("nothing drawn: %d\n", r);
    glPopMatrix();
    return fb_end();
}
