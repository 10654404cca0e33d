/* A lit torus drawn with glPolygonMode(GL_FRONT_AND_BACK, GL_LINE): every
 * quad's outline, the diagonal of its split hidden, front and back faces. */
#include "polygon_torus.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    polygon_torus_view();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.9f, 0.7f, 0.3f);
    polygon_torus(1.5f, 0.55f, 18, 10);
    return scene_end();
}
