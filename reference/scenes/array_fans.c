/* Triangle fans and polygons through arrays: a 3001-vertex GL_TRIANGLE_FAN
 * disc (Mesa draws fans in segments of 1024 that repeat the hub, the later
 * ones indexed), partly outside the view in one segment, smooth and flat,
 * last- and first-vertex conventions; a GL_POLYGON with glDrawArrays and an
 * indexed 4-vertex fan with glDrawElements. */
#include "scene.h"

#include <math.h>

#define N 3001

static float pos[N][2], col[N][4];

int main(int argc, char **argv)
{
    int i, pass;
    static const GLushort fan4[4] = {0, 1, 2, 3};
    static const float quad[4][2] = {{4, 4}, {40, 6}, {44, 40}, {2, 36}};
    static const float qcol[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}};
    scene_begin(argc, argv, 200, 100);
    scene_ortho_pixels();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    for (pass = 0; pass < 2; pass++) {
        float cx = 50 + pass * 100, cy = 50;
        pos[0][0] = cx;
        pos[0][1] = cy;
        col[0][0] = 1; col[0][1] = 1; col[0][2] = 1; col[0][3] = 1;
        for (i = 1; i < N; i++) {
            float a = 6.2831853f * (i - 1) / (N - 2);
            float r = 45.0f + 3.0f * sinf(a * 7);
            if (i == 1500) r = 400.0f; /* outside: only the second segment needs clipping */
            pos[i][0] = cx + r * cosf(a);
            pos[i][1] = cy + r * sinf(a);
            col[i][0] = 0.5f + 0.5f * cosf(a * 3);
            col[i][1] = 0.5f + 0.5f * sinf(a * 5);
            col[i][2] = (i % 17) / 16.0f;
            col[i][3] = 1;
        }
        glVertexPointer(2, GL_FLOAT, 0, pos);
        glColorPointer(4, GL_FLOAT, 0, col);
        glShadeModel(pass ? GL_FLAT : GL_SMOOTH);
        glProvokingVertex(pass ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION);
        glDrawArrays(GL_TRIANGLE_FAN, 0, N);
    }
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glVertexPointer(2, GL_FLOAT, 0, quad);
    glColorPointer(4, GL_FLOAT, 0, qcol);
    glShadeModel(GL_SMOOTH);
    glDrawArrays(GL_POLYGON, 0, 4);
    glTranslatef(150, 0, 0);
    glDrawElements(GL_TRIANGLE_FAN, 4, GL_UNSIGNED_SHORT, fan4);
    glTranslatef(0, 55, 0);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glTranslatef(-150, 0, 0);
    glShadeModel(GL_FLAT);
    glDrawArrays(GL_POLYGON, 0, 4);
    scene_readpixels_check();
    return scene_end();
}
