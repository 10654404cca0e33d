/* The alpha test: every function against references around which the
 * fragments' alpha varies finely (llvmpipe compares the alpha byte with the
 * reference byte), references out of [0, 1] (clamped), the test in a display
 * list and across glPushAttrib/glPopAttrib, and the late depth test it forces
 * (a discarded fragment writes no depth; a later quad shows the depth buffer). */
#include "scene.h"

static const GLenum kFuncs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const float kRefs[8] = {0.0f, 0.25f, 0.5f, 0.5f + 0.5f / 255.0f, 0.73f, 1.0f, -0.5f, 1.5f};

static float clampf(float v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

/* One cell: x in [x0, x0 + 32), y in [y0, y0 + 20); alpha spans ref +- 0.04
 * across the cell (the whole range for the clamped references). */
static void cell(int x0, int y0, float ref, float z)
{
    float lo = ref - 0.04f, hi = ref + 0.04f;
    if (ref <= 0.0f || ref >= 1.0f) lo = 0.0f, hi = 1.0f;
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.3f, 0.1f, clampf(lo));
    glVertex3f((float)x0, (float)y0, z);
    glColor4f(0.1f, 0.9f, 0.3f, clampf(hi));
    glVertex3f((float)x0 + 32, (float)y0, z);
    glColor4f(0.2f, 0.4f, 0.9f, clampf(hi + 0.003f));
    glVertex3f((float)x0 + 32, (float)y0 + 20, z);
    glColor4f(0.8f, 0.8f, 0.2f, clampf(lo + 0.003f));
    glVertex3f((float)x0, (float)y0 + 20, z);
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 160);
    scene_ortho_pixels();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    /* Rows 0..3 immediately, rows 4..7 from a list. */
    glEnable(GL_ALPHA_TEST);
    for (int r = 0; r < 4; ++r)
        for (int f = 0; f < 8; ++f) {
            glAlphaFunc(kFuncs[f], kRefs[r]);
            cell(f * 32, r * 20, kRefs[r], 0.5f);
        }
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    for (int r = 4; r < 8; ++r)
        for (int f = 0; f < 8; ++f) {
            glAlphaFunc(kFuncs[f], kRefs[r]);
            cell(f * 32, r * 20, kRefs[r], 0.5f);
        }
    glEndList();
    /* The list's state changes stay inside a push/pop. */
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    glPopAttrib();
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_ALPHA_TEST);
    glPopAttrib();

    /* Behind the cells (window depth 0.95 against 0.25): only where the alpha test discarded. */
    glAlphaFunc(GL_ALWAYS, 0);
    glColor4f(0.35f, 0.35f, 0.35f, 1.0f);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, -0.9f);
    glVertex3f(256, 0, -0.9f);
    glVertex3f(256, 160, -0.9f);
    glVertex3f(0, 160, -0.9f);
    glEnd();
    return scene_end();
}
