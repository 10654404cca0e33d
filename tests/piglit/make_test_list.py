#!/usr/bin/env python3
"""Writes fixed_function_tests.txt: piglit's fixed-function tests with the feature
groups each needs that libglfixed lacks.

  make_test_list.py PIGLIT_SOURCE > tests/piglit/fixed_function_tests.txt

The tests come from the installed piglit's opengl.xml.gz profile (its command
lines); the needs column from piglit's source tree (a checkout of the piglit
repository near the installed version), by the GL commands each test's sources
call, with the overrides below checked by hand.
"""
import ast
import glob
import gzip
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

EXT_GROUPS = {'ext_provoking_vertex','arb_vertex_buffer_object','arb_point_parameters',
 'arb_multisample','arb_vertex_array_bgra','ext_vertex_array_bgra','nv_primitive_restart',
 'arb_depth_clamp','ext_polygon_offset_clamp','apple_vertex_array_object','arb_vertex_array_object',
 'arb_draw_elements_base_vertex','ext_fog_coord','arb_copy_buffer','arb_map_buffer_range',
 'arb_occlusion_query','arb_provoking_vertex','ext_depth_bounds_test',
 'arb_half_float_vertex','mesa_pack_invert','nv_fog_distance'}

# Feature groups the library lacks, each with the commands that show a test uses
# it; a test needs every group whose commands its sources call, in this order.
RULES = [
 ('glsl', r'glCreateShader|piglit_compile_shader|piglit_build_simple_program|piglit_link_simple_program|glUseProgram|GL_ARB_vertex_program|GL_ARB_fragment_program|glProgramStringARB|GL_VERTEX_PROGRAM_ARB|GL_FRAGMENT_PROGRAM_ARB|piglit_require_GLSL|glVertexAttribPointer|glVertexAttrib[1-4]|glGetAttribLocation'),
 ('fbo', r'glGenFramebuffers|glBindFramebuffer|glFramebufferTexture|glRenderbufferStorage|glBlitFramebuffer'),
 ('texture', r'glTexImage[123]D|glBindTexture|piglit_rgbw_texture|piglit_checkerboard_texture|glTexSubImage|glCopyTex|glTexEnv|glGetTexImage|glTexGen|piglit_depth_texture|glGenTextures|glCompressedTex|glTexParameter|glMultiTexCoord|glTexStorage|GL_TEXTURE_GEN_|glEnable\(\s*GL_TEXTURE_[123]D'),
 ('pixels', r'glDrawPixels|glBitmap\s*\(|glCopyPixels|glPixelTransfer|glPixelMap|glPixelZoom|glWindowPos|glColorTable|glConvolution|glHistogram|glMinmax|piglit_draw_pixels'),
 ('accum', r'glAccum|glClearAccum'),
 ('stencil', r'glStencil(Op|Func|Mask)|GL_STENCIL_TEST|glClearStencil|GL_STENCIL_BUFFER_BIT|piglit_probe_rect_stencil|piglit_probe_pixel_stencil|GL_STENCIL_INDEX'),
 ('blend', r'glBlendFunc|glBlendEquation|glBlendColor|glEnable\(\s*GL_BLEND|glLogicOp|glEnable\(\s*GL_COLOR_LOGIC_OP'),
 ('fog', r'glFog|glEnable\(\s*GL_FOG\b'),
 ('alphatest', r'glAlphaFunc|glEnable\(\s*GL_ALPHA_TEST'),
 ('query', r'glGenQueries|glBeginQuery|GL_SAMPLES_PASSED'),
 ('multisample', r'GL_MULTISAMPLE|glSampleCoverage|GL_SAMPLE_ALPHA_TO'),
 ('sync', r'glFenceSync|glClientWaitSync'),
 ('mapbufferrange', r'glMapBufferRange|glFlushMappedBufferRange'),
 ('copybuffer', r'glCopyBufferSubData'),
 ('primrestart', r'glPrimitiveRestart|GL_PRIMITIVE_RESTART'),
 ('vao', r'glBindVertexArray|glGenVertexArrays'),
 ('basevertex', r'BaseVertex'),
 ('depthclamp', r'GL_DEPTH_CLAMP'),
 ('depthbounds', r'glDepthBoundsEXT'),
 ('colorindex', r'glIndexMask|glClearIndex|PIGLIT_GL_VISUAL_INDEX|GL_COLOR_INDEX\b'),
]


# Checked by hand: what the rules get wrong for these tests.
OVERRIDES = {
 'gl-1.0-beginend-coverage':'-',   # calls every command inside Begin/End only for the error
 'gl-1.0-long-dlist':'-',          # stencil/texture/fog state commands compiled into a list; passes if it does not crash
 'gl-1.5-get-array-attribs':'-',   # queries the fog-coordinate array state only
 'select gl11':'-','select depth':'-','select scissor':'-','select stencil':'stencil','select alpha':'alphatest',
 'mesa_pack_invert-readpixels':'pbo',
 'arb_copy_buffer-get':'copybuffer',
 'nv_primitive_restart-no-core-profile':'core',
 'arb-provoking-vertex-control':'gl3','arb-provoking-vertex-initial':'gl3','arb-quads-follow-provoking-vertex':'gl3',
 'gl-2.1-minmax':'glsl',
 'push-pop-texture-state':'texture',
 'draw-batch':'colorsum',        # GL_COLOR_SUM with glSecondaryColor, unlit
}

HEADER = '''# piglit's fixed-function tests, one test command line a line, after the feature
# group(s) it needs that libglfixed does not have yet ("-": nothing missing).
# Format: <needs> <test binary> [arguments...]   (fields split on white space)
#
# Chosen from piglit's installed opengl.xml.gz profile (Debian's piglit
# 0~git20220119): every test of the groups spec/!opengl 1.0 .. 2.1 (the old
# general/ tests are there too), the fixed-function extension groups (buffer
# objects, provoking vertex, primitive restart, copy/map buffer, occlusion query,
# depth clamp, vertex array objects, fog coordinate, point parameters, multisample
# state), security/initialized-vbo and hiz's window-system tests; without the
# "-samples=N" variants (multisample visuals), and without the tests of the 2.x
# and extension groups that need GLSL (they are not fixed-function tests). The
# needs column comes from piglit's source, the GL commands each test draws with
# (glsl: shaders or ARB programs; pixels: glDrawPixels/glBitmap/glCopyPixels/
# glWindowPos; colorsum: glSecondaryColor summed without lighting; gl3/core: a
# GL 3.2 or a core context), checked by hand for the tests issue 13 names.
'''


def installed_profile():
    """The installed piglit's opengl.xml.gz."""
    try:
        files = subprocess.run(["dpkg", "-L", "piglit"], capture_output=True, text=True).stdout.split()
    except OSError:
        files = []
    files += glob.glob("/usr/lib/*/piglit/tests/opengl.xml.gz")
    for f in files:
        if f.endswith("/tests/opengl.xml.gz") and os.path.exists(f):
            return f
    sys.exit("make_test_list.py: piglit's opengl.xml.gz not found (apt-get install piglit)")


def executables(src):
    """Binary name -> its source files, from piglit's CMakeLists."""
    exe = {}
    for cm in glob.glob(os.path.join(src, "tests", "**", "CMakeLists*.txt"), recursive=True):
        text = re.sub(r"#.*", "", open(cm, errors="replace").read())
        for m in re.finditer(r"piglit_add_executable\s*\(\s*([^\s)]+)\s+([^)]*)\)", text, re.S):
            d = os.path.dirname(cm)
            files = [os.path.join(d, s) for s in m.group(2).split() if re.search(r"\.(c|cpp)$", s)]
            exe.setdefault(m.group(1), files)
    return exe


def selected(profile):
    """(piglit name, argv) of the fixed-function tests, in the profile's order."""
    for e in ET.parse(gzip.open(profile)).getroot():
        name, parts = e.get("name"), e.get("name").split("@")
        if e.get("type") != "gl" or parts[0] not in ("spec", "security", "hiz"):
            continue
        if parts[0] == "security" and parts[1] != "initialized-vbo":
            continue
        if parts[0] == "hiz" and "window" not in parts[1]:
            continue
        if parts[0] == "spec" and not (re.match(r"!opengl (1\.[0-5]|2\.[01])$", parts[1])
                                       or parts[1] in EXT_GROUPS):
            continue
        opts = {o.get("name"): o.get("value") for o in e.findall("option")}
        argv = [a for a in ast.literal_eval(opts["command"]) if a != ""]
        if any(a.startswith("-samples=") for a in argv):
            continue
        yield name, argv


def source_text(files):
    text = ""
    for f in files:
        try:
            text += open(f, errors="replace").read()
        except OSError:
            pass
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    exe = executables(sys.argv[1])
    out = [HEADER]
    for name, argv in selected(installed_profile()):
        cmd = " ".join(argv)
        files = exe.get(argv[0])
        text = source_text(files) if files else ""
        found = [g for g, rx in RULES if re.search(rx, text)] if files else ["?"]
        if "glsl" in found and not name.startswith("spec@!opengl 1.") and cmd not in OVERRIDES:
            continue  # a shader test of the 2.x or extension groups: not fixed-function
        needs = OVERRIDES.get(cmd)
        if needs is None and argv[0].startswith("hiz-stencil-"):
            needs = "stencil"
        if needs is None:
            needs = ",".join(found) if found else "-"
        out.append(f"{needs:<28} {cmd}\n")
    sys.stdout.write("".join(out))


if __name__ == "__main__":
    main()
