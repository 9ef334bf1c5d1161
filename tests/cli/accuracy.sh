#!/bin/sh
# tests/cli/accuracy.sh -- pipetrace accuracy: tables, known answers, the plot, exit codes
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/accuracy.sh PIPETRACE.  Run from the repository root.  Also
# runs test_accuracy (the unit test of src/tools/accuracy/) from PIPETRACE's
# directory and adds its counts.  Everything but two plots (one per camera)
# runs with --no-time.
exe=$1
. tests/lib/testlib.sh
dir=$(dirname "$exe")
ref=tests/reference
[ -d ../shared/reference ] && ref=../shared/reference

acc() {     # acc ARGS...: run "$exe accuracy ARGS" (see testlib.sh's run)
    run accuracy "$@"
}

field() {   # field ROW_PREFIX N: the Nth word of the first line starting with ROW_PREFIX
    grep "^$1" "$tmp/out" | head -1 | awk -v n="$2" '{ print $n }'
}

# ---- the unit test of src/tools/accuracy/
if [ -x "$dir/test_accuracy" ]; then
    "$dir/test_accuracy" "$ref" > "$tmp/unit" 2>&1
    grep '^FAIL' "$tmp/unit"
    last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$tmp/unit" | tail -1)
    if [ -n "$last" ]; then
        passed=$((passed + ${last%% passed*})); f=${last#*, }; failed=$((failed + ${f%% failed*}))
    else
        failed=$((failed + 1)); echo "FAIL test_accuracy crashed or printed no count"
    fi
else
    failed=$((failed + 1)); echo "FAIL $dir/test_accuracy is not built"
fi

# ---- every example scene: the whole table, the same bytes every run
for scene in docs/examples/*.scene; do
    grep -q '^camera lookat' "$scene" && continue    # the matrix camera: below
    name=${scene##*/}
    acc "$scene" --no-time
    cp "$tmp/out" "$tmp/first"
    check "acc-sh-1.1 $name: exit 0" test "$rc" = 0
    check "acc-sh-1.2 $name: every stage, float and double" \
        test "$(grep -cE '^(model|camera|image|pixel|viewport|framebuffer|index|raster) +(float|double) ' "$tmp/out")" = 16
    check "acc-sh-1.3 $name: the three arithmetics" \
        test "$(grep -cE '^(float +24|double +53|double-double +106) ' "$tmp/out")" = 3
    check "acc-sh-1.4 $name: the reference's precision" grep -q 'double-double, 106 significant bits' "$tmp/out"
    check "acc-sh-1.5 $name: no time columns with --no-time" test "$(grep -c 'ns/' "$tmp/out")" = 0
    check "acc-sh-1.6 $name: double's model and camera stages are exact" \
        test "$(field 'model        double' 3)$(field 'camera       double' 3)" = 00
    acc "$scene" --no-time
    check "acc-sh-1.7 $name: the same output on a second run" cmp -s "$tmp/out" "$tmp/first"
done
acc --no-time
check "acc-sh-1.8 the built-in scene by default" grep -q '^pipetrace accuracy: <builtin>$' "$tmp/out"

# ---- every example scene of the matrix camera: its own stages
for scene in docs/examples/*.scene; do
    grep -q '^camera lookat' "$scene" || continue
    name=${scene##*/}
    acc "$scene" --no-time
    cp "$tmp/out" "$tmp/first"
    check "acc-sh-5.1 $name: exit 0" test "$rc" = 0
    check "acc-sh-5.2 $name: every matrix stage, float and double" \
        test "$(grep -cE '^(model|world|view|clip|cvv|ndc|screen|viewport|framebuffer|index|raster) +(float|double) ' "$tmp/out")" = 22
    check "acc-sh-5.3 $name: no classic stage" \
        test "$(grep -cE '^(camera|image|pixel) +(float|double) ' "$tmp/out")" = 0
    check "acc-sh-5.4 $name: the three arithmetics" \
        test "$(grep -cE '^(float +24|double +53|double-double +106) ' "$tmp/out")" = 3
    check "acc-sh-5.5 $name: the matrix camera named in the header" grep -q 'matrix camera: look-at' "$tmp/out"
    check "acc-sh-5.6 $name: 2.001 or 2.0 said not to apply, no table" \
        test -n "$(grep 'does not apply to the matrix camera' "$tmp/out")" \
             -a -z "$(grep '^constant ' "$tmp/out")"
    check "acc-sh-5.7 $name: the DDA choice, float and double" \
        test "$(grep -cE '^(float|double) +(y \+= m|recompute) ' "$tmp/out")" = 4
    check "acc-sh-5.8 $name: double's model stage is exact" test "$(field 'model        double' 3)" = 0
    check "acc-sh-5.9 $name: float has an error somewhere" \
        test -n "$(grep -E '^[a-z]+ +float ' "$tmp/out" | awk '$3 != "0" && $3 != "-"')"
    check "acc-sh-5.10 $name: no time columns with --no-time" test "$(grep -c 'ns/' "$tmp/out")" = 0
    acc "$scene" --no-time
    check "acc-sh-5.11 $name: the same output on a second run" cmp -s "$tmp/out" "$tmp/first"
done
acc docs/examples/lookat-near.scene --no-time
check "acc-sh-5.12 lookat-near: the reference's clipping makes 2 points" \
    grep -q '^ *2 points and culled 0 segments$' "$tmp/out"
check "acc-sh-5.13 ... and every vertex keeps its outcode in float and double" \
    test "$(field 'cvv          float' 6)$(field 'cvv          double' 6)" = 0/30/3
check "acc-sh-5.14 ... ndc..index count the vertex inside and the 2 points" \
    test "$(field 'viewport     double' 6)" = 0/3
acc tests/data/near-tie.scene --no-time
check "acc-sh-5.15 near-tie: double puts the near-plane vertex outside" \
    test "$(field 'cvv          double' 6)" = 1/2
check "acc-sh-5.16 ... float and the reference keep it inside" test "$(field 'cvv          float' 6)" = 0/2
check "acc-sh-5.17 ... the point clipping makes lands on the same pixels" \
    test "$(field 'raster       double' 6 | cut -d/ -f1)" = 0

# ---- known answers
acc tests/extreme/cancel-translate.scene --no-time
check "acc-sh-2.1 cancel-translate: float's camera stage has an error" \
    test "$(field 'camera       float' 3)" != 0
check "acc-sh-2.2 ... double's has none (one exactly rounded addition)" \
    test "$(field 'camera       double' 3)" = 0
acc tests/extreme/corner-plus-one.scene --no-time
check "acc-sh-2.3 corner-plus-one: with 2.001 no vertex leaves the viewport" \
    test "$(field '2.001 ' 4)" = 0
check "acc-sh-2.4 ... with 2.0 the corner x_ip = 1 does" test "$(field '2.0 ' 4)" = 1
acc tests/data/drift.scene --no-time
check "acc-sh-2.5 drift: double's y += m is a pixel or more off the exact line" \
    awk -v e="$(field 'double      y += m' 5)" 'BEGIN { exit !(e + 0 >= 1) }'
check "acc-sh-2.6 ... and lights other pixels than the reference" \
    test "$(field 'double      y += m' 7 | cut -d/ -f1)" -gt 0
check "acc-sh-2.7 ... recomputing y = y0 + m*(x - x0) lights the reference's" \
    test "$(field 'double      recompute' 5 | cut -d/ -f1)" = 0

# ---- timing and the plot (the only timed runs: one repeat each)
stage_times() {  # stage_times N: the rows of the per-stage time table with N numbers > 0, finite
    sed -n '/^time per stage alone/,/^$/p' "$tmp/out" | tail -n +3 | grep -v '^$' |
        awk 'NF == 4 && $2 + 0 > 0 && $3 + 0 > 0 && $4 + 0 > 0 &&
             $2 !~ /inf|nan/ && $3 !~ /inf|nan/ && $4 !~ /inf|nan/' | wc -l | tr -d ' '
}
svg_check() {    # svg_check ID FILE: panels, axes and label boxes (tests/cli/accuracy_svg.py)
    if command -v python3 >/dev/null 2>&1; then
        python3 tests/cli/accuracy_svg.py "$2" > "$tmp/svgcheck" 2>&1
        check "$1 one panel per unit, axes named, no two texts overlap (accuracy_svg.py)" \
            test $? = 0
        grep '^FAIL' "$tmp/svgcheck" | head -5
    fi
}
acc docs/examples/cube.scene --repeat 1 --svg "$tmp/plot.svg"
check "acc-sh-3.1 --svg: exit 0" test "$rc" = 0
check "acc-sh-3.2 timed: ns/vertex and ns/pixel columns" grep -q 'ns/vertex  ns/pixel' "$tmp/out"
check "acc-sh-3.3 the plot is written" test -s "$tmp/plot.svg"
if command -v xmllint >/dev/null 2>&1; then
    check "acc-sh-3.4 the plot is well-formed XML (xmllint)" xmllint --noout "$tmp/plot.svg"
elif command -v python3 >/dev/null 2>&1; then
    check "acc-sh-3.4 the plot is well-formed XML (python3)" python3 -c '
import sys, xml.etree.ElementTree as ET
assert ET.parse(sys.argv[1]).getroot().tag == "{http://www.w3.org/2000/svg}svg"' "$tmp/plot.svg"
fi
check "acc-sh-3.5 the plot is self-contained (no links)" test "$(grep -c 'href' "$tmp/plot.svg")" = 0
check "acc-sh-3.6 ... a point per stage and arithmetic (8 x 3), 4 choices, 4 in the legend" \
    test "$(grep -c '<circle' "$tmp/plot.svg")" = 32
check "acc-sh-3.7 ... says where errors of 0 are drawn" grep -q 'dashed line marked 0' "$tmp/plot.svg"
check "acc-sh-3.11 every classic stage timed alone, in every arithmetic: > 0 and finite" \
    test "$(stage_times)" = 8
check "acc-sh-3.12 ... float's stages are not all at one time" \
    test "$(grep 'fill="#d95f02" stroke="#d95f02"' "$tmp/plot.svg" | sed 's/.*cx="\([0-9.]*\)".*/\1/' | sort -u | wc -l)" -gt 3
svg_check acc-sh-3.13 "$tmp/plot.svg"
acc --repeat 1 --svg "$tmp/bplot.svg"
svg_check acc-sh-3.14 "$tmp/bplot.svg"
acc docs/examples/lookat-near.scene --repeat 1 --svg "$tmp/mplot.svg"
check "acc-sh-3.8 matrix camera timed: exit 0, ns/vertex and ns/pixel columns" \
    test "$rc" = 0 -a -n "$(grep 'ns/vertex  ns/pixel' "$tmp/out")"
check "acc-sh-3.9 ... its plot has the matrix stages" grep -q '>ndc</text>' "$tmp/mplot.svg"
check "acc-sh-3.10 ... a point per stage but the cvv (10 x 3), 2 choices, 4 in the legend" \
    test "$(grep -c '<circle' "$tmp/mplot.svg")" = 36
check "acc-sh-3.15 every matrix stage timed alone, in every arithmetic: > 0 and finite" \
    test "$(stage_times)" = 11
svg_check acc-sh-3.16 "$tmp/mplot.svg"
acc docs/examples/lookat-cube.scene --repeat 1 --svg "$tmp/cplot.svg"
svg_check acc-sh-3.17 "$tmp/cplot.svg"

# ---- exit codes
printf 'framebuffer 10 10\nmodel m\nv 1 2\n' > "$tmp/bad.scene"
acc "$tmp/bad.scene" --no-time
check "acc-sh-4.1 bad scene: exit 2" test "$rc" = 2
check "acc-sh-4.2 ... with FILE:LINE:COL: error:" grep -q "^$tmp/bad.scene:3:[0-9]*: error: " "$tmp/err"
acc "$tmp/missing.scene"
check "acc-sh-4.3 missing scene: exit 2" test "$rc" = 2
acc --frobnicate
check "acc-sh-4.4 unknown option: exit 1" test "$rc" = 1
acc --repeat 0
check "acc-sh-4.5 --repeat 0: exit 1" test "$rc" = 1
acc --repeat
check "acc-sh-4.6 --repeat without a value: exit 1" test "$rc" = 1
acc --no-time --svg "$tmp/x.svg"
check "acc-sh-4.7 --svg with --no-time: exit 1" test "$rc" = 1 -a ! -e "$tmp/x.svg"
acc a.scene b.scene
check "acc-sh-4.8 two scenes: exit 1" test "$rc" = 1
acc --help
check "acc-sh-4.9 --help: exit 0, usage" test "$rc" = 0 -a -n "$(grep 'usage: pipetrace accuracy' "$tmp/out")"
acc docs/examples/triangle.scene --repeat 1 --svg "$tmp/nodir/plot.svg"
check "acc-sh-4.10 unwritable --svg path: exit 2" test "$rc" = 2

# a direction of 1e200 and an up of 1e-310: every arithmetic scales them by a
# power of two before normalising, so the reference is no NaN and double is close
printf 'framebuffer 20 10\ncamera lookat 0 0 0 1e200 0 1e200 0 1e-310 0\nprojection perspective 60 1 1 10\nmodel m\nv 0 0 5\nv 1 0 5\nl 1 2\n' > "$tmp/tiny.scene"
acc "$tmp/tiny.scene" --no-time
check "acc-sh-5.1 extreme look-at vectors: double's view within 1 ulp of the reference" \
    grep -qE '^view +double +[0-9.e+-]+ +[0-9.e+-]+ +1 ' "$tmp/out"

# ---- renderers 7 and 9: their own stages and both clips
acc tests/course79/r9-mat-14-camera-translate.scene --no-time
cp "$tmp/out" "$tmp/r9a"
check "acc-sh-6.1 renderer 9: exit 0, rows world, nearclip, image, clip, pixel" \
    test "$rc" = 0 -a "$(grep -cE '^(world|nearclip|image|clip|pixel) +(float|double) ' "$tmp/out")" = 10
check "acc-sh-6.2 ... double calls the stages: world exact (the matrix is double's)" \
    test "$(field 'world        double' 3)" = 0
acc tests/course79/r9-mat-14-camera-translate.scene --no-time
check "acc-sh-6.3 ... the same bytes on a second run" cmp -s "$tmp/out" "$tmp/r9a"
acc tests/course79/r7-near-01.scene --no-time
check "acc-sh-6.4 renderer 7: no world row, view and camera rows" \
    test "$rc" = 0 -a -z "$(grep '^world ' "$tmp/out")" -a -n "$(grep '^camera  *double ' "$tmp/out")"
check "acc-sh-6.5 ... the near clip cuts 2 of 4 segments, the reference's clips make 6 points" \
    test "$(field 'nearclip     double' 6)" = 2/4 -a -n "$(grep 'clips made 6 points' "$tmp/out")"
check "acc-sh-6.6 ... double's near clip within 16 ulps, float's far beyond" \
    test "$(field 'nearclip     double' 5)" -le 16 -a "$(field 'nearclip     double' 3)" != 0
# z = -0.09999999999 is beyond the near plane z = -0.1 in double; rounded to
# float it is (float)-0.1, on the plane: float keeps what the reference cuts
acc tests/data/rv-near-float.scene --no-time
check "acc-sh-6.7 float decides the near clip otherwise: counted (1/1), error inf" \
    test "$(grep -A3 '^clips decided' "$tmp/out" | awk '$1 == "nearclip" { print $2 "," $3 }')" = "1/1,0/1" \
         -a "$(field 'nearclip     float' 3)" = inf
check "acc-sh-6.8 ... and its image row counts the near point on one side only as inf" \
    test "$(field 'image        float' 3)" = inf
acc tests/course79/r7-clip-08-corner-ur.scene --no-time
check "acc-sh-6.9 the clip to -1..1: cuts counted per segment, double within 16 ulps" \
    test "$rc" = 0 -a "$(field 'clip         double' 5)" -le 16 -a "$(field 'clip         double' 6)" != ""
acc tests/course79/r9-clip-12-through-x.scene --repeat 1 --svg "$tmp/r9plot.svg"
check "acc-sh-6.10 renderer 9 --svg: exit 0, every stage timed" test "$rc" = 0 -a "$(stage_times)" = 12
check "acc-sh-6.11 ... its plot has the clips" grep -q '>nearclip</text>' "$tmp/r9plot.svg"
svg_check acc-sh-6.12 "$tmp/r9plot.svg"
# huge, tiny and zero coordinates through renderer 9's matrix, no near clip
printf 'renderer 9\nframebuffer 30 20\nnearclip off\nmodel a\nmatrix rotate 33 0.3 0.4 0.5\nmatrix scale 1e300\nv 0 0 -1\nv 1e308 -1e308 0\nv 0 0 0\nv 1 1 1\nv 1e-320 2e-320 -1e-310\nsegment 1 2\nsegment 2 3\nsegment 3 4\nsegment 1 4\nsegment 4 5\nsegment 1 5\n' > "$tmp/rvh.scene"
acc "$tmp/rvh.scene" --no-time
check "acc-sh-6.13 renderer 9, overflow and subnormals: exit 0, every row, nothing on stderr" \
    test "$rc" = 0 -a "$(grep -cE '^[a-z]+ +(float|double) +[-0-9i]' "$tmp/out")" = 24 -a ! -s "$tmp/err"

# ---- the pixel cap counts the image's pixels, each once (overdraw costs
# nothing): 21 segments over one row, 3999 or 4000 pixels a run, 84,000
# writes; PIPETRACE_ACC_MAXPIX lowers the cap of 8000000 to reach it cheaply
awk 'BEGIN { print "framebuffer 4000 4"; print "model m"; print "v -2 0 -2"; print "v 2 0 -2";
             for (i = 0; i < 21; i++) print "l 1 2" }' > "$tmp/big.scene"
PIPETRACE_ACC_MAXPIX=3999 acc "$tmp/big.scene" --no-time
check "acc-sh-7.1 a run lighting 4000 pixels over a cap of 3999: exit 2, the cap named, nothing on stdout" \
    test "$rc" = 2 -a -n "$(grep 'lights more than 3999 pixels' "$tmp/err")" -a ! -s "$tmp/out"
PIPETRACE_ACC_MAXPIX=4000 acc "$tmp/big.scene" --no-time
check "acc-sh-7.2 ... and under a cap of 4000 (its 84,000 writes not counted): done" \
    test "$rc" = 0 -a -n "$(grep '3999 pixels in the reference image' "$tmp/out")"
PIPETRACE_ACC_MAXPIX=0 acc "$tmp/big.scene" --no-time
check "acc-sh-7.3 PIPETRACE_ACC_MAXPIX=0: a usage error" \
    test "$rc" = 1 -a -n "$(grep 'PIPETRACE_ACC_MAXPIX takes 1 to 8000000, not 0' "$tmp/err")"

# ---- a block at a time (PT_ACC_BLOCK vertices or segments): the same bytes
# as when every journey was kept, on scenes of several blocks per model, each
# pipeline (tests/data/accblock/*.out: that output, stored)
for d in classic matrix r7 r9; do
    acc tests/data/accblock/$d.scene --no-time
    check "acc-sh-8.1 accblock/$d.scene (4 blocks of vertices, 7 of segments): the output of the whole-scene runs, byte for byte" \
        sh -c 'test "$1" = 0 && cmp -s "$2" "$3"' _ "$rc" "$tmp/out" tests/data/accblock/$d.out
done
acc tests/data/accblock/classic.scene --repeat 1
check "acc-sh-8.2 ... timed: every stage and the rasterizer a time, summed over the blocks" \
    test "$rc" = 0 -a "$(awk '/^stage +float +double/ { t = 1; next } t && NF == 4 && $2 + 0 > 0 && $3 + 0 > 0 && $4 + 0 > 0 { n++ } t && NF == 0 { t = 0 } END { print n + 0 }' "$tmp/out")" = 8
# the image is kept across the blocks of segments: 4096 segments lighting
# half a row, then one lighting the other half, 3999 pixels in all
awk 'BEGIN { print "framebuffer 4000 4"; print "model m"; print "v -2 0 -2"; print "v 0 0 -2";
             print "v 2 0 -2"; for (i = 0; i < 4096; i++) print "l 1 2"; print "l 2 3" }' > "$tmp/half.scene"
PIPETRACE_ACC_MAXPIX=3998 acc "$tmp/half.scene" --no-time
check "acc-sh-8.3 two blocks of segments lighting 3999 pixels together over a cap of 3998: exit 2" \
    test "$rc" = 2 -a -n "$(grep 'lights more than 3998 pixels' "$tmp/err")"
PIPETRACE_ACC_MAXPIX=4000 acc "$tmp/half.scene" --no-time
check "acc-sh-8.4 ... under a cap of 4000: the 3999 pixels of both blocks in one image" \
    test "$rc" = 0 -a -n "$(grep '4097 segments, 3999 pixels in the reference image' "$tmp/out")"

# segments whose ends are far apart in their model, neighbours or the same
# vertex: a block of segments holds each end once, however they fall
# (tests/data/accblock/scatter-*.out: the output from before accuracy ran in
# blocks, without its first line, which names the scene)
scatter() {     # scatter HEAD: 3000 vertices, 9000 segments: neighbours, far pairs, degenerate
    awk -v head="$1" 'BEGIN {
        s = 20261129; n = 3000
        printf "%s\nmodel a\n", head
        for (i = 0; i < 3 * n; i++) { s = (s * 16807) % 2147483647; r[i] = s / 2147483647 }
        for (i = 0; i < n; i++)
            printf "v %.6f %.6f %.6f\n", 4 * r[3 * i] - 2, 3 * r[3 * i + 1] - 1.5, 3 * r[3 * i + 2] - 1.5
        for (q = 0; q < 3 * n; q++) {
            s = (s * 16807) % 2147483647; a = 1 + s % n
            s = (s * 16807) % 2147483647
            if (q % 97 == 0) b = a
            else if (s % 10 < 7) b = 1 + (a + s % 5) % n
            else b = 1 + s % n
            printf "l %d %d\n", a, b
        }
        print "translate 0 0 -3.5"
    }'
}
fb='framebuffer 320 240'
for d in classic matrix r7 r9; do
    case $d in
    classic) scatter "$fb" ;;
    matrix) scatter "$fb
camera lookat-target 0 0 0  0 0 -3.5  0 1 0
projection perspective 60 auto 0.5 50" ;;
    *) scatter "renderer ${d#r}
$fb
camera perspective" ;;
    esac > "$tmp/scatter.scene"
    acc "$tmp/scatter.scene" --no-time
    tail -n +2 "$tmp/out" > "$tmp/out2"
    check "acc-sh-8.5 $d: 9000 segments, far apart, neighbours and degenerate, in three blocks: the output of the whole-scene runs, byte for byte" \
        sh -c 'test "$1" = 0 && cmp -s "$2" "$3"' _ "$rc" "$tmp/out2" tests/data/accblock/scatter-$d.out
done

report
