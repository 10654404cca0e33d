/* GLFIXED_DEBUG (README, "Diagnostics"): provokes GL errors and checks what
 * the library prints on stderr. "diagnostics messages" expects each error with
 * its entry point and the unimplemented entry point once; "diagnostics
 * silence" expects nothing at all. The errors are recorded either way. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int failures = 0;

static void expectError(GLenum expected, const char *what) {
  const GLenum error = glGetError();
  if (error != expected) {
    printf("FAIL: %s gave 0x%04X, not 0x%04X\n", what, error, expected);
    ++failures;
  }
}

static int occurrences(const char *text, const char *line) {
  int n = 0;
  for (const char *p = strstr(text, line); p; p = strstr(p + 1, line)) ++n;
  return n;
}

static void expectLine(const char *text, const char *line, int count) {
  const int n = occurrences(text, line);
  if (n != count) {
    printf("FAIL: \"%s\" printed %d times, not %d\n", line, n, count);
    ++failures;
  }
}

int main(int argc, char **argv) {
  if (argc != 2 || (strcmp(argv[1], "messages") != 0 && strcmp(argv[1], "silence") != 0)) {
    fprintf(stderr, "usage: diagnostics messages|silence\n");
    return 2;
  }
  const int messages = strcmp(argv[1], "messages") == 0;

  /* stderr goes to a file while the library runs. */
  FILE *capture = tmpfile();
  const int savedStderr = dup(2);
  if (!capture || savedStderr < 0 || dup2(fileno(capture), 2) < 0) return 2;

  static GLubyte pixels[16 * 16 * 4];
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!context || !OSMesaMakeCurrent(context, pixels, GL_UNSIGNED_BYTE, 16, 16)) return 2;

  glEnable(0x1234);
  expectError(GL_INVALID_ENUM, "glEnable(0x1234)");
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  expectError(GL_INVALID_OPERATION, "glBegin inside glBegin");
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  expectError(GL_STACK_UNDERFLOW, "glPopMatrix on a stack of one");
  /* Two errors before glGetError: both printed, the first kept. */
  glLineWidth(-1.0f);
  glPointSize(0.0f);
  expectError(GL_INVALID_VALUE, "glLineWidth(-1) then glPointSize(0)");
  /* An entry point without an implementation, while there is none. */
  const int unimplemented = OSMesaGetProcAddress("glCompileShader") == NULL;
  if (unimplemented) {
    glCompileShader(1);
    glCompileShader(1);
    expectError(GL_INVALID_OPERATION, "glCompileShader (unimplemented)");
    expectError(GL_NO_ERROR, "glGetError after glGetError");
  }
  OSMesaDestroyContext(context);

  fflush(stderr);
  dup2(savedStderr, 2);
  char text[4096] = "";
  rewind(capture);
  const size_t length = fread(text, 1, sizeof text - 1, capture);
  text[length] = '\0';
  printf("stderr of the library:\n%s(end)\n", text);

  if (messages) {
    expectLine(text, "libglfixed: GL_INVALID_ENUM in glEnable\n", 1);
    expectLine(text, "libglfixed: GL_INVALID_OPERATION in glBegin\n", 1);
    expectLine(text, "libglfixed: GL_STACK_UNDERFLOW in glPopMatrix\n", 1);
    expectLine(text, "libglfixed: GL_INVALID_VALUE in glLineWidth\n", 1);
    expectLine(text, "libglfixed: GL_INVALID_VALUE in glPointSize\n", 1);
    if (unimplemented) {
      expectLine(text, "libglfixed: glCompileShader is not implemented\n", 1);
      expectLine(text, "libglfixed: GL_INVALID_OPERATION in glCompileShader\n", 2);
    }
    expectLine(text, "(unknown entry point)", 0);
  } else {
    expectLine(text, "libglfixed", 0);
  }
  printf(failures ? "FAIL\n" : "PASS\n");
  return failures ? 1 : 0;
}
