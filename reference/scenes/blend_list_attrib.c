/* Blend and logic-op state in display lists and under
 * glPushAttrib(GL_COLOR_BUFFER_BIT) / glPushAttrib(GL_ENABLE_BIT): a list
 * sets blending and draws, the state pushed around changes is restored, and
 * the colour mask applies after blending. */
#include "scene.h"

static void quad(float x, float y, float w)
{
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.3f, 0.1f, 0.4f); glVertex2f(x, y);
    glColor4f(0.1f, 1.0f, 0.3f, 0.6f); glVertex2f(x + w, y);
    glColor4f(0.3f, 0.1f, 1.0f, 0.8f); glVertex2f(x + w, y + w);
    glColor4f(0.9f, 0.9f, 0.9f, 0.2f); glVertex2f(x, y + w);
    glEnd();
}

int main(int argc, char **argv)
{
    GLuint list;
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glBegin(GL_QUADS);
    glColor4f(0.2f, 0.4f, 0.8f, 0.5f); glVertex2f(0, 0);
    glColor4f(0.8f, 0.4f, 0.2f, 0.9f); glVertex2f(128, 0);
    glColor4f(0.4f, 0.8f, 0.2f, 0.1f); glVertex2f(128, 128);
    glColor4f(0.6f, 0.6f, 0.6f, 0.7f); glVertex2f(0, 128);
    glEnd();
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEnable(GL_BLEND);
    glBlendColor(0.25f, 0.5f, 0.75f, 0.5f);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_DST_ALPHA);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_REVERSE_SUBTRACT);
    quad(4, 4, 36);
    glEndList();
    /* the list sets the blending state and draws */
    glCallList(list);
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_SUBTRACT);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_OR_REVERSE);
    quad(46, 4, 36);
    glPopAttrib();
    quad(88, 4, 36);  /* the list's blending again */
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_BLEND);
    quad(4, 46, 36);
    glPopAttrib();
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    quad(46, 46, 36);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glNewList(list, GL_COMPILE_AND_EXECUTE);
    glLogicOp(GL_NAND);
    glEnable(GL_COLOR_LOGIC_OP);
    quad(88, 46, 36);
    glEndList();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_COLOR_LOGIC_OP);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glCallList(list);
    glDisable(GL_COLOR_LOGIC_OP);
    quad(4, 88, 36);
    glDeleteLists(list, 1);
    scene_readpixels_check();
    return scene_end();
}
