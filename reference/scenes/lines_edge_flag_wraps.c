/* glEdgeFlag inside glBegin/glEnd grows Mesa's vertex format as glNormal does
 * (VBO_ATTRIB_EDGEFLAG), so it wraps the open primitive: a stippled line strip
 * restarts its pattern at the cut, a line loop is drawn in pieces (see
 * lines_loop_wraps). Minimised from fuzz_primitives seeds 5 and 37. */
#include "scene.h"

static void stippled_strip(void)
{
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0xD5D0);
    glBegin(GL_LINE_STRIP);
    glNormal3f(-1.21479177, 2.12116456, 0.878488541);
    glVertex3f(-0.208948493, -1.05432272, 0.164253354);
    glVertex3f(-0.208263636, 0.344239473, 0.0211415291);
    glEdgeFlag(0);
    glVertex3f(-0.41929853, -0.741357088, -0.613947272);
    glVertex3f(-0.494186401, 0.379004478, -0.421409547);
    glVertex3f(-0.27494657, -0.616276324, -0.14720273);
    glVertex3f(-0.0542888641, -0.725859225, -0.204530001);
    glVertex4f(-0.683644056, 0.549259067, -0.497639596, 1.94676721);
    glColor4f(0.804789424, 0.935807884, 0.107313454, 0.942412972);
    glVertex3f(-0.201645136, 0.250019908, -0.000872612);
    glNormal3f(0.490688443, -0.155954719, 0.708506405);
    glVertex3f(-0.678021312, -0.00837177038, 0.162190318);
    glVertex3f(-1.08439779, -0.742820561, -0.656251431);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
}

static void loop(void)
{
    glBegin(GL_LINE_LOOP);
    glVertex3f(0.629846573, 0.0561547279, -0.771296203);
    glVertex3f(0.498323619, 0.118309379, -0.223587394);
    glColor4f(0.313502908, 0.546653807, 0.20553875, 0.356390178);
    glVertex3f(0.939625621, -0.0994722247, -0.386168301);
    glVertex3f(0.486165702, -0.00943225622, -0.393735349);
    glVertex3f(1.45260572, -0.433649212, -0.287926078);
    glColor4f(0.365444243, 0.466201127, 0.804148257, 0.558678329);
    glVertex3f(0.732308984, 0.0303745866, -0.31215024);
    glVertex3f(0.409240305, 0.404705048, -0.851540983);
    glVertex3f(1.3624568, -0.352043629, -0.409662843);
    glColor3ub(74, 100, 121);
    glVertex3f(1.10513067, -0.230379045, -0.370619416);
    glEdgeFlag(0);
    glVertex3f(1.05033374, -0.40160647, 3.04087734);
    glVertex4f(1.38868642, -0.652978539, -1.82589304, 1.9418714);
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 150);
    glColor3f(1, 1, 1);
    glViewport(0, 0, 200, 150);
    stippled_strip();
    glViewport(-40, 20, 160, 120);
    loop();
    return scene_end();
}
