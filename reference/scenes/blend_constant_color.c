/* glBlendColor with the four constant factors, in rows of colours that
 * round at .5 (0.3, 0.5, 0.7 times 255) and out of [0,1] (clamped), over a
 * smooth background; glBlendColorEXT and glBlendEquationEXT, too. */
#include "scene.h"

int main(int argc, char **argv)
{
    static const float colors[6][4] = {{0.3f, 0.5f, 0.7f, 0.1f}, {0.5f, 0.5f, 0.5f, 0.5f},
                                       {1.5f, -0.5f, 0.25f, 2.0f}, {0.002f, 0.998f, 0.9f, 0.7f},
                                       {0.1f, 0.2f, 0.3f, 0.9f},   {0.75f, 0.25f, 0.6f, 0.4f}};
    static const GLenum pairs[6][2] = {{GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR},
                                       {GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA},
                                       {GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_COLOR},
                                       {GL_SRC_COLOR, GL_CONSTANT_COLOR},
                                       {GL_CONSTANT_ALPHA, GL_DST_COLOR},
                                       {GL_ONE_MINUS_CONSTANT_ALPHA, GL_ONE}};
    int i, j;
    scene_begin(argc, argv, 144, 144);
    scene_ortho_pixels();
    glBegin(GL_QUADS);
    glColor4f(0.1f, 0.9f, 0.4f, 0.8f); glVertex2f(0, 0);
    glColor4f(0.9f, 0.2f, 0.6f, 0.2f); glVertex2f(144, 0);
    glColor4f(0.3f, 0.4f, 1.0f, 0.5f); glVertex2f(144, 144);
    glColor4f(1.0f, 1.0f, 0.0f, 1.0f); glVertex2f(0, 144);
    glEnd();
    glEnable(GL_BLEND);
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) {
            float x = j * 24 + 2.0f, y = i * 24 + 2.0f;
            if (j & 1)
                glBlendColorEXT(colors[i][0], colors[i][1], colors[i][2], colors[i][3]);
            else
                glBlendColor(colors[i][0], colors[i][1], colors[i][2], colors[i][3]);
            glBlendEquationEXT(j == 5 ? GL_FUNC_REVERSE_SUBTRACT : GL_FUNC_ADD);
            glBlendFunc(pairs[j][0], pairs[j][1]);
            glBegin(GL_TRIANGLES);
            glColor4f(0.9f, 0.5f, 0.1f, 0.6f); glVertex2f(x, y);
            glColor4f(0.2f, 0.6f, 0.9f, 0.3f); glVertex2f(x + 20, y);
            glColor4f(0.7f, 0.1f, 0.5f, 0.9f); glVertex2f(x + 10, y + 20);
            glEnd();
        }
    scene_readpixels_check();
    return scene_end();
}
