/* Rubber-band lines with glLogicOp(GL_XOR): a lit scene, then lines and a
 * rectangle XORed in white, some drawn twice (which erases them exactly),
 * wide and stippled lines, points; then GL_INVERT on a box. */
#include "scene.h"

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.2f, 0.1f); glVertex2f(5, 5);
    glColor3f(0.1f, 0.8f, 0.3f); glVertex2f(120, 15);
    glColor3f(0.2f, 0.3f, 0.9f); glVertex2f(50, 122);
    glEnd();
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColor3f(1, 1, 1);
    for (i = 0; i < 6; ++i) {  /* drawn once: stays */
        glBegin(GL_LINES);
        glVertex2f(10.3f + i * 7, 100.2f); glVertex2f(118.3f - i * 9, 20.2f + i * 5);
        glEnd();
    }
    for (i = 0; i < 2; ++i) {  /* drawn twice: erased */
        glBegin(GL_LINE_LOOP);
        glVertex2f(20.5f, 30.5f); glVertex2f(90.5f, 30.5f); glVertex2f(90.5f, 80.5f); glVertex2f(20.5f, 80.5f);
        glEnd();
    }
    glBegin(GL_LINE_LOOP);  /* the last rubber band stays */
    glVertex2f(30.5f, 40.5f); glVertex2f(100.5f, 40.5f); glVertex2f(100.5f, 95.5f); glVertex2f(30.5f, 95.5f);
    glEnd();
    glLineWidth(3);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0xf0f0);
    glColor3f(0.5f, 0.25f, 1.0f);
    glBegin(GL_LINES);
    glVertex2f(5, 60); glVertex2f(125, 70);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glPointSize(4);
    glBegin(GL_POINTS);
    for (i = 0; i < 10; ++i) glVertex2f(10.0f + i * 11, 115.0f);
    glEnd();
    glLogicOp(GL_INVERT);
    glRectf(60, 5, 80, 25);
    scene_readpixels_check();
    return scene_end();
}
