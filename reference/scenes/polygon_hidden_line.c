/* Hidden-line rendering: the torus filled in a dark colour and pushed back
 * with glPolygonOffset, then its edges in GL_LINE on top with GL_LEQUAL; the
 * offset decides which edge pixels survive. */
#include "polygon_torus.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    polygon_torus_view();
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glColor3f(0.15f, 0.2f, 0.3f);
    polygon_torus(1.5f, 0.55f, 18, 10);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_LIGHTING);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1.0f, 0.95f, 0.6f);
    polygon_torus(1.5f, 0.55f, 18, 10);
    return scene_end();
}
