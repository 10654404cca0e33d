/* Lines and points clipped by user clip planes: GL_LINES, strips and loops (1 and 3 wide, stippled, smooth and flat) cut by planes set under different modelview matrices and a perspective projection; points of sizes 1, 4 and 7 dropped whole when their centre is outside a plane; then the same under a scissor box, which also bounds wide points and lines. */
#include "scene.h"
#include <math.h>

static void colour(int i)
{
    glColor3f(0.2f + 0.1f * (float)(i % 8), 0.9f - 0.09f * (float)(i % 9), 0.3f + 0.12f * (float)(i % 5));
}

static void star(GLenum mode, int n, float cx, float cy, float r, float z)
{
    int i;
    glBegin(mode);
    for (i = 0; i < n; ++i) {
        const float a = 6.2831853f * (float)i / (float)n + 0.2f;
        const float rr = (i % 2) ? r : 0.45f * r;
        colour(i);
        glVertex3f(cx + rr * cosf(a), cy + rr * sinf(a), z + 0.05f * (float)(i % 3));
    }
    glEnd();
}

static void grid_points(float x0, float y0, float step, int n, float z)
{
    int i, j;
    glBegin(GL_POINTS);
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            colour(i + j);
            glVertex3f(x0 + step * (float)i, y0 + step * (float)j, z);
        }
    glEnd();
}

static void draw_all(void)
{
    glLineWidth(1.0f);
    star(GL_LINE_LOOP, 14, -0.1f, 0.8f, 0.55f, -3.0f);
    glLineWidth(3.0f);
    star(GL_LINE_STRIP, 11, 0.1f, 0.0f, 0.6f, -3.2f);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3f3f);
    glLineWidth(1.0f);
    star(GL_LINES, 16, 0.0f, 0.3f, 1.0f, -3.5f);
    glDisable(GL_LINE_STIPPLE);
    glPointSize(1.0f);
    grid_points(-0.85f, -1.3f, 0.1f, 9, -3.0f);
    glPointSize(4.0f);
    grid_points(0.05f, -1.3f, 0.13f, 7, -3.0f);
    glPointSize(7.0f);
    grid_points(-0.7f, -0.6f, 0.3f, 5, -2.8f);
}

int main(int argc, char **argv)
{
    const GLdouble left_cut[4] = {1.0, 0.0, 0.0, 0.45};
    const GLdouble slant[4] = {-1.0, -1.0, 0.0, 0.9};
    const GLdouble ring[4] = {0.0, 1.0, 0.1, 1.5};
    scene_begin(argc, argv, 160, 120);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.3, 0.3, -0.45, 0.45, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glClipPlane(GL_CLIP_PLANE0, left_cut);
    glLoadIdentity();
    glRotatef(15.0f, 0.0f, 0.0f, 1.0f);
    glClipPlane(GL_CLIP_PLANE2, slant);
    glLoadIdentity();
    glClipPlane(GL_CLIP_PLANE0 + 7, ring);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE2);
    glEnable(GL_CLIP_PLANE0 + 7);

    glViewport(0, 0, 80, 120);
    draw_all();
    glShadeModel(GL_FLAT);
    glViewport(80, 0, 80, 120);
    glEnable(GL_SCISSOR_TEST);
    glScissor(86, 10, 66, 96);
    draw_all();
    glDisable(GL_SCISSOR_TEST);
    glShadeModel(GL_SMOOTH);
    scene_readpixels_check();
    return scene_end();
}
