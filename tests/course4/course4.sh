#!/bin/sh
# tests/course4/course4.sh -- renderer 4 byte for byte: images and logs against the course's own
# See LICENSE for copyright and license.
#
# Usage: sh tests/course4/course4.sh PIPETRACE.  Run from the repository root.
# Each NAME.scene here has NAME.ppm.gz, the course's renderer 4's framebuffer,
# and NAME.DEBUG.log.gz, what it printed with the debug switches DEBUG
# (make_expected.sh made them with the course's jar).  The image of
# `pipetrace NAME.scene --image` and the log of `--kraft-debug DEBUG` must be
# those bytes.
exe=$1
dir=tests/course4
. tests/lib/testlib.sh

n=0
for scene in "$dir"/*.scene; do
    name=$(basename "$scene" .scene)
    run "$scene" --image "$tmp/$name.ppm"
    check "course4-1.1 $name: exit 0" test "$rc" = 0
    gzip -dc "$dir/$name.ppm.gz" > "$tmp/want.ppm"
    check "course4-1.2 $name: the image byte for byte" cmp -s "$tmp/want.ppm" "$tmp/$name.ppm"
    for log in "$dir/$name".*.log.gz; do
        d=${log#"$dir/$name."}
        d=${d%.log.gz}
        run "$scene" --kraft-debug "$d"
        gzip -dc "$log" > "$tmp/want.log"
        check "course4-2.1 $name --kraft-debug $d: the log byte for byte" cmp -s "$tmp/want.log" "$tmp/out"
        n=$((n + 1))
    done
done
check "course4-2.2 20 logs" test "$n" = 20

# ---- course4-3: the switches' spellings
run "$dir/switches.scene" --kraft-debug scene,bogus
check "course4-3.1 an unknown switch: usage error" test "$rc" = 1
check "course4-3.2 ... naming the list" grep -q "scene, position, rasterize" "$tmp/err"
run "$dir/switches.scene" --kraft-debug all --format csv
check "course4-3.3 --kraft-debug with --format csv: usage error" test "$rc" = 1
run "$dir/switches.scene" --format kraft-pixels
cp "$tmp/out" "$tmp/pixels.log"
run "$dir/switches.scene" --kraft-debug scene,rasterize
check "course4-3.4 kraft-pixels is scene,rasterize" cmp -s "$tmp/pixels.log" "$tmp/out"
run "$dir/switches.scene" --format kraft
gzip -dc "$dir/switches.scene.log.gz" > "$tmp/want.log"
check "course4-3.5 kraft is scene" cmp -s "$tmp/want.log" "$tmp/out"
run "$dir/switches.scene" --kraft-debug none
check "course4-3.6 none: the warnings alone" test "$(grep -cv '^\*\*\*WARNING\|^Model\|^[0-9]*: \|^This Model\|^$' "$tmp/out")" = 0
check "course4-3.7 ... and some" grep -q "WARNING: Added default color to model: plain." "$tmp/out"

# ---- course4-4: the fast path and the walked path draw the same image
run "$dir/aa-edges.scene" --image "$tmp/a.ppm" --format kraft-pixels --trace "$tmp/a.log"
check "course4-4.1 an image drawn beside the pixel log is the same" cmp -s "$tmp/a.ppm" "$tmp/aa-edges.ppm"
run "$dir/colors-int.scene" --image "$tmp/c.ppm" --format jsonl --trace "$tmp/c.jsonl"
check "course4-4.2 ... and beside a trace of every pixel" cmp -s "$tmp/c.ppm" "$tmp/colors-int.ppm"

# ---- course4-5: pipetrace diff reads the course's log: anti-aliased pairs as
# two pixels each, points' vertices as used, their pixels passed over
for name in aa-edges points; do
    run "$dir/$name.scene" --trace "$tmp/$name.txt"
    gzip -dc "$dir/$name.all.log.gz" > "$tmp/$name.log"
    run diff "$tmp/$name.txt" "$tmp/$name.log"
    check "course4-5.1 $name: the trace and the course's log agree" test "$rc" = 0
    check "course4-5.2 ... on every pixel" grep -q "The traces agree" "$tmp/out"
done
sed 's/{y_hi = *-*[0-9]*/{y_hi =  -7/' "$tmp/aa-edges.log" > "$tmp/moved.log"
run diff "$tmp/aa-edges.txt" "$tmp/moved.log"
check "course4-5.3 a pair's upper pixel moved: the pixels differ" test "$rc" = 1
# ---- course4-6: segments with an end that has no integer pixel (NaN, an
# infinity): the course rounds it as Math.round does and draws on; the
# traces say so in a note record before the segment's pixels
run "$dir/nan-segment.scene" --trace "$tmp/nan.txt"
check "course4-6.1 NaN ends: exit 0" test "$rc" = 0
check "course4-6.2 ... the text trace's note on v1, rounded to (0, 0)" grep -q "^m s1 *note *v1: endpoint (x_pp, y_pp) = (nan, nan) .* makes it (0, 0)" "$tmp/nan.txt"
check "course4-6.3 ... no segment skipped" grep -q "segments_skipped 0" "$tmp/nan.txt"
check "course4-6.4 ... the note before the segment's pixels" test "$(grep -m1 -n ' s1 ' "$tmp/nan.txt" | cut -d: -f2 | grep -c note)" = 1
run "$dir/nan-segment.scene" --format jsonl
check "course4-6.5 ... the JSON Lines trace's note" grep -q '"type":"note","model":"m","segment":2,"v":1,"what":"endpoint (x_pp, y_pp) = (nan, nan)' "$tmp/out"
gzip -dc "$dir/nan-segment.all.log.gz" > "$tmp/nan.log"
run diff "$tmp/nan.txt" "$tmp/nan.log"
check "course4-6.6 ... the trace and the course's log agree on every pixel" grep -q "The traces agree" "$tmp/out"
run "$dir/inf-segment.scene" --kraft-debug all
check "course4-6.7 an infinite start: the pixel log refused (2^31 lines)" grep -q "2147483669 steps, more than the 16777216 lines" "$tmp/err"
check "course4-6.8 ... exit 2, nothing written" test "$rc" = 2 -a ! -s "$tmp/out"
run "$dir/inf-segment.scene"
check "course4-6.9 ... its trace's note: -inf rounded to Long.MIN_VALUE" grep -q "(-inf, -inf) .* makes it (-9223372036854775808, -9223372036854775808)" "$tmp/out"
check "course4-6.10 ... 2^31 + 21 steps clipped" grep -q "clipped *2147483669 steps" "$tmp/out"
sed 's/^v 1 0.5 0$/v -1 0.5 0/' "$dir/inf-segment.scene" > "$tmp/endless.scene"
run "$tmp/endless.scene" --image "$tmp/endless.ppm"
check "course4-6.11 an infinite end: the course's loop never ends, pipetrace's does" test "$rc" = 0 -a -s "$tmp/endless.ppm"
run "$tmp/endless.scene"
check "course4-6.12 ... and its trace says so" grep -q "note *the course's loop never ends: its last step is the largest int" "$tmp/out"
run "$tmp/endless.scene" --kraft-debug all
check "course4-6.13 ... its pixel log refused: the course's would never end" grep -q "segment 1: its last step is (int) 2147483647, the largest int" "$tmp/err"
# ---- course4-7: hidden models: the course's Pipeline.render runs no stage of
# a hidden position or model (nor logs its vertices), and pipetrace's traces
# leave them out alike, saying so in the header
printf 'framebuffer 20 20\ncamera perspective\nmodel a\nv 0 0 -1\nv 0.5 0.5 -1\nsegment 1 2\nmodel b\nhidden-model\nv 0.1 0 -1\nv 0.5 0.2 -1\nsegment 1 2\nmodel c\nhidden-position\nv 0.2 0 -1\nv 0.5 0.3 -1\nsegment 1 2\n' > "$tmp/hid.scene"
run "$tmp/hid.scene"
check "course4-7.1 a hidden model's vertices are not traced" test "$(grep -c '^[bc] v' "$tmp/out")" = 0
check "course4-7.2 ... the visible one's are" test "$(grep -c '^a v' "$tmp/out")" = 10
check "course4-7.3 ... the header says which and why" sh -c 'grep -q "^model        b: .*, hidden (hidden-model): not drawn, not traced$" "$1" && grep -q "^model        c: .*, hidden (hidden-position): not drawn, not traced$" "$1"' _ "$tmp/out"
check "course4-7.4 ... vertices_traced counts the visible ones" grep -q "vertices_traced 2$" "$tmp/out"
run "$tmp/hid.scene" --format jsonl
check "course4-7.5 JSON Lines: no vertex record of b or c, both traced false" sh -c '! grep -q "\"type\":\"vertex\",\"model\":\"[bc]\"" "$1" && test "$(grep -o "\"traced\":false" "$1" | wc -l)" = 2' _ "$tmp/out"
run "$tmp/hid.scene" --kraft-debug all
check "course4-7.6 the course's log: b and c hidden, their vertices not logged" sh -c 'grep -q "Hidden model: b" "$1" && grep -q "Hidden position: c" "$1" && test "$(grep -c "^[0-9]. .*: vIndex" "$1")" = 8' _ "$tmp/out"
# ---- course4-8: a point's pixels are in the traces (pixel records of "pN"),
# in the order the course draws them among the segments; why finds them
run "$dir/points.scene"
check "course4-8.1 point 1's pixel in the text trace" grep -q "^dots p1 *pixel *x_fb = *6  y_fb = *27  idx = 1086$" "$tmp/out"
check "course4-8.2 ... in drawing order: p1 p2 s1 p3 p4 p5 s2 p7 p10" test "$(grep -o "^dots [sp][0-9]*" "$tmp/out" | uniq | cut -d' ' -f2 | tr '\n' ' ')" = "p1 p2 s1 p3 p4 p5 s2 p7 p10 "
check "course4-8.3 ... 134 of them, 54 of the segments'" test "$(grep -c "^dots p[0-9]* *pixel" "$tmp/out")" = 134 -a "$(grep -c "^dots s[0-9]* *pixel" "$tmp/out")" = 54
run "$dir/points.scene" --format jsonl
check "course4-8.4 JSON Lines: the same 134, keyed by point" test "$(grep -c '^{"type":"pixel","model":"dots","point":[0-9]*,"x":' "$tmp/out")" = 134
check "course4-8.5 ... point 1's" grep -q '^{"type":"pixel","model":"dots","point":1,"x":6,"y":27,"i":1086}$' "$tmp/out"
run why "$dir/points.scene" 6 27
check "course4-8.6 why: lit by point 1, in its color" grep -q "^  dots p1 (point 1: v1, radius 0): a pixel of its square, in color 131 137 142" "$tmp/out"
check "course4-8.7 ... the last drawn there" grep -q "^color 131 137 142: dots p1 is the last point drawn there$" "$tmp/out"
report
