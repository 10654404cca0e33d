/* All 16 logic ops (GL 2.1 table 4.3), each on a cell of a smooth-shaded
 * background with a smooth-shaded quad; blending enabled too (the logic op
 * wins, §4.1.10); GL_LOGIC_OP (GL_INDEX_LOGIC_OP) enabled changes nothing. */
#include "scene.h"

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 128, 160);
    scene_ortho_pixels();
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.1f, 0.5f, 0.2f); glVertex2f(0, 0);
    glColor4f(0.1f, 0.9f, 0.2f, 0.8f); glVertex2f(128, 0);
    glColor4f(0.4f, 0.2f, 1.0f, 0.5f); glVertex2f(128, 160);
    glColor4f(1.0f, 0.8f, 0.1f, 1.0f); glVertex2f(0, 160);
    glEnd();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glEnable(GL_COLOR_LOGIC_OP);
    for (i = 0; i < 16; ++i) {
        float x = (i % 4) * 32 + 2.0f, y = (i / 4) * 32 + 2.0f;
        glLogicOp(GL_CLEAR + i);
        glBegin(GL_QUADS);
        glColor4f(1.0f, 0.4f, 0.0f, 0.3f); glVertex2f(x, y);
        glColor4f(0.0f, 1.0f, 0.6f, 0.9f); glVertex2f(x + 28, y);
        glColor4f(0.3f, 0.1f, 1.0f, 0.6f); glVertex2f(x + 28, y + 28);
        glColor4f(0.7f, 0.7f, 0.7f, 0.1f); glVertex2f(x, y + 28);
        glEnd();
    }
    /* GL_LOGIC_OP is the index logic op: no effect on RGBA, blending applies */
    glDisable(GL_COLOR_LOGIC_OP);
    glEnable(GL_LOGIC_OP);
    glLogicOp(GL_XOR);
    glBegin(GL_TRIANGLES);
    glColor4f(0.2f, 0.5f, 0.9f, 0.5f); glVertex2f(10, 132);
    glColor4f(0.9f, 0.5f, 0.2f, 0.5f); glVertex2f(118, 132);
    glColor4f(0.5f, 0.9f, 0.5f, 0.5f); glVertex2f(64, 158);
    glEnd();
    scene_readpixels_check();
    return scene_end();
}
