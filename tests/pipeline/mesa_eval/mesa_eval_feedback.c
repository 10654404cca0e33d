/* Mesa's side of the evaluator comparison: every case of eval_cases.h drawn
 * as GL_POINTS of glEvalCoord in GL_FEEDBACK mode (GL_4D_COLOR_TEXTURE), with
 * identity matrices and a viewport of scale 1 and offset 0, so that window x
 * is the evaluated x exactly; prints x, r, g, b, a, s, t, r, q of each vertex
 * as hexadecimal floats. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#include "eval_cases.h"

int main(void)
{
    static eval_case c;
    static GLfloat rotated[30 * 30 * 3], fb[EVAL_COORDS * 16 + 16];
    static unsigned char pixels[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    int n, k, i;
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4)) return 2;
    glViewport(-1, -1, 2, 2);
    for (n = 0; n < EVAL_CASES; n++) {
        eval_make_case(n, &c);
        for (k = 0; k < EVAL_ROTATIONS; k++) {
            GLint values;
            eval_rotate_vertices(&c, k, rotated);
            if (c.two_d) {
                glMap2f(GL_MAP2_VERTEX_3, c.u1, c.u2, 3 * c.vorder, c.uorder, c.v1, c.v2, 3, c.vorder, rotated);
                glMap2f(GL_MAP2_COLOR_4, c.u1, c.u2, 4 * c.vorder, c.uorder, c.v1, c.v2, 4, c.vorder, c.color);
                glMap2f(GL_MAP2_TEXTURE_COORD_4, c.u1, c.u2, 4 * c.vorder, c.uorder, c.v1, c.v2, 4, c.vorder, c.tex);
                glEnable(GL_MAP2_VERTEX_3);
                glEnable(GL_MAP2_COLOR_4);
                glEnable(GL_MAP2_TEXTURE_COORD_4);
                if (c.auto_normal) glEnable(GL_AUTO_NORMAL); else glDisable(GL_AUTO_NORMAL);
            } else {
                glMap1f(GL_MAP1_VERTEX_3, c.u1, c.u2, 3, c.uorder, rotated);
                glMap1f(GL_MAP1_COLOR_4, c.u1, c.u2, 4, c.uorder, c.color);
                glMap1f(GL_MAP1_TEXTURE_COORD_4, c.u1, c.u2, 4, c.uorder, c.tex);
                glEnable(GL_MAP1_VERTEX_3);
                glEnable(GL_MAP1_COLOR_4);
                glEnable(GL_MAP1_TEXTURE_COORD_4);
            }
            glFeedbackBuffer(sizeof fb / sizeof fb[0], GL_4D_COLOR_TEXTURE, fb);
            glRenderMode(GL_FEEDBACK);
            glBegin(GL_POINTS);
            for (i = 0; i < EVAL_COORDS; i++) {
                if (c.two_d) glEvalCoord2f(c.u[i], c.v[i]);
                else glEvalCoord1f(c.u[i]);
            }
            glEnd();
            values = glRenderMode(GL_RENDER);
            for (i = 0; i + 12 < values; i += 13) {
                const GLfloat *p = fb + i;
                if (p[0] != GL_POINT_TOKEN) return 3;
                printf("%d %d %a  %a %a %a %a  %a %a %a %a\n", n, k, p[1], p[5], p[6], p[7], p[8], p[9], p[10],
                       p[11], p[12]);
            }
            glDisable(GL_MAP1_VERTEX_3);
            glDisable(GL_MAP2_VERTEX_3);
        }
    }
    /* The grids: glEvalMesh1/2(GL_POINT) and glEvalPoint1/2, window x only. */
    for (n = 0; n < EVAL_GRIDS; n++) {
        static GLfloat big[(15 * 15 + 8) * 13 + 16];
        eval_grid g;
        GLint values;
        eval_make_case(n, &c);
        eval_make_grid(n, &g);
        for (k = 0; k < EVAL_ROTATIONS; k++) {
            eval_rotate_vertices(&c, k, rotated);
            glDisable(GL_AUTO_NORMAL);
            if (c.two_d) {
                glMap2f(GL_MAP2_VERTEX_3, c.u1, c.u2, 3 * c.vorder, c.uorder, c.v1, c.v2, 3, c.vorder, rotated);
                glEnable(GL_MAP2_VERTEX_3);
                glMapGrid2f(g.n, g.gu1, g.gu2, g.m, g.gv1, g.gv2);
            } else {
                glMap1f(GL_MAP1_VERTEX_3, c.u1, c.u2, 3, c.uorder, rotated);
                glEnable(GL_MAP1_VERTEX_3);
                glMapGrid1f(g.n, g.gu1, g.gu2);
            }
            glFeedbackBuffer(sizeof big / sizeof big[0], GL_3D, big);
            glRenderMode(GL_FEEDBACK);
            if (c.two_d) glEvalMesh2(GL_POINT, g.i1, g.i2, g.j1, g.j2);
            else glEvalMesh1(GL_POINT, g.i1, g.i2);
            glBegin(GL_POINTS);
            for (i = 0; i < 8; i++) {
                if (c.two_d) glEvalPoint2(g.points[i][0], g.points[i][1]);
                else glEvalPoint1(g.points[i][0]);
            }
            glEnd();
            values = glRenderMode(GL_RENDER);
            if (values < 0) return 5;
            for (i = 0; i + 3 < values; i += 4) {
                if (big[i] != GL_POINT_TOKEN) return 3;
                printf("grid %d %d %a\n", n, k, big[i + 1]);
            }
            glDisable(GL_MAP1_VERTEX_3);
            glDisable(GL_MAP2_VERTEX_3);
        }
    }
    if (glGetError() != GL_NO_ERROR) return 4;
    OSMesaDestroyContext(ctx);
    return 0;
}
