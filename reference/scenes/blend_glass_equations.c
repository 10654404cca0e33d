/* Glass spheres over a lit scene: a lit floor and lit opaque spheres, then
 * translucent lit spheres (depth test on, depth writes off) in each blend
 * equation: GL_FUNC_ADD with SRC_ALPHA / ONE_MINUS_SRC_ALPHA, additive
 * ONE / ONE, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX. */
#include "scene.h"
#include <GL/glu.h>

int main(int argc, char **argv)
{
    static const GLenum equations[6] = {GL_FUNC_ADD, GL_FUNC_ADD, GL_FUNC_SUBTRACT,
                                        GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    static const GLenum src[6] = {GL_SRC_ALPHA, GL_ONE, GL_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE, GL_ONE};
    static const GLenum dst[6] = {GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE};
    GLUquadric *q;
    int i;
    scene_begin(argc, argv, 192, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.9, 0.9, -0.6, 0.6, 1.5, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -0.3f, -5);
    glRotatef(20, 1, 0, 0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    {
        const GLfloat pos[4] = {2, 4, 3, 1}, spec[4] = {1, 1, 1, 1};
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    }
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    q = gluNewQuadric();
    /* floor: a checkerboard of lit quads */
    glNormal3f(0, 1, 0);
    glBegin(GL_QUADS);
    for (i = 0; i < 64; ++i) {
        int x = i % 8, z = i / 8;
        float x0 = -4 + x, z0 = -4 + z;
        if ((x + z) & 1) glColor3f(0.8f, 0.7f, 0.5f); else glColor3f(0.2f, 0.3f, 0.6f);
        glVertex3f(x0, -1, z0); glVertex3f(x0, -1, z0 + 1); glVertex3f(x0 + 1, -1, z0 + 1); glVertex3f(x0 + 1, -1, z0);
    }
    glEnd();
    /* opaque spheres behind the glass */
    for (i = 0; i < 3; ++i) {
        glPushMatrix();
        glTranslatef(-2 + 2 * i, -0.3f, -1.5f);
        glColor3f(i == 0, i == 1, i == 2 ? 1.0f : 0.3f);
        gluSphere(q, 0.7, 20, 14);
        glPopMatrix();
    }
    /* glass spheres, one per equation, depth test on, no depth writes */
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);
    {
        const GLfloat spec[4] = {1, 1, 1, 1};
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
    }
    for (i = 0; i < 6; ++i) {
        glBlendEquation(equations[i]);
        glBlendFunc(src[i], dst[i]);
        glPushMatrix();
        glTranslatef(-2.5f + i * 1.0f, (i & 1) ? 0.6f : -0.2f, 0.2f);
        glColor4f(0.3f + 0.1f * i, 0.9f - 0.12f * i, 0.6f, 0.35f + 0.08f * i);
        gluSphere(q, 0.55, 18, 12);
        glPopMatrix();
    }
    gluDeleteQuadric(q);
    scene_readpixels_check();
    return scene_end();
}
