/* The selection and feedback commands in GL_RENDER mode between glBegin/glEnd
 * pairs of smooth GL_QUADS that Mesa would merge into one draw, the last quad
 * of each row partly outside the view volume (so the whole draw is split as a
 * clipped draw, merge_quads_clipped). Whether each command ends the draw
 * (Mesa's FLUSH_VERTICES) shows in how the first quads of its row are split:
 * glPushName, glLoadName, glPopName, glInitNames and glPassThrough do not;
 * glRenderMode, glSelectBuffer, glFeedbackBuffer, glRasterPos, glBitmap, and
 * even empty glDrawPixels and glCopyPixels do (MESA_FACTS.md). */
#include <stddef.h>

#include "scene.h"
#include "smooth_quad.h"

static GLuint select_buffer[64];
static GLfloat feedback_buffer[64];

static void command(int which)
{
    switch (which) {
    case 0: glPushName(1); break;
    case 1: glLoadName(2); break;
    case 2: glPopName(); break;
    case 3: glInitNames(); break;
    case 4: glPassThrough(1.0f); break;
    case 5: glRenderMode(GL_RENDER); break;
    case 6: glSelectBuffer(64, select_buffer); break;
    case 7: glFeedbackBuffer(64, GL_2D, feedback_buffer); break;
    case 8: glRasterPos2f(3.0f, 3.0f); break;
    case 9: glBitmap(0, 0, 0, 0, 1.0f, 1.0f, NULL); break;
    case 10: glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL); break;
    case 11: glCopyPixels(0, 0, 0, 0, GL_COLOR); break;
    default: break;
    }
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    for (int row = 0; row < 12; ++row) {
        float y = 2.0f + 10.5f * (float)row;
        glTranslatef(0, 0, 0); /* a state change: each row starts a new draw */
        quad(4, y, 9);
        command(row);
        quad(40, y, 9);
        quad(122, y, 9); /* crosses the right edge */
    }
    return scene_end();
}
