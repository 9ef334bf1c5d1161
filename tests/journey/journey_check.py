#!/usr/bin/env python3
# tests/journey/journey_check.py -- checks of pipetrace journey's SVG, HTML and PNG output
# See LICENSE for copyright and license.
#
# Python's standard library only.  Each mode prints "FAIL ..." lines and, last,
# "N passed, N failed"; exit status 1 when anything failed.
#
#   svg EXE FILE MODEL V [SCENE]     well-formed XML, scalable root, one panel per
#                                    stage of the scene's camera (seven, or the
#                                    matrix camera's ten) in pipeline order, each
#                                    panel's coordinates label equal to the JSONL
#                                    trace's values; the matrix camera: the stages
#                                    a vertex outside the view volume does not
#                                    reach say so, and the clip panel marks the
#                                    cuts exactly when the trace has clipvertex
#                                    records of the vertex's segments
#   html EXE FILE [SCENE]            self-contained page (no network, no other
#                                    file), the ids the page promises, every
#                                    listed vertex's coordinates equal to the
#                                    trace, every panel fragment well-formed
#   clicks EXE DOM [SCENE]           tests/journey/journey_clicks.html's outcome
#                                    (chromium --dump-dom): "ok ...", every vertex
#                                    of the trace, every stage, values equal to it
#   dom EXE DOM MODEL V STAGE [SCENE]  #stage and #coords of a dumped page
#   marked EXE FILE.png FILE.ppm MODEL V [SCENE]  journey --image: the render
#                                    FILE.ppm with vertex V's pixel ringed in red
#   clicks79 EXE DOM SCENE N        the same for a page of the course's renderer 7
#                                    or 9: N vertices listed, each stage's #coords
#                                    the label of that panel of the vertex's SVG
#                                    (which tests/journey/journey79.sh ties to
#                                    the trace)
#   html79 EXE FILE SCENE MODEL      a course page without a browser: self-
#                                    contained, its panels those of the SVG, each
#                                    listed vertex's coords its SVG's labels
#   marked79 EXE FILE.png FILE.ppm SCENE MODEL V  journey --image of a course
#                                    scene: the render, vertex V's pixel (the
#                                    SVG's viewport label plus the viewport's
#                                    corner) ringed in red, or the plain render
#   png FILE.png FILE.ppm            the PNG decodes (CRC of every chunk, zlib's
#                                    Adler-32) to the PPM's pixels
#   color FILE.png RRGGBB            the PNG holds a pixel of that color
#   frame FILE.svg FILE.ppm RRGGBB K  the framebuffer panel draws the whole
#                                    frame FILE.ppm (every model's pixels, the
#                                    background RRGGBB left out) in blocks of
#                                    K x K pixels: data-pixels counts them, and
#                                    with K = 1 its runs cover just as many
import html
import os
import json
import re
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
import zlib

STAGES = ["model", "camera", "image", "pixel", "viewport", "framebuffer", "index"]
MATRIX = ["model", "world", "view", "clip", "cvv", "ndc", "screen", "viewport", "framebuffer",
          "index"]
KEYS = {"index": ["i"], "cvv": ["code"], "pixel": ["x", "y"], "viewport": ["x", "y"],
        "framebuffer": ["x", "y"], "world": ["x", "y", "z", "w"], "view": ["x", "y", "z", "w"],
        "clip": ["x", "y", "z", "w"]}          # the rest: x, y, z
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish as report  # noqa: E402


def jsonl(exe, scene):
    args = [exe] + ([scene] if scene else []) + ["--format", "jsonl", "--all-stages"]
    return subprocess.run(args, stdout=subprocess.PIPE, check=True).stdout.decode("utf-8")


def stages_of(exe, scene):
    """The stages of the scene's camera, in pipeline order."""
    head = json.loads(jsonl(exe, scene).splitlines()[0])
    return MATRIX if head.get("camera") == "lookat" else STAGES


def clipped(exe, scene, model, v):
    """1 when clipping cut a segment of vertex v of model (clipvertex records)."""
    for line in jsonl(exe, scene).splitlines():
        if line.startswith('{"type":"clipvertex"'):
            obj = json.loads(line)
            if obj["model"] == model and v in (obj["from"], obj["to"]):
                return True
    return False


def trace(exe, scene):
    """{(model, v, stage): [raw JSON value tokens]} of every traced record."""
    out = jsonl(exe, scene)
    recs = {}
    for line in out.splitlines():
        if not line.startswith('{"type":"vertex"'):
            continue
        obj = json.loads(line)
        keys = KEYS.get(obj["stage"], ["x", "y", "z"])
        toks = []
        for k in keys:        # the value exactly as written in the line
            m = re.search(r'"%s":("[^"]*"|[^,}]*)' % k, line)
            toks.append(m.group(1))
        recs[(obj["model"], obj["v"], obj["stage"])] = toks
    return recs


def parse_coords(text):
    """'(x_c, y_c, z_c) = (-2.5, -0.75, -6)' -> ['-2.5', '-0.75', '-6'];
    'idx = 66133' -> ['66133']; '... = none' -> ['none'] * n."""
    lhs, _, rhs = text.partition(" = ")
    n = 1 if lhs == "idx" else lhs.count(",") + 1
    if rhs == "none":
        return ["none"] * n
    return [t.strip() for t in rhs.strip("()").split(",")]


def as_trace(tok):
    """A JSONL token as the page and the SVG spell it."""
    if tok == "null":
        return "none"
    return tok.strip('"')          # "inf", "-inf", "nan"


def same(text, toks):
    return parse_coords(text) == [as_trace(t) for t in toks]


def svg_mode(exe, path, model, v, scene):
    recs = trace(exe, scene)
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        check("svg-1 well-formed XML", False, str(e))
        return
    check("svg-1 well-formed XML", True)
    ns = "{http://www.w3.org/2000/svg}"
    check("svg-2 root is svg", root.tag == ns + "svg", root.tag)
    vb = root.get("viewBox", "").split()
    check("svg-3 viewBox with 4 numbers", len(vb) == 4 and float(vb[2]) > 0 and float(vb[3]) > 0)
    check("svg-4 scales: width 100%, no fixed height", root.get("width") == "100%" and
          root.get("height") is None)
    panels = [g for g in root.iter(ns + "g") if g.get("class") == "panel"]
    order = stages_of(exe, scene)
    check("svg-5 one panel per stage, in pipeline order",
          [g.get("data-stage") for g in panels] == order, str([g.get("data-stage") for g in panels]))
    if order == MATRIX:
        for g in panels:
            key = (model, int(v), g.get("data-stage"))
            text = "".join("".join(t.itertext()) for t in g.iter(ns + "text")
                           if t.get("class") == "coords")
            check("svg-10 %s: %s in the trace, or 'not reached'" % (key[2], text),
                  (key in recs) != text.endswith(": not reached"), text)
        cuts = [r for g in panels if g.get("data-stage") == "clip"
                for r in g.iter(ns + "rect") if r.get("class") == "cut"]
        want = clipped(exe, scene, model, int(v))
        check("svg-11 cuts marked in clip space (%d) exactly when the trace has clipvertex "
              "records of v%s's segments (%s)" % (len(cuts), v, want), bool(cuts) == want)
    for g in panels:
        st = g.get("data-stage")
        labels = [t for t in g.iter(ns + "text") if t.get("class") == "coords"]
        check("svg-6 %s: one coordinates label" % st, len(labels) == 1)
        if not labels:
            continue
        text = "".join(labels[0].itertext())
        key = (model, int(v), st)
        if key in recs:
            check("svg-7 %s: label %r equals the trace %r" % (st, text, recs[key]),
                  same(text, recs[key]))
        notes = [t for t in g.iter(ns + "text") if t.get("class") == "note"]
        check("svg-8 %s: a note" % st, len(notes) == 1)
    for el in root.iter():           # every coordinate attribute is a plain number
        for a in ("x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height"):
            val = el.get(a)
            if val is not None and el is not root:
                if not re.fullmatch(r"-?\d+(\.\d+)?", val):
                    check("svg-9 attribute %s=%r is a plain number" % (a, val), False)
                    return
    check("svg-9 every coordinate attribute is a plain number", True)


def page_data(text):
    m = re.search(r'<script type="application/json" id="data">\n(.*?)\n</script>', text, re.S)
    return json.loads(m.group(1)) if m else None


def html_mode(exe, path, scene):
    text = open(path, encoding="utf-8").read()
    recs = trace(exe, scene)
    lower = text.lower()
    urls = [u for u in re.findall(r"https?://[^\s\"'<>]*", text)
            if u != "http://www.w3.org/2000/svg"]
    check("html-1 no URL but the SVG namespace", not urls, str(urls[:3]))
    check("html-2 no external file (src=, href=, <link, @import, url()",
          not re.search(r"\bsrc\s*=|\bhref\s*=|<link|@import|url\(", lower))
    for i in ("prev", "next", "vertex", "stage", "coords", "formula"):
        check("html-3 has id=%s" % i, ('id="%s"' % i) in text)
    data = page_data(text)
    check("html-4 the data blob is JSON", data is not None)
    if data is None:
        return
    order = stages_of(exe, scene)
    check("html-5 the camera's stages", [s["name"] for s in data["stages"]] == order)
    used = sorted({(m, v) for (m, v, _) in recs})
    listed = [(data["models"][x["m"]]["name"], x["v"]) for x in data["vertices"] if x["used"]]
    if not data["capped"]:
        check("html-6 every used vertex is listed, in scene order", listed == used or
              sorted(listed) == used, "%d listed, %d used" % (len(listed), len(used)))
    bad = 0
    for x in data["vertices"]:
        name = data["models"][x["m"]]["name"]
        for k, st in enumerate(order):
            key = (name, x["v"], st)
            if key in recs and not same(x["coords"][k], recs[key]):
                bad += 1
                if bad < 5:
                    print("  %s v%d %s: %r vs %r" % (name, x["v"], st, x["coords"][k], recs[key]))
    check("html-7 every listed vertex's coordinates equal the trace", bad == 0)
    ok = True
    for mo in data["models"]:
        for k, bg in enumerate(mo["bg"]):
            for x in data["vertices"][:20]:
                if data["models"][x["m"]] is not mo:
                    continue
                try:
                    ET.fromstring('<svg xmlns="http://www.w3.org/2000/svg">' + bg + x["fg"][k] +
                                  "</svg>")
                except ET.ParseError as e:
                    ok = False
                    print("  %s %s: %s" % (mo["name"], order[k], e))
                    break
    check("html-8 every panel fragment is well-formed", ok)


def clicks_mode(exe, dom, scene):
    text = open(dom, encoding="utf-8", errors="replace").read()
    recs = trace(exe, scene)
    m = re.search(r'<pre id="clicks">(.*?)</pre>', text, re.S)
    check("page-1 the clicks ran (<pre id=clicks>)", m is not None)
    if not m:
        return
    lines = html.unescape(m.group(1)).strip("\n").split("\n")
    check("page-2 the clicks say ok", lines[0].startswith("ok "), lines[0][:300])
    seen = set()
    for ln in lines[1:]:
        model, v, st, coords = ln.split("\t")
        key = (model, int(v), st)
        seen.add(key)
        if key in recs:
            check("page-3 %s v%s %s: shown %r, trace %r" % (model, v, st, coords, recs[key]),
                  same(coords, recs[key]))
    check("page-4 the clicks reached every record of the trace", set(recs) <= seen,
          "%d of %d" % (len(set(recs) & seen), len(recs)))


def dom_mode(exe, dom, model, v, stage, scene):
    text = open(dom, encoding="utf-8", errors="replace").read()
    recs = trace(exe, scene)

    def by_id(i):       # the element's text, its tags (span.expr) left out
        m = re.search(r'<(\w+)[^>]*\bid="%s"[^>]*>(.*?)</\1>' % i, text, re.S)
        return html.unescape(re.sub(r"<[^>]*>", "", m.group(2))) if m else None
    check("dom-1 #stage is %s" % stage, by_id("stage") == stage, repr(by_id("stage")))
    c = by_id("coords")
    key = (model, int(v), stage)
    check("dom-2 #coords %r equals the trace" % c, c is not None and key in recs and
          same(c, recs[key]), repr(recs.get(key)))
    check("dom-3 #formula is not empty", bool(by_id("formula")))


def svg_labels(exe, scene, model, v):
    """{panel key: its coordinates label} of the course SVG of vertex v."""
    r = subprocess.run([exe, "journey", scene, "--model", model, "--vertex", str(v), "--svg",
                        "-"], capture_output=True, text=True)
    out = {}
    for g in re.finditer(r'<g class="panel" data-stage="(\w+)"(.*?)</g>', r.stdout, re.S):
        t = re.search(r'<text[^>]*class="coords"[^>]*>([^<]*)', g.group(2))
        out[g.group(1)] = html.unescape(t.group(1)) if t else None
    return out


def clicks79_mode(exe, dom, scene, n):
    text = open(dom, encoding="utf-8", errors="replace").read()
    m = re.search(r'<pre id="clicks">(.*?)</pre>', text, re.S)
    check("page79-1 the clicks ran (<pre id=clicks>)", m is not None)
    if not m:
        return
    lines = html.unescape(m.group(1)).strip("\n").split("\n")
    check("page79-2 the clicks say ok, %s vertices" % n,
          lines[0].startswith("ok %s vertices, " % n), lines[0][:300])
    shown, labels = {}, {}
    for ln in lines[1:]:
        model, v, st, coords = ln.split("\t")
        shown.setdefault((model, v), {})[st] = coords
    for (model, v), got in sorted(shown.items()):
        want = svg_labels(exe, scene, model, v)
        check("page79-3 %s %s v%s: every panel's #coords is the SVG's label" % (
            os.path.basename(scene), model, v), got == want, "page %r, svg %r" % (got, want))


def html79_mode(exe, path, scene, model):
    text = open(path, encoding="utf-8").read()
    check("page79-4 self-contained: no http(s) reference, no src= or href=",
          not re.search(r'(https?:|src=|href=|@import)', text.replace(
              'xmlns="http://www.w3.org/2000/svg"', '')))
    for i in ("prev", "next", "vertex", "stage", "coords", "formula", "panel", "present",
              "live"):
        check("page79-5 the page has #%s" % i, ('id="%s"' % i) in text)
    data = page_data(text)
    names = [s["name"] for s in data["stages"]]
    for x in data["vertices"]:
        want = svg_labels(exe, scene, model, x["v"])
        got = dict(zip(names, x["coords"]))
        check("page79-6 %s v%s: the listed coords are the SVG's labels" % (model, x["v"]),
              got == want, "page %r, svg %r" % (got, want))
        for st, frag in zip(names, x["fg"]):
            try:
                ET.fromstring('<svg xmlns="http://www.w3.org/2000/svg">%s</svg>' % frag)
                ok = True
            except ET.ParseError:
                ok = False
            check("page79-7 %s v%s %s: the panel is well-formed" % (model, x["v"], st), ok)


def marked79_mode(exe, png, ppm, scene, model, v):
    w, h, ctype, rows = png_read(png)
    pw, ph, plain = ppm_read(ppm)
    got = b"".join(rows)
    check("png79-1 the marked image has the render's (the framebuffer's) size",
          (w, h) == (pw, ph))
    head = json.loads(subprocess.run([exe, scene, "--format", "jsonl"], capture_output=True,
                                     text=True).stdout.splitlines()[0])
    lab = svg_labels(exe, scene, model, v)["viewport"]
    m = re.match(r"\(x_vp, y_vp\) = \((-?\d+), (-?\d+)\)$", lab)
    at = None if not m else (head["viewport"]["x"] + int(m.group(1)),
                             head["viewport"]["y"] + int(m.group(2)))
    red, bad = bytes.fromhex("d62728"), []
    for yy in range(h):
        for xx in range(w):
            i = 3 * (yy * w + xx)
            ring = at is not None and (max(abs(xx - at[0]), abs(yy - at[1])) == 3 or
                                       (xx, yy) == at)
            if got[i:i + 3] != (red if ring else plain[i:i + 3]):
                bad.append((xx, yy))
    check("png79-2 %s v%s: red at %s and on the ring around it, else the render" % (
        model, v, at), not bad, "first differing pixels: %r" % bad[:5])


def png_read(path):
    """(w, h, color type, rows of bytes) after checking every chunk's CRC."""
    data = open(path, "rb").read()
    check("png-1 %s: signature" % path, data[:8] == b"\x89PNG\r\n\x1a\n")
    pos, idat, ihdr, crc_ok, ended = 8, b"", None, True, False
    while pos + 12 <= len(data):
        n, = struct.unpack(">I", data[pos:pos + 4])
        typ, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        crc, = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
        crc_ok &= crc == zlib.crc32(typ + body) & 0xffffffff
        if typ == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif typ == b"IDAT":
            idat += body
        elif typ == b"IEND":
            ended = pos + 12 == len(data)
        pos += 12 + n
    check("png-2 %s: every chunk's CRC-32" % path, crc_ok)
    check("png-3 %s: IHDR first, IEND last" % path, ihdr is not None and ended)
    raw = zlib.decompress(idat)           # checks the zlib header and Adler-32
    w, h, depth, ctype, _, _, interlace = ihdr
    bpp = {2: 3, 6: 4}[ctype]
    check("png-4 %s: 8 bits, not interlaced" % path, depth == 8 and interlace == 0)
    stride, rows, prev = w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):           # undo the row filter (PNG spec 9.2)
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, ctype, rows


def png_mode(png, ppm):
    w, h, ctype, rows = png_read(png)
    data = open(ppm, "rb").read()
    m = re.match(rb"P6\n(\d+) (\d+)\n255\n", data)
    pw, ph = int(m.group(1)), int(m.group(2))
    check("png-5 same size as the PPM", (w, h) == (pw, ph), "%dx%d vs %dx%d" % (w, h, pw, ph))
    check("png-6 RGB", ctype == 2)
    check("png-7 same pixels as the PPM", b"".join(rows) == data[m.end():])


def color_mode(png, color):
    w, h, ctype, rows = png_read(png)
    want = bytes.fromhex(color)
    bpp = 3 if ctype == 2 else 4
    found = any(bytes(r[i:i + 3]) == want for r in rows for i in range(0, w * bpp, bpp))
    check("png-8 %s holds the color #%s" % (png, color), found)


def ppm_read(path):
    data = open(path, "rb").read()
    m = re.match(rb"P6\n(\d+) (\d+)\n255\n", data)
    return int(m.group(1)), int(m.group(2)), data[m.end():]


def marked_mode(exe, png, ppm, model, v, scene):
    """journey --image: the render's pixels, but the vertex's framebuffer pixel
    and the square 3 pixels around it in red (#d62728), inside the image."""
    w, h, ctype, rows = png_read(png)
    pw, ph, plain = ppm_read(ppm)
    got = b"".join(rows)
    check("png-9 the marked image has the render's size", (w, h) == (pw, ph))
    fb = trace(exe, scene).get((model, int(v), "framebuffer"))
    check("png-10 the trace has the vertex's framebuffer pixel", fb is not None)
    if fb is None or (w, h) != (pw, ph):
        return
    x, y = int(fb[0]), int(fb[1])
    red, bad = bytes.fromhex("d62728"), []
    for yy in range(h):
        for xx in range(w):
            i = 3 * (yy * w + xx)
            ring = max(abs(xx - x), abs(yy - y)) == 3 or (xx, yy) == (x, y)
            want = red if ring else plain[i:i + 3]
            if got[i:i + 3] != want:
                bad.append((xx, yy))
    check("png-11 %s v%s: red at (%d, %d) and on the ring around it, else the render" % (model, v, x, y),
          not bad, "first differing pixels: %r" % bad[:5])


def frame_mode(svg, ppm, bg, k):
    w, h, data = ppm_read(ppm)
    bg = bytes.fromhex(bg)
    lit = sum(1 for i in range(0, len(data), 3) if data[i:i + 3] != bg)
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    panel = [g for g in root.iter(ns + "g") if g.get("data-stage") == "framebuffer"
             and g.get("class") == "panel"]
    check("frame-1 %s: a framebuffer panel" % svg, len(panel) == 1)
    if len(panel) != 1:
        return
    paths = [e for e in panel[0].iter(ns + "path") if e.get("class") == "frame"]
    check("frame-2 ... with the frame's pixels (%d lit in the render)" % lit,
          len(paths) == 1 and lit > 0)
    if len(paths) != 1:
        return
    f = paths[0]
    check("frame-3 ... all %d of them counted" % lit, f.get("data-pixels") == str(lit),
          "data-pixels=%s" % f.get("data-pixels"))
    check("frame-4 ... in blocks of %s x %s" % (k, k), f.get("data-k") == k, f.get("data-k"))
    if k != "1":
        return
    fbrect = [e for e in panel[0].iter(ns + "rect") if e.get("fill") == "#eef0f3"][0]
    s = float(fbrect.get("width")) / w                 # panel units per pixel
    runs = re.findall(r"M([-\d.]+) [-\d.]+H([-\d.]+)V", f.get("d"))
    total = sum((float(b) - float(a)) / s for a, b in runs)
    check("frame-5 ... whose runs cover %d pixels" % lit, abs(total - lit) <= 0.5 * len(runs),
          "%.1f pixels in %d runs" % (total, len(runs)))


def main():
    mode, a = sys.argv[1], sys.argv[2:]
    scene = None
    if mode == "svg":
        svg_mode(a[0], a[1], a[2], a[3], a[4] if len(a) > 4 else None)
    elif mode == "html":
        html_mode(a[0], a[1], a[2] if len(a) > 2 else None)
    elif mode == "clicks":
        clicks_mode(a[0], a[1], a[2] if len(a) > 2 else None)
    elif mode == "clicks79":
        clicks79_mode(a[0], a[1], a[2], a[3])
    elif mode == "html79":
        html79_mode(a[0], a[1], a[2], a[3])
    elif mode == "marked79":
        marked79_mode(a[0], a[1], a[2], a[3], a[4], a[5])
    elif mode == "dom":
        dom_mode(a[0], a[1], a[2], a[3], a[4], a[5] if len(a) > 5 else scene)
    elif mode == "png":
        png_mode(a[0], a[1])
    elif mode == "color":
        color_mode(a[0], a[1])
    elif mode == "marked":
        marked_mode(a[0], a[1], a[2], a[3], a[4], a[5] if len(a) > 5 else None)
    elif mode == "frame":
        frame_mode(a[0], a[1], a[2], a[3])
    report()


main()
