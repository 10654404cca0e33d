/* Shared by blend_format_*.c: translucent layers in several factor pairs on
 * a buffer of the given OSMesa format (factors that read destination alpha
 * only where the format has alpha: Mesa's RGB side is emulated on RGBA). */
#include "scene.h"

static int blend_formats_draw(int argc, char **argv, GLenum format, int has_alpha)
{
    static const GLenum pairs[6][2] = {{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, {GL_ONE, GL_ONE},
                                       {GL_DST_COLOR, GL_ZERO}, {GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR},
                                       {GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA}, {GL_SRC_ALPHA_SATURATE, GL_ONE}};
    scene_options o = {96, 64, format, 24, 0, 0};
    int i;
    if (scene_begin_try(argc, argv, &o) == 0) {
        scene_ortho_pixels();
        glBegin(GL_QUADS);
        glColor4f(0.8f, 0.2f, 0.3f, 0.4f); glVertex2f(0, 0);
        glColor4f(0.2f, 0.9f, 0.3f, 0.9f); glVertex2f(96, 0);
        glColor4f(0.3f, 0.2f, 0.9f, 0.1f); glVertex2f(96, 64);
        glColor4f(0.9f, 0.9f, 0.2f, 0.6f); glVertex2f(0, 64);
        glEnd();
        glEnable(GL_BLEND);
        for (i = 0; i < 6; ++i) {
            float x = (i % 3) * 32 + 2.0f, y = (i / 3) * 32 + 2.0f;
            if (!has_alpha && i >= 4) break;
            glBlendFunc(pairs[i][0], pairs[i][1]);
            glBegin(GL_TRIANGLES);
            glColor4f(1.0f, 0.5f, 0.1f, 0.3f); glVertex2f(x, y);
            glColor4f(0.1f, 1.0f, 0.5f, 0.8f); glVertex2f(x + 28, y + 4);
            glColor4f(0.5f, 0.1f, 1.0f, 0.6f); glVertex2f(x + 10, y + 28);
            glEnd();
        }
        glDisable(GL_BLEND);
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_XOR);
        glColor3f(1, 1, 1);
        glBegin(GL_LINES);
        glVertex2f(2, 60.5f); glVertex2f(94, 34.5f);
        glEnd();
        scene_readpixels_check();
    }
    return scene_end();
}
