/* Array state and array draws between glBegin/glEnd pairs: glVertexPointer,
 * glEnableClientState and glClientActiveTexture do not end Mesa's run of
 * merged glBegin/glEnd quads (a clipped quad later in the run still decides
 * the split of the earlier ones), while glDrawArrays draws the run first
 * and starts a new one. Smooth colours make each quad's split visible. */
#include "scene.h"

static void quad(float x, float y, float s, const float c[4][3])
{
    glBegin(GL_QUADS);
    glColor3fv(c[0]); glVertex2f(x, y);
    glColor3fv(c[1]); glVertex2f(x + s, y);
    glColor3fv(c[2]); glVertex2f(x + s, y + s);
    glColor3fv(c[3]); glVertex2f(x, y + s);
    glEnd();
}

int main(int argc, char **argv)
{
    static const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};
    static const float tri[6] = {100, 50, 120, 50, 110, 70};
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    quad(4, 4, 28, c);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    quad(40, 4, 28, c);
    glEnableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE1);
    quad(110, 4, 30, c);          /* crosses the right edge: clipped */

    quad(4, 40, 28, c);
    glColor3f(0.2f, 0.6f, 0.9f);
    glDrawArrays(GL_TRIANGLES, 0, 3); /* draws the pending quad first */
    quad(40, 40, 28, c);
    quad(110, 40, 30, c);         /* clipped: splits only the quads after the draw */

    glDisableClientState(GL_VERTEX_ARRAY);
    quad(4, 80, 28, c);
    quad(110, 80, 30, c);
    return scene_end();
}
