#!/usr/bin/env python3
# tests/course/gen.py -- the course corpus's scenes, from a fixed seed
# See LICENSE for copyright and license.
#
#   python3 tests/course/gen.py [DIR]     (default tests/course)
#
# Writes DIR/r4/NAME.scene, DIR/r7/NAME.scene and DIR/r9/NAME.scene: pipetrace
# scenes for the course's renderers 4, 7 and 9 in named families (the list
# FAMILIES below says what each covers).  Every family draws from a random
# generator of its own, seeded with its name, so a family's scenes do not
# change when another family changes.  Framebuffers are small (16x12 ..
# 80x60): a log with every debug switch stays small.  make-corpus.sh runs
# each scene through the course's jar and stores what it gives.
import os
import random
import struct
import sys

SEED = 45500


def num(x):
    """x as a scene number that reads back to the same double."""
    x = float(x)
    s = repr(x)
    assert "inf" not in s and "nan" not in s, s
    return s


def f32(x):
    """x rounded to the nearest float (the course's float colours)."""
    return struct.unpack("f", struct.pack("f", x))[0]


class Scene:
    """One scene's lines; models are added with model()."""

    def __init__(self, r, name, w, h, named=True):
        self.r = r
        self.lines = ["# %s: renderer %d" % (name, r), "renderer %d" % r]
        if named:
            self.lines.append("scene %s" % name)
        self.lines.append("framebuffer %d %d" % (w, h))
        self.w, self.h = w, h
        self.vw, self.vh = w, h

    def add(self, line):
        self.lines.append(line)

    def text(self):
        return "\n".join(self.lines) + "\n"

    def attach(self, name, text):
        """A file the scene reads (an OBJ file), written beside it."""
        if not hasattr(self, "files"):
            self.files = {}
        self.files[name] = text


def camera_line(rng, r, kind, params=None):
    """The camera line: kind persp|ortho|perspfov|orthofov; params a tuple."""
    word = {"persp": "perspective", "ortho": "orthographic",
            "perspfov": "perspective-fov", "orthofov": "orthographic-fov"}[kind]
    if params:
        return "camera %s %s" % (word, " ".join(num(p) for p in params))
    return "camera %s" % word


def rand_color(rng, floats=0.0):
    """('c', r, g, b) ints or ('cf', r, g, b) floats (exact floats)."""
    if rng.random() < floats:
        kind = rng.random()
        if kind < 0.4:      # k/256: exact, short
            return ("cf",) + tuple(rng.randrange(0, 257) / 256.0 for _ in range(3))
        return ("cf",) + tuple(f32(rng.random()) for _ in range(3))
    return ("c",) + tuple(rng.randrange(0, 256) for _ in range(3))


def emit_model(sc, name, verts, colors=(), prims=(), position=None, translate=None,
               mats=(), hidden=(), color=None):
    """A model: verts (x, y, z); colors ('c'|'cf', r, g, b); prims ('s', i, j
    [, ci, cj]) / ('l', i, j, ...) / ('p', i [, c [, radius]]), 0-based;
    mats (directive, op) for renderer 9; hidden: 'position', 'model'."""
    sc.add("model %s%s" % (name, " " + position if position else ""))
    if translate is not None:
        sc.add("translate %s" % " ".join(num(t) for t in translate))
    for d, op in mats:
        sc.add("%s %s" % (d, op))
    for v in verts:
        sc.add("v %s" % " ".join(num(t) for t in v))
    for c in colors:
        if c[0] == "c":
            sc.add("vcolor %d %d %d" % c[1:])
        else:
            sc.add("vcolor-float %s" % " ".join(num(t) for t in c[1:]))
    if color is not None:
        sc.add("color %d %d %d" % color)
    for p in prims:
        if p[0] == "s":
            sc.add("segment %s" % " ".join(str(i + 1) for i in p[1:]))
        elif p[0] == "l":
            sc.add("l %s" % " ".join(str(i + 1) for i in p[1:]))
        else:
            parts = [str(p[1] + 1)]
            if len(p) > 2:
                parts.append(str(p[2] + 1))
            if len(p) > 3:
                parts.append(str(p[3]))
            sc.add("point %s" % " ".join(parts))
    for h in hidden:
        sc.add("hidden-%s" % h)


CUBE_V = [(x, y, z) for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)]
CUBE_E = [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7),
          (0, 4), (1, 5), (2, 6), (3, 7)]


def cube(rng, scale=1.0, floats=0.0):
    verts = [(x * scale, y * scale, z * scale) for x, y, z in CUBE_V]
    colors = [rand_color(rng, floats) for _ in verts]
    prims = [("s", a, b) for a, b in CUBE_E]
    return verts, colors, prims


def place(sc, rng, verts, tz, spread=0.5):
    """Where a model sits: r4/r7 `translate`, r9 `translate` too (Matrix.translate)."""
    return (rng.uniform(-spread, spread), rng.uniform(-spread, spread), tz)


def fbsize(rng, big=False):
    if big:
        return rng.choice([(64, 48), (80, 60), (72, 54), (60, 80)])
    return rng.choice([(16, 12), (20, 20), (24, 18), (32, 24), (40, 30), (48, 36), (30, 40)])


def switches(sc, rng, aa=None, gamma=None, nearclip=None):
    if aa is None:
        aa = rng.random() < 0.3
    if gamma is None:
        gamma = rng.random() < 0.7
    sc.add("antialias %s" % ("on" if aa else "off"))
    sc.add("gamma %s" % ("on" if gamma else "off"))
    if sc.r != 4 and nearclip is not None:
        sc.add("nearclip %s" % ("on" if nearclip else "off"))


def image_point(u, v, d, persp):
    """A camera-space point that projects (default camera) to about (u, v)."""
    return (u * d, v * d, -d) if persp else (u, v, -d)


# ---------------------------------------------------------------- families
# Each family: f(rng, r, i) -> Scene or None; (name, renderers, count).

def fam_basic(rng, r, name):
    w, h = fbsize(rng, big=rng.random() < 0.3)
    sc = Scene(r, name, w, h)
    persp = rng.random() < 0.7
    sc.add(camera_line(rng, r, "persp" if persp else "ortho"))
    switches(sc, rng)
    verts, colors, prims = cube(rng, 1.0 if persp else 0.5, floats=0.2)
    emit_model(sc, "cube", verts, colors, prims,
               translate=place(sc, rng, verts, rng.uniform(-6, -3.5) if persp else -2.0))
    return sc


def segments_through(rng, sc, persp, pts, colors_float=0.3, cidx=False):
    """One model of segments between the image-plane points pts (pairs)."""
    verts, prims, colors = [], [], []
    for (u0, v0), (u1, v1) in pts:
        d0, d1 = (rng.uniform(1.5, 4.0), rng.uniform(1.5, 4.0)) if persp else (2.0, 2.0)
        if persp and rng.random() < 0.5:
            d1 = d0
        for u, v, d in ((u0, v0, d0), (u1, v1, d1)):
            verts.append((u * d, v * d, -d) if persp else (u, v, -d))
            colors.append(rand_color(rng, colors_float))
        i = len(verts) - 2
        if cidx and rng.random() < 0.5:
            prims.append(("s", i, i + 1, rng.randrange(len(colors)), rng.randrange(len(colors))))
        else:
            prims.append(("s", i, i + 1))
    return verts, colors, prims


def inside(rng, lo=-0.9, hi=0.9):
    return rng.uniform(lo, hi)


SIDES = {"left": (-1, 0), "right": (1, 0), "bottom": (0, -1), "top": (0, 1)}


def outside_on(rng, side, far=2.5):
    sx, sy = SIDES[side]
    if sx:
        return (sx * rng.uniform(1.02, far), inside(rng))
    return (inside(rng), sy * rng.uniform(1.02, far))


def fam_clip_edge(rng, r, name, side):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    persp = rng.random() < 0.5
    sc.add(camera_line(rng, r, "persp" if persp else "ortho"))
    switches(sc, rng)
    pts = []
    for k in range(rng.randint(2, 4)):
        a = (inside(rng), inside(rng))
        b = outside_on(rng, side)
        if k == 0 and rng.random() < 0.5:
            # through: both ends outside, on opposite sides
            opp = {"left": "right", "right": "left", "top": "bottom", "bottom": "top"}[side]
            a = outside_on(rng, opp)
        if k == 1 and rng.random() < 0.4:
            sx, sy = SIDES[side]   # an end exactly on the edge
            a = (float(sx), inside(rng)) if sx else (inside(rng), float(sy))
        if k == 2 and rng.random() < 0.4:
            a = outside_on(rng, side)   # both outside the same edge: trivial delete
        pts.append((a, b) if rng.random() < 0.5 else (b, a))
    verts, colors, prims = segments_through(rng, sc, persp, pts, cidx=True)
    if rng.random() < 0.4:      # a point outside that edge, one inside
        verts.append(image_point(*outside_on(rng, side), 2.0, persp))
        verts.append(image_point(inside(rng), inside(rng), 2.0, persp))
        colors += [rand_color(rng), rand_color(rng)]
        prims += [("p", len(verts) - 2), ("p", len(verts) - 1, len(verts) - 1, rng.randint(0, 1))]
    emit_model(sc, "edge", verts, colors, prims)
    return sc


def fam_clip_corner(rng, r, name, corner):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    persp = rng.random() < 0.5
    sc.add(camera_line(rng, r, "persp" if persp else "ortho"))
    switches(sc, rng)
    sx, sy = corner
    pts = []
    for k in range(rng.randint(2, 4)):
        o = (sx * rng.uniform(1.02, 2.2), sy * rng.uniform(1.02, 2.2))
        if k == 0:
            a = (inside(rng), inside(rng))
        elif k == 1:    # outside beyond x only, to outside beyond y only: cuts or misses the corner
            a = (sx * rng.uniform(0.5, 1.3), sy * rng.uniform(1.02, 1.6))
            o = (sx * rng.uniform(1.02, 1.6), sy * rng.uniform(0.5, 1.3))
        elif k == 2:    # through the exact corner
            t = rng.uniform(0.2, 0.8)
            a = (sx * (1 - t), sy * (1 - t))
            o = (sx * (1 + t), sy * (1 + t))
        else:
            a = (-sx * rng.uniform(0.0, 1.5), -sy * rng.uniform(0.0, 1.5))
        pts.append((a, o) if rng.random() < 0.5 else (o, a))
    verts, colors, prims = segments_through(rng, sc, persp, pts)
    emit_model(sc, "corner", verts, colors, prims)
    return sc


def fam_near(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    ortho = rng.random() < 0.2
    sc.add(camera_line(rng, r, "ortho" if ortho else "persp"))
    near = rng.choice([0.1, 0.5, 1.0, 1.5, 2.0, 3.0, 0.25])
    n = 1.0 if ortho else -0.1          # the Camera's n without `near`
    if rng.random() < 0.85:
        sc.add("near %s" % num(near))
        n = -near
    if r == 9 and rng.random() < 0.3:
        sc.add("view %s %s %s" % (num(rng.uniform(-0.5, 0.5)), num(rng.uniform(-0.5, 0.5)),
                                  num(rng.uniform(-1, 1))))
    switches(sc, rng, nearclip=rng.random() < 0.8)
    verts, colors, prims = [], [], []
    for k in range(rng.randint(3, 6)):
        za = n - rng.uniform(0.05, 3.0)                 # in front of the plane
        zb = n + rng.uniform(0.05, 1.5)                 # behind it
        if k == 0:
            zb = n                                      # on the plane
        if k == 1 and rng.random() < 0.5:
            za = n + rng.uniform(0.05, 0.5)             # both behind: trivial delete
        if k == 2 and rng.random() < 0.5:
            za, zb = n, n - rng.uniform(0.5, 2)         # one end on it, the other in front
        for z in (za, zb):
            d = max(-z, 0.3)
            verts.append((rng.uniform(-0.8, 0.8) * d, rng.uniform(-0.8, 0.8) * d, z))
            colors.append(rand_color(rng, 0.3))
        i = len(verts) - 2
        prims.append(("s", i, i + 1) if rng.random() < 0.5 else ("s", i + 1, i))
    if rng.random() < 0.5:
        verts.append((0.1, 0.1, n + 0.2))
        verts.append((-0.1 * 2, 0.05 * 2, n - 1.0))
        colors += [rand_color(rng), rand_color(rng)]
        prims += [("p", len(verts) - 2, len(verts) - 2, 1), ("p", len(verts) - 1)]
    emit_model(sc, "near", verts, colors, prims)
    return sc


def fam_ortho(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    if r == 4 or rng.random() < 0.25:
        sc.add(camera_line(rng, r, "ortho"))
        l, rr, b, t = -1.0, 1.0, -1.0, 1.0
    else:
        l = -rng.uniform(0.5, 3.0)
        rr = rng.uniform(0.5, 3.0)
        b = -rng.uniform(0.5, 3.0)
        t = rng.uniform(0.5, 3.0)
        if rng.random() < 0.3:
            l, rr = rr - 4.0, rr        # off-centre
        sc.add(camera_line(rng, r, "ortho", (l, rr, b, t)))
    switches(sc, rng, nearclip=rng.random() < 0.7)
    verts, colors, prims = cube(rng, rng.uniform(0.3, 1.2), floats=0.2)
    tz = rng.choice([-3.0, -0.5, 0.5, 2.0])
    emit_model(sc, "box", verts, colors, prims,
               translate=(rng.uniform(l, rr) * 0.5, rng.uniform(b, t) * 0.5, tz))
    return sc


def fam_asym(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    l = -rng.uniform(0.3, 2.5)
    rr = rng.uniform(0.3, 2.5)
    b = -rng.uniform(0.3, 2.5)
    t = rng.uniform(0.3, 2.5)
    if rng.random() < 0.3:
        l, rr = l + 1.0, rr + 1.0
    params = (l, rr, b, t)
    if rng.random() < 0.5:
        params += (rng.choice([0.5, 0.75, 1.0, 2.0, rng.uniform(0.3, 3.0)]),)
    sc.add(camera_line(rng, r, "persp", params))
    switches(sc, rng, nearclip=True)
    verts, colors, prims = cube(rng, 1.0, floats=0.2)
    emit_model(sc, "cube", verts, colors, prims, translate=place(sc, rng, verts, -3.0, 1.0))
    return sc


def fam_fov(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    ortho = rng.random() < 0.3
    fovy = rng.choice([30.0, 45.0, 60.0, 90.0, 120.0, rng.uniform(10, 150)])
    aspect = rng.choice([1.0, w / h, 4.0 / 3.0, 0.5, rng.uniform(0.4, 2.5)])
    sc.add(camera_line(rng, r, "orthofov" if ortho else "perspfov", (fovy, aspect)))
    switches(sc, rng, nearclip=True)
    verts, colors, prims = cube(rng, 1.0 if not ortho else 0.4, floats=0.2)
    emit_model(sc, "cube", verts, colors, prims,
               translate=place(sc, rng, verts, -rng.uniform(2.5, 6.0), 0.8))
    return sc


def fam_vp(rng, r, name):
    w, h = fbsize(rng, big=True)
    sc = Scene(r, name, w, h)
    vw = rng.randint(1, w)
    vh = rng.randint(1, h)
    if rng.random() < 0.6:
        vw, vh = rng.randint(w // 3, w), rng.randint(h // 3, h)
    vx = rng.randint(0, w - vw)
    vy = rng.randint(0, h - vh)
    viewport_cube(sc, rng, r, (vx, vy, vw, vh), 0.6, 0.6, None, 5.0)
    return sc


def viewport_cube(sc, rng, r, vp, bg_p, vpbg_p, aa, far):
    """The viewport vp (x, y, w, h), a background with chance bg_p, a viewport
    background with chance vpbg_p, a camera, the switches (aa None: random)
    and a cube in front of it, at most `far` away."""
    if rng.random() < bg_p:
        sc.add("background %d %d %d" % tuple(rng.randrange(0, 256) for _ in range(3)))
    sc.add("viewport %d %d %d %d" % vp)
    if rng.random() < vpbg_p:
        sc.add("viewport-background %d %d %d" % tuple(rng.randrange(0, 256) for _ in range(3)))
    persp = rng.random() < 0.7
    sc.add(camera_line(rng, r, "persp" if persp else "ortho"))
    switches(sc, rng, aa=aa)
    verts, colors, prims = cube(rng, 1.0 if persp else 0.6, floats=0.2)
    emit_model(sc, "cube", verts, colors, prims,
               translate=place(sc, rng, verts, -rng.uniform(2.5, far) if persp else -2.0, 0.6))


def fam_color(rng, r, name, k):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng)
    n = rng.randint(4, 8)
    verts = [(rng.uniform(-0.95, 0.95), rng.uniform(-0.95, 0.95), -1.0) for _ in range(n)]
    mode = k % 5
    colors, color = [], None
    if mode == 0:       # ints
        colors = [rand_color(rng, 0.0) for _ in range(n)]
    elif mode == 1:     # floats
        colors = [rand_color(rng, 1.0) for _ in range(n)]
    elif mode == 2:     # mixed, more colours than vertices, indices of their own
        colors = [rand_color(rng, 0.5) for _ in range(n + 3)]
    elif mode == 3:     # `color`: one for every vertex
        color = tuple(rng.randrange(0, 256) for _ in range(3))
    # mode 4: none (white, and the course's warnings)
    prims = []
    nc = len(colors) if colors else n
    for _ in range(rng.randint(3, 6)):
        a, b = rng.sample(range(n), 2)
        if mode == 2 or (mode in (0, 1) and rng.random() < 0.3):
            prims.append(("s", a, b, rng.randrange(nc), rng.randrange(nc)))
        else:
            prims.append(("s", a, b))
    if rng.random() < 0.3:
        prims.append(("l", *rng.sample(range(n), 3)))
    emit_model(sc, "paint", verts, colors, prims, color=color)
    return sc


def fam_aa(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    if rng.random() < 0.5:
        sc.add("viewport-background %d %d %d" % tuple(rng.randrange(0, 256) for _ in range(3)))
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng, aa=True)
    pts = [((-1.0, 1.0), (1.0, 1.0)), ((1.0, -1.0), (1.0, 1.0)),      # top row, right column
           ((-1.0, -1.0), (1.0, -1.0)), ((-1.0, -1.0), (-1.0, 1.0))]  # bottom row, left column
    rng.shuffle(pts)
    pts = pts[:rng.randint(1, 4)]
    for _ in range(rng.randint(2, 5)):
        pts.append(((inside(rng, -1.1, 1.1), inside(rng, -1.1, 1.1)),
                    (inside(rng, -1.1, 1.1), inside(rng, -1.1, 1.1))))
    verts, colors, prims = segments_through(rng, sc, False, pts)
    emit_model(sc, "aa", verts, colors, prims)
    return sc


def fam_gamma(rng, r, name, k):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    if rng.random() < 0.6:
        sc.add("viewport-background %d %d %d" % tuple(rng.randrange(0, 120) for _ in range(3)))
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng, aa=bool(k & 1), gamma=bool(k & 2))
    verts, colors, prims = [], [], []
    for j in range(rng.randint(2, 4)):      # grey ramps
        y = rng.uniform(-0.9, 0.9)
        verts += [(-0.95, y, 0.0), (0.95, y + rng.uniform(-0.4, 0.4), 0.0)]
        g0, g1 = rng.randrange(0, 256), rng.randrange(0, 256)
        colors += [("c", g0, g0, g0), ("c", g1, g1, g1)]
        prims.append(("s", 2 * j, 2 * j + 1))
    verts.append((0.0, 0.0, 0.0))
    colors.append(rand_color(rng))
    prims.append(("s", len(verts) - 1, len(verts) - 1))   # degenerate: no gamma
    emit_model(sc, "ramp", verts, colors, prims)
    return sc


def aim_r4(rng, w, h):
    """An image-plane point that renderer 4, which maps a point to the pixel
    plane twice, draws at a pixel of a w x h viewport chosen at random."""
    px, py = rng.randint(1, w), rng.randint(1, h)
    x1 = (px - 0.5) * 2.001 / w - 1
    y1 = (py - 0.5) * 2.001 / h - 1
    return (x1 - 0.5) * 2.001 / w - 1, (y1 - 0.5) * 2.001 / h - 1


def fam_point(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng)
    verts, colors, prims = [], [], []
    for j in range(rng.randint(4, 9)):
        if r == 4 and rng.random() < 0.7:
            u, v = aim_r4(rng, w, h)
        else:
            u, v = rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)
        verts.append((u, v, 0.0))
        colors.append(rand_color(rng, 0.3))
        rad = rng.choice([None, 0, 1, 2, 3, -1])
        c = rng.randrange(len(colors)) if rng.random() < 0.5 else j
        prims.append(("p", j) if rad is None and c == j else ("p", j, c) if rad is None
                     else ("p", j, c, rad))
    if rng.random() < 0.5:      # a segment among the points
        prims.insert(rng.randrange(len(prims)), ("s", 0, 1))
    emit_model(sc, "pts", verts, colors, prims)
    return sc


MAT_OPS = ["identity", "translate", "scale", "scale3", "rotx", "roty", "rotz", "rot", "rows"]


def mat_op(rng, kind):
    if kind == "identity":
        return "identity"
    if kind == "translate":
        return "translate %s %s %s" % tuple(num(rng.uniform(-1, 1)) for _ in range(3))
    if kind == "scale":
        return "scale %s" % num(rng.choice([0.5, 2.0, rng.uniform(0.3, 1.5)]))
    if kind == "scale3":
        return "scale %s %s %s" % tuple(num(rng.uniform(0.3, 1.6)) for _ in range(3))
    if kind in ("rotx", "roty", "rotz"):
        return "rotate %s %s" % (kind[3], num(rng.choice([30.0, 45.0, 90.0, -60.0,
                                                          rng.uniform(-180, 180)])))
    if kind == "rot":
        return "rotate %s %s %s %s" % (num(rng.uniform(-180, 180)),
                                       num(rng.uniform(-1, 1)), num(rng.uniform(-1, 1)),
                                       num(rng.uniform(0.1, 1)))
    rows = [[0.0] * 4 for _ in range(4)]
    for i in range(4):
        rows[i][i] = 1.0
    for i in range(3):
        for j in range(3):
            rows[i][j] += rng.uniform(-0.3, 0.3)
    if rng.random() < 0.3:
        rows[3] = [rng.uniform(-0.1, 0.1) for _ in range(3)] + [rng.uniform(0.8, 1.2)]
    return "rows %s" % " ".join(num(x) for row in rows for x in row)


def fam_mat(rng, r, name, k):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "persp"))
    if rng.random() < 0.3:
        sc.add("view %s %s %s" % tuple(num(rng.uniform(-1, 1)) for _ in range(3)))
    switches(sc, rng, nearclip=True)
    verts, colors, prims = cube(rng, 1.0, floats=0.1)
    mats = []
    tz = -rng.uniform(4.0, 7.0)
    style = k % 4
    if style == 0:      # post-multiplied: translate * R * S (the scale acts first)
        mats.append(("matrix", "translate %s %s %s" % (num(rng.uniform(-1, 1)),
                                                       num(rng.uniform(-1, 1)), num(tz))))
        for _ in range(rng.randint(1, 3)):
            mats.append(("matrix", mat_op(rng, rng.choice(MAT_OPS))))
    elif style == 1:    # pre-multiplied: the last line acts last
        for _ in range(rng.randint(1, 3)):
            mats.append(("matrix-pre", mat_op(rng, rng.choice(MAT_OPS))))
        mats.append(("matrix-pre", "translate 0.0 0.0 %s" % num(tz)))
    elif style == 2:    # set, then more; or translate (SET) then post
        mats.append(("matrix-set", mat_op(rng, rng.choice(MAT_OPS))))
        mats.append(("matrix-set", "translate 0.0 0.0 %s" % num(tz)))
        mats.append(("matrix", mat_op(rng, rng.choice(MAT_OPS))))
    else:
        mats.append(("matrix", mat_op(rng, rng.choice(MAT_OPS))))
        mats.append(("matrix-pre", "translate %s 0.0 %s" % (num(rng.uniform(-1, 1)), num(tz))))
        mats.append(("matrix-pre", mat_op(rng, rng.choice(["rotz", "scale"]))))
    translate = None
    if style == 1 and rng.random() < 0.3:
        translate = (0.0, 0.0, tz)          # Matrix.translate, SET, before the others
    emit_model(sc, "obj", verts, colors, prims, translate=translate, mats=mats)
    return sc


def fam_tie(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng)
    # k/64 and k/32 print as ties in %10.5f and %.4f; float colours k/32 too
    verts = [(rng.randrange(-60, 61) / 64.0, rng.randrange(-60, 61) / 64.0,
              rng.randrange(-64, 1) / 64.0) for _ in range(rng.randint(4, 7))]
    colors = [("cf",) + tuple(rng.randrange(0, 33) / 32.0 for _ in range(3)) if rng.random() < 0.6
              else ("c",) + tuple(rng.randrange(0, 256) for _ in range(3)) for _ in verts]
    prims = [("s",) + tuple(rng.sample(range(len(verts)), 2)) for _ in range(rng.randint(2, 5))]
    emit_model(sc, "tie", verts, colors, prims,
               translate=(rng.randrange(-8, 9) / 64.0, rng.randrange(-8, 9) / 32.0, -1.0))
    return sc


def fam_slope(rng, r, name):
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "ortho"))
    switches(sc, rng)
    pts = []
    for _ in range(rng.randint(3, 6)):
        kind = rng.choice(["deg", "diag", "antidiag", "vert", "horiz", "steep", "shallow"])
        a = (inside(rng), inside(rng))
        dlt = rng.uniform(0.1, 0.8)
        if kind == "deg":
            b = a
        elif kind == "diag":
            b = (a[0] + dlt, a[1] + dlt)
        elif kind == "antidiag":
            b = (a[0] + dlt, a[1] - dlt)
        elif kind == "vert":
            b = (a[0], a[1] + dlt)
        elif kind == "horiz":
            b = (a[0] - dlt, a[1])
        elif kind == "steep":
            b = (a[0] + dlt / 5, a[1] - dlt)
        else:
            b = (a[0] - dlt, a[1] + dlt / 7)
        pts.append((a, b))
    verts, colors, prims = segments_through(rng, sc, False, pts)
    emit_model(sc, "slope", verts, colors, prims)
    return sc


def models_scene(rng, r, name, nmodels, hide=False, p2=False):
    w, h = fbsize(rng, big=rng.random() < 0.3)
    sc = Scene(r, name, w, h, named=rng.random() < 0.8)
    sc.add(camera_line(rng, r, "persp"))
    if p2:
        sc.add("pipeline2")
    switches(sc, rng)
    hidden_done = False
    for m in range(nmodels):
        verts, colors, prims = cube(rng, rng.uniform(0.4, 1.0), floats=0.2)
        if rng.random() < 0.3:
            colors = []
        hidden = ()
        if hide and (not hidden_done or rng.random() < 0.3):
            hidden = (rng.choice(["position", "model"]),)
            if rng.random() < 0.2:
                hidden = ("position", "model")
            hidden_done = True
        pos = "pos%d" % m if rng.random() < 0.5 else None
        mats = ()
        translate = (rng.uniform(-2, 2), rng.uniform(-1.5, 1.5), -rng.uniform(4, 8))
        if r == 9 and rng.random() < 0.4:
            mats = (("matrix", mat_op(rng, rng.choice(["rotx", "roty", "rotz", "scale"]))),)
        emit_model(sc, "m%d" % m, verts, colors, prims, position=pos, translate=translate,
                   mats=mats, hidden=hidden)
    return sc


def fam_hidden(rng, r, name):
    return models_scene(rng, r, name, rng.randint(2, 3), hide=True)


def fam_pipeline2(rng, r, name):
    return models_scene(rng, r, name, rng.randint(1, 3), hide=rng.random() < 0.3, p2=True)


def fam_multi(rng, r, name):
    return models_scene(rng, r, name, rng.randint(2, 4))


def fam_deflog(rng, r, name):
    sc = fam_basic(rng, r, name) if rng.random() < 0.5 else fam_multi(rng, r, name)
    return sc


def fam_face(rng, r, name):
    """`f` faces (closed outlines) and `l` polylines: a pyramid."""
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "persp"))
    switches(sc, rng)
    verts = [(-1.0, -1.0, -1.0), (1.0, -1.0, -1.0), (1.0, -1.0, 1.0), (-1.0, -1.0, 1.0),
             (0.0, 1.0, 0.0)]
    sc.add("model pyramid")
    sc.add("translate %s %s %s" % (num(rng.uniform(-0.5, 0.5)), num(rng.uniform(-0.5, 0.5)),
                                   num(-rng.uniform(3.5, 5.0))))
    for v in verts:
        sc.add("v %s" % " ".join(num(t) for t in v))
    for _ in verts:
        c = rand_color(rng, 0.3)
        sc.add("vcolor %d %d %d" % c[1:] if c[0] == "c" else
               "vcolor-float %s" % " ".join(num(t) for t in c[1:]))
    sc.add("f 1 2 3 4")
    sc.add("f 1 2 5" if rng.random() < 0.5 else "f -5 -4 -1")
    sc.add("l 3 5 4")
    return sc


def fam_near_edge(rng, r, name, k):
    """near 0 (n = -0.0: the camera plane itself) and a negative near (the
    plane behind the camera): the course accepts both."""
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    sc.add(camera_line(rng, r, "persp" if k % 3 else "ortho"))
    near = [0.0, -0.5, 0.0, -1.0][k % 4]
    sc.add("near %s" % num(near))
    switches(sc, rng, nearclip=k < 4)
    verts = [(0.5, 0.25, -2.0), (rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 0.0),
             (-0.5, 0.5, -1.0), (0.25, -0.5, 0.5), (rng.uniform(-1, 1), 0.5, -near)]
    colors = [rand_color(rng) for _ in verts]
    prims = [("s", 0, 2), ("s", 0, 3), ("s", 2, 4), ("p", 2, 2, 1)]
    if k % 2:
        prims.append(("s", 1, 2))       # an end on the camera plane: Infinity
    emit_model(sc, "edge", verts, colors, prims)
    return sc


def fam_err(rng, r, name, k):
    """What the course's renderer throws on: a colour index past the colour list."""
    sc = Scene(r, name, 16, 12)
    sc.add(camera_line(rng, r, "ortho"))
    verts = [(rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), 0.0) for _ in range(4)]
    colors = [rand_color(rng) for _ in range(2)]
    if k % 3 == 0:
        prims = [("s", 0, 1), ("s", 2, 3)]              # vertex 2, 3's colours missing
    elif k % 3 == 1:
        prims = [("s", 0, 1, 0, 5)]
    else:
        prims = [("p", 3)]
    emit_model(sc, "bad", verts, colors, prims)
    return sc


def fam_obj(rng, r, name, k):
    """`obj FILE`: a pyramid's OBJ file (v, f with v/vt/vn and negative
    indices, l, lines the scene's reader passes over) read into a model,
    with vertices and segments of the scene's own before and after it."""
    w, h = fbsize(rng)
    sc = Scene(r, name, w, h)
    persp = k % 4 != 3
    sc.add(camera_line(rng, r, "persp" if persp else "ortho"))
    switches(sc, rng)
    s = rng.uniform(0.4, 0.9) if persp else rng.uniform(0.2, 0.45)
    verts = [(-s, -s, -s), (s, -s, -s), (s, -s, s), (-s, -s, s), (0.0, s, 0.0)]
    if k % 2:                               # beyond the view rectangle, for the clip
        verts[4] = (0.0, 3.0 * s, 0.0)
    obj = ["# %s: a pyramid" % name, "o pyramid", "mtllib none.mtl"]
    obj += ["v %s" % " ".join(num(t) for t in v) for v in verts]
    obj += ["vt 0 0", "vn 0 1 0", "s off", "usemtl none"]
    obj += ["f 1/1/1 2/1/1 3/1/1 4/1/1", "f -5//1 -4//1 -1//1", "l 3 5 4"]
    fname = name + ".obj"
    sc.attach(fname, "\n".join(obj) + "\n")
    sc.add("model pyr")
    tz = -rng.uniform(2.5, 4.0) if persp else -2.0
    sc.add("translate %s %s %s" % (num(rng.uniform(-0.4, 0.4)), num(rng.uniform(-0.4, 0.4)),
                                   num(tz)))
    sc.add("v %s" % " ".join(num(t) for t in (-s, s, -s)))      # before the file's
    for _ in range(len(verts) + 2):
        c = rand_color(rng, 0.3)
        sc.add("vcolor %d %d %d" % c[1:] if c[0] == "c" else
               "vcolor-float %s" % " ".join(num(t) for t in c[1:]))
    sc.add("obj %s" % fname)
    sc.add("v %s" % " ".join(num(t) for t in (s, s, s)))        # after it
    sc.add("segment 1 %d" % (len(verts) + 2))
    sc.add("segment 6 7 1 3")
    if k % 3 == 0:
        sc.add("point 6 2 1")
    return sc


SHAPES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "shapes")


def shape_size(spec):
    """`shape SPEC`'s vertex count and largest |coordinate|, from the model
    the course's jar built (tests/data/shapes; scene2case.py reads it too)."""
    with open(os.path.join(SHAPES, spec.replace(" ", "_") + ".expect")) as f:
        vs = [[float(t) for t in line.split()[1:4]] for line in f if line.startswith("v ")]
    assert vs, spec
    return len(vs), max(abs(t) for v in vs for t in v)


# Per renderer: (shapes, style); each shape has a model of the jar in SHAPES.
SHAPE_SCENES = {
    4: [(["torus 1 0.25 3 3"], "plain"), (["sphere 3 4 7"], "vcolor"),
        (["icosahedron", "circle 1 3"], "mixed"), (["pyramid 2 1 3 2"], "ortho"),
        (["cone 1 2 3 5"], "clip"), (["ring 2 0.5 3 10", "disk 1.5 3 8"], "multi"),
        (["squaregrid 1 2 5"], "clip")],
    7: [(["cylinder 1 0.25 3 9"], "plain"), (["dodecahedron"], "vcolor"),
        (["octahedron", "circle 0.3 7"], "mixed"), (["torus 2 0.75 5 7"], "ortho"),
        (["cone 2 -1 4 6"], "clip"), (["sphere 3 4 7"], "near"),
        (["box 1 2 3", "tetrahedron"], "multi"), (["pyramid 1.5 2 4 5"], "near")],
    9: [(["icosidodecahedron"], "plain"), (["cone 0.75 1.5 2 4"], "vcolor"),
        (["cube", "axes3d 2 3 -1"], "mixed"), (["disk 1.5 3 8"], "ortho"),
        (["torus 2 0.75 5 7"], "clip"), (["cylinder 2 1 2 4"], "near"),
        (["ring 1 0.5 1 3", "sphere 3 4 7"], "multi"), (["square 2.5"], "near")],
}


def fam_shape(rng, r, name, k):
    """`shape NAME ARGS`: the course's models (scene2case.py writes the
    jar's vertices and segments into the case), alone, per-vertex coloured,
    two in one model joined by an `l`, two models; orthographic, across an
    edge of the view rectangle, across the near plane (7, 9); renderer 9
    turns them with `matrix rotate`."""
    if k >= len(SHAPE_SCENES[r]):
        return None
    specs, style = SHAPE_SCENES[r][k]
    w, h = fbsize(rng, big=rng.random() < 0.4)
    sc = Scene(r, name, w, h)
    sizes = [shape_size(sp) for sp in specs]
    ext = max(e for _, e in sizes)
    if style == "ortho" and r == 4:
        sc.add(camera_line(rng, r, "ortho"))
    elif style == "ortho":
        e = ext * rng.uniform(1.1, 1.5)
        sc.add(camera_line(rng, r, "ortho", (-e, e, -e * h / w, e * h / w)))
    else:
        sc.add(camera_line(rng, r, "persp"))
    near = None
    if style == "near":
        near = rng.choice([0.5, 1.0, 1.5])
        sc.add("near %s" % num(near))
    switches(sc, rng, aa=k % 3 == 1 or None, nearclip=True)
    models = [specs] if style != "multi" else [[sp] for sp in specs]
    for m, group in enumerate(models):
        sc.add("model s%d%s" % (m, " at%d" % m if style == "multi" else ""))
        d = ext * 2.5 + 1.0
        if style == "ortho":
            t = (0.0, 0.0, -3.0)
        elif style == "clip":
            side = rng.choice([-1, 1])
            t = (side * d * rng.uniform(0.85, 1.1), rng.uniform(-0.3, 0.3) * d, -d)
            if rng.random() < 0.5:
                t = (t[1], t[0], t[2])
        elif style == "near":
            t = (rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                 -near - rng.uniform(-0.5, 0.5) * ext)
        elif style == "multi":
            t = ((m * 2 - 1) * ext * 1.2, rng.uniform(-0.5, 0.5), -(ext * 4.0 + 1.0))
        else:
            t = (rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), -d)
        sc.add("translate %s" % " ".join(num(x) for x in t))
        if r == 9:
            for axis in rng.sample("xyz", rng.randint(1, 2)):
                sc.add("matrix rotate %s %s" % (axis, num(rng.choice([30.0, 45.0, -60.0,
                                                                     rng.uniform(-90, 90)]))))
        for sp in group:
            sc.add("shape %s" % sp)
        if style == "mixed":
            sc.add("l 1 %d" % (sizes[0][0] + 1))
        if style == "vcolor":
            for _ in range(sum(n for n, _ in sizes)):
                c = rand_color(rng, 0.3)
                sc.add("vcolor %d %d %d" % c[1:] if c[0] == "c" else
                       "vcolor-float %s" % " ".join(num(x) for x in c[1:]))
        else:
            sc.add("color %d %d %d" % tuple(rng.randrange(64, 256) for _ in range(3)))
    return sc


VPOUT = ["left", "right", "top", "bottom", "ul", "ur", "ll", "lr", "out-left", "out-right",
         "out-above", "out-below", "wide", "tall", "huge", "far"]


def fam_vpout(rng, r, name, k):
    """A viewport that sticks out of the framebuffer (setViewport checks
    nothing): off one side or corner, wholly outside, wider or taller than
    the framebuffer (rows wrap), far off; negative origins."""
    kind = VPOUT[k % len(VPOUT)]
    w, h = rng.choice([(16, 12), (20, 16), (24, 18), (12, 20)])
    sc = Scene(r, name, w, h)
    vw, vh = rng.randint(w // 2, w), rng.randint(h // 2, h)
    vx, vy = rng.randint(0, w - vw), rng.randint(0, h - vh)
    if kind in ("left", "ul", "ll"):
        vx = -rng.randint(1, vw - 1)
    if kind in ("right", "ur", "lr"):
        vx = w - vw + rng.randint(1, vw - 1)
    if kind in ("top", "ul", "ur"):
        vy = -rng.randint(1, vh - 1)
    if kind in ("bottom", "ll", "lr"):
        vy = h - vh + rng.randint(1, vh - 1)
    if kind == "out-left":
        vx = -vw - rng.randint(0, 4)
    if kind == "out-right":
        vx = w + rng.randint(0, 4)
    if kind == "out-above":
        vy = -vh - rng.randint(0, 3)
    if kind == "out-below":
        vy = h + rng.randint(0, 3)
    if kind in ("wide", "huge"):
        vw = w + rng.randint(1, w)
        vx = rng.randint(-w // 2, 2)
    if kind in ("tall", "huge"):
        vh = h + rng.randint(1, h // 2)
        vy = rng.randint(-h // 2, 1)
    if kind == "far":
        vx, vy = -3 * w - rng.randint(0, 9), rng.randint(-2 * h, 2 * h)
    viewport_cube(sc, rng, r, (vx, vy, vw, vh), 0.5, 0.7, k % 3 == 1, 4.0)
    if k % 2 == 0:              # points among segments, inside the viewport
        verts, colors, prims = [], [], []
        for j in range(rng.randint(3, 6)):
            if r == 4:
                u, v = aim_r4(rng, vw, vh)
            else:
                u, v = rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)
            verts.append((u, v, -1.0))
            colors.append(rand_color(rng, 0.3))
            prims.append(("p", j, j, rng.choice([0, 1, 2])))
        prims.insert(rng.randrange(len(prims)), ("s", 0, len(verts) - 1))
        emit_model(sc, "pts", verts, colors, prims)
    return sc


ALL, R79, R9 = (4, 7, 9), (7, 9), (9,)
FAMILIES = [  # (family, renderers, count, function(rng, r, name, k))
    ("basic", ALL, 12, lambda g, r, n, k: fam_basic(g, r, n)),
    ("clip-edge-left", ALL, 8, lambda g, r, n, k: fam_clip_edge(g, r, n, "left")),
    ("clip-edge-right", ALL, 8, lambda g, r, n, k: fam_clip_edge(g, r, n, "right")),
    ("clip-edge-top", ALL, 8, lambda g, r, n, k: fam_clip_edge(g, r, n, "top")),
    ("clip-edge-bottom", ALL, 8, lambda g, r, n, k: fam_clip_edge(g, r, n, "bottom")),
    ("clip-corner-ul", ALL, 6, lambda g, r, n, k: fam_clip_corner(g, r, n, (-1, 1))),
    ("clip-corner-ur", ALL, 6, lambda g, r, n, k: fam_clip_corner(g, r, n, (1, 1))),
    ("clip-corner-ll", ALL, 6, lambda g, r, n, k: fam_clip_corner(g, r, n, (-1, -1))),
    ("clip-corner-lr", ALL, 6, lambda g, r, n, k: fam_clip_corner(g, r, n, (1, -1))),
    ("near", R79, 24, lambda g, r, n, k: fam_near(g, r, n)),
    ("ortho", ALL, 12, lambda g, r, n, k: fam_ortho(g, r, n)),
    ("asym", R79, 14, lambda g, r, n, k: fam_asym(g, r, n)),
    ("fov", R79, 12, lambda g, r, n, k: fam_fov(g, r, n)),
    ("vp", ALL, 14, lambda g, r, n, k: fam_vp(g, r, n)),
    ("vpout", ALL, 16, fam_vpout),
    ("color", ALL, 15, fam_color),
    ("aa", ALL, 12, lambda g, r, n, k: fam_aa(g, r, n)),
    ("gamma", ALL, 8, fam_gamma),
    ("point", ALL, 14, lambda g, r, n, k: fam_point(g, r, n)),
    ("mat", R9, 32, fam_mat),
    ("tie", ALL, 12, lambda g, r, n, k: fam_tie(g, r, n)),
    ("slope", ALL, 10, lambda g, r, n, k: fam_slope(g, r, n)),
    ("hidden", ALL, 8, lambda g, r, n, k: fam_hidden(g, r, n)),
    ("pipeline2", R9, 10, lambda g, r, n, k: fam_pipeline2(g, r, n)),
    ("multi", ALL, 8, lambda g, r, n, k: fam_multi(g, r, n)),
    ("deflog", ALL, 6, lambda g, r, n, k: fam_deflog(g, r, n)),
    ("face", ALL, 4, lambda g, r, n, k: fam_face(g, r, n)),
    ("near-edge", R79, 6, fam_near_edge),
    ("err", ALL, 3, fam_err),
    ("obj", ALL, 4, fam_obj),
    ("shape", ALL, 8, fam_shape),
]


def generate():
    """Yield (renderer, name, text, files) for every scene of the corpus:
    files, {NAME: text}, are what it reads beside it."""
    for fam, rends, count, fn in FAMILIES:
        for r in rends:
            rng = random.Random("%d-%s-%d" % (SEED, fam, r))
            for k in range(count):
                name = "%s-%02d" % (fam, k)
                sc = fn(rng, r, name, k)
                if sc is None:
                    continue
                yield r, name, sc.text(), getattr(sc, "files", {})


def main():
    top = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(
        os.path.abspath(__file__)))
    n = {}
    for r, name, text, files in generate():
        d = os.path.join(top, "r%d" % r)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, name + ".scene"), "w") as f:
            f.write(text)
        for fname, ftext in sorted(files.items()):
            with open(os.path.join(d, fname), "w") as f:
                f.write(ftext)
        n[r] = n.get(r, 0) + 1
    print(" ".join("r%d: %d scenes" % (r, n[r]) for r in sorted(n)))


if __name__ == "__main__":
    main()
