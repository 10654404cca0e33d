#!/usr/bin/env python3
"""Random clip-space scenes for mesa_clip_dump / glfixed_clip_dump (README.md).

usage: gen_scenes.py KIND SEED FRAMES > scene.txt
KIND: grid (vertices on the half-pixel grid), flat2d (w = 1, a little outside
the view volume), persp (random w, inside), clip (anything, w < 0 too), tiny,
sliver, near (w close to 0), mix (all of these).
Environment: DEPTH=16|24 forces the depth buffer size, SIZE=WxH the buffer,
CONST=p the probability of constant (non-per-vertex) colours in a frame,
OFFSET=p the probability of polygon offset in a frame, STIPPLE=p of polygon
stipple, SMOOTH=p of GL_POINT_SMOOTH or GL_LINE_SMOOTH, POLYMODE=p of glPolygonMode
other than GL_FILL (their own random streams, so the scenes without them do
not change).
"""
import random, sys, os

GL = dict(POINTS=0, LINES=1, TRIANGLES=4, TRIANGLE_STRIP=5, TRIANGLE_FAN=6, QUADS=7, QUAD_STRIP=8, POLYGON=9,
          FRONT=0x404, BACK=0x405, FRONT_AND_BACK=0x408, CW=0x900, CCW=0x901)
FUNCS = [0x200 + i for i in range(8)]  # NEVER..ALWAYS

kind, seed, frames = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
R = random.Random(seed)
RO = random.Random(seed + 1000)  # polygon offset
RS = random.Random(seed + 2000)  # polygon stipple
RM = random.Random(seed + 3000)  # point and line smoothing
RP = random.Random(seed + 4000)  # polygon modes

def f(x):
    return repr(float(x))

def col():
    return [R.random() for _ in range(4)]

def vertex(kind, W, H):
    if kind == 'grid':  # window-aligned: half-pixel grid in NDC
        gx = R.randint(-4, 2 * W + 4) / 2.0
        gy = R.randint(-4, 2 * H + 4) / 2.0
        return [gx / W * 2 - 1, gy / H * 2 - 1, R.uniform(-1, 1), 1.0]
    if kind == 'flat2d':
        return [R.uniform(-1.1, 1.1), R.uniform(-1.1, 1.1), R.uniform(-1, 1), 1.0]
    if kind == 'persp':  # inside the view volume with random w
        w = R.uniform(0.2, 5)
        return [R.uniform(-w, w), R.uniform(-w, w), R.uniform(-w, w), w]
    if kind == 'clip':  # anything, including behind the eye
        w = R.uniform(-2, 5)
        s = abs(w) * 1.8 + 0.5
        return [R.uniform(-s, s), R.uniform(-s, s), R.uniform(-s, s), w]
    if kind == 'tiny':  # sub-pixel and few-pixel triangles around a shared point
        global _tiny
        if R.random() < 0.34 or '_tiny' not in globals():
            _tiny = (R.uniform(-1, 1), R.uniform(-1, 1))
        s = R.choice([0.5, 2, 4]) / W
        return [_tiny[0] + R.uniform(-s, s), _tiny[1] + R.uniform(-s, s), R.uniform(-1, 1), 1.0]
    if kind == 'sliver':  # long thin triangles, nearly degenerate
        a = R.uniform(-1.2, 1.2); b = R.uniform(-1.2, 1.2)
        return [a + R.uniform(-0.01, 0.01), a * 0.7 + b * 0.01 + R.uniform(-0.003, 0.003), R.uniform(-1, 1), 1.0]
    if kind == 'near':  # close to the eye: tiny w, clipped by the near plane
        w = R.choice([R.uniform(-0.01, 0.05), R.uniform(0.5, 3)])
        return [R.uniform(-1, 1), R.uniform(-1, 1), R.uniform(-1.5, 1.5) * abs(w) - 0.01, w]
    raise SystemExit('kind')

out = []
W, H = R.choice([(64, 64), (37, 29), (100, 60), (16, 48)])
if os.environ.get('SIZE'): W, H = map(int, os.environ['SIZE'].split('x'))
import os
depth = int(os.environ.get('DEPTH', 0)) or R.choice([24, 24, 16])
out.append(f"fb {W} {H} {depth}")
for fr in range(frames):
    out.append(f"clear {f(R.random())} {f(R.random())} {f(R.random())} 0 {f(R.choice([1.0, R.random()]))}")
    out.append(f"shade {R.randint(0, 1)}")
    out.append(f"provoking {R.randint(0, 1)}")
    cull = R.random() < 0.3
    out.append(f"cull {int(cull)} {R.choice([GL['FRONT'], GL['BACK'], GL['BACK'], GL['FRONT_AND_BACK']])} {R.choice([GL['CW'], GL['CCW']])}")
    out.append(f"depth {int(R.random() < 0.7)} {R.choice(FUNCS)} {int(R.random() < 0.85)}")
    if R.random() < 0.3:
        vx, vy = R.randint(-W // 2, W // 2), R.randint(-H // 2, H // 2)
        out.append(f"viewport {vx} {vy} {R.randint(1, 2 * W)} {R.randint(1, 2 * H)}")
    else:
        out.append(f"viewport 0 0 {W} {H}")
    if R.random() < 0.3:
        out.append(f"range {f(R.random())} {f(R.random())}")
    else:
        out.append("range 0 1")
    cs = R.random() < 0.25
    out.append(f"colorsum {int(cs)}")
    ts = R.random() < 0.25
    out.append(f"twoside {int(ts)}")
    out.append(f"constcolor {int(R.random() < float(os.environ.get('CONST', '0.2')))}")
    if RO.random() < float(os.environ.get('OFFSET', '0')):
        en = RO.choice([(1, 0, 0), (1, 0, 0), (1, 1, 1), (0, 1, 0), (0, 0, 1)])
        factor = RO.choice([0.0, 1.0, -1.0, 2.5, RO.uniform(-4, 4), RO.uniform(-300, 300)])
        units = RO.choice([0.0, 1.0, -1.0, 2.0, 4.0, RO.uniform(-100, 100), RO.uniform(-3e5, 3e5)])
        out.append(f"offset {en[0]} {en[1]} {en[2]} {f(factor)} {f(units)}")
    else:
        out.append("offset 0 0 0 0 0")
    if RS.random() < float(os.environ.get('STIPPLE', '0')):
        out.append(f"stipple 1 {RS.randint(0, 1 << 30)}")
    else:
        out.append("stipple 0 0")
    if RP.random() < float(os.environ.get('POLYMODE', '0')):
        modes = [0x1B00, 0x1B01, 0x1B02]  # GL_POINT, GL_LINE, GL_FILL
        out.append(f"polymode {RP.choice(modes)} {RP.choice(modes)}")
    else:
        out.append("polymode 6914 6914")
    if RM.random() < float(os.environ.get('SMOOTH', '0')):
        out.append(f"smooth {RM.randint(0, 1)} {RM.randint(0, 1)}")
    else:
        out.append("smooth 0 0")
    for p in range(R.randint(1, 6)):
        mode = R.choice(['TRIANGLES', 'TRIANGLES', 'TRIANGLE_STRIP', 'TRIANGLE_FAN', 'QUADS', 'QUAD_STRIP', 'POLYGON'])
        n = {'TRIANGLES': 3 * R.randint(1, 4), 'QUADS': 4 * R.randint(1, 3)}.get(mode, R.randint(3, 9))
        vk = kind if kind != 'mix' else R.choice(['grid', 'flat2d', 'persp', 'clip', 'tiny', 'sliver', 'near'])
        out.append(f"begin {GL[mode]} {n}")
        for i in range(n):
            p4 = vertex(vk, W, H)
            c = col()
            s = col()[:3]
            b = col()
            out.append(' '.join(f(x) for x in p4 + c + s + b))
    out.append("dump")
print('\n'.join(out))
