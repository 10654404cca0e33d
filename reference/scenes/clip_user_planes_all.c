/* All eight user clip planes at once on smooth quads and triangles (an octagon cut, planes under a perspective projection and a scaled modelview), then planes with NaN, infinite and zero coefficients, and a plane that leaves a vertex exactly on it. */
#include "scene.h"
#include <math.h>

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.2f, 0.1f); glVertex3f(x0, y0, z);
    glColor3f(0.1f, 1.0f, 0.2f); glVertex3f(x1, y0, z);
    glColor3f(0.2f, 0.1f, 1.0f); glVertex3f(x1, y1, z);
    glColor3f(0.9f, 0.9f, 0.3f); glVertex3f(x0, y1, z);
    glEnd();
}

static void enable_all(int on)
{
    int i;
    for (i = 0; i < 8; ++i) {
        if (on) glEnable(GL_CLIP_PLANE0 + i);
        else glDisable(GL_CLIP_PLANE0 + i);
    }
}

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 160, 160);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.5, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);

    /* Top left: an octagon from eight planes around (-0.8, 0.8). */
    glPushMatrix();
    glTranslatef(-0.8f, 0.8f, 0.0f);
    for (i = 0; i < 8; ++i) {
        const double a = i * 3.14159265358979 / 4.0 + 0.2;
        GLdouble eq[4];
        eq[0] = -cos(a); eq[1] = -sin(a); eq[2] = 0.0; eq[3] = 0.55;
        glClipPlane(GL_CLIP_PLANE0 + i, eq);
    }
    enable_all(1);
    quad(-0.75f, -0.7f, 0.7f, 0.75f, 0.1f);
    glPopMatrix();

    /* Top right: the same planes under a scaled, rotated modelview (set
       again there), on triangles that reach behind the near plane too. */
    glPushMatrix();
    glTranslatef(0.8f, 0.8f, 0.0f);
    glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
    glScalef(1.3f, 0.8f, 1.0f);
    for (i = 0; i < 8; ++i) {
        const double a = i * 3.14159265358979 / 4.0;
        GLdouble eq[4];
        eq[0] = -cos(a); eq[1] = -sin(a); eq[2] = 0.1 * i; eq[3] = 0.5;
        glClipPlane(GL_CLIP_PLANE0 + i, eq);
    }
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1); glVertex3f(-0.6f, -0.6f, 0.0f);
    glColor3f(1, 0, 0); glVertex3f(0.6f, -0.5f, 2.9f);
    glColor3f(0, 0, 1); glVertex3f(0.1f, 0.7f, 0.2f);
    glEnd();
    glPopMatrix();
    enable_all(0);

    /* Bottom left: NaN, infinite and all-zero planes. A zero plane keeps
       everything (0 >= 0); a NaN or infinite one drops what it touches. */
    {
        const GLdouble zero[4] = {0.0, 0.0, 0.0, 0.0};
        const GLdouble nan_plane[4] = {NAN, 0.0, 0.0, 1.0};
        const GLdouble inf_plane[4] = {0.0, INFINITY, 0.0, 0.0};
        const GLdouble zero_x[4] = {0.0, 0.0, 0.0, 1.0};
        glClipPlane(GL_CLIP_PLANE2, zero);
        glEnable(GL_CLIP_PLANE2);
        quad(-1.15f, -1.15f, -0.85f, -0.85f, 0.0f);
        glDisable(GL_CLIP_PLANE2);
        glClipPlane(GL_CLIP_PLANE5, nan_plane);
        glEnable(GL_CLIP_PLANE5);
        quad(-0.75f, -1.15f, -0.45f, -0.85f, 0.0f);
        glDisable(GL_CLIP_PLANE5);
        glClipPlane((GL_CLIP_PLANE0 + 7), inf_plane);
        glEnable((GL_CLIP_PLANE0 + 7));
        quad(-1.15f, -0.75f, -0.85f, -0.45f, 0.0f);
        glDisable((GL_CLIP_PLANE0 + 7));
        glClipPlane((GL_CLIP_PLANE0 + 6), zero_x);
        glEnable((GL_CLIP_PLANE0 + 6));
        quad(-0.75f, -0.75f, -0.45f, -0.45f, 0.0f);
        glDisable((GL_CLIP_PLANE0 + 6));
    }

    /* Bottom right: a plane through a vertex (distance exactly 0 keeps it),
       and one whose fused and unfused distances at a vertex differ in sign
       (llvmpipe's clip mask uses the fused one: the quad is drawn through
       the draw pipeline, split (0,1,3)(1,2,3), but not cut). */
    glLoadIdentity();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    {
        const float cz = 0.5f + ldexpf(1.0f, -13) + ldexpf(1.0f, -24);
        const float pz = 1.0f + ldexpf(1.0f, -12);
        const float q = -(1.0f + ldexpf(1.0f, -11) + ldexpf(1.0f, -22)) / 2;
        GLdouble eq[4];
        const GLdouble through[4] = {1.0, 0.0, 0.0, -0.1};
        eq[0] = 2.0 * q; eq[1] = 0.0; eq[2] = pz; eq[3] = 0.0;
        glClipPlane(GL_CLIP_PLANE3, eq);
        glEnable(GL_CLIP_PLANE3);
        glBegin(GL_QUADS);
        glColor3f(1, 0, 0); glVertex3f(0.5f, -0.5f, cz);
        glColor3f(0, 1, 0); glVertex3f(0.5f, -0.1f, 0.6f);
        glColor3f(0, 0, 1); glVertex3f(0.1f, -0.1f, 0.6f);
        glColor3f(1, 1, 1); glVertex3f(0.1f, -0.5f, 0.6f);
        glEnd();
        glDisable(GL_CLIP_PLANE3);
        glClipPlane(GL_CLIP_PLANE4, through);
        glEnable(GL_CLIP_PLANE4);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 1, 0); glVertex3f(0.1f, -0.6f, 0.0f);
        glColor3f(0, 1, 1); glVertex3f(0.9f, -0.9f, 0.0f);
        glColor3f(1, 0, 1); glVertex3f(0.7f, -0.55f, 0.0f);
        glEnd();
        glDisable(GL_CLIP_PLANE4);
    }
    scene_readpixels_check();
    return scene_end();
}
