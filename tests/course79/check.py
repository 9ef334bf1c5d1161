# tests/course79/check.py -- renderers 7 and 9 end to end against the course's own output
# See LICENSE for copyright and license.
#
# Usage: python3 tests/course79/check.py PIPETRACE (from the repository root).
# Each NAME.scene here is one of the course's cases written as a pipetrace
# scene; NAME.log.gz is what the course's renderer printed with the switches
# its first line names, NAME.deflog.log.gz (where there is one) with scene.debug
# only, NAME.ppm.gz its framebuffer, NAME.stages.gz every stage's vertices at
# full precision (README.md says where they come from).
import glob
import gzip
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish  # noqa: E402

exe = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
tmp = tempfile.mkdtemp()


def run(*args):
    p = subprocess.run([exe] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    return p.returncode, p.stdout, p.stderr


def gz(path):
    with gzip.open(path, "rb") as f:
        return f.read()


def first_diff(a, b):
    la, lb = a.split(b"\n"), b.split(b"\n")
    for k in range(max(len(la), len(lb))):
        x = la[k] if k < len(la) else b"<end>"
        y = lb[k] if k < len(lb) else b"<end>"
        if x != y:
            return "line %d: expected %r, got %r" % (k + 1, x, y)
    return ""


# the course's stage names in its .stages dump, per pipetrace stage
STAGES = {7: {"model": "0.model", "view": "1.view", "camera": "2.camera",
              "nearclip": "3.nearclipped", "image": "4.projected", "clip": "5.clipped"},
          9: {"model": "0.model", "world": "1.world", "view": "2.view", "camera": "3.camera",
              "nearclip": "4.nearclipped", "image": "5.projected", "clip": "6.clipped"}}


def stages_of(path):
    """{(position, stage, index): (x, y, z[, w])} from a .stages dump."""
    out, pos = {}, None
    for line in gz(path).decode().splitlines():
        t = line.split()
        if t and t[0] == "position":
            pos = t[1]
        elif t and t[0] == "V":
            out[(pos, t[1], int(t[2]))] = tuple(float(x) for x in t[3:])
    return out


scenes = sorted(glob.glob(os.path.join(here, "*.scene")))
check("c79-0.1 the cases are here (16 of the course's, 6 more)", len(scenes) == 22, str(len(scenes)))
for scene in scenes:
    name = os.path.basename(scene)[:-6]
    head = open(scene).readline()
    m = re.search(r"--kraft-debug (\S+)", head)
    dbg = m.group(1) if m else "all"
    renderer = 9 if name.startswith("r9") else 7
    log, ppm = os.path.join(tmp, "out.log"), os.path.join(tmp, "out.ppm")

    # c79-1: the log with the case's switches and the image, byte for byte
    rc, out, err = run(scene, "--kraft-debug", dbg, "--trace", log, "--image", ppm)
    check("c79-1.1 %s: exit 0" % name, rc == 0, err.decode(errors="replace"))
    if rc == 0:
        want = gz(os.path.join(here, name + ".log.gz"))
        got = open(log, "rb").read()
        check("c79-1.2 %s: the log (--kraft-debug %s) byte for byte" % (name, dbg),
              got == want, first_diff(want, got))
        want = gz(os.path.join(here, name + ".ppm.gz"))
        check("c79-1.3 %s: the image byte for byte" % name, open(ppm, "rb").read() == want)

    # c79-2: scene.debug only (the course's default level), as --format kraft
    dl = os.path.join(here, name + ".deflog.log.gz")
    if os.path.exists(dl):
        rc, out, err = run(scene, "--format", "kraft")
        want = gz(dl)
        check("c79-2.1 %s: --format kraft is the course's default log" % name,
              rc == 0 and out == want, first_diff(want, out))

    # c79-3: JSON Lines: every vertex record is the course's value at that stage
    st = os.path.join(here, name + ".stages.gz")
    if not os.path.exists(st) or "pos" in name or "posclip" in name:
        continue
    ref = stages_of(st)
    rc, out, err = run(scene, "--format", "jsonl")
    recs = [json.loads(x) for x in out.decode().splitlines()] if rc == 0 else []
    verts = [r for r in recs if r["type"] == "vertex"]
    bad, seen = [], set()
    for r in verts:
        key = (r["position"], STAGES[renderer][r["stage"]], r["v"] - 1)
        want = ref.get(key)
        got = (r["x"], r["y"], r["z"]) + ((r["w"],) if renderer == 9 else ())
        got = tuple(float(x) for x in got)
        if want is None or [repr(x) for x in want] != [repr(x) for x in got]:
            bad.append("%s: want %s got %s" % (key, want, got))
        seen.add(key)
    check("c79-3.1 %s: jsonl: %d vertex records, each the course's value" % (name, len(verts)),
          rc == 0 and verts and not bad, "; ".join(bad[:3]))
    made = [r for r in verts if r["stage"] in ("nearclip", "clip")]
    check("c79-3.2 %s: jsonl: a clip stage's vertices are the ones it made, each with "
          "where it came from" % name,
          all("from" in r and r["from"]["segment"] >= 1 and "color" in r for r in made),
          str(made[:1]))
    check("c79-3.3 %s: jsonl: header first, summary last" % name,
          recs and recs[0]["type"] == "header" and recs[-1]["type"] == "summary"
          and recs[0]["renderer"] == renderer)
    # the pixel records, applied in order, give the course's image where they write
    img = gz(os.path.join(here, name + ".ppm.gz"))
    W, H = (int(x) for x in img.split(b"\n")[1].split())
    body = img[len(img) - 3 * W * H:]
    last = {}
    for r in recs:
        if r["type"] == "pixel" and 0 <= r["y"] * W + r["x"] < W * H:
            last[r["y"] * W + r["x"]] = bytes(r["rgb"])
    wrong = [i for i, c in last.items() if body[3 * i:3 * i + 3] != c]
    check("c79-3.6 %s: jsonl: %d pixels written, each as the course's image has it"
          % (name, len(last)), last and not wrong, str(wrong[:5]))
    rc2, csv, _ = run(scene, "--format", "csv")
    rows = csv.decode().splitlines()
    check("c79-3.4 %s: csv: a row per vertex record" % name,
          rc2 == 0 and rows[0].startswith("model,position,v,stage,")
          and len(rows) - 1 == len(verts), "%d rows, %d records" % (len(rows) - 1, len(verts)))
    rc3, text, _ = run(scene)
    lines = text.decode().splitlines()
    check("c79-3.5 %s: text: a line per vertex record" % name,
          rc3 == 0 and sum(1 for x in lines if re.match(r"^\S+ v\d+ +\w+ +x =", x)) == len(verts))

# c79-5: the course's warnings are records of the trace too
rc, out, err = run(os.path.join(here, "r7-hidden-warn.scene"), "--format", "jsonl")
warns = [(r["model"], r["warning"]) for r in map(json.loads, out.decode().splitlines())
         if r["type"] == "warning"]
check("c79-5.1 warnings: a model without colours, one without primitives",
      warns == [("nocol", "no_colors"), ("nocol", "default_color"),
                ("noprim", "no_primitives"), ("noprim", "no_colors"),
                ("noprim", "default_color")], str(warns))
models = {r["model"] for r in map(json.loads, out.decode().splitlines()) if r["type"] == "vertex"}
check("c79-5.2 hidden position and hidden model: no records", models == {"vis", "nocol", "noprim"},
      str(models))

# c79-4: the teaching tools that do not follow renderers 7 and 9 refuse such a
# scene with a clear message (step and why follow them: tests/teach/teach79.sh;
# quiz: tests/teach/quiz79.sh; accuracy: c79-4.2 and tests/cli/accuracy.sh)
# journey draws such a scene: SVG, page and image (tests/journey/journey79.sh)
sc = os.path.join(here, "r7-near-01.scene")
for tool in ([sc, "--vertex", "1"],):
    rc, out, err = run(*tool)
    check("c79-4.1 %s refuses a renderer 7 scene: exit 2, says why" % " ".join(tool[:1] + tool[4:5]),
          rc == 2 and b"renderer 7" in err and b"error" in err, err.decode(errors="replace")[:200])
rc, out, err = run("journey", sc, "--vertex", "1", "--svg", os.path.join(tmp, "j.svg"))
check("c79-4.3 journey --svg takes a renderer 7 scene: exit 0, an SVG",
      rc == 0 and open(os.path.join(tmp, "j.svg"), "rb").read().startswith(b"<?xml"),
      err.decode(errors="replace")[:200])
rc, out, err = run("journey", sc, "--vertex", "1", "--html", os.path.join(tmp, "j.html"),
                   "--image", os.path.join(tmp, "j.png"))
check("c79-4.4 journey --html and --image take a renderer 7 scene: exit 0, a page, a PNG",
      rc == 0 and open(os.path.join(tmp, "j.html"), "rb").read().startswith(b"<!DOCTYPE html>")
      and open(os.path.join(tmp, "j.png"), "rb").read().startswith(b"\x89PNG"),
      err.decode(errors="replace")[:200])
rc, out, err = run("accuracy", sc, "--no-time")    # accuracy takes it (docs/accuracy.md)
check("c79-4.2 accuracy takes a renderer 7 scene: exit 0, its nearclip and clip rows",
      rc == 0 and b"\nnearclip " in out and b"\nclip " in out, err.decode(errors="replace")[:200])

# c79-6: diff reads the logs and traces of such scenes (tests/teach/diff79.sh: the rest)
for fmt in ("kraft", "text", "jsonl", "csv"):
    path = os.path.join(tmp, "t." + fmt)
    run(sc, "--format", fmt, "--trace", path)
    rc, out, err = run("diff", path, path)
    check("c79-6.1 diff reads a renderer 7 scene's %s: exit 0, the same" % fmt,
          rc == 0 and out.startswith(b"Renderer 7:") and not err, (out + err).decode(errors="replace")[:200])

# c79-7: the three traces spell the same numbers, on a scene of more distinct
# values than the writers keep spellings of (trace_course_rec.c): each
# vertex record's numbers in text ("%.6f") and in CSV (the shortest, as
# JSON's) against its JSON Lines record's
rnd = __import__("random").Random(79)
lines = ["renderer 9", "scene many", "framebuffer 64 48", "camera perspective", "near 1.0",
         "nearclip on", "model m", "matrix translate 0.0 0.0 0.0"]
for k in range(600):
    lines.append("v %r %r %r" % (rnd.uniform(-2, 2), rnd.uniform(-2, 2), rnd.uniform(-6, 0.5)))
    lines.append("vcolor-float %r %r %r" % (rnd.random(), rnd.random(), rnd.random()))
lines += ["segment %d %d" % (k, k + 1) for k in range(1, 600, 2)]
many = os.path.join(tmp, "many.scene")
with open(many, "w") as f:
    f.write("\n".join(lines) + "\n")
rc, out, _ = run(many, "--format", "jsonl")
jl = [x for x in out.decode().splitlines() if x.startswith('{"type":"vertex"')]
rc2, text, _ = run(many)
tl = [x for x in text.decode().splitlines() if re.match(r"^\S+ v\d+ +\w+ +x =", x)]
rc3, csv, _ = run(many, "--format", "csv")
cl = csv.decode().splitlines()[1:]
bad_t, bad_c = [], []
for j, t, c in zip(jl, tl, cl):
    raw = re.findall(r'"[xyzw]":([^,}]+)', j.split('"from"')[0])
    m = re.search(r'"color":\[([^]]*)\]', j)
    raw += m.group(1).split(",") if m else []
    m = re.search(r'"t":([^,}]+)', j)
    t_raw = m.group(1) if m else ""
    got = re.findall(r" [xyzw] = +(\S+)", t)
    m = re.search(r"  rgb = (\S+) (\S+) (\S+)", t)
    got += list(m.groups()) if m else []
    if ["%.6f" % float(x) for x in raw] != got:
        bad_t.append("%r: JSON's %s" % (t, raw))
    cells = c.split(",")
    if cells[4:4 + len(raw)] != [("-0" if x == "-0.0" else x) for x in raw] or cells[14] != t_raw:
        bad_c.append("%r: JSON's %s %s" % (c, raw, t_raw))
check("c79-7.1 600 vertices and colours: text spells the numbers of each JSON Lines record",
      rc == rc2 == 0 and len(tl) == len(jl) > 3000 and not bad_t, "; ".join(bad_t[:3]))
check("c79-7.2 600 vertices and colours: CSV spells them as JSON Lines does",
      rc3 == 0 and len(cl) == len(jl) and not bad_c, "; ".join(bad_c[:3]))

# c79-8: a model whose name makes the opening of its pixel records longer
# than the writer keeps for one copy of a fixed size (trace_course_rec.c,
# on_pixels): its records are those of the same scene with a short name
src = open(os.path.join(here, "r9-basic-two-models.scene")).read()
longname = "L" * 150
sc8 = os.path.join(tmp, "long.scene")
with open(sc8, "w") as f:
    f.write(re.sub(r"(?m)^model a$", "model " + longname, src))
for fmt in ("jsonl", "text"):
    rc, short, _ = run(os.path.join(here, "r9-basic-two-models.scene"), "--format", fmt)
    rc2, long_, _ = run(sc8, "--format", fmt)
    if fmt == "jsonl":
        try:
            a8 = [json.loads(x) for x in short.decode().splitlines()[1:]]
            b8 = [json.loads(x) for x in long_.decode().splitlines()[1:]]
        except ValueError as e:
            a8, b8 = [], [str(e)]
        for r in [x for x in b8 if isinstance(x, dict)]:
            for k in ("model", "position"):
                if r.get(k) == longname:
                    r[k] = "a"
    else:
        a8 = [x for x in short.decode().splitlines() if not x.startswith("scene ")]
        b8 = ["a" + x[len(longname):] if x.startswith(longname) else x
              for x in long_.decode().splitlines() if not x.startswith("scene ")]
    npix = sum(1 for x in a8 if "pixel" in str(x))
    check("c79-8.1 %s: a model's name of 150 bytes: the same %d records, %d of them pixels"
          % (fmt, len(a8), npix), rc == rc2 == 0 and npix > 100 and a8 == b8,
          str([(x, y) for x, y in zip(a8, b8) if x != y][:1]))

finish()
