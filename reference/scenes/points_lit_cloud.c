/* A lit point cloud in perspective: points on spheres and in a random cloud,
 * several fractional sizes (1, 1.5, 2.5, 2.51, 3.5, 4, 6.49), flat and smooth
 * shading, two lights (one positional), separate specular on part of it,
 * depth test on, so nearer points hide farther ones. */
#include <math.h>

#include "light_common.h"

static void sphere_points(float cx, float cy, float cz, float r, int rings, int segs)
{
    glBegin(GL_POINTS);
    for (int i = 1; i < rings; ++i) {
        float th = 3.14159265f * (float)i / (float)rings;
        for (int j = 0; j < segs; ++j) {
            float ph = 6.2831853f * (float)j / (float)segs;
            float nx = sinf(th) * cosf(ph), ny = cosf(th), nz = sinf(th) * sinf(ph);
            glNormal3f(nx, ny, nz);
            glVertex3f(cx + r * nx, cy + r * ny, cz + r * nz);
        }
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static const float sizes[] = {1.0f, 1.5f, 2.5f, 2.51f, 3.5f, 4.0f, 6.49f};
    scene_begin(argc, argv, 192, 160);
    light_frustum(0.6f, 1.2f, 2.0f, 12.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.7f, 0.6f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.6f, 1.0f, 0.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.4f, 0.9f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 2.0f, -1.0f, -3.0f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.3f, 0.3f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.7f, 0.6f, 0.5f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
    glTranslatef(0.0f, 0.0f, -6.0f);

    for (int k = 0; k < 7; ++k) {
        glPointSize(sizes[k]);
        glShadeModel((k & 1) ? GL_FLAT : GL_SMOOTH);
        float x = -2.4f + 0.8f * (float)k;
        sphere_points(x, (k & 1) ? 0.9f : -0.9f, -0.3f * (float)k, 0.55f, 9, 18);
    }

    /* A random cloud, sizes cycling, with separate specular. */
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    scene_srand(7);
    for (int k = 0; k < 7; ++k) {
        glPointSize(sizes[6 - k]);
        glShadeModel((k & 1) ? GL_SMOOTH : GL_FLAT);
        glBegin(GL_POINTS);
        for (int i = 0; i < 60; ++i) {
            float nx = scene_randf(-1, 1), ny = scene_randf(-1, 1), nz = scene_randf(0, 1);
            glNormal3f(nx, ny, nz);
            glVertex3f(scene_randf(-3.0f, 3.0f), scene_randf(-2.2f, 2.2f), scene_randf(-4.0f, 3.0f));
        }
        glEnd();
    }

    /* Unlit points with per-vertex colours, behind and in front of the rest. */
    glDisable(GL_LIGHTING);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 200; ++i) {
        glColor3f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1));
        glVertex3f(scene_randf(-3.0f, 3.0f), scene_randf(-2.2f, 2.2f), scene_randf(-5.0f, 3.5f));
    }
    glEnd();
    return scene_end();
}
