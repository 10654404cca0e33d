/* Fog with a positional light and a local viewer (the fog distance then
 * comes from lighting's eye position), GL_FLAT faces, smooth points and
 * lines, GL_LINE polygons and triangles cut by the near plane, in GL_EXP
 * fog of |z_eye| (GL 2.1 §3.10). */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 120);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.4, 0.4, -0.3, 0.3, 0.5, 30);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.2f, 0.2f, 0.25f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    const GLfloat fogColor[4] = {0.7f, 0.75f, 0.8f, 1};
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fogColor);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.1f);

    const GLfloat lamp[4] = {1, 2, -3, 1}, white[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, lamp);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    /* A smooth lit floor reaching behind the near plane (clipped). */
    glNormal3f(0, 1, 0);
    glColor3f(0.3f, 0.6f, 0.9f);
    glBegin(GL_TRIANGLES);
    glVertex3f(-4, -1, 1); glVertex3f(4, -1, 1); glVertex3f(0, -1, -28);
    glEnd();
    /* Flat-shaded lit boxes' faces at several depths. */
    glShadeModel(GL_FLAT);
    for (int i = 0; i < 5; ++i) {
        const float z = -2 - 4 * i, x = (i % 2 ? 0.8f : -0.8f);
        glColor3f(0.9f, 0.4f + 0.1f * i, 0.2f);
        glBegin(GL_QUADS);
        glNormal3f(0.3f, 0.2f, 1);
        glVertex3f(x - 0.4f, -0.8f, z); glVertex3f(x + 0.4f, -0.8f, z);
        glVertex3f(x + 0.4f, 0.2f, z - 0.5f); glVertex3f(x - 0.4f, 0.2f, z - 0.5f);
        glEnd();
    }
    glShadeModel(GL_SMOOTH);
    glDisable(GL_LIGHTING);
    /* GL_LINE polygons. */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 1, 0.3f);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.5f, 0.3f, -1.5f); glVertex3f(-0.5f, 0.3f, -12); glVertex3f(-1.2f, 1.2f, -6);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    /* Smooth lines and points, blended. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(1.5f);
    glBegin(GL_LINES);
    for (int i = 0; i < 6; ++i) {
        glColor3f(1, 0.3f, 0.3f); glVertex3f(0.5f + 0.2f * i, 1.0f, -1.5f);
        glColor3f(0.3f, 1, 0.3f); glVertex3f(0.3f + 0.3f * i, 0.2f, -20);
    }
    glEnd();
    glEnable(GL_POINT_SMOOTH);
    glPointSize(4);
    glBegin(GL_POINTS);
    for (int i = 0; i < 10; ++i) {
        glColor3f(0.4f, 0.9f, 1);
        glVertex3f(-2 + 0.4f * i, 1.1f, -1.5f - 2.5f * i);
    }
    glEnd();
    scene_readpixels_check();
    return scene_end();
}
