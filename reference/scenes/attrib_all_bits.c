/* glPushAttrib(GL_ALL_ATTRIB_BITS) around objects that change nearly every
 * group the library holds: viewport and depth range, matrix mode, normalize,
 * the current colour and normal, colour material, lights set under another
 * modelview (their eye-space positions come back as stored), colour mask,
 * clear colour. Objects drawn between the pops use the restored state; nested
 * pushes give back each level. */
#include "light_common.h"

static void lit_base(void)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.8f, 0.7f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.4f, 0.7f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.5f, 0.5f, 0.7f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.5f, 0.7f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 128);
    glViewport(0, 0, 192, 128);
    light_ortho(1.0f, 1.5f);
    lit_base();
    glColor3f(0.9f, 0.5f, 0.2f);

    /* 1: a sphere in its own small viewport, colour material from a new
     * current colour, a point light placed under a rotated modelview. */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glViewport(8, 72, 48, 48);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(-1.2, 1.2, -1.2, 1.2, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glRotatef(60.0f, 0.0f, 1.0f, 0.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.0f, 0.5f, 2.0f, 1.0f);
    glPopMatrix();
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glColor3f(0.2f, 0.9f, 0.4f);
    light_sphere(1.0f, 24, 12);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glPopAttrib();  /* matrix mode back to GL_MODELVIEW, colour (0.9,0.5,0.2) */

    /* 2: base state, full viewport: must not track the colour. */
    glPushMatrix();
    glTranslatef(-0.6f, 0.4f, 0.0f);
    light_sphere(0.35f, 24, 12);
    glPopMatrix();

    /* 3: a scaled sphere, normalized; the scale is not in any group. */
    glPushMatrix();
    glTranslatef(0.2f, 0.4f, 0.0f);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glScalef(0.4f, 0.4f, 0.4f);
    glEnable(GL_NORMALIZE);
    glDepthRange(0.2, 0.6);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.9f, 0.9f, 1.0f);
    light_sphere(1.0f, 24, 12);
    glPopAttrib();
    glPopMatrix();

    /* 4: nested: the outer push changes lights, the inner the shade model
     * and the colour mask; each level's objects use their own state. */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glEnable(GL_LIGHT1);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.9f, 0.1f, 0.3f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -1.0f, -0.5f, 0.5f, 0.0f);
    glPushMatrix();
    glTranslatef(0.9f, 0.4f, 0.0f);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glShadeModel(GL_FLAT);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    light_sphere(0.35f, 16, 8);
    glPopAttrib();
    glTranslatef(0.0f, -0.8f, 0.0f);
    light_sphere(0.35f, 24, 12);  /* light 1 still on, smooth, all channels */
    glPopMatrix();
    glPopAttrib();

    /* 5: base state again, below: one light, unlit ground grid in the
     * current colour (restored to (0.9,0.5,0.2) by the first pop). */
    glPushMatrix();
    glTranslatef(-0.6f, -0.45f, 0.0f);
    light_sphere(0.35f, 24, 12);
    glPopMatrix();
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHTING);
    light_grid(-1.4f, -0.95f, 0.4f, -0.85f, 0.0f, 8, 1);
    glPopAttrib();
    return scene_end();
}
