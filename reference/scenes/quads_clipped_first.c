/* One glBegin(GL_QUADS) whose first quad is clipped and whose second, concave
 * quad is inside, its last vertex a glVertex4f after glVertex3f calls. The
 * 4-component position grows Mesa's vertex format, which draws the first quad
 * alone (clipped) and starts the second in a draw of its own, unclipped: so
 * the inside quad splits (0,1,2)(0,2,3), as if drawn alone.
 * Minimised from fuzz_random_state seed 2. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 120);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.75595236, 1.4001019, -1.18352032, 1.18352032, 1.13714385, 6.87182522);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -3.5f);
    glColor3f(0.8f, 0.6f, 0.2f);
    glBegin(GL_QUADS);
    glVertex3f(-6.37119865f, 1.25276315f, 0.429468274f);
    glVertex3f(-0.610154152f, 0.896188915f, 0.623535097f);
    glVertex3f(-0.530551016f, 1.1690253f, 0.267658412f);
    glVertex3f(-0.653014243f, 1.12175822f, 0.863975644f);
    glVertex3f(-0.524363041f, 0.734698057f, 0.0492551923f);
    glVertex3f(-0.777294934f, 1.27656126f, 0.867178082f);
    glVertex3f(-0.248953938f, 0.85489285f, 0.268251657f);
    glVertex4f(-0.766062021f, 0.439412713f, 1.072685f, 1.09999394f);
    glEnd();
    return scene_end();
}
