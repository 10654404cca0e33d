/* GL_POINT_SMOOTH at sizes 1 to 24 (the draw module's aapoint quad and
 * coverage shader: alpha is scaled up inside the disc, the rim keeps the
 * vertex alpha), alphas 1, 0.5 and 0.2, at pixel centres, corners and random
 * positions, flat and smooth, with depth test, and attenuated sizes. No
 * blending: the alpha the shader computes is what the buffer holds. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>

#include "scene.h"

#ifndef GL_POINT_SIZE_MIN
#include <GL/glext.h>
#endif

int main(int argc, char **argv)
{
    static const float sizes[] = {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 4.0f, 5.0f, 6.0f, 7.5f, 9.0f, 12.0f, 16.0f, 24.0f};
    static const float alphas[] = {1.0f, 0.5f, 0.2f};
    static const float offs[][2] = {{0.5f, 0.5f}, {0.0f, 0.0f}, {0.3f, 0.7f}};
    scene_begin(argc, argv, 256, 224);
    scene_ortho_pixels();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POINT_SMOOTH);

    for (int r = 0; r < 9; ++r) {
        glShadeModel((r & 1) ? GL_FLAT : GL_SMOOTH);
        for (int i = 0; i < 13; ++i) {
            glPointSize(sizes[i]);
            glBegin(GL_POINTS);
            glColor4f(0.2f + 0.06f * (float)i, 1.0f - 0.1f * (float)r, 0.6f, alphas[r % 3]);
            glVertex2f(10.0f + 19.0f * (float)i + offs[r / 3][0], 210.0f - 20.0f * (float)r + offs[r / 3][1]);
            glEnd();
        }
    }

    /* Random sizes and positions in one glBegin/glEnd per size. */
    scene_srand(11);
    for (int i = 0; i < 6; ++i) {
        glPointSize(scene_randf(0.5f, 10.0f));
        glBegin(GL_POINTS);
        for (int j = 0; j < 12; ++j) {
            glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0.2f, 1.0f));
            glVertex3f(scene_randf(8, 248), scene_randf(8, 36), scene_randf(-0.5f, 0.5f));
        }
        glEnd();
    }

    /* Attenuated smooth points: the radius is half the vertex's size. */
    {
        GLfloat att[3] = {0.5f, 0.0f, 0.0f};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glPointSize(3.0f);
        glBegin(GL_POINTS);
        glColor4f(1.0f, 0.9f, 0.2f, 0.75f);
        for (int i = 0; i < 8; ++i) glVertex2f(20.0f + 28.0f * (float)i + 0.25f * (float)i, 46.5f);
        glEnd();
    }

    /* In perspective (1/w is not 1: the shader's s, t are divided back per
     * fragment), a cloud of sizes 1 to 14 and alphas, depth-tested. */
    {
        GLfloat one[3] = {1.0f, 0.0f, 0.0f};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, one);
    }
    glViewport(0, 56, 256, 40);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.6, 1.6, -0.25, 0.25, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (int i = 0; i < 8; ++i) {
        glPointSize(1.0f + 1.7f * (float)i);
        glBegin(GL_POINTS);
        for (int j = 0; j < 10; ++j) {
            glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0.1f, 1.0f));
            float z = scene_randf(-12.0f, -1.5f);
            glVertex3f(scene_randf(-1.5f, 1.5f) * -z, scene_randf(-0.22f, 0.22f) * -z, z);
        }
        glEnd();
    }

    /* Bad sizes: NaN (radius NaN: nothing), 1e30 clamped to 255, then 1e30
     * with GL_POINT_SIZE_MAX 1e30 (a quad far larger than the buffer). */
    glViewport(0, 0, 256, 224);
    scene_ortho_pixels();
    glPointSize(NAN);
    glBegin(GL_POINTS);
    glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
    glVertex3f(128.0f, 50.0f, -0.95f);
    glEnd();
    glPointSize(1e30f);
    glBegin(GL_POINTS);
    glColor4f(0.3f, 0.3f, 0.9f, 0.6f);
    glVertex3f(100.0f, 100.0f, -0.99f);
    glEnd();
    glPointParameterf(GL_POINT_SIZE_MAX, 1e30f);
    glBegin(GL_POINTS);
    glColor4f(0.9f, 0.3f, 0.3f, 0.6f);
    glVertex3f(30.0f, 100.0f, -0.995f);
    glEnd();
    return scene_end();
}
