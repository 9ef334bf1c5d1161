#!/usr/bin/env python3
# tests/journey/journey_wasm.py -- the journey page's sliders against the command line, bit for bit
# See LICENSE for copyright and license.
#
# Usage: python3 tests/journey/journey_wasm.py PIPETRACE DOM SCENE|- TMPDIR
# DOM is tests/journey/journey_sliders.html's --dump-dom after moving the sliders of
# a page made from SCENE ("-": the built-in scene, docs/examples/builtin.scene).
# It writes SCENE again with the page's framebuffer, viewport and the vertex's
# model's translation (the matrix camera: eye, fov, near and far too), runs `PIPETRACE NEW --format jsonl` for that vertex and
# checks every stage's values against the page's (#livetable: reals as IEEE
# bits, so equal means bit for bit), and #coords against the #coords the
# command line's own page gives for NEW.  When the page says it has no camera,
# pipetrace must refuse NEW with the same reason.  A page of the course's
# renderer 7 or 9 (sliders l, r, b, t, n, the translation or view vector,
# renderer 9's matrix operations' arguments, the viewport, the framebuffer):
# the camera, near, translate or view, matrix, viewport and framebuffer lines
# are written again, and each stage's values (renderer 9: w too) compared
# with the trace's record of the vertex at that stage (a clip stage leaves a
# vertex it did not make as the stage before gave it), the viewport and
# framebuffer pixel with the command line's page, the index with the
# course's y_fb*W + x_fb in Java ints.  Prints "N passed, N failed".
import html
import json
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish  # noqa: E402


def rewrite(text, p, model):
    """The scene with the page's framebuffer, viewport and model translation,
    and for the matrix camera its eye, fov, near and far."""
    out = ["framebuffer %s %s" % (p["W"], p["H"]),
           "viewport %s %s %s %s" % (p["x_ul"], p["y_ul"], p["w"], p["h"])]
    here = False
    for line in text.splitlines():
        words = line.split("#")[0].split()
        d = words[0] if words else ""
        if d in ("framebuffer", "viewport"):
            continue
        if d == "camera" and "fov" in p:       # camera lookat[-target] EYE ...
            line = " ".join(words[:2] + [p["eye_x"], p["eye_y"], p["eye_z"]] + words[5:])
        if d == "projection" and "fov" in p:   # projection perspective FOV ASPECT NEAR FAR
            line = " ".join(words[:2] + [p["fov"], words[3], p["near"], p["far"]])
        if d == "model":
            here = len(words) > 1 and words[1] == model
        if here and d == "translate":
            continue
        out.append(line)
        if d == "model" and here:
            out.append("translate %s %s %s" % (p["x_t"], p["y_t"], p["z_t"]))
    return "\n".join(out) + "\n"


def rewrite79(text, p, model):
    """A renderer 7 or 9 scene with the page's camera, near plane, viewport,
    framebuffer size and the position's translation (7) or the camera's view
    vector and its matrix's angles, translations, scale factors and rows (9)."""
    n = p["n"]
    near = n[1:] if n.startswith("-") else "-" + n
    out, here, proj = [], False, "perspective"
    for line in text.splitlines():
        words = line.split("#")[0].split()
        d = words[0] if words else ""
        if d == "camera":
            proj = "orthographic" if words[1].startswith("orthographic") else "perspective"
            continue
        if d in ("near", "viewport", "view") or (d == "translate" and here and "x_t" in p):
            continue
        if d == "framebuffer":                   # framebuffer W H
            words[1:3] = [p["W"], p["H"]]
            line = " ".join(words)
        if d == "model":
            here, op = len(words) > 1 and words[1] == model, 0
        if here and "view_x" in p and d in ("matrix", "matrix-pre", "matrix-set", "translate"):
            op += 1                              # renderer 9: the matrix's K-th operation
            if "angle_%d" % op in p:             # rotate x|y|z DEG, or rotate DEG X Y Z
                words[3 if words[2] in ("x", "y", "z") else 2] = p["angle_%d" % op]
            if "tx_%d" % op in p:
                words[len(words) - 3:] = [p["%s_%d" % (c, op)] for c in ("tx", "ty", "tz")]
            if "scale_%d" % op in p:             # scale S
                words[2:] = [p["scale_%d" % op]]
            if "sx_%d" % op in p:                # scale X Y Z
                words[2:] = [p["%s_%d" % (c, op)] for c in ("sx", "sy", "sz")]
            if "a00_%d" % op in p:               # rows A00 A01 ... A33
                words[2:] = [p["a%d%d_%d" % (i // 4, i % 4, op)] for i in range(16)]
            line = " ".join(words)
        out.append(line)
        if d == "model" and here and "x_t" in p:
            out.append("translate %s %s %s" % (p["x_t"], p["y_t"], p["z_t"]))
        if d == "renderer":
            out.append("viewport %s %s %s %s" % (p["x_ul"], p["y_ul"], p["w"], p["h"]))
            out.append("near %s" % near)
            if "view_x" in p:
                out.append("view %s %s %s" % (p["view_x"], p["view_y"], p["view_z"]))
    cam = "camera %s %s %s %s %s" % (proj, p["l"], p["r"], p["b"], p["t"])
    k = [i for i, ln in enumerate(out) if ln.split()[:1] == ["renderer"]][0]
    return "\n".join(out[:k + 1] + [cam] + out[k + 1:]) + "\n"


def course(exe, src, p, page, info, tmp):
    """The course page's table against the moved scene's trace and page."""
    model, v = info["vertex"][0], info["vertex"][1]
    new = os.path.join(tmp, "moved.scene")
    with open(new, "w", encoding="utf-8") as f:
        f.write(rewrite79(open(src, encoding="utf-8").read(), p, model))
    r = subprocess.run([exe, new, "--format", "jsonl", "--trace", "-"], capture_output=True,
                       text=True)
    check("slider79-1 the command line reads the moved scene", r.returncode == 0, r.stderr)
    rec = {}
    for ln in r.stdout.splitlines():
        x = json.loads(ln)
        if x.get("type") == "vertex" and x["model"] == model and str(x["v"]) == v:
            rec[x["stage"]] = x
    order = [st for st in ("model", "world", "view", "camera", "nearclip", "image", "clip")
             if st in page]
    check("slider79-2 the table's stages", order == [st for st in (
        "model", "world", "view", "camera", "nearclip", "image", "clip")
        if st != "world" or "view_x" in p], "%s" % sorted(page))
    before = None
    for st in order:
        got = rec.get(st) or (before if st in ("nearclip", "clip") else None)
        keys = [k for k in ("x", "y", "z", "w") if got is not None and k in got]  # r9: w too
        want = ["none"] * 4 if got is None else [bits(got[k]) for k in keys]
        have = page.get(st) if got is None else (page.get(st) or [])[:len(keys)]
        check("slider79-3 %s %s v%s %s: the page's values are the trace's" % (
            os.path.basename(src), model, v, st), have == want,
            "page %s, pipetrace %s" % (page.get(st), want))
        before = got
    h = os.path.join(tmp, "moved.html")
    r = subprocess.run([exe, "journey", new, "--model", model, "--vertex", v, "--html", h],
                       capture_output=True, text=True)
    check("slider79-4 the command line draws the moved scene's page", r.returncode == 0,
          r.stderr)
    d = re.search(r'<script type="application/json" id="data">\n(.*?)\n</script>',
                  open(h, encoding="utf-8").read(), re.S)
    data = json.loads(d.group(1))
    names = [s["name"] for s in data["stages"]]
    x = [x for x in data["vertices"] if str(x["v"]) == v][0]
    vp = re.match(r"\(x_vp, y_vp\) = \((-?\d+), (-?\d+)\)$", x["coords"][names.index("viewport")])
    fb = re.search(r"\(x_fb, y_fb\) = .* = \((-?\d+), (-?\d+)\)\n", x["here"][names.index("viewport")])
    check("slider79-5 %s v%s: the viewport and framebuffer pixel are the command line's" % (
        model, v), page.get("viewport") == (list(vp.groups()) if vp else ["none", "none"]) and
        page.get("framebuffer") == (list(fb.groups()) if fb else ["none", "none"]),
        "page %s %s, pipetrace %s" % (page.get("viewport"), page.get("framebuffer"),
                                      x["here"][names.index("viewport")]))
    # the index: the course's setPixelFB, y_fb*W + x_fb in Java ints (a row
    # past W wraps into the next), none outside the W*H array; where the
    # framebuffer holds the pixel, the command line's page says the same
    W, H = int(p["W"]), int(p["H"])
    want = ["none"]
    if fb:
        xf, yf = int(fb.group(1)), int(fb.group(2))
        i = jint(jint(yf * W) + xf)
        want = [str(i)] if 0 <= i < W * H else ["none"]
        cli = re.search(r"index = y_fb\*W \+ x_fb = .* = (-?\d+)$", x["here"][names.index("viewport")])
        check("slider79-7 %s v%s: the command line's index, where it gives one, is y_fb*W + x_fb" % (
            model, v), cli is None or [cli.group(1)] == want, "%s / %s" % (cli and cli.group(1), want))
    check("slider79-8 %s v%s: the index is the course's y_fb*W + x_fb (rows wrap), none outside"
          " the array" % (model, v), page.get("index") == want,
          "page %s, want %s" % (page.get("index"), want))
    shown = info["shown"][0]
    check("slider79-6 %s v%s %s: #coords is the command line's page's" % (model, v, shown),
          info["coords"][0] == x["coords"][names.index(shown)],
          "page %r, pipetrace %r" % (info["coords"][0], x["coords"][names.index(shown)]))


def jint(v):
    """v as a Java int: its low 32 bits, two's complement."""
    return (v + 2 ** 31) % 2 ** 32 - 2 ** 31


def bits(x):
    return struct.pack(">d", float(x)).hex()


def main():
    exe, dom, scene, tmp = sys.argv[1:5]
    m = re.search(r'<pre id="sliders">(.*?)</pre>', open(dom, encoding="utf-8").read(), re.S)
    check("slider-0 the harness reported", m is not None)
    if not m:
        return
    lines = html.unescape(m.group(1)).splitlines()
    check("slider-1 the harness moved every slider", lines[0] == "ok", lines[0])
    p, page, info = {}, {}, {}
    for ln in lines[1:]:
        f = ln.split("\t")
        if f[0] == "param":
            p[f[1]] = f[2]
        elif f[0] == "stage":
            page[f[1]] = f[2].split(",")
        else:
            info[f[0]] = f[1:]
    model, v = info["vertex"][0], info["vertex"][1]
    src = "docs/examples/builtin.scene" if scene == "-" else scene
    if "n" in p and "l" in p:                    # the course's renderer 7 or 9
        return course(exe, src, p, page, info, tmp)
    new = os.path.join(tmp, "moved.scene")
    with open(new, "w", encoding="utf-8") as f:
        f.write(rewrite(open(src, encoding="utf-8").read(), p, model))
    r = subprocess.run([exe, new, "--model", model, "--vertex", v, "--all-stages",
                        "--format", "jsonl", "--trace", "-"], capture_output=True, text=True)
    note = info["note"][0]
    if note.startswith("No camera: "):           # the page refuses: so must pipetrace
        why = note[len("No camera: "):].split(" (")[0]
        check("slider-6 %s: the command line refuses the camera too, saying why" % why,
              r.returncode == 2 and why in r.stderr and not page, r.stderr)
        return
    check("slider-2 the command line reads the moved scene", r.returncode == 0, r.stderr)
    cli = {}
    for ln in r.stdout.splitlines():
        rec = json.loads(ln)
        if rec.get("type") == "vertex":
            cli[rec["stage"]] = rec
    reached = sorted(st for st, val in page.items() if val != ["unreached"])
    check("slider-3 seven (classic) or ten (matrix) stages; the same reached on both sides",
          len(page) == (10 if "fov" in p else 7) and sorted(cli) == reached,
          "%s / %s" % (sorted(cli), sorted(page)))
    ints = ("viewport", "framebuffer", "index", "cvv")
    for st, rec in cli.items():
        keys = ["i"] if st == "index" else ["code"] if st == "cvv" else ["x", "y"] if st in (
            "pixel", "viewport", "framebuffer") else ["x", "y", "z", "w"] if st in (
            "world", "view", "clip") else ["x", "y", "z"]
        want = []
        for k in keys:
            val = rec.get(k)
            if val is None:
                want.append("none")
            elif st in ints:
                want.append(str(val))
            else:
                want.append(bits(val))
        check("slider-4 %s %s v%s %s: the page's values are the command line's" % (
            os.path.basename(src), model, v, st), page.get(st) == want,
            "page %s, pipetrace %s (%s)" % (page.get(st), want, json.dumps(rec)))
    h = os.path.join(tmp, "moved.html")
    r = subprocess.run([exe, "journey", new, "--model", model, "--vertex", v, "--html", h],
                       capture_output=True, text=True)
    d = re.search(r'<script type="application/json" id="data">\n(.*?)\n</script>',
                  open(h, encoding="utf-8").read(), re.S)
    data = json.loads(d.group(1))
    names = [s["name"] for s in data["stages"]]
    x = [x for x in data["vertices"]
         if data["models"][x["m"]]["name"] == model and str(x["v"]) == v][0]
    shown = info["shown"][0]
    check("slider-5 %s %s v%s %s: #coords is the command line's page's" % (
        os.path.basename(src), model, v, shown),
        info["coords"][0] == x["coords"][names.index(shown)],
        "page %r, pipetrace %r" % (info["coords"][0], x["coords"][names.index(shown)]))


main()
finish()
