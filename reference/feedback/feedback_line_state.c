/* Lines in GL_FEEDBACK and GL_SELECT with the line state on: width, stipple
 * and GL_LINE_SMOOTH change nothing there (one GL_LINE_TOKEN a line, no
 * stipple pieces, no reset tokens), clipped lines included. */
#include "fb_common.h"

static void lines(void)
{
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 0, 0); glVertex2f(2.5f, 3.5f);
    glColor3f(0, 1, 0); glVertex2f(40.5f, 10.5f);
    glColor3f(0, 0, 1); glVertex2f(30.0f, 60.0f);
    glColor3f(1, 1, 1); glVertex2f(90.0f, 20.0f);  /* clipped at the right */
    glEnd();
    glBegin(GL_LINES);
    glVertex2f(-10.0f, 30.5f); glVertex2f(20.0f, 31.5f);
    glEnd();
}

int main(void)
{
    static GLfloat buf[1024];
    static GLuint sel[64];
    int pass;
    GLint n;
    fb_begin(64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    for (pass = 0; pass < 4; pass++) {
        char title[64];
        if (pass & 1) { glEnable(GL_LINE_STIPPLE); glLineStipple(2, 0x0f0f); } else glDisable(GL_LINE_STIPPLE);
        if (pass & 2) { glEnable(GL_LINE_SMOOTH); glLineWidth(5.0f); } else { glDisable(GL_LINE_SMOOTH); glLineWidth(1.0f); }
        glFeedbackBuffer(1024, GL_3D_COLOR, buf);
        glRenderMode(GL_FEEDBACK);
        lines();
        n = glRenderMode(GL_RENDER);
        snprintf(title, sizeof title, "feedback pass %d", pass);
        fb_print_feedback(title, GL_3D_COLOR, n, buf, 1024);
        glSelectBuffer(64, sel);
        glRenderMode(GL_SELECT);
        glInitNames();
        glPushName(7);
        lines();
        n = glRenderMode(GL_RENDER);
        snprintf(title, sizeof title, "select pass %d", pass);
        fb_print_select(title, n, sel, 64);
    }
    return fb_end();
}
