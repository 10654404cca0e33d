/* glBlendFuncSeparate and glBlendEquationSeparate: different factors and
 * equations for RGB and alpha (the alpha written is then blended against by
 * DST_ALPHA factors in a second layer), also under their EXT, INGR and ATI
 * names, with a colour mask on one column. */
#include "scene.h"

static const GLenum kEquations[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
static const GLenum kFactors[8] = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA,
                                   GL_SRC_COLOR, GL_ONE,       GL_ZERO,             GL_SRC_ALPHA_SATURATE};

typedef void (*blend_func_separate_fn)(GLenum, GLenum, GLenum, GLenum);
typedef void (*blend_equation_separate_fn)(GLenum, GLenum);

int main(int argc, char **argv)
{
    int i, j;
    blend_func_separate_fn funcExt, funcIngr;
    blend_equation_separate_fn eqExt, eqAti;
    scene_begin(argc, argv, 160, 160);
    /* the extension names, as a program finds them */
    funcExt = (blend_func_separate_fn)OSMesaGetProcAddress("glBlendFuncSeparateEXT");
    funcIngr = (blend_func_separate_fn)OSMesaGetProcAddress("glBlendFuncSeparateINGR");
    eqExt = (blend_equation_separate_fn)OSMesaGetProcAddress("glBlendEquationSeparateEXT");
    eqAti = (blend_equation_separate_fn)OSMesaGetProcAddress("glBlendEquationSeparateATI");
    if (!funcExt || !funcIngr || !eqExt || !eqAti) return 3;
    scene_ortho_pixels();
    glBegin(GL_QUADS);
    glColor4f(0.8f, 0.3f, 0.2f, 0.3f); glVertex2f(0, 0);
    glColor4f(0.2f, 0.8f, 0.4f, 0.7f); glVertex2f(160, 0);
    glColor4f(0.2f, 0.2f, 0.9f, 1.0f); glVertex2f(160, 160);
    glColor4f(0.9f, 0.9f, 0.3f, 0.0f); glVertex2f(0, 160);
    glEnd();
    glEnable(GL_BLEND);
    for (i = 0; i < 8; ++i)
        for (j = 0; j < 8; ++j) {
            float x = j * 20 + 1.0f, y = i * 20 + 1.0f;
            GLenum sr = kFactors[(i + j) % 8], dr = kFactors[(3 * i + j + 1) % 8];
            GLenum sa = kFactors[(i + 2 * j + 2) % 8], da = kFactors[(i * j + 5) % 8];
            switch ((i + j) % 3) {
            case 0: glBlendFuncSeparate(sr, dr, sa, da); break;
            case 1: funcExt(sr, dr, sa, da); break;
            default: funcIngr(sr, dr, sa, da); break;
            }
            if (j & 1)
                glBlendEquationSeparate(kEquations[i % 5], kEquations[(i + j) % 5]);
            else
                eqExt(kEquations[(i + j) % 5], kEquations[j % 5]);
            glColorMask(GL_TRUE, j != 6, GL_TRUE, GL_TRUE);
            glBegin(GL_QUADS);
            glColor4f(1.0f, 0.5f, 0.0f, 0.25f); glVertex2f(x, y);
            glColor4f(0.0f, 1.0f, 0.5f, 0.75f); glVertex2f(x + 18, y);
            glColor4f(0.5f, 0.0f, 1.0f, 0.5f); glVertex2f(x + 18, y + 18);
            glColor4f(0.6f, 0.6f, 0.6f, 1.0f); glVertex2f(x, y + 18);
            glEnd();
            /* a second layer reads the alpha just written */
            glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ZERO);
            eqAti(GL_FUNC_ADD, GL_FUNC_ADD);
            glBegin(GL_TRIANGLES);
            glColor4f(0.1f, 0.2f, 0.9f, 0.5f); glVertex2f(x + 4, y + 4);
            glColor4f(0.9f, 0.9f, 0.1f, 0.5f); glVertex2f(x + 14, y + 4);
            glColor4f(0.9f, 0.1f, 0.1f, 0.5f); glVertex2f(x + 9, y + 14);
            glEnd();
        }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    scene_readpixels_check();
    return scene_end();
}
