# tests/teach/why_vpout.py -- pipetrace why on a scene whose viewport sticks out
# See LICENSE for copyright and license.
#
# Usage: python3 tests/teach/why_vpout.py PIPETRACE SCENE PREFIX [every] [lit2]
#
# SCENE (renderer 4, 7 or 9) has a viewport that sticks out of its
# framebuffer.  Its pixels are sorted by how many viewport pixels land on
# them: the index y_fb * W + x_fb of every viewport pixel, computed here from
# the trace's header, not asked of pipetrace.  On pixels of each count (0, 1,
# 2 and more; all of those reached twice or more; with `every` the scene must
# have pixels of each count, lit ones among those reached once; with `lit2`,
# lit ones among those reached twice or more), why must list exactly the viewport pixels that land there, in the clearing's order; say "lit" under
# exactly those from which the trace's pixel records (their index: the
# record's `i`, renderer 4, or y * W + x of its pixel, renderers 7 and 9) write
# the pixel, naming the same segments, points or primitives; and name as the
# last write the trace's last record on that index (or the viewport's
# clearing of the last viewport pixel listed, when no record lands there),
# in the colour the image shows.  Prints FAIL lines and "N passed, N failed".
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish  # noqa: E402

exe, scene, prefix = sys.argv[1], sys.argv[2], sys.argv[3]
every = "every" in sys.argv[4:]       # the scene must reach pixels 0, 1 and 2+ times
lit2 = "lit2" in sys.argv[4:]         # ... and light some reached 2+ times
name = os.path.basename(scene)


def ppm(path):      # binary PPM: "P6", width, height, 255, one whitespace, the bytes
    data = open(path, "rb").read()
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    w, h = int(m.group(1)), int(m.group(2))
    return w, h, data[m.end():m.end() + 3 * w * h]


with tempfile.TemporaryDirectory() as tmp:
    img = os.path.join(tmp, "img.ppm")
    trace = subprocess.run([exe, scene, "--format", "jsonl", "--image", img, "--trace", "-"],
                           capture_output=True, text=True, check=True).stdout
    iw, ih, rgb = ppm(img)

recs = [json.loads(line) for line in trace.splitlines()]
head = recs[0]
r4 = "renderer" not in head
W, H = head["framebuffer"]["w"], head["framebuffer"]["h"]
vp = head["viewport"]
x_ul, y_ul, vw, vh = vp["x"], vp["y"], vp["w"], vp["h"]
check(prefix + ".0 %s: the viewport sticks out" % name,
      (x_ul < 0 or y_ul < 0 or x_ul + vw > W or y_ul + vh > H) and (iw, ih) == (W, H))


def index(x_fb, y_fb):
    i = y_fb * W + x_fb
    return i if 0 <= i < W * H else -1


# the viewport pixels landing on each index, in the clearing's order (row by row)
sources = {}
for y_vp in range(vh):
    for x_vp in range(vw):
        i = index(x_ul + x_vp, y_ul + y_vp)
        if i >= 0:
            sources.setdefault(i, []).append((x_vp, y_vp))

# the writes, in drawing order: (index, viewport pixel, who); who is
# ("s" or "p", model, k) for renderer 4, (model, primitive) for 7 and 9
writes = []
for r in recs:
    if r.get("type") != "pixel":
        continue
    xv, yv = r["x"] - x_ul, r["y"] - y_ul
    if not (0 <= xv < vw and 0 <= yv < vh):
        continue
    if r4:
        i = r["i"]
        who = ("p", r["model"], r["point"]) if "point" in r else ("s", r["model"], r["segment"])
    else:
        i = index(r["x"], r["y"])
        who = (r["model"], r["primitive"])
    if i >= 0:
        writes.append((i, (xv, yv), who))

# the pixels asked about: every one reached twice or more, some of the others
by_count = {}
for y in range(H):
    for x in range(W):
        n = len(sources.get(y * W + x, []))
        by_count.setdefault(min(n, 2), []).append((x, y))
lit = set(i for i, _, _ in writes)
pick = list(by_count.get(2, []))
ones = by_count.get(1, [])
pick += [p for p in ones if p[1] * W + p[0] in lit][:6]
pick += [p for p in ones if p[1] * W + p[0] not in lit][:3]
pick += by_count.get(0, [])[:3]
if every:
    check(prefix + ".1 %s: pixels reached by 0, 1 and 2 viewport pixels, lit ones among the 1"
          % name, all(by_count.get(k) for k in (0, 1, 2)) and
          any(p[1] * W + p[0] in lit for p in by_count[1]))
if lit2:
    check(prefix + ".1 %s: lit pixels among those reached twice or more" % name,
          any(p[1] * W + p[0] in lit for p in by_count.get(2, [])))
if not every and not lit2:
    check(prefix + ".1 %s: lit pixels among those asked about" % name,
          any(p[1] * W + p[0] in lit for p in pick))

src_re = re.compile(r"^viewport pixel \(x_vp, y_vp\) = \((-?\d+), (-?\d+)\) -> framebuffer "
                    r"\(x_fb, y_fb\) = \((-?\d+), (-?\d+)\) -> index y_fb \* W \+ x_fb = "
                    r"-?\d+ \* \d+ \+ \(?-?\d+\)? = (-?\d+)")
lit4_re = re.compile(r"^  (\S+) ([sp])(\d+) \((?:v|point)")
lit79_re = re.compile(r"^  (\S+) (?:segment|point) \d+ \(.*\), drawn as primitive (\d+): ")
last_re = re.compile(r"^color (\d+) (\d+) (\d+): the last write, by (\S+) (.*), from viewport "
                     r"pixel \(x_vp, y_vp\) = \((-?\d+), (-?\d+)\)$")
clear_re = re.compile(r"^color (\d+) (\d+) (\d+): no (?:segment or point|primitive) writes it; "
                      r"the last write is the viewport's clearing, of viewport pixel "
                      r"\(x_vp, y_vp\) = \((-?\d+), (-?\d+)\), to the viewport background$")
none_re = re.compile(r"(?:keeps the background(?: color)?|keeps the viewport's background) "
                     r"(\d+) (\d+) (\d+)$")

for (X, Y) in pick:
    T = Y * W + X
    want = sources.get(T, [])
    here = "%s (%d, %d), %d viewport pixels" % (name, X, Y, len(want))
    p = subprocess.run([exe, "why", scene, str(X), str(Y)], capture_output=True, text=True)
    lines = p.stdout.splitlines()
    check(prefix + ".2 why %s: exit 0" % here, p.returncode == 0, p.stderr)
    shown = tuple(rgb[3 * T:3 * T + 3])
    # the viewport pixels listed, and what each section says lit it
    listed, sections, cur, on = [], {}, None, False
    for ln in lines:
        m = src_re.match(ln)
        if m:
            cur = (int(m.group(1)), int(m.group(2)))
            listed.append(cur)
            sections[cur] = set()
            on = False
            check(prefix + ".3 ... %s: (x_fb, y_fb) and index of viewport pixel %s" % (here, cur),
                  (int(m.group(3)), int(m.group(4))) == (x_ul + cur[0], y_ul + cur[1])
                  and int(m.group(5)) == T, ln)
            continue
        if ln.startswith("lit by"):
            on = True
        elif not ln.startswith(" "):
            on = False
        m = (lit4_re if r4 else lit79_re).match(ln)
        if cur is not None and on and m:
            if r4:
                sections[cur].add((m.group(2), m.group(1), int(m.group(3))))
            else:
                sections[cur].add((m.group(1), int(m.group(2))))
    check(prefix + ".4 ... %s: the viewport pixels listed are those landing on index %d" % (here, T),
          listed == want, "listed %s, want %s" % (listed, want))
    if want:
        check(prefix + ".5 ... %s: how many, said" % here,
              any(ln.startswith("%d viewport pixel" % len(want)) for ln in lines))
    else:
        check(prefix + ".5 ... %s: none, said" % here,
              any(ln.startswith("no viewport pixel lands on index %d" % T) for ln in lines))
    for s in want:
        got = sections.get(s, set())
        exp = set(w for i, v, w in writes if i == T and v == s)
        check(prefix + ".6 ... %s: from %s lit by the trace's writes %s" % (here, s, sorted(exp)),
              got == exp, "why says %s" % sorted(got))
    last = [(v, w) for i, v, w in writes if i == T]
    colour = [ln for ln in lines if ln.startswith("color ") or ln.startswith("not lit: ")]
    if last:
        v, w = last[-1]
        m = last_re.match(colour[-1]) if colour else None
        who = None
        if m and r4:
            k = re.match(r"([sp])(\d+)$", m.group(5))
            who = (k.group(1), m.group(4), int(k.group(2))) if k else None
        elif m:
            k = re.search(r", drawn as primitive (\d+)$", m.group(5))
            who = (m.group(4), int(k.group(1))) if k else None
        check(prefix + ".7 ... %s: the last write is the trace's last record there, %s from %s, "
              "in the image's colour %s" % (here, w, v, shown),
              m is not None and who == w and (int(m.group(6)), int(m.group(7))) == v and
              tuple(int(m.group(k)) for k in (1, 2, 3)) == shown, str(colour))
    elif want:
        m = clear_re.match(colour[-1]) if colour else None
        check(prefix + ".7 ... %s: the last write is the clearing of %s, in the image's colour %s"
              % (here, want[-1], shown),
              m is not None and (int(m.group(4)), int(m.group(5))) == want[-1] and
              tuple(int(m.group(k)) for k in (1, 2, 3)) == shown, str(colour))
    else:
        m = none_re.search(colour[-1]) if colour else None
        check(prefix + ".7 ... %s: the background, in the image's colour %s" % (here, shown),
              m is not None and tuple(int(m.group(k)) for k in (1, 2, 3)) == shown, str(colour))
finish()
