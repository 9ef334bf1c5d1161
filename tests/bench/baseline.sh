#!/bin/sh
# tests/bench/baseline.sh -- the benchmark's plain-C baselines draw what pipetrace draws
# See LICENSE for copyright and license.
#
# Usage: sh tests/bench/baseline.sh BUILD_DIR.  `make bench` compares pipetrace's
# speed with tests/bench/baseline.c, a second copy of the classic formulas and the
# DDA, and (for a scene that says `renderer 7` or `9`) of the course's renderers
# 7 and 9; this ties the copies to the originals: on scenes of tests/bench/benchgen.c both
# must write the same image, byte for byte (floor(x + 0.5) and Java's round
# differ only on inputs these scenes do not have).
B=${1:-build}
exe=$B/pipetrace
. tests/lib/testlib.sh

"$B/benchgen" 3000 > "$tmp/a.scene"
"$B/benchgen" 500 7 > "$tmp/b.scene"
check "baseline-1.1 the generator writes the same scene twice" \
    sh -c "'$B/benchgen' 3000 | cmp -s - '$tmp/a.scene'"
for s in a b; do
    "$B/baseline" "$tmp/$s.scene" "$tmp/$s-base.ppm" > "$tmp/$s-base.out"
    run "$tmp/$s.scene" --image "$tmp/$s.ppm"
    check "baseline-1.2 $s.scene: pipetrace draws it" test "$rc" = 0
    check "baseline-1.3 $s.scene: the baseline draws the same image" \
        cmp -s "$tmp/$s.ppm" "$tmp/$s-base.ppm"
done
check "baseline-1.4 it counts pixels" grep -q "pixels [1-9]" "$tmp/a-base.out"

# renderers 7 and 9 (anti-aliasing off and on); "near": renderer 9's octagons
# turned 80 degrees about x and moved to z = -0.3, where some cross the near
# plane and many leave the view rectangle
"$B/benchgen" 2000 300 7 > "$tmp/r7.scene"
"$B/benchgen" 2000 300 7 aa > "$tmp/r7aa.scene"
"$B/benchgen" 2000 300 9 > "$tmp/r9.scene"
"$B/benchgen" 2000 300 9 aa > "$tmp/r9aa.scene"
sed 's/^matrix translate 0 0 -4$/matrix translate 0 0 -0.3\nmatrix rotate x 80/' "$tmp/r9aa.scene" > "$tmp/r9near.scene"
check "baseline-2.1 the renderer 9 scene says so, with anti-aliasing" \
    grep -q "^antialias on" "$tmp/r9aa.scene"
check "baseline-2.2 the near scenes differ from theirs" \
    sh -c "! cmp -s '$tmp/r9aa.scene' '$tmp/r9near.scene'"
for s in r7 r7aa r9 r9aa r9near; do
    "$B/baseline" "$tmp/$s.scene" "$tmp/$s-base.ppm" > "$tmp/$s-base.out"
    run "$tmp/$s.scene" --image "$tmp/$s.ppm"
    check "baseline-2.3 $s.scene: pipetrace draws it" test "$rc" = 0
    check "baseline-2.4 $s.scene: the baseline draws the same image" \
        cmp -s "$tmp/$s.ppm" "$tmp/$s-base.ppm"
    check "baseline-2.5 $s.scene: the baseline counts pixels" grep -q "pixels [1-9]" "$tmp/$s-base.out"
done
check "baseline-2.6 anti-aliasing changes the image" \
    sh -c "! cmp -s '$tmp/r9.ppm' '$tmp/r9aa.ppm'"

# the JSON Lines records of renderers 7 and 9 are spelt in place, their names
# made once a position, and a CSV trace (no pixel rows) draws with nobody
# listening (src/io/trace_course_rec.c): the traces they wrote before
check "baseline-3.1 a renderer 9 trace of two models, one named beyond ASCII: the stored one" \
    sh -c "'$exe' tests/bench/r9-names.scene --format jsonl --trace - | cmp -s - tests/bench/r9-names.jsonl"
check "baseline-3.2 its CSV trace and image: the stored trace, the untraced image" \
    sh -c "'$exe' tests/bench/r9-names.scene --format csv --trace - --image '$tmp/n.ppm' | cmp -s - tests/bench/r9-names.csv && '$exe' tests/bench/r9-names.scene --image '$tmp/m.ppm' && cmp -s '$tmp/n.ppm' '$tmp/m.ppm'"
report
