/* The drawing of the osmesa_*_lit scenes: lit smooth-shaded spheres with the
 * depth test, a blended translucent sphere and quads over them, alpha-tested
 * quads, smooth lines and points, a glBitmap, a clear of part of the buffer
 * through the scissor and a colour mask, drawn into an OSMesa buffer of
 * `type` (GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT or GL_FLOAT). */
#include "light_common.h"

static inline int osmesa_buffer_scene(int argc, char **argv, GLenum format, GLenum type, int accum)
{
    static const GLubyte heart[16] = {0x00, 0x00, 0x10, 0x08, 0x38, 0x1c, 0x7c, 0x3e,
                                      0xfe, 0x7f, 0xfe, 0x7f, 0xfe, 0x7f, 0x7c, 0x3e};
    scene_options o = {160, 128, format, 24, 1, 0};
    int i;
    scene_set_buffer_type(type);
    if (accum) scene_set_accum_bits(16);
    if (scene_begin_try(argc, argv, &o) != 0) return scene_end();

    /* A clear of a corner through the scissor with red and alpha masked. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(120, 96, 40, 32);
    glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
    glClearColor(0.9f, 0.41f, 0.77f, 0.3f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.25, 1.25, -1.0, 1.0, -2.0, 2.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.6f, 1.0f, 0.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.85f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_model_ambient(0.15f, 0.15f, 0.2f, 1.0f);
    for (i = 0; i < 3; i++) {
        glPushMatrix();
        glTranslatef(-0.7f + 0.7f * i, -0.3f + 0.25f * (i % 2), -0.2f * i);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.3f + 0.3f * i, 0.8f - 0.2f * i, 0.4f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 12.0f + 20.0f * i);
        light_sphere(0.42f, 24, 16);
        glPopMatrix();
    }
    /* A translucent lit sphere blended over them. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glPushMatrix();
    glTranslatef(0.15f, 0.2f, 0.8f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 0.45f);
    light_sphere(0.38f, 20, 12);
    glPopMatrix();
    glDisable(GL_LIGHTING);
    /* Additive and modulating quads. */
    glBlendFunc(GL_ONE, GL_ONE);
    glBegin(GL_QUADS);
    glColor4f(0.2f, 0.1f, 0.05f, 0.5f); glVertex3f(-1.2f, 0.5f, 1.0f);
    glColor4f(0.05f, 0.2f, 0.1f, 0.5f); glVertex3f(-0.4f, 0.5f, 1.0f);
    glColor4f(0.1f, 0.05f, 0.3f, 0.5f); glVertex3f(-0.4f, 0.95f, 1.0f);
    glColor4f(0.3f, 0.3f, 0.3f, 0.5f); glVertex3f(-1.2f, 0.95f, 1.0f);
    glEnd();
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.6f, 0.3f); glVertex3f(0.5f, -0.95f, 1.0f);
    glColor3f(0.3f, 0.9f, 0.6f); glVertex3f(1.2f, -0.95f, 1.0f);
    glColor3f(0.6f, 0.3f, 0.9f); glVertex3f(1.2f, -0.5f, 1.0f);
    glColor3f(0.8f, 0.8f, 0.8f); glVertex3f(0.5f, -0.5f, 1.0f);
    glEnd();
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_TRUE);
    /* Smooth lines and points, blended. */
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(1.5f);
    glBegin(GL_LINES);
    for (i = 0; i < 6; i++) {
        glColor4f(1.0f, 0.2f * i, 0.1f, 0.9f); glVertex3f(-1.2f, -0.9f + 0.07f * i, 1.5f);
        glColor4f(0.1f, 0.9f, 0.2f * i, 0.9f); glVertex3f(-0.2f, -0.6f + 0.11f * i, 1.5f);
    }
    glEnd();
    glDisable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) {
        glColor4f(0.1f * i, 1.0f - 0.1f * i, 0.5f, 1.0f);
        glVertex3f(0.3f + 0.1f * i, 0.8f, 1.5f);
    }
    glEnd();
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_BLEND);
    /* Alpha-tested quads: alpha sweeps across GL_GREATER 0.5. */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.9f, 0.2f, 0.0f); glVertex3f(0.55f, 0.3f, 1.2f);
    glColor4f(0.9f, 0.5f, 0.2f, 1.0f); glVertex3f(1.2f, 0.3f, 1.2f);
    glColor4f(0.9f, 0.5f, 0.2f, 1.0f); glVertex3f(1.2f, 0.6f, 1.2f);
    glColor4f(0.9f, 0.9f, 0.2f, 0.0f); glVertex3f(0.55f, 0.6f, 1.2f);
    glEnd();
    glDisable(GL_ALPHA_TEST);
    /* A bitmap in a flat colour, and a quad with blue masked. */
    glColor3f(0.95f, 0.25f, 0.45f);
    glRasterPos3f(-1.1f, 0.0f, 1.9f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(16, 8, 0, 0, 18, 0, heart);
    glBitmap(16, 8, 0, 0, 18, 0, heart);
    glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.7f, 0.2f, 0.9f); glVertex3f(-0.3f, -0.95f, 1.8f);
    glColor3f(0.2f, 0.7f, 0.9f); glVertex3f(0.3f, -0.95f, 1.8f);
    glColor3f(0.9f, 0.9f, 0.9f); glVertex3f(0.0f, -0.7f, 1.8f);
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (accum) {
        /* The picture accumulated at 0.5, then a darker copy added, returned at 1.2. */
        glAccum(GL_LOAD, 0.5f);
        glAccum(GL_ACCUM, 0.25f);
        glAccum(GL_RETURN, 1.2f);
    }
    scene_readpixels_check();
    return scene_end();
}
