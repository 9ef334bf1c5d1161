#!/bin/sh
# tests/bench/baseline.sh -- the benchmark's plain-C baseline draws what pipetrace draws
# See LICENSE for copyright and license.
#
# Usage: sh tests/bench/baseline.sh BUILD_DIR.  `make bench` compares pipetrace's
# speed with tests/bench/baseline.c, a second copy of the classic formulas and the
# DDA; this ties the copy to the original: on scenes of tests/bench/benchgen.c both
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
report
