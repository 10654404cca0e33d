/* glLoadMatrixf/d, glMultMatrixf/d and glLoadTransposeMatrixf /
 * glMultTransposeMatrixd with shears and a projective (w != 1) matrix. */
#include "scene.h"

static void square(float r, float g, float b)
{
    glBegin(GL_QUADS);
    glColor3f(r, g, b); glVertex2f(0, 0);
    glColor3f(1, 1, 1); glVertex2f(1, 0);
    glColor3f(b, g, r); glVertex2f(1, 1);
    glColor3f(g, r, b); glVertex2f(0, 1);
    glEnd();
}

int main(int argc, char **argv)
{
    /* column-major: x' = 30x + 10y + 8, y' = 5x + 25y + 6 */
    static const GLfloat shear_f[16] = {30, 5, 0, 0, 10, 25, 0, 0, 0, 0, 1, 0, 8, 6, 0, 1};
    static const GLdouble shear_d[16] = {20, -8, 0, 0, 4, 28, 0, 0, 0, 0, 1, 0, 90, 20, 0, 1};
    static const GLfloat scale_f[16] = {1.5f, 0, 0, 0, 0, 0.75f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const GLdouble rot_d[16] = {0.8, 0.6, 0, 0, -0.6, 0.8, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    /* row-major (transpose) translation by (40, 110) and scale 24 */
    static const GLfloat t_rows[16] = {24, 0, 0, 40, 0, 24, 0, 110, 0, 0, 1, 0, 0, 0, 0, 1};
    /* projective: w = 1 + 0.6x */
    static const GLdouble persp_rows[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.6, 0, 0, 1};
    scene_begin(argc, argv, 160, 160);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);

    glLoadMatrixf(shear_f);
    square(1, 0, 0);
    glLoadMatrixd(shear_d);
    glMultMatrixf(scale_f);
    square(0, 1, 0);
    glLoadIdentity();
    glTranslatef(120, 40, 0);
    glMultMatrixd(rot_d);
    glScalef(28, 28, 1);
    square(0, 0, 1);
    glLoadTransposeMatrixf(t_rows);
    square(1, 1, 0);
    glLoadIdentity();
    glTranslatef(90, 80, 0);
    glScalef(60, 60, 1);
    glMultTransposeMatrixd(persp_rows);
    square(0, 1, 1);

    /* the projection matrix can be loaded too */
    glMatrixMode(GL_PROJECTION);
    {
        GLfloat p[16] = {2.0f / 160, 0, 0, 0, 0, 2.0f / 160, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};
        glLoadMatrixf(p);
    }
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(8, 120, 0);
    glScalef(25, 30, 1);
    square(1, 0, 1);
    return scene_end();
}
