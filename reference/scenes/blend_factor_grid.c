/* Every blend factor pair of GL 2.1's table 4.2 (15 source x 14 destination
 * factors, the constant colour set), each a smooth-shaded translucent quad
 * over a smooth-shaded background with alpha, in one grid cell. */
#include "scene.h"

static const GLenum kFactors[15] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};

int main(int argc, char **argv)
{
    int s, d;
    const int cell = 12;
    scene_begin(argc, argv, 15 * cell, 14 * cell);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    /* background: a gradient in every channel, alpha included */
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.1f, 0.2f, 0.1f); glVertex2f(0, 0);
    glColor4f(0.2f, 0.8f, 0.3f, 0.9f); glVertex2f(15 * cell, 0);
    glColor4f(0.1f, 0.3f, 0.9f, 0.6f); glVertex2f(15 * cell, 14 * cell);
    glColor4f(0.7f, 0.7f, 0.1f, 0.3f); glVertex2f(0, 14 * cell);
    glEnd();
    glEnable(GL_BLEND);
    glBlendColor(0.3f, 0.5f, 0.7f, 0.4f);
    for (s = 0; s < 15; ++s)
        for (d = 0; d < 14; ++d) {
            float x = (float)(s * cell + 1), y = (float)(d * cell + 1), w = (float)(cell - 2);
            glBlendFunc(kFactors[s], kFactors[d]);
            glBegin(GL_QUADS);
            glColor4f(1.0f, 0.6f, 0.2f, 0.2f); glVertex2f(x, y);
            glColor4f(0.2f, 1.0f, 0.5f, 0.7f); glVertex2f(x + w, y);
            glColor4f(0.4f, 0.2f, 1.0f, 1.0f); glVertex2f(x + w, y + w);
            glColor4f(0.8f, 0.8f, 0.8f, 0.5f); glVertex2f(x, y + w);
            glEnd();
        }
    scene_readpixels_check();
    return scene_end();
}
