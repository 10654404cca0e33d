/* GL_LINE_LOOPs whose vertex format grows inside glBegin/glEnd (a first
 * glNormal, glColor or glVertex4 there): Mesa's vbo wraps the loop, draws
 * each piece as a line strip and closes the loop at glEnd with its first
 * vertex; a later piece keeps its second-to-last vertex, not its last
 * (vbo_copy_vertices: a Mesa defect that decides which segments are drawn;
 * MESA_FACTS.md "Immediate mode"). Minimised from fuzz_primitives seeds 12
 * and 16; each loop has a vertex outside the view. */
#include "scene.h"
#include <math.h>

static void loop_two_wraps(void)   /* normal, then colour, grow the format */
{
    glBegin(GL_LINE_LOOP);
    glVertex3f(1.3040669f, -0.268264949f, 0.197715402f);
    glVertex3f(0.406404108f, 0.0697105527f, 0.504842818f);
    glVertex3f(0.474334657f, -0.814496875f, -0.0805001855f);
    glVertex3f(0.633949041f, -0.654291213f, 0.286687791f);
    glVertex3f(0.294873178f, -0.518797278f, 0.263744056f);
    glNormal3f(-0.299635768f, -0.276744604f, -0.139808401f);
    glVertex3f(0.926132679f, 0.0429775119f, 0.5804407f);
    glColor4f(0.680435359f, 0.840064406f, 0.0853681564f, 0.433300614f);
    glVertex3f(0.366827726f, -0.289804697f, 0.464594603f);
    glVertex3f(0.936550319f, -0.258522511f, 0.42433542f);
    glEnd();
}

static void loop_wrap_after_one_vertex(void)   /* glVertex4 after one vertex: nothing is cut */
{
    glBegin(GL_LINE_LOOP);
    glVertex3f(0.468663812f, -0.441678405f, -0.923081219f);
    glVertex4f(1.45419061f, -0.432913929f, -1.50747657f, 1.53883994f);
    glVertex3f(0.393714368f, -0.84268707f, -0.352236629f);
    glVertex3f(6.81988525f, -0.667582452f, -0.122779906f);
    glVertex3f(0.638095021f, -0.333724618f, -1.05131531f);
    glVertex3f(0.81087184f, -1.42330182f, -0.952002585f);
    glVertex3f(0.496535599f, -1.02086616f, -0.258530974f);
    glVertex3f(1.18268943f, -1.35825682f, -0.184784949f);
    glVertex3f(1.29652345f, -0.62944895f, -0.258846581f);
    glColor4f(0.822939396f, 0.0586822629f, 0.219527185f, 0.966067851f);
    glVertex3f(1.35567427f, -1.33670843f, -0.326333106f);
    glEnd();
}

static void loop_three_wraps(void)   /* three growths in a row, two with no vertex between */
{
    int i;
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 12; i++) {
        float a = (float)i * 0.5236f;
        if (i == 4) glNormal3f(0, 0, 1);
        if (i == 4) glColor4f(0.2f, 0.9f, 0.5f, 1.0f);
        if (i == 8) glVertex4f(0.9f * cosf(a), 0.7f * sinf(a), 0.0f, 1.0f);
        else glVertex3f((i % 3 ? 0.9f : 1.2f) * cosf(a), 0.7f * sinf(a), 0.0f);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 240, 160);
    glColor3f(1, 1, 1);
    glViewport(0, 40, 160, 120);
    loop_two_wraps();
    glViewport(80, 0, 160, 120);
    loop_wrap_after_one_vertex();
    glColor3f(0.9f, 0.6f, 0.2f);
    glViewport(10, 10, 120, 90);
    loop_three_wraps();
    return scene_end();
}
