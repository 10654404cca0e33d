/* polygon_torus.h - a lit torus of quad strips, normals per vertex, for the
 * polygon mode scenes. */
#ifndef POLYGON_TORUS_H
#define POLYGON_TORUS_H
#include <math.h>

#include "scene.h"

static inline void polygon_torus(float major, float minor, int rings, int sides)
{
    int i, j, k;
    const float pi2 = 6.28318530718f;
    for (i = 0; i < rings; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= sides; j++) {
            for (k = 1; k >= 0; k--) {
                float s = (float)((i + k) % rings) / (float)rings * pi2;
                float t = (float)(j % sides) / (float)sides * pi2;
                float cx = cosf(s), cy = sinf(s);
                float nx = cosf(t) * cx, ny = cosf(t) * cy, nz = sinf(t);
                glNormal3f(nx, ny, nz);
                glVertex3f(major * cx + minor * nx, major * cy + minor * ny, minor * nz);
            }
        }
        glEnd();
    }
}

static inline void polygon_torus_view(void)
{
    static const float light[4] = {0.5f, 0.8f, 1.0f, 0};
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 2, 12);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5.5f);
    glRotatef(62, 1, 0.3f, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_DEPTH_TEST);
}
#endif
