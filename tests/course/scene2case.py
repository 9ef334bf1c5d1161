#!/usr/bin/env python3
# tests/course/scene2case.py -- a pipetrace scene as a case of the course's harness
# See LICENSE for copyright and license.
#
#   python3 tests/course/scene2case.py SCENE [DEBUG] > CASE
#
# Writes the case (the harness's line format: KraftN.java, the course
# README's "Case format") that builds SCENE with the course's API.  DEBUG is
# the case's debug line (default "all").  The case's first line is a comment
# naming the renderer (`# renderer N`), whose harness reads it.  Knows the
# directives gen.py writes
# and the classic ones (v, l polylines, f faces, color); `obj PATH` is read
# (relative to the scene's folder) as its v, l and f lines, indices counting
# the file's own vertices; `shape NAME ARGS` is read as the model the
# course's jar builds, stored in tests/data/shapes/NAME_ARGS.expect (made by
# that folder's make.sh and ShapeDump.java), so the case does not take
# pipetrace's word for a shape: a shape with no such file is refused (exit
# 2), as is anything it does not know.
import os
import sys

SHAPES = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                      "..", "data", "shapes"))

CAMERAS = {"perspective": "persp", "orthographic": "ortho",
           "perspective-fov": "perspfov", "orthographic-fov": "orthofov"}
ONOFF = {"on": "1", "off": "0"}


class Bad(Exception):
    pass


def matop(f):
    """A scene matrix OP (fields) as the harness's OP."""
    if f[0] == "rotate" and len(f) == 3 and f[1] in ("x", "y", "z"):
        return "rot%s %s" % (f[1], f[2])
    if f[0] == "rotate":
        return "rot " + " ".join(f[1:])
    return " ".join(f)


class Model:
    def __init__(self, name, pos):
        self.head = ["model %s%s" % (name, " " + pos if pos else "")]
        self.nv = 0
        self.body = []          # v, c, cf, l, p, hide lines in order
        self.color = None       # `color R G B`

    def index(self, s, what):
        i = int(s.split("/")[0])
        if i < 0:
            i += self.nv + 1
        if not 1 <= i <= self.nv:
            raise Bad("%s index %s out of range" % (what, s))
        return i - 1

    def lines(self):
        out = self.head + self.body
        if self.color is not None:
            out += ["c %d %d %d" % self.color] * self.nv
        return out


OBJ_IGNORED = ("vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib")


def obj_lines(path):
    """An OBJ file's v, l and f lines as scene lines, indices shifted to
    count the model's vertices (negative ones resolved within the file)."""
    out, nv = [], 0
    with open(path) as f:
        for raw in f:
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            w = line.split()
            if w[0] == "v":
                out.append(("v", w[1:4]))
                nv += 1
            elif w[0] in ("l", "f"):
                ix = []
                for x in w[1:]:
                    i = int(x.split("/")[0])
                    ix.append(i + nv + 1 if i < 0 else i)
                out.append((w[0], ix))
            elif w[0] not in OBJ_IGNORED:
                raise Bad("%s: '%s' is not OBJ" % (path, w[0]))
    return out


def shape_model(args, shapes=SHAPES):
    """`shape NAME ARGS` (its fields) as the course's jar builds it: its
    vertices (coordinates as Java printed them) and segments (0-based)."""
    path = os.path.join(shapes, "_".join(args) + ".expect")
    if not os.path.exists(path):
        raise Bad("shape %s: no model of the course's jar in %s" % (" ".join(args), path))
    verts, segs = [], []
    with open(path) as f:
        for raw in f:
            w = raw.split()
            if w[0] == "v":
                verts.append(w[1:4])
            elif w[0] == "l":
                segs.append((int(w[1]), int(w[2])))
            elif w[0] == "error":
                raise Bad("shape %s: the course's constructor refuses it" % " ".join(args))
    return verts, segs


def convert(text, debug="all", base=".", shapes=SHAPES):
    renderer = 4
    head = {}
    models = []
    m = None
    for no, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        f = line.split()
        d, a = f[0], f[1:]
        if d == "renderer":
            renderer = int(a[0])
        elif d == "scene":
            head["scene"] = a[0]
        elif d == "framebuffer":
            head["fb"] = a
        elif d == "background":
            head["bg"] = a
        elif d == "viewport":
            head["vp"] = a
        elif d == "viewport-background":
            head["vpbg"] = a
        elif d == "camera":
            head["camera"] = [CAMERAS[a[0]]] + a[1:]
        elif d in ("near", "view"):
            head.setdefault("after", []).append("%s %s" % (d, " ".join(a)))
        elif d == "nearclip":
            head["nearclip"] = ONOFF[a[0]]
        elif d == "antialias":
            head["aa"] = ONOFF[a[0]]
        elif d == "gamma":
            head["gamma"] = ONOFF[a[0]]
        elif d == "pipeline2":
            head["pipeline"] = "2"
        elif d == "model":
            m = Model(a[0], a[1] if len(a) > 1 else None)
            models.append(m)
        elif m is None:
            raise Bad("line %d: '%s' before any model" % (no, d))
        elif d == "translate":
            m.body.append("t " + " ".join(a))
        elif d in ("matrix", "matrix-pre", "matrix-set"):
            m.body.append({"matrix": "m", "matrix-pre": "mpre", "matrix-set": "mset"}[d]
                          + " " + matop(a))
        elif d == "v":
            m.body.append("v " + " ".join(a[:3]))
            m.nv += 1
        elif d == "vcolor":
            m.body.append("c " + " ".join(a))
        elif d == "vcolor-float":
            m.body.append("cf " + " ".join(a))
        elif d == "color":
            m.color = tuple(int(x) for x in a)
        elif d == "segment":
            ix = [m.index(a[0], "vertex"), m.index(a[1], "vertex")]
            if len(a) > 2:
                ix += [int(a[2]) - 1, int(a[3]) - 1]
            m.body.append("l " + " ".join(str(i) for i in ix))
        elif d == "obj":
            first = m.nv                    # the file's vertex 1
            for kind, args in obj_lines(os.path.join(base, a[0])):
                if kind == "v":
                    m.body.append("v " + " ".join(args))
                    m.nv += 1
                    continue
                ix = [first + i - 1 for i in args]
                if not all(first <= i < m.nv for i in ix):
                    raise Bad("line %d: an index of %s out of range" % (no, a[0]))
                if kind == "f":
                    ix.append(ix[0])
                m.body += ["l %d %d" % (i, j) for i, j in zip(ix, ix[1:])]
        elif d == "shape":
            verts, segs = shape_model(a, shapes)
            first = m.nv
            m.body += ["v " + " ".join(v) for v in verts]
            m.nv += len(verts)
            m.body += ["l %d %d" % (first + i, first + j) for i, j in segs]
        elif d in ("l", "f"):
            ix = [m.index(x, "vertex") for x in a]
            if d == "f":
                ix.append(ix[0])
            m.body += ["l %d %d" % (i, j) for i, j in zip(ix, ix[1:])]
        elif d == "point":
            parts = [str(m.index(a[0], "vertex"))]
            if len(a) > 1:
                parts.append(str(int(a[1]) - 1))
            if len(a) > 2:
                parts.append(a[2])
            m.body.append("p " + " ".join(parts))
        elif d == "hidden-position":
            m.body.append("hidepos")
        elif d == "hidden-model":
            m.body.append("hidemodel")
        else:
            raise Bad("line %d: '%s' has no case directive" % (no, d))
    fb = head.get("fb", ["800", "600"])
    out = ["# renderer %d" % renderer, "scene %s" % head.get("scene", "")]
    out.append("fb %s %s%s" % (fb[0], fb[1], " " + " ".join(head["bg"]) if "bg" in head else ""))
    if "vp" in head or "vpbg" in head:
        vp = head.get("vp", ["0", "0"] + fb)
        out.append("vp %s%s" % (" ".join(vp), " " + " ".join(head["vpbg"]) if "vpbg" in head
                                else ""))
    out.append("camera " + " ".join(head.get("camera", ["persp"])))
    out += head.get("after", [])
    if renderer != 4:
        out.append("nearclip %s" % head.get("nearclip", "1"))
    if "pipeline" in head:
        out.append("pipeline 2")
    out.append("aa %s" % head.get("aa", "0"))
    out.append("gamma %s" % head.get("gamma", "1"))
    out.append("debug %s" % debug)
    for mod in models:
        out += mod.lines()
    if head.get("scene", "") == "":
        out[1] = "# scene: none"
    return renderer, "\n".join(out) + "\n"


def main():
    if len(sys.argv) < 2:
        sys.stderr.write("usage: scene2case.py SCENE [DEBUG]\n")
        sys.exit(1)
    with open(sys.argv[1]) as f:
        text = f.read()
    try:
        _, case = convert(text, sys.argv[2] if len(sys.argv) > 2 else "all",
                          os.path.dirname(sys.argv[1]) or ".")
    except (Bad, ValueError, IndexError, KeyError, OSError) as e:
        sys.stderr.write("%s: %s\n" % (sys.argv[1], e))
        sys.exit(2)
    sys.stdout.write(case)


if __name__ == "__main__":
    main()
