/* Accumulation-buffer antialiasing (the red book's jittered frustum): lit
 * intersecting spheres drawn eight times with sub-pixel jitter, the first
 * pass loaded with GL_LOAD, the rest added, the sum returned. */
#include <string.h>

#include "light_common.h"

static const float kJitter[8][2] = {
    {0.5625f, 0.4375f}, {0.0625f, 0.9375f}, {0.3125f, 0.6875f}, {0.6875f, 0.8125f},
    {0.8125f, 0.1875f}, {0.9375f, 0.5625f}, {0.4375f, 0.0625f}, {0.1875f, 0.3125f}};

static void spheres(void)
{
    glPushMatrix();
    glTranslatef(-0.45f, 0.1f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.3f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.3f, 0.2f, 1.0f);
    light_sphere(0.8f, 24, 12);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.5f, 0.0f, 0.2f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.7f, 0.9f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.7f, 0.9f, 1.0f);
    light_sphere(0.7f, 24, 12);
    glPopMatrix();
}

int main(int argc, char **argv)
{
    scene_options o;
    memset(&o, 0, sizeof o);
    o.width = 128;
    o.height = 128;
    o.format = OSMESA_BGRA;
    o.depth_bits = 24;
    o.y_up = 1;
    scene_set_accum_bits(16);
    scene_begin_ext(argc, argv, &o);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.12f, 0.12f, 0.12f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.85f, 0.85f, 0.85f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    for (int i = 0; i < 8; ++i) {
        /* The frustum moved by a fraction of a pixel: 2 units over 128 pixels at the near plane. */
        const float dx = (kJitter[i][0] - 0.5f) * 1.2f / 128.0f, dy = (kJitter[i][1] - 0.5f) * 1.2f / 128.0f;
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.6f + dx, 0.6f + dx, -0.6f + dy, 0.6f + dy, 2.0f, 8.0f);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.0f, 0.0f, -4.5f);
        glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        spheres();
        glAccum(i == 0 ? GL_LOAD : GL_ACCUM, 1.0f / 8.0f);
    }
    glAccum(GL_RETURN, 1.0f);
    return scene_end();
}
