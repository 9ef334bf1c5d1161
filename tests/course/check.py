#!/usr/bin/env python3
# tests/course/check.py -- pipetrace against the course corpus (tests/course/rN/)
# See LICENSE for copyright and license.
#
#   python3 tests/course/check.py [PIPETRACE] [-r 4,7,9] [-c CHECKS] [--case GLOB] [-v]
#                                 [--dir DIR]     (the corpus, default tests/course)
#
# For every stored case NAME of tests/course/r4, r7 and r9 (make-corpus.sh made
# them with the course's jars) runs PIPETRACE (default build/pipetrace) on
# NAME.scene and compares, byte for byte or bit for bit:
#   image   --image F.ppm                              with NAME.ppm.gz
#   log     --format kraft --kraft-debug all           with NAME.log.gz
#   deflog  --format kraft                             with NAME.deflog.gz
#   stages  --format jsonl (--all-stages where taken): each vertex record's x y z (w) with the
#           dump's V lines (NAME.stages.gz) of the same stage, model and index:
#           model camera image pixel (renderer 4: 0..3), model view|world
#           camera nearclip image clip (renderers 7, 9); stages and vertices
#           the trace does not have are not compared
#   error   NAME.error (the course's renderer threw): exit 2 and one
#           FILE:LINE:COL: error: line
# Prints one line per mismatch (the first differing line, pixel or value),
# then per renderer and check a summary and one test line (tests/lib/checks.py).
# known.txt lists expected mismatches (CASE CHECK REASON): they are counted,
# not failed; any other mismatch fails.  A renderer that pipetrace refuses
# (`renderer N` is a parse error) or does not have yet (PROBES) is skipped,
# as is the log check when pipetrace has no --kraft-debug: "  skipped: WHY".
import fnmatch
import glob
import gzip
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
from checks import check, finish  # noqa: E402

CHECKS = ["image", "log", "deflog", "stages", "error"]
STAGE_OF = {"model": "model", "world": "world", "view": "view", "camera": "camera",
            "nearclip": "nearclipped", "image": "projected", "clip": "clipped",
            "pixel": "pixelplane"}
TIMEOUT = 60


def run(exe, args):
    """(exit status, stdout bytes, stderr text) of exe args."""
    try:
        p = subprocess.run([exe] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           stdin=subprocess.DEVNULL, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return -1, b"", "timed out after %d s" % TIMEOUT
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def gunzip(path):
    with gzip.open(path, "rb") as f:
        return f.read()


def load_known(path):
    known = {}
    if not os.path.exists(path):
        return known
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            parts = line.split(None, 2)
            if len(parts) < 3:
                raise SystemExit("%s: '%s': CASE CHECK REASON" % (path, line))
            known[(parts[0], parts[1])] = parts[2]
    return known


# ----------------------------------------------------------------- compare

def first_line_diff(want, got):
    """None, or where the texts want and got first differ."""
    if want == got:
        return None
    a, b = want.split(b"\n"), got.split(b"\n")
    for i in range(max(len(a), len(b))):
        x = a[i] if i < len(a) else None
        y = b[i] if i < len(b) else None
        if x != y:
            show = (lambda s: "(end of log)" if s is None else
                    repr(s.decode("utf-8", "replace"))[:160])
            return "line %d: expected %s, got %s" % (i + 1, show(x), show(y))
    return "the same lines, different bytes"


def ppm(data):
    """(w, h, pixel bytes) of a binary P6 image, or None."""
    parts, pos = [], 0
    while len(parts) < 4:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while end < len(data) and not data[end:end + 1].isspace():
            end += 1
        if end == pos:
            return None
        parts.append(data[pos:end])
        pos = end
    if parts[0] != b"P6":
        return None
    return int(parts[1]), int(parts[2]), data[pos + 1:]


def image_diff(want, got):
    if want == got:
        return None
    a, b = ppm(want), ppm(got)
    if a is None or b is None:
        return "not a P6 image" if b is None else "the stored image is no P6 image"
    if a[:2] != b[:2]:
        return "size %dx%d, expected %dx%d" % (b[0], b[1], a[0], a[1])
    w = a[0]
    n = sum(1 for i in range(0, len(a[2]), 3) if a[2][i:i + 3] != b[2][i:i + 3])
    for i in range(0, min(len(a[2]), len(b[2])), 3):
        if a[2][i:i + 3] != b[2][i:i + 3]:
            k = i // 3
            return "%d pixels differ, the first (%d, %d): expected %s, got %s" % (
                n, k % w, k // w, tuple(a[2][i:i + 3]), tuple(b[2][i:i + 3]))
    return "the same pixels, different bytes"


def dump_values(text):
    """{(stage, name, index): [x, y, z(, w)]} from a .stages dump: stage without
    its number, name each of the position's, the model's and POS::MODEL."""
    vals, names = {}, []
    for line in text.decode().splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "position":
            model = [x[6:] for x in f if x.startswith("model=")]
            names = [f[1]] + model + ["%s::%s" % (f[1], m) for m in model]
        elif f[0] == "V" and len(f) >= 6:
            stage = f[1].split(".", 1)[1]
            for n in names:
                vals[(stage, n, int(f[2]))] = [float(x) for x in f[3:]]
    return vals


def bits(x):
    return struct.pack(">d", x)


def stages_diff(dump, trace):
    """(values compared, None or the first difference)."""
    want = dump_values(dump)
    n = 0
    for line in trace.decode("utf-8", "replace").splitlines():
        try:
            rec = json.loads(line, parse_int=float)
        except ValueError:
            return n, "not JSON: %s" % line[:80]
        if rec.get("type") != "vertex" or rec.get("stage") not in STAGE_OF:
            continue
        key = (STAGE_OF[rec["stage"]], rec.get("model"), int(rec.get("v", 0)) - 1)
        if key not in want:
            continue
        exp = want[key]
        for i, c in enumerate("xyzw"):
            if c not in rec or i >= len(exp):
                continue
            got = rec[c]
            if got is None:     # JSON has no NaN or Infinity
                if math.isfinite(exp[i]):
                    return n, "%s %s v%d %s: expected %r, got null" % (
                        rec["stage"], rec["model"], key[2] + 1, c, exp[i])
                continue
            n += 1
            if bits(float(got)) != bits(exp[i]):
                return n, "%s %s v%d %s: expected %r, got %r" % (
                    rec["stage"], rec["model"], key[2] + 1, c, exp[i], float(got))
    return n, None


# ----------------------------------------------------------------- driver

def selftest(top):
    """The comparisons find what they must; every stored case is whole."""
    img = b"P6\n2 2\n255\n" + bytes(range(12))
    bad = bytearray(img)
    bad[-1] ^= 1
    check("course-0.1 an image differing in one byte: pixel (1, 1) named",
          image_diff(img, bytes(bad)) == "1 pixels differ, the first (1, 1): expected "
          "(9, 10, 11), got (9, 10, 10)", image_diff(img, bytes(bad)))
    check("course-0.2 ... the same image: no difference", image_diff(img, img) is None)
    d = first_line_diff(b"a\nb\nc\n", b"a\nb\nd\n")
    check("course-0.3 a log differing in line 3: line 3 named", d is not None and
          d.startswith("line 3: "), d)
    dump = b"position p visible=true model=m\nV 1.camera 0 0.1 -0.0 -2.0\n"
    good = b'{"type":"vertex","model":"m","v":1,"stage":"camera","x":0.1,"y":-0,"z":-2}\n'
    check("course-0.4 stage values equal to the bit: 3 values, no difference",
          stages_diff(dump, good) == (3, None), stages_diff(dump, good))
    n, d = stages_diff(dump, good.replace(b'"y":-0', b'"y":0'))
    check("course-0.5 ... 0 for -0.0 is a difference", d is not None and " y: " in d, d)
    n, d = stages_diff(dump, good.replace(b"0.1", b"0.10000000000000002"))
    check("course-0.6 ... so is the last bit", d is not None and " x: " in d, d)
    sys.path.insert(0, HERE)
    import scene2case
    missing, unconverted, total = [], [], 0
    for scene in sorted(glob.glob(os.path.join(top, "r[479]", "*.scene"))):
        base = scene[:-6]
        total += 1
        if not os.path.exists(base + ".error") and not all(
                os.path.exists(base + e) for e in (".ppm.gz", ".log.gz", ".deflog.gz",
                                                   ".stages.gz")):
            missing.append(os.path.basename(base))
        try:
            scene2case.convert(open(scene).read(), "all", os.path.dirname(scene))
        except (scene2case.Bad, ValueError, IndexError, KeyError, OSError):
            unconverted.append(os.path.basename(base))
    check("course-0.7 every stored scene has its image, logs and stages, or its error",
          total > 0 and not missing, "%d scenes; incomplete: %s" % (total, missing[:5]))
    check("course-0.8 scene2case.py converts every stored scene", not unconverted,
          str(unconverted[:5]))
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "t.obj"), "w") as f:
            f.write("o t\nv 0 0 0\nv 1 0 0\nvn 0 0 1\nv 0 1 0\nf 1/1/1 -2//1 3\nl 2 3\n")
        _, case = scene2case.convert("model m\nv 5 5 5\nobj t.obj\n", "all", d)
    check("course-0.9 scene2case.py reads an obj file: its vertices after the model's, "
          "a face closed, indices shifted", case.endswith(
              "v 5 5 5\nv 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\nl 3 1\nl 2 3\n"), case)
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "tri_2.expect"), "w") as f:
            f.write("# shape tri 2\nv 2.0 0.0 -0.0\nv 0.0 2.0 0.0\nl 0 1\nl 1 0\n")
        with open(os.path.join(d, "tri_0.expect"), "w") as f:
            f.write("# shape tri 0\nerror r must be greater than 0\n")
        _, case = scene2case.convert("model m\nv 5 5 5\nshape tri 2\nl 1 3\n", "all", d, d)
        refused = []
        for text in ("model m\nshape tri 3\n", "model m\nshape tri 0\n"):
            try:
                scene2case.convert(text, "all", d, d)
            except scene2case.Bad:
                refused.append(text.split()[-1])
    check("course-0.10 scene2case.py writes a shape as the jar built it (tests/data/shapes): "
          "its vertices after the model's, segments shifted, a later l counting them",
          case.endswith("v 5 5 5\nv 2.0 0.0 -0.0\nv 0.0 2.0 0.0\nl 1 2\nl 2 1\nl 0 2\n"),
          case)
    check("course-0.11 ... a shape with no stored model, or one the jar refused, is refused",
          refused == ["3", "0"], str(refused))


# What pipetrace must show to have renderer N (else its cases are skipped):
# renderer 4 draws a segment of its colour list's red in anything but white
# (the classic pipeline draws every model white); renderers 7 and 9 trace a
# stage of their own (View2Camera's view, Model2World's world).
PROBES = {
    4: ("renderer 4\nframebuffer 8 8\ncamera orthographic\ngamma off\nmodel m\n"
        "v -0.5 0 0\nv 0.5 0 0\nvcolor 255 0 0\nvcolor 255 0 0\nsegment 1 2\n",
        "its image draws a red vcolor segment white", None),
    7: ("renderer 7\nframebuffer 8 8\nmodel m\nv 0 0 -2\nv 0.5 0 -2\nsegment 1 2\n",
        "its trace has no stage 'view'", "view"),
    9: ("renderer 9\nframebuffer 8 8\nmodel m\nv 0 0 -2\nv 0.5 0 -2\nsegment 1 2\n",
        "its trace has no stage 'world'", "world"),
}


def probe(exe, tmp, r, flags):
    """None when pipetrace has renderer r, else why not.  Sets flags[r] to
    the trace's options: with --all-stages where pipetrace takes it."""
    text, why, stage = PROBES[r]
    path = os.path.join(tmp, "probe%d.scene" % r)
    with open(path, "w") as f:
        f.write(text)
    img = os.path.join(tmp, "probe.ppm")
    flags[r] = ["--format", "jsonl", "--all-stages", "--trace", "-"]
    rc, out, err = run(exe, [path, "--image", img] + flags[r])
    if rc != 0:
        flags[r] = ["--format", "jsonl", "--trace", "-"]
        rc, out, err = run(exe, [path, "--image", img] + flags[r])
    if rc == 2 and ":1:" in err:
        return "pipetrace has no renderer %d (%s)" % (r, err.strip().split(": error: ")[-1])
    if rc != 0:
        return None             # a failure the checks will show
    if stage is None:           # skip only what the classic pipeline draws: white
        p = ppm(open(img, "rb").read()) if os.path.exists(img) else None
        ok = p is None or any(p[2][i:i + 3] not in (b"\0\0\0", b"\xff\xff\xff")
                              for i in range(0, len(p[2]), 3))
    else:
        ok = ('"stage":"%s"' % stage).encode() in out
    return None if ok else "pipetrace has no renderer %d yet: %s" % (r, why)


def main():
    args = sys.argv[1:]
    exe, rends, checks, pattern, verbose = "build/pipetrace", [4, 7, 9], list(CHECKS), "*", False
    top = HERE
    i = 0
    while i < len(args):
        a = args[i]
        if a == "-r":
            rends = [int(x) for x in args[i + 1].split(",")]
            i += 1
        elif a == "-c":
            checks = args[i + 1].split(",")
            i += 1
        elif a == "--case":
            pattern = args[i + 1]
            i += 1
        elif a == "--dir":
            top = args[i + 1]
            i += 1
        elif a == "-v":
            verbose = True
        else:
            exe = a
        i += 1
    known = load_known(os.path.join(HERE, "known.txt"))
    used = set()
    flags = {}
    tmp = tempfile.mkdtemp(prefix="pt-course-")
    out_ppm = os.path.join(tmp, "out.ppm")
    try:
        selftest(top)
        plain = os.path.join(tmp, "plain.scene")
        with open(plain, "w") as f:
            f.write("framebuffer 4 4\n")
        kprobe = run(exe, [plain, "--format", "kraft", "--kraft-debug", "all"])[0] != 1
        for r in rends:
            cases = sorted(glob.glob(os.path.join(top, "r%d" % r, "*.scene")))
            cases = [c for c in cases if fnmatch.fnmatch(os.path.basename(c)[:-6], pattern)]
            why = probe(exe, tmp, r, flags)
            if why:
                print("  skipped: renderer %d (%d cases): %s" % (r, len(cases), why))
                continue
            tally = {c: [0, 0, 0, 0] for c in checks}   # match, known, mismatch, values
            for scene in cases:
                base = scene[:-6]
                name = "r%d/%s" % (r, os.path.basename(base))
                results = {}
                if os.path.exists(base + ".error"):
                    if "error" in checks:
                        rc, _, err = run(exe, [scene, "--image", out_ppm])
                        lines = err.strip().split("\n")
                        ok = (rc == 2 and len(lines) == 1 and
                              lines[0].startswith(scene + ":") and ": error: " in lines[0])
                        results["error"] = None if ok else (
                            "exit %d, expected 2 and one FILE:LINE:COL: error: line (the course "
                            "throws %s); stderr %r" % (rc, open(base + ".error").read().strip(),
                                                      err[:200]))
                else:
                    if "image" in checks or "stages" in checks:
                        if os.path.exists(out_ppm):
                            os.unlink(out_ppm)
                        rc, out, err = run(exe, [scene, "--image", out_ppm] + flags[r])
                        got = open(out_ppm, "rb").read() if os.path.exists(out_ppm) else b""
                        if "image" in checks:
                            results["image"] = ("exit %d: %s" % (rc, err.strip()[:200]) if rc
                                                else image_diff(gunzip(base + ".ppm.gz"), got))
                        if "stages" in checks:
                            n, d = (0, "exit %d: %s" % (rc, err.strip()[:200])) if rc else \
                                stages_diff(gunzip(base + ".stages.gz"), out)
                            tally["stages"][3] += n
                            results["stages"] = d
                    for c, extra, stored in (("log", ["--kraft-debug", "all"], ".log.gz"),
                                             ("deflog", [], ".deflog.gz")):
                        if c not in checks or (c == "log" and not kprobe):
                            continue
                        rc, out, err = run(exe, [scene, "--format", "kraft"] + extra +
                                           ["--trace", "-"])
                        results[c] = ("exit %d: %s" % (rc, err.strip()[:200]) if rc
                                      else first_line_diff(gunzip(base + stored), out))
                for c, d in results.items():
                    k = known.get((name, c))
                    used.add((name, c))
                    if d is None:
                        tally[c][0] += 1
                        if k:
                            print("  %s %s: matches, but known.txt lists it (%s)" % (name, c, k))
                    elif k:
                        tally[c][1] += 1
                        if verbose:
                            print("  %s %s: known: %s: %s" % (name, c, k, d))
                    else:
                        tally[c][2] += 1
                        print("  %s %s: %s" % (name, c, d))
            for c in checks:
                if c == "log" and not kprobe:
                    print("  skipped: renderer %d log: pipetrace has no --kraft-debug" % r)
                    continue
                m, k, x, n = tally[c]
                extra = ", %d values compared" % n if c == "stages" else ""
                print("renderer %d %-7s %4d match, %d known, %d mismatch%s" % (
                    r, c, m, k, x, extra))
                check("course-%d.%s renderer %d %s: every case matches (or is known)"
                      % (r, c, r, c), x == 0, "%d mismatches" % x)
    finally:
        for f in os.listdir(tmp):
            os.unlink(os.path.join(tmp, f))
        os.rmdir(tmp)
    finish()


if __name__ == "__main__":
    main()
