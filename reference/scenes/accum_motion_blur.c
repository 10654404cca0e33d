/* Accumulation-buffer motion blur: a lit sphere drawn at eight positions
 * along its path, each frame added with GL_ACCUM 1/8 and the sum returned;
 * then GL_MULT fades the trail and GL_ADD lifts it (GL 2.1 §4.2.4). */
#include <string.h>

#include "light_common.h"

static void frame(float t)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(-1.2f + 2.4f * t, 0.3f * t, 0.0f);
    light_sphere(0.55f, 32, 16);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.0f, -0.9f, -0.5f);
    glRotatef(90.0f * t, 0.0f, 1.0f, 0.0f);
    glBegin(GL_QUADS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-0.4f, -0.25f, 0.0f);
    glVertex3f(0.4f, -0.25f, 0.0f);
    glVertex3f(0.4f, 0.25f, 0.0f);
    glVertex3f(-0.4f, 0.25f, 0.0f);
    glEnd();
    glPopMatrix();
}

int main(int argc, char **argv)
{
    scene_options o;
    memset(&o, 0, sizeof o);
    o.width = 160;
    o.height = 120;
    o.format = OSMESA_RGBA;
    o.depth_bits = 24;
    o.y_up = 1;
    scene_set_accum_bits(16);
    scene_begin_ext(argc, argv, &o);
    light_frustum(0.6f, 1.0f, 2.0f, 8.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.4f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.4f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    glTranslatef(0.0f, 0.0f, -4.5f);

    glClearColor(0.05f, 0.08f, 0.12f, 1.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_ACCUM_BUFFER_BIT);
    for (int i = 0; i < 8; ++i) {
        frame(i / 7.0f);
        glAccum(GL_ACCUM, 1.0f / 8.0f);
    }
    glAccum(GL_RETURN, 1.0f);
    /* The trail fades: the sum scaled, a newer frame loaded over part of it. */
    glAccum(GL_MULT, 0.6f);
    frame(1.0f);
    glAccum(GL_ACCUM, 0.4f);
    glAccum(GL_ADD, 0.02f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 80, 120);
    glAccum(GL_RETURN, 1.25f);
    glDisable(GL_SCISSOR_TEST);
    return scene_end();
}
