/* Fog after texturing and the colour sum (GL 2.1 §3.10), then blending: a
 * modulated, mipmapped checker floor with separate specular lighting receding
 * in GL_EXP2 fog, and GL_LINEAR-fogged translucent quads blended over it;
 * lines and points in fog too. */
#include "scene.h"

static GLubyte tex[32 * 32 * 4];

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 128);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            GLubyte *p = tex + 4 * (y * 32 + x);
            const int on = ((x >> 2) ^ (y >> 2)) & 1;
            p[0] = on ? 230 : 40; p[1] = on ? 210 : 90; p[2] = on ? 120 : 160; p[3] = 255;
        }
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);

    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.5, 0.5, -0.4, 0.4, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.5f, 0.5f, 0.55f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    const GLfloat fogColor[4] = {0.6f, 0.62f, 0.66f, 1};
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fogColor);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.08f);

    const GLfloat light[4] = {0.2f, 1, 0.6f, 0}, spec[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 12);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glNormal3f(0, 1, 0);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(-6, -1, -1);
    glTexCoord2f(6, 0); glVertex3f(6, -1, -1);
    glTexCoord2f(6, 12); glVertex3f(6, -1, -38);
    glTexCoord2f(0, 12); glVertex3f(-6, -1, -38);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);

    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 25);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (int i = 0; i < 5; ++i) {
        const float z = -3 - 4.5f * i, x = -1.2f + 0.6f * i;
        glBegin(GL_TRIANGLES);
        glColor4f(1, 0.2f, 0.1f * i, 0.6f); glVertex3f(x - 0.5f, -0.6f, z);
        glColor4f(0.1f, 1, 0.3f, 0.4f); glVertex3f(x + 0.5f, -0.6f, z - 1);
        glColor4f(0.2f, 0.3f, 1, 0.8f); glVertex3f(x, 0.6f, z - 0.5f);
        glEnd();
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);

    /* Lines and points in GL_EXP fog with the radial distance. */
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.12f);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    glLineWidth(2);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; ++i) {
        glColor3f(1, 1, 0.2f);
        glVertex3f(-3 + 0.8f * i, 0.9f, -2);
        glColor3f(0.2f, 0.2f, 1);
        glVertex3f(-3 + 0.8f * i, 0.4f, -30);
    }
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; ++i) {
        glColor3f(1, 0.5f, 1);
        glVertex3f(2.5f - 0.3f * i, 1.2f - 0.05f * i, -2 - 2.5f * i);
    }
    glEnd();
    scene_readpixels_check();
    return scene_end();
}
