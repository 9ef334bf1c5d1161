#!/bin/sh
# tests/journey/journey79.sh -- pipetrace journey --svg on scenes of the course's renderers 7 and 9
# See LICENSE for copyright and license.
#
# Usage: sh tests/journey/journey79.sh PIPETRACE.  Run from the repository root.
# The SVG must be well-formed XML with the expected panels, and the vertex's
# coordinates in each panel's label must be the JSON Lines trace's values for
# that vertex at that stage: renderers 7 and 9, perspective and orthographic,
# a vertex the near clip cuts off, vertices the near clip and the rectangle
# clip make.  Same bytes on two runs.  The page (--html): self-contained,
# each listed vertex's coordinates and panels the SVG's, the list as asked;
# the image (--image): the render with the vertex's pixel ringed.
# The parsing checks need python3 (standard library only); without it they
# are skipped and say so.
exe=$1
. tests/lib/testlib.sh
c=tests/course79

# ---- errors (exit 2, a clear message, no file)
run journey $c/r7-near-01.scene --vertex 99 --svg "$tmp/x.svg"
check "j79-1.4 a vertex no position has, not even after the clips: exit 2, no file" \
    sh -c 'test "$1" = 2 && grep -q "no position of .* has a vertex 99" "$2" && test ! -e "$3"' \
    - "$rc" "$tmp/err" "$tmp/x.svg"
run journey $c/r7-near-01.scene --vertex 1 --model nosuch --svg "$tmp/x.svg"
check "j79-1.5 no such model: exit 2" test "$rc" = 2 -a ! -e "$tmp/x.svg"

# ---- the SVG: same bytes twice
run journey $c/r7-near-01.scene --vertex 6 --svg "$tmp/a.svg"
check "j79-2.1 renderer 7 scene, --svg: exit 0" test "$rc" = 0 -a -s "$tmp/a.svg"
run journey $c/r7-near-01.scene --vertex 6 --svg "$tmp/b.svg"
check "j79-2.2 same bytes on two runs" cmp -s "$tmp/a.svg" "$tmp/b.svg"
run journey $c/r7-near-01.scene --vertex 6 --svg -
check "j79-2.3 --svg - writes the same to standard output" \
    sh -c 'printf "%s\n" "$1" | cmp -s - "$2"' - "$out" "$tmp/a.svg"

# ---- numbers past a double's range: the labels say inf, the drawing stays finite
printf 'renderer 7\nframebuffer 20 20\ncamera perspective\nmodel m\nv 1e308 1e308 -1e-300\nv 0 0 -2\nv 0.5 0.5 -1\nsegment 1 2\nsegment 2 3\n' > "$tmp/huge.scene"
run journey "$tmp/huge.scene" --vertex 1 --svg "$tmp/h.svg"
check "j79-2.4 a vertex that overflows to inf: exit 0, the label says inf" \
    sh -c 'test "$1" = 0 && grep -q "(x_c, y_c, z_c) = (inf, inf" "$2"' - "$rc" "$tmp/h.svg"
check "j79-2.5 ... no attribute holds nan or inf" \
    sh -c '! grep -E -i -q "=\"[^\"]*(nan|inf)" "$1"' - "$tmp/h.svg"

# ---- the page and the image
run journey $c/r7-near-01.scene --vertex 9 --html "$tmp/p.html" --image "$tmp/p.png"
check "j79-4.1 --html and --image of a renderer 7 scene: exit 0, both written" \
    test "$rc" = 0 -a -s "$tmp/p.html" -a -s "$tmp/p.png"
run journey $c/r7-near-01.scene --vertex 9 --html "$tmp/q.html"
check "j79-4.2 the page: same bytes on two runs" cmp -s "$tmp/p.html" "$tmp/q.html"
check "j79-4.3 the page lists every vertex of the position (8 and the clips' 6)" \
    test "$(grep -c '^{"m":0,"v":[0-9]*,' "$tmp/p.html")" = 14
check "j79-4.4 ... and shows vertex 9 first (the 9th listed)" grep -q '"start":8,' "$tmp/p.html"
run journey $c/r9-near-05.scene --vertex 13,2-3 --html "$tmp/l.html"
check "j79-4.5 --vertex 13,2-3 on a renderer 9 scene: vertices 2, 3 and 13, 13 first" \
    sh -c 'test "$(grep -o "^{\"m\":0,\"v\":[0-9]*" "$1" | tr -d "{\"mv:" | tr "\n" " ")" = "0,2 0,3 0,13 " &&
           grep -q "\"start\":2," "$1"' - "$tmp/l.html"
run journey $c/r7-near-01.scene --vertex 9 --svg "$tmp/l.svg" --image "$tmp/l.svg"
check "j79-4.6 two outputs naming one file: exit 1" test "$rc" = 1
run journey $c/r7-near-01.scene --vertex 1,2 --image "$tmp/x.png"
check "j79-4.7 --image of a list: exit 1, no file" test "$rc" = 1 -a ! -e "$tmp/x.png"
run journey $c/r9-near-05.scene --vertex 2,99 --html "$tmp/x10.html"
check "j79-4.10 --vertex 2,99: the position has no vertex 99: exit 2, says so, no file" \
    sh -c 'test "$1" = 2 && grep -q "has no vertex 99" "$2" && test ! -e "$3"' \
    - "$rc" "$tmp/err" "$tmp/x10.html"
run journey $c/r9-near-05.scene --vertex 99 --html "$tmp/x.html"
check "j79-4.8 --html of a vertex no position has: exit 2, no file" \
    test "$rc" = 2 -a ! -e "$tmp/x.html"
run journey $c/r9-aa-04.scene --vertex 1 --image "$tmp/aa.ppm"
check "j79-4.9 --image FILE.ppm: a binary PPM" sh -c 'test "$1" = 0 && head -c 2 "$2" | grep -q P6' \
    - "$rc" "$tmp/aa.ppm"

if ! command -v python3 >/dev/null 2>&1; then
    echo "note: python3 not found: the parsing checks are skipped" >&2
    report; exit $?
fi

# ---- the panels and their numbers against the trace
# CASE: ID SCENE VERTEX KIND (what the vertex is: model, cutoff, near-made, clip-made)
cases="7p $c/r7-near-01.scene 1 model
7n $c/r7-near-01.scene 6 cutoff
7m $c/r7-near-01.scene 9 near-made
7c $c/r7-near-01.scene 11 clip-made
7o $c/r7-clip-08-corner-ur.scene 1 model
9p $c/r9-near-05.scene 2 model
9m $c/r9-near-05.scene 13 near-made
9o $c/r9-aa-04.scene 1 model
9c $c/r9-clip-12-through-x.scene 3 clip-made"
echo "$cases" | while read -r id sc v kind; do
    "$exe" "$sc" --format jsonl --trace "$tmp/$id.jsonl" >/dev/null 2>&1
    "$exe" journey "$sc" --vertex "$v" --svg "$tmp/$id.svg" >/dev/null 2>"$tmp/$id.err"
    echo "$?" > "$tmp/$id.rc"
done
echo "$cases" > "$tmp/cases"
pyrun - "$tmp" <<'EOF'
import json, re, sys, xml.etree.ElementTree as ET
tmp = sys.argv[1]
passed = failed = 0
def check(name, ok, why=""):
    global passed, failed
    if ok: passed += 1
    else:
        failed += 1
        print("FAIL " + name + ("  (" + why + ")" if why else ""))
NS = "{http://www.w3.org/2000/svg}"
for line in open(tmp + "/cases").read().split("\n"):
    if not line.strip(): continue
    cid, scene, v, kind = line.split()
    v = int(v)
    tag = "j79-3 %s vertex %d (%s)" % (scene.split("/")[-1], v, kind)
    rc = open("%s/%s.rc" % (tmp, cid)).read().strip()
    check(tag + ": exit 0", rc == "0", open("%s/%s.err" % (tmp, cid)).read()[:200])
    if rc != "0": continue
    try:
        root = ET.parse("%s/%s.svg" % (tmp, cid)).getroot()
    except ET.ParseError as e:
        check(tag + ": well-formed XML", False, str(e)); continue
    check(tag + ": well-formed XML", root.tag == NS + "svg")
    recs = [json.loads(l) for l in open("%s/%s.jsonl" % (tmp, cid))]
    head = recs[0]
    title = root.find(NS + "title").text
    model = re.search(r"of model (.*), renderer", title).group(1)
    renderer = head["renderer"]
    want = ["model"] + (["world"] if renderer == 9 else []) + \
        ["view", "volume", "camera", "nearclip", "image", "viewport"]
    panels = {}
    order = []
    for g in root.iter(NS + "g"):
        if g.get("class") == "panel":
            order.append(g.get("data-stage"))
            labs = [t for t in g.iter(NS + "text") if t.get("class") == "coords"]
            panels[g.get("data-stage")] = "".join(labs[0].itertext()) if labs else None
    check(tag + ": the panels, in order", order == want, str(order))
    at = {}
    for r in recs:
        if r["type"] == "vertex" and r["model"] == model and r["v"] == v:
            at[r["stage"]] = (r["x"], r["y"], r["z"])
    pix = {(r["x"], r["y"]) for r in recs if r["type"] == "pixel" and r["model"] == model}
    stage_of = {"model": ["model"], "world": ["world"], "view": ["view"], "volume": ["view"],
                "camera": ["camera"], "nearclip": ["nearclip", "camera"],
                "image": ["clip", "image"] if kind == "clip-made" else ["image"]}
    for p, st in stage_of.items():
        if p not in panels: continue
        lab = panels[p] or ""
        rec = next((at[s] for s in st if s in at), None)
        if rec is None:
            check("%s: panel %s says the vertex is not made yet" % (tag, p),
                  "not yet" in lab, lab)
            texts = ["".join(t.itertext()) for g in root.iter(NS + "g")
                     if g.get("data-stage") == p for t in g.iter(NS + "text")]
            check("%s: panel %s marks no vertex that is not made yet" % (tag, p),
                  "v%d" % v not in texts and "off the panel" not in texts, str(texts))
            continue
        m = re.search(r"= \(([^)]*)\)$", lab)
        nums = [float(x) for x in m.group(1).split(", ")] if m else []
        check("%s: panel %s's label is the trace's %s record" % (tag, p, st[0]),
              nums == list(rec), "%s vs %s" % (lab, rec))
    lab = panels.get("viewport") or ""
    m = re.search(r"= \((-?\d+), (-?\d+)\)$", lab)
    if m:
        xy = (int(m.group(1)) + head["viewport"]["x"], int(m.group(2)) + head["viewport"]["y"])
        check(tag + ": the viewport pixel is one the trace writes", xy in pix, lab)
    else:
        check(tag + ": no viewport pixel: the vertex is outside the square after the clip",
              "none" in lab and "clip" not in at and (at.get("image") is None or
              max(abs(at["image"][0]), abs(at["image"][1])) > 1), lab)
    def notes(stage):
        return ["".join(t.itertext()) for g in root.iter(NS + "g")
                if g.get("data-stage") == stage
                for t in g.iter(NS + "text") if t.get("class") == "note"]
    def t_in_note(name, panel, stage):    # the note's t is the trace's for the vertex
        ns = notes(panel)
        rec = next(r for r in recs if r["type"] == "vertex" and r["model"] == model
                   and r["v"] == v and r["stage"] == stage)
        m = re.search(r"t = ([-0-9.eE]+)", ns[0] if ns else "")
        check(tag + ": " + name, m is not None and float(m.group(1)) == rec["from"]["t"],
              str(ns))
    if kind == "cutoff":
        check(tag + ": the near clip's note says it cut the vertex off",
              any("cut off" in n for n in notes("nearclip")), str(notes("nearclip")))
    if kind == "near-made":
        cuts = [t for g in root.iter(NS + "g") if g.get("data-stage") == "nearclip"
                for t in g.iter(NS + "circle") if t.get("class") == "cut"]
        check(tag + ": the near clip panel marks its cut points", len(cuts) > 0)
        t_in_note("the near clip's note gives the trace's t", "nearclip", "nearclip")
    if kind == "clip-made":
        t_in_note("the image plane's note gives the clip's t from the trace", "image", "clip")
print("%d passed, %d failed" % (passed, failed))
EOF

py() {      # py MODE ARGS...: tests/journey/journey_check.py, its counts added to ours
    pyrun tests/journey/journey_check.py "$@"
}
# ---- the page's data against the SVG (no browser); the image against the render
py html79 "$exe" "$tmp/p.html" $c/r7-near-01.scene near
py html79 "$exe" "$tmp/l.html" $c/r9-near-05.scene near
"$exe" journey $c/r9-aa-04.scene --vertex 1 --html "$tmp/o.html"
py html79 "$exe" "$tmp/o.html" $c/r9-aa-04.scene aa
for cs in "r7-near-01 near 9" "r7-near-01 near 1" "r9-near-05 near 2" "r9-aa-04 aa 1" \
          "r9-vp-02 cube 3" "r7-clip-08-corner-ur seg 3"; do
    set -- $cs
    "$exe" $c/$1.scene --image "$tmp/r.ppm"
    "$exe" journey $c/$1.scene --model $2 --vertex $3 --image "$tmp/m.png"
    py marked79 "$exe" "$tmp/m.png" "$tmp/r.ppm" $c/$1.scene $2 $3
done
report
