/* ARB_depth_clamp: pairs of lit tori centred on the near and the far plane
 * (9.6 and 10.4 from the eye) with GL_DEPTH_CLAMP on, depth-tested
 * against each other, under the full depth range, a narrow one and a
 * reversed one; then lines and points past both planes, and a row without
 * the clamp where the planes cut the tori open. */
#include "array_common.h"

static torus_mesh m;

static void draw_torus(void)
{
    glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_INT, m.tri);
}

int main(int argc, char **argv)
{
    int cell = 0, i;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.48f, 0.48f, -0.48f, 0.48f, 9.6f, 10.4f);
    glMatrixMode(GL_MODELVIEW);
    torus_build(&m, 0.45f, 0.18f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);  /* the tori are scaled down */
    glVertexPointer(3, GL_FLOAT, 0, m.pos);
    glNormalPointer(GL_FLOAT, 0, m.nrm);
    glColorPointer(4, GL_FLOAT, 0, m.col);
    glEnable(GL_DEPTH_CLAMP);
    for (int row = 0; row < 4; row++) {
        if (row == 1) glDepthRange(0.3, 0.6);
        if (row == 2) { glDepthRange(0.8, 0.2); glDepthFunc(GL_GREATER); glClearDepth(0.0); }
        if (row == 3) { glDepthRange(0.0, 1.0); glDepthFunc(GL_LESS); glDisable(GL_DEPTH_CLAMP); }
        if (row == 2) {
            /* clear only this row's band of the depth buffer */
            glEnable(GL_SCISSOR_TEST);
            glScissor(0, 40, 160, 40);
            glClear(GL_DEPTH_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        for (int col = 0; col < 4; col++, cell++) {
            const float x = -1.5f + col, y = 1.5f - row;
            const float depth[4] = {-9.6f, -9.8f, -10.2f, -10.4f};  /* on the near and far planes */
            glLoadIdentity();
            glTranslatef(x * 0.25f, y * 0.25f, depth[col]);
            glRotatef(25.0f + 17 * cell, 1.0f, 0.6f, 0.2f);
            glScalef(0.18f, 0.18f, 0.18f);
            draw_torus();
            /* a second torus through the first: their depths meet past the planes */
            glRotatef(90.0f, 0.0f, 1.0f, 0.0f);
            draw_torus();
        }
    }
    /* lines and points reaching past both planes, clamp on again */
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_LIGHTING);
    glDisableClientState(GL_COLOR_ARRAY);
    glLoadIdentity();
    glColor3f(1.0f, 1.0f, 0.2f);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        glVertex3f(-0.4f + 0.1f * i, -0.45f, -9.0f);
        glVertex3f(-0.3f + 0.1f * i, 0.45f, -11.0f);
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) glVertex3f(-0.4f + 0.1f * i, -0.2f, i % 2 ? -9.2f : -10.8f);
    glEnd();
    scene_readpixels_check();
    return scene_end();
}
