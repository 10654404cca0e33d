/* A library with no symbols of its own: used for libOpenGL.so.0 in the drop-in
 * folder, whose only job is to need libGL.so.1 (see CMakeLists.txt). */
int glfixed_empty_translation_unit_;
