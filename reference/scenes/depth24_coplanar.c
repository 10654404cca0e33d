/* 24-bit depth: nearly coplanar surfaces close to the 24-bit resolution and a
 * GL_LEQUAL re-draw of identical geometry (depth invariance). */
#include "depth_common.h"

int main(int argc, char **argv)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, blue[3] = {0, 0, 1},
                       white[3] = {1, 1, 1};
    int i;
    depth_begin(argc, argv);
    for (i = 0; i < 8; i++) {
        float y = 4.0f + i * 10.0f;
        float dz = (float)(i + 1) * (2.0f / 16777216.0f);
        depth_quad(4, y, 124, y + 8, 0.35f, -0.25f, blue, white);
        depth_quad(4, y, 124, y + 8, 0.35f + ((i & 1) ? dz : -dz), -0.25f - dz, yellow, red);
    }
    glDepthFunc(GL_LEQUAL);
    glBegin(GL_TRIANGLES);   /* same triangle twice: the second must win everywhere */
    glColor3f(1, 0, 0); glVertex3f(4.3f, 86.1f, 0.37f);
    glColor3f(0, 1, 0); glVertex3f(123.7f, 90.6f, -0.41f);
    glColor3f(0, 0, 1); glVertex3f(60.2f, 125.9f, 0.05f);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1); glVertex3f(4.3f, 86.1f, 0.37f);
    glColor3f(0, 1, 1); glVertex3f(123.7f, 90.6f, -0.41f);
    glColor3f(1, 0, 1); glVertex3f(60.2f, 125.9f, 0.05f);
    glEnd();
    return scene_end();
}
