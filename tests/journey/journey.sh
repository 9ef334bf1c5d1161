#!/bin/sh
# tests/journey/journey.sh -- pipetrace journey (SVG, HTML) and --image FILE.png
# See LICENSE for copyright and license.
#
# Usage: sh tests/journey/journey.sh PIPETRACE.  Run from the repository root.  The
# SVG must be well-formed XML with one panel per stage whose labels equal the
# JSONL trace; the HTML page self-contained with the trace's numbers; the PNG
# must decode to the PPM's pixels.  The checks that parse need python3
# (standard library only); without it they are skipped and say so.
exe=$1
. tests/lib/testlib.sh

py() {      # py MODE ARGS...: tests/journey/journey_check.py, its counts added to ours
    pyrun tests/journey/journey_check.py "$@"
}
command -v python3 >/dev/null 2>&1 ||
    echo "note: python3 not found: the parsing checks are skipped" >&2

# ---- exit codes
run journey
check "jny-1.1 no --vertex: exit 1" test "$rc" = 1
check "jny-1.2 ... says so" grep -q -- "--vertex N is required" "$tmp/err"
run journey --vertex 1
check "jny-1.3 no --svg, --html or --image: exit 1" test "$rc" = 1
run journey --vertex 0 --svg "$tmp/x.svg"
check "jny-1.4 --vertex 0: exit 1" test "$rc" = 1
run journey --vertex 1 --frob --svg "$tmp/x.svg"
check "jny-1.5 unknown option: exit 1" test "$rc" = 1
run journey --help
check "jny-1.6 --help: exit 0" test "$rc" = 0 -a -n "$(echo "$out" | grep 'usage: pipetrace journey')"
printf 'framebuffer 10 10\nmodel m\nv 1 2\n' > "$tmp/bad.scene"
echo keep > "$tmp/keep.svg"
run journey "$tmp/bad.scene" --vertex 1 --svg "$tmp/keep.svg" --html "$tmp/new.html"
check "jny-1.7 bad scene: exit 2" test "$rc" = 2
check "jny-1.8 ... FILE:LINE:COL message" grep -q "^$tmp/bad.scene:3:[0-9]*: error: " "$tmp/err"
check "jny-1.9 ... the old file kept, no new file" test "$(cat "$tmp/keep.svg")" = keep -a ! -e "$tmp/new.html"
run journey docs/examples/triangle.scene --vertex 4 --svg "$tmp/x.svg"
check "jny-1.10 vertex out of range: exit 2" test "$rc" = 2 -a ! -e "$tmp/x.svg"
run journey docs/examples/triangle.scene --vertex 1 --model nosuch --svg "$tmp/x.svg"
check "jny-1.11 no such model: exit 2" test "$rc" = 2
run journey docs/examples/triangle.scene --vertex 1 --svg "$tmp/nodir/x.svg"
check "jny-1.14 unwritable path: exit 2" test "$rc" = 2
check "jny-1.15 no temporary file left" test "$(ls "$tmp" | grep -c '\.svg\.\|\.html\.')" = 0

# ---- the SVG
run journey --vertex 1 --svg "$tmp/b1.svg"
check "jny-2.1 built-in scene, vertex 1: exit 0, nothing on stdout" test "$rc" = 0 -a -z "$out"
check "jny-2.2 the same SVG as docs/journey-builtin.svg (make screenshots)" \
    cmp -s "$tmp/b1.svg" docs/journey-builtin.svg
"$exe" journey --vertex 1 --svg - > "$tmp/b1-stdout.svg"
check "jny-2.3 --svg - writes the same to stdout" cmp -s "$tmp/b1.svg" "$tmp/b1-stdout.svg"
"$exe" journey --vertex 1 --svg "$tmp/b1-again.svg"
check "jny-2.4 byte-identical on a second run" cmp -s "$tmp/b1.svg" "$tmp/b1-again.svg"
if command -v xmllint >/dev/null 2>&1; then
    check "jny-2.5 xmllint: well-formed" xmllint --noout "$tmp/b1.svg"
fi
py svg "$exe" "$tmp/b1.svg" cube 1
# vertices off the view rectangle, behind the camera, outside the framebuffer,
# not finite, huge, unused; an orthographic camera
printf 'framebuffer 20 10\nmodel m\nv 1 0.5 0\nv 0 0 -2\nl 1 2\n' > "$tmp/z0.scene"
printf 'framebuffer 20 10\ncamera orthographic\nmodel m\nv 1e17 0 0\nv 1e18 0 0\nv 0 0 0\nl 3 1\nl 3 2\n' \
    > "$tmp/big.scene"
for c in "docs/examples/behind.scene stick 2" "docs/examples/clip.scene m 1" \
         "docs/examples/clip.scene m 2" "docs/examples/ortho.scene far 3" \
         "$tmp/z0.scene m 1" "$tmp/big.scene m 2" "$tmp/big.scene m 1" \
         "docs/examples/two-models.scene arrow 2" "docs/examples/builtin.scene floor 3"; do
    set -- $c
    "$exe" journey "$1" --model "$2" --vertex "$3" --svg "$tmp/e.svg" 2>"$tmp/err"
    check "jny-2.6 $c: exit 0" test $? = 0
    py svg "$exe" "$tmp/e.svg" "$2" "$3" "$1"
done
# names that need escaping, and UTF-8
printf "framebuffer 30 20\nmodel a<b&c'>\303\251\nv 0 0 -2\nv 1 1 -3\nl 1 2\n" > "$tmp/name.scene"
"$exe" journey "$tmp/name.scene" --vertex 1 --svg "$tmp/n.svg" --html "$tmp/n.html"
check "jny-2.7 a model name with < & ' > and UTF-8: exit 0" test $? = 0
check "jny-2.8 ... escaped in the SVG" grep -q 'a&lt;b&amp;c&apos;&gt;' "$tmp/n.svg"
py svg "$exe" "$tmp/n.svg" "$(printf "a<b&c'>\303\251")" 1 "$tmp/name.scene"
py html "$exe" "$tmp/n.html" "$tmp/name.scene"

# ---- the HTML page
run journey --vertex 1 --html "$tmp/b1.html"
check "jny-3.1 --html: exit 0" test "$rc" = 0 -a -s "$tmp/b1.html"
check "jny-3.2 starts as HTML5" test "$(head -c 15 "$tmp/b1.html")" = "<!DOCTYPE html>"
py html "$exe" "$tmp/b1.html"
"$exe" journey docs/examples/clip.scene --vertex 1 --html "$tmp/c.html"
py html "$exe" "$tmp/c.html" docs/examples/clip.scene

# ---- PNG beside PPM
for s in "" docs/examples/triangle.scene docs/examples/clip.scene; do
    "$exe" $s --image "$tmp/i.ppm" && "$exe" $s --image "$tmp/i.png"
    check "jny-4.1 --image .png and .ppm ${s:-builtin}: exit 0" test $? = 0
    check "jny-4.2 ... the PNG starts with the PNG signature" \
        test "$(head -c 4 "$tmp/i.png" | tail -c 3)" = PNG
    py png "$tmp/i.png" "$tmp/i.ppm"
done
"$exe" docs/examples/triangle.scene --image "$tmp/upper.PNG"
check "jny-4.3 .PNG in capitals is PNG too" test "$(head -c 4 "$tmp/upper.PNG" | tail -c 3)" = PNG

# ---- journey --image: the render with the vertex's pixel ringed
"$exe" --image "$tmp/r.ppm"
run journey --vertex 1 --image "$tmp/m.png"
check "jny-5.1 journey --image: exit 0" test "$rc" = 0 -a -s "$tmp/m.png"
py marked "$exe" "$tmp/m.png" "$tmp/r.ppm" cube 1
"$exe" docs/examples/clip.scene --image "$tmp/r2.ppm"
"$exe" journey docs/examples/clip.scene --vertex 1 --image "$tmp/m2.png"
py marked "$exe" "$tmp/m2.png" "$tmp/r2.ppm" m 1 docs/examples/clip.scene
run journey --vertex 1 --svg "$tmp/same" --image "$tmp/same"
check "jny-5.2 two outputs naming one file: exit 1" test "$rc" = 1

# ---- the matrix camera: ten panels; v2 of lookat-near lies behind the eye
# (outside the view volume), v3 off to the right: their segments are clipped
for c in "docs/examples/lookat-near.scene stick 1" "docs/examples/lookat-near.scene stick 2" \
         "docs/examples/lookat-near.scene stick 3" "docs/examples/lookat-cube.scene cube 8" \
         "docs/examples/compare-matrix.scene tri 1" "docs/examples/lookat-world.scene square 1"; do
    set -- $c
    run journey "$1" --model "$2" --vertex "$3" --svg "$tmp/mx.svg" --html "$tmp/mx.html"
    check "jny-6.1 matrix camera $c: exit 0" test "$rc" = 0 -a -s "$tmp/mx.svg" -a -s "$tmp/mx.html"
    py svg "$exe" "$tmp/mx.svg" "$2" "$3" "$1"
    py html "$exe" "$tmp/mx.html" "$1"
    check "jny-6.7 matrix camera $c: the camera's sliders (or, built without the module, a note)" \
        sh -c "grep -q '\"matrix\":true' '$tmp/mx.html' && grep -q \"'fov', 'eye_x'\" '$tmp/mx.html' ||
               grep -q 'No sliders on this page: pipetrace was built without' '$tmp/mx.html'"
done
"$exe" journey docs/examples/lookat-near.scene --vertex 2 --svg "$tmp/mx2.svg"
"$exe" journey docs/examples/lookat-near.scene --vertex 1 --svg "$tmp/mx1a.svg"; "$exe" journey docs/examples/lookat-near.scene --vertex 1 --svg "$tmp/mx1b.svg"
check "jny-6.2 matrix camera: byte-identical on a second run" cmp -s "$tmp/mx1a.svg" "$tmp/mx1b.svg"
"$exe" journey docs/examples/lookat-near.scene --vertex 2 --svg "$tmp/mx2b.svg"
check "jny-6.3 ... (vertex outside the view volume)" cmp -s "$tmp/mx2.svg" "$tmp/mx2b.svg"
check "jny-6.4 ... its panels after the cvv say it stops there" \
    grep -q ">v2 stops at the cvv<" "$tmp/mx2.svg"
"$exe" docs/examples/lookat-near.scene --image "$tmp/rn.ppm"
"$exe" journey docs/examples/lookat-near.scene --vertex 1 --image "$tmp/mn.png"
check "jny-6.5 matrix camera --image: exit 0" test $? = 0
py marked "$exe" "$tmp/mn.png" "$tmp/rn.ppm" stick 1 docs/examples/lookat-near.scene
"$exe" journey docs/examples/lookat-near.scene --vertex 2 --image "$tmp/mn2.ppm"
check "jny-6.6 --image of a vertex outside the view volume: the render, nothing ringed" \
    cmp -s "$tmp/mn2.ppm" "$tmp/rn.ppm"

# ---- axes named in the classic panels, with the way each grows (rows go down)
for s in "" docs/examples/ortho.scene docs/examples/behind.scene; do
    "$exe" journey $s --vertex 1 --svg "$tmp/ax.svg"
    for name in "x_pp →" "y_pp ↑" "x_vp →" "y_vp ↓" "x_fb →" "y_fb ↓" "idx →"; do
        check "jny-7.1 ${s:-builtin}: a panel names the axis '$name'" \
            grep -q ">$name</text>" "$tmp/ax.svg"
    done
done

# ---- --vertex LIST: the page lists just those vertices of the model
vs() { grep -o '{"m":[0-9]*,"v":[0-9]*' "$1" | sed 's/.*"v"://' | tr '\n' ' '; }
"$exe" journey --vertex 3,1 --model pyramid --html "$tmp/l1.html"
check "jny-8.1 --vertex 3,1: the page has pyramid's v1 and v3" test "$(vs "$tmp/l1.html")" = "1 3 "
check "jny-8.2 ... and shows v3 first" grep -q '"start":1[,}]' "$tmp/l1.html"
"$exe" journey --vertex 2-4,4,7 --html "$tmp/l2.html"
check "jny-8.3 --vertex 2-4,4,7: ranges, a vertex named twice listed once" test "$(vs "$tmp/l2.html")" = "2 3 4 7 "
"$exe" journey --vertex all --model pyramid --html "$tmp/l3.html"
check "jny-8.4 --vertex all: every vertex of the model" test "$(vs "$tmp/l3.html" | wc -w)" = "$("$exe" --format jsonl | grep -c '"model":"pyramid","v":[0-9]*,"stage":"model"')"
for bad in 0 3-1 1,,2 x 2- ,1 1, 99999999999; do
    "$exe" journey --vertex "$bad" --html "$tmp/lb.html" 2>"$tmp/err"
    check "jny-8.5 --vertex '$bad': usage error (exit 1), no file" test $? = 1 -a ! -e "$tmp/lb.html" -a -s "$tmp/err"
done
"$exe" journey --vertex 1-99 --html "$tmp/lb.html" 2>"$tmp/err"
check "jny-8.6 --vertex 1-99 past the model's vertices: exit 2, no file" test $? = 2 -a ! -e "$tmp/lb.html"
"$exe" journey --vertex 1,2 --svg "$tmp/lb.svg" 2>"$tmp/err"
check "jny-8.7 a list with --svg: usage error, it draws one vertex" test $? = 1 -a ! -e "$tmp/lb.svg"
"$exe" journey --vertex all --image "$tmp/lb.ppm" 2>"$tmp/err"
check "jny-8.8 a list with --image: usage error" test $? = 1 -a ! -e "$tmp/lb.ppm"

# ---- the framebuffer panel shows the whole frame: every model's pixels
"$exe" docs/examples/two-models.scene --image "$tmp/two.ppm"
for m in square arrow; do
    "$exe" journey docs/examples/two-models.scene --model $m --vertex 2 --svg "$tmp/two-$m.svg"
    py frame "$tmp/two-$m.svg" "$tmp/two.ppm" 000040 1
done
sed '/^model arrow/,$d' docs/examples/two-models.scene > "$tmp/one.scene"
"$exe" "$tmp/one.scene" --image "$tmp/one.ppm"
check "jny-9.1 two models light more pixels than one (the test scene)" \
    test "$(wc -c < "$tmp/two.ppm")" = "$(wc -c < "$tmp/one.ppm")" -a "$(cmp -l "$tmp/two.ppm" "$tmp/one.ppm" | wc -l)" -gt 0
"$exe" --image "$tmp/b.ppm"
"$exe" journey --vertex 1 --svg "$tmp/bf.svg"
py frame "$tmp/bf.svg" "$tmp/b.ppm" 181828 2
printf 'framebuffer 5000 4000\nviewport 0 0 5000 4000\nmodel m\nv 0 0 -2\nv 0.5 0.5 -2\nl 1 2\n' > "$tmp/big.scene"
"$exe" journey "$tmp/big.scene" --vertex 1 --svg "$tmp/big.svg"
check "jny-9.2 a frame past PT_JOURNEY_FRAMEMAX pixels is not drawn" \
    sh -c "test -s '$tmp/big.svg' && ! grep -q 'class=\"frame\"' '$tmp/big.svg'"

# ---- the labels' widths (src/tools/journey/jplace.c) against the font files
pyrun tests/journey/journey_fontwidths.py

report
