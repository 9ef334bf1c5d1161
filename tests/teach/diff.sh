#!/bin/sh
# tests/teach/diff.sh -- pipetrace diff: every known mistake, built as a student stage, is named
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/diff.sh PIPETRACE.  Run from the repository root.  Builds
# pipetrace once more in a temporary directory with each mistaken stage that
# tests/teach/student.sh makes from stages/ in place of its stage (make STAGE_x=FILE,
# the Makefile's student block),
# renders a scene of tests/data/diff/ that exposes the mistake, and checks that
# `PIPETRACE diff REFERENCE STUDENT` exits 1 and names that mistake and no
# other.  Then: a stage that reports nothing, the documented `make STAGE_x=F`
# itself, agreeing traces, text against JSON Lines, bad input, images.
exe=$1
. tests/lib/testlib.sh
data=tests/data/diff


. tests/lib/studentlib.sh

# mistake ID SCENE FORMAT NAME: diff the reference's trace of SCENE (in FORMAT)
# against the student build's (JSON Lines); the output must name NAME only.
mistake() {
    id=$1 scene=$2 fmt=$3 name=$4
    "$exe" "$scene" --format "$fmt" --trace "$tmp/want.$fmt"
    "$tmp/sb/pipetrace" "$scene" --format jsonl --trace "$tmp/got.jsonl"
    "$exe" diff "$tmp/want.$fmt" "$tmp/got.jsonl" >"$tmp/out" 2>&1; rc=$?
    check "$id exit 1" test "$rc" = 1
    check "$id names '$name'" grep -qF "likely mistake: $name" "$tmp/out"
    check "$id ... and no other mistake" \
        test "$(grep 'likely mistake' "$tmp/out" | grep -cvF "$name")" = 0
    awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
    check "$id ... in the summary too" grep -qF "Likely mistake${5- there}: $name" "$tmp/summary"
    [ "$failed" -gt "$failed_before" ] && sed 's/^/  /' "$tmp/out" | head -30
    failed_before=$failed
}
failed_before=0

# ---- one student stage per known mistake
if ! mistaken s1_subtract; then
    failed=$((failed + 1)); echo "FAIL diff-0 student build"; sed 's/^/  /' "$tmp/make.log" | head -20
    echo "$passed passed, $failed failed"; exit 1
fi
check "diff-0.1 the student build goes to its own directory" test -x "$tmp/sb/pipetrace"
mistake diff-1.1 $data/offset.scene jsonl "translation subtracted"
mistaken s2_divz
mistake diff-1.2 $data/offset.scene jsonl "projection divides by z_c instead of -z_c"
mistaken s3_two
mistake diff-1.3 $data/offset.scene jsonl "2 instead of 2.001"
mistaken s3_swapwh
mistake diff-1.4 $data/offset.scene jsonl "w and h swapped"
mistaken s4_cround
mistake diff-1.5 $data/ties.scene jsonl "C round() instead of Java's Math.round"
# a text EXPECTED prints -2.500000: still a tie, so floor(x + 0.5) is not named
mistake diff-1.6 $data/ties.scene text "C round() instead of Java's Math.round"
mistaken s4_floor
# (on a segment that starts left of the viewport: its first clipped step,
# x_pp = -3, tells floor(x + 0.5) from truncation, which lights the same
# pixels; tests/data/diff/floor.scene cannot, diff-15.6)
mistake diff-1.7 tests/data/students/left.scene jsonl "floor(x + 0.5) instead of Java's Math.round" ""
# ... and in a viewport off the framebuffer's corner, h != H: diff takes
# EXPECTED's pixels back to logical pixels to replay the DDA (dpixels.c,
# vp_to_pp: the viewport and framebuffer stages backwards), and names the
# mistake only when the replay gives EXPECTED's own pixels
sed 's/^framebuffer 12 4$/framebuffer 19 9\nviewport 4 3 12 4/' tests/data/students/left.scene > "$tmp/floor-vp.scene"
check "diff-1.7a (the scene has its viewport at 4,3)" grep -q '^viewport 4 3 12 4$' "$tmp/floor-vp.scene"
mistake diff-1.7b "$tmp/floor-vp.scene" jsonl "floor(x + 0.5) instead of Java's Math.round" ""
mistaken s4_noflip
mistake diff-1.8 $data/offset.scene jsonl "missing y flip"
mistaken s4_nominus1
mistake diff-1.9 $data/offset.scene jsonl "missing -1 in x_vp"
mistake diff-1.10 $data/offset.scene text "missing -1 in x_vp"
mistaken s6_xh
mistake diff-1.11 $data/offset.scene jsonl "index x * H + y"
# the viewport at 0,0: no framebuffer records, the viewport's stand in
mistake diff-1.12 $data/ties.scene jsonl "index x * H + y"
mistaken s6_vpw
mistake diff-1.13 $data/offset.scene jsonl "viewport width instead of framebuffer width"
# ... whose index lies past the pixel array for the bottom rows of a 10 x 10
# framebuffer: the trace shows it, the image is left alone, nothing fails
printf 'framebuffer 10 10\nmodel m\ntranslate 0 0 -2\nv -1.5 -1.5 0\nv 1.5 -1.5 0\nl 1 2\n' > "$tmp/low.scene"
"$tmp/sb/pipetrace" "$tmp/low.scene" --image "$tmp/low.ppm" --format jsonl --trace "$tmp/low.jsonl"
check "diff-1.13a an index past the pixel array: exit 0" test $? = 0
check "diff-1.13b ... the trace has the pixels, index 193 among them" grep -q '"y":8,"i":193}' "$tmp/low.jsonl"
printf 'framebuffer 10 10\n' > "$tmp/empty.scene"
"$exe" "$tmp/empty.scene" --image "$tmp/empty.ppm"
check "diff-1.13c ... and the image has none of them" cmp "$tmp/low.ppm" "$tmp/empty.ppm"

# the image is drawn through the stages: a viewport stage one row off moves the
# picture too, and diff says so (2026-11: the rasterizer rounded and flipped by
# itself, so this stage changed the trace and left the image as it was)
rm -f "$tmp/sb/pipetrace"
mistaken s4_yminus1
check "diff-1.20a the s4_yminus1 student build" test -x "$tmp/sb/pipetrace"
"$exe" docs/examples/cube.scene --image "$tmp/want.ppm" --format jsonl --trace "$tmp/want.jsonl"
"$tmp/sb/pipetrace" docs/examples/cube.scene --image "$tmp/got.ppm" --format jsonl --trace "$tmp/got.jsonl"
# the reference image moved up one row (P6: a 3-line header, then rows of
# 3 * width bytes; the bottom row becomes the background, 0 0 0)
hl=$(head -n 3 "$tmp/want.ppm" | wc -c)
row=$((3 * $(sed -n 2p "$tmp/want.ppm" | cut -d' ' -f1)))
{ head -c "$hl" "$tmp/want.ppm"; tail -c +$((hl + row + 1)) "$tmp/want.ppm"
  head -c "$row" /dev/zero; } > "$tmp/up.ppm"
check "diff-1.21 a viewport stage one row off moves the whole image up one row" \
    cmp "$tmp/got.ppm" "$tmp/up.ppm"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
check "diff-1.22 ... and diff does not say both light the same pixels" \
    sh -c "! grep -q 'Both light the same pixels' '$tmp/out'"
tr '\n' ' ' < "$tmp/out" > "$tmp/flat"
check "diff-1.23 ... its pixels differ: all moved up one row" \
    grep -qF "Lit pixels: 156 in EXPECTED, 156 in ACTUAL: ACTUAL's are EXPECTED's moved by (0, -1)." "$tmp/flat"
check "diff-1.24 ... not listed as missing and extra ones" test "$(grep -c 'missing in ACTUAL' "$tmp/out")" = 0

# ---- the examples of issue 11, on the built-in scene: before, diff named
# "missing -1 in x_vp" for (int64_t)(x + 0.5) (which moves 1 vertex of 15),
# "missing y flip" for y_vp = h - 1 - round(y_pp), and nothing for a forgotten
# viewport offset or float arithmetic; a mistake is named now only when it
# reproduces every differing vertex and leaves every agreeing one as it is
"$exe" --format jsonl --trace "$tmp/bi.jsonl"
"$exe" --image "$tmp/bi-want.ppm"
# bi_diff NAME [swap]: the built-in scene through student build NAME, diffed
# against the reference (swap: the student's trace given first)
bi_diff() {
    mistaken "$1"
    "$tmp/sb/pipetrace" --format jsonl --trace "$tmp/got.jsonl" --image "$tmp/bi-got.ppm"
    if [ "${2-}" = swap ]; then "$exe" diff "$tmp/got.jsonl" "$tmp/bi.jsonl" >"$tmp/out" 2>&1
    else "$exe" diff "$tmp/bi.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1; fi
    summary
}
summary() {
    awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
    tr '\n' ' ' < "$tmp/out" | tr -s ' ' > "$tmp/flat"
}
bi_diff s4_trunc
check "diff-11.1 (int64_t)(x + 0.5): truncation named, with its fit" grep -qF "Likely mistake there: truncation toward zero instead of Java's Math.round, which reproduces the 1 differing vertex and leaves the 14 agreeing ones as they are." "$tmp/summary"
check "diff-11.2 ... 'missing -1' only as a partial candidate, which it says does not explain the trace" \
    grep -qF "partial: missing -1 in x_vp (viewport stage), which reproduces 1 of the 1 differing vertices and would change 14 of the 14 agreeing ones: it does NOT explain the trace." "$tmp/flat"
check "diff-11.3 ... and never as the likely one" test "$(grep -c 'ikely mistake.*missing -1' "$tmp/out")" = 0
bi_diff s4_yminus1
check "diff-11.4 y_vp = h - 1 - round(y_pp): a constant -1 in y_vp, from the numbers" \
    grep -qF "Likely mistake there: an extra -1 in y_vp, which reproduces all 15 differing vertices." "$tmp/summary"
check "diff-11.5 ... not 'missing y flip'" test "$(grep -c 'ikely mistake.*y flip' "$tmp/out")" = 0
# diff's arguments the wrong way round: the student's trace as EXPECTED
"$exe" diff "$tmp/got.jsonl" "$tmp/bi.jsonl" >"$tmp/out" 2>&1; summary
check "diff-11.6 the arguments swapped: said" \
    grep -qF "With EXPECTED and ACTUAL swapped, an extra -1 in y_vp explains every vertex: are the arguments in the wrong order?" "$tmp/summary"
check "diff-11.6a ... no likely mistake" test "$(grep -c 'ikely mistake' "$tmp/out")" = 0
bi_diff s4_nominus1 swap
check "diff-11.7 a catalogue mistake with the arguments swapped: said" \
    grep -qF "With EXPECTED and ACTUAL swapped, missing -1 in x_vp explains every vertex: are the arguments in the wrong order? (pipetrace diff REFERENCE STUDENT)" "$tmp/summary"
check "diff-11.7a ... no likely mistake the wrong way round" test "$(grep -c 'ikely mistake' "$tmp/out")" = 0
bi_diff s5_nooffset
check "diff-11.8 a forgotten viewport offset: named" \
    grep -qF "Likely mistake there: viewport offset (x_ul, y_ul) forgotten, which reproduces all 15 differing vertices." "$tmp/summary"
check "diff-11.9 ... the pixels: a shift by (-40, -30)" \
    grep -qF "Lit pixels: 1243 in EXPECTED, 1243 in ACTUAL: ACTUAL's are EXPECTED's moved by (-40, -30)." "$tmp/flat"
check "diff-11.10 ... not 1217 missing and 1217 extra" test "$(grep -c 'missing in ACTUAL' "$tmp/out")" = 0
check "diff-11.11 ... in the summary too, the consequence checked" grep -qF "The lit pixels differ too: all of them moved by (-40, -30), as a consequence: from ACTUAL's own end pixels the reference rasterizer draws ACTUAL's pixels in every segment that differs." "$tmp/summary"
"$exe" diff "$tmp/bi-want.ppm" "$tmp/bi-got.ppm" --image-out "$tmp/hl.png" >"$tmp/out" 2>&1
check "diff-11.12 the two images: a shift by (-40, -30)" \
    grep -qxF "ACTUAL is EXPECTED moved by (-40, -30): the same picture, shifted." "$tmp/out"
check "diff-11.13 --image-out FILE.png writes a PNG" test "$(head -c 4 "$tmp/hl.png" | od -An -c | tr -d ' ')" = "211PNG"
"$exe" diff "$tmp/bi-want.ppm" "$tmp/bi-got.ppm" --image-out "$tmp/hl.ppm" >/dev/null 2>&1
"$exe" diff "$tmp/hl.png" "$tmp/hl.ppm" >"$tmp/out" 2>&1
check "diff-11.14 ... the same picture as the PPM one" test $? = 0
"$exe" diff "$tmp/bi-want.ppm" "$tmp/bi.jsonl" >/dev/null 2>&1
bi_diff s3_float
check "diff-11.15 the pixel stage in float: named from the numbers" \
    grep -qF "Likely mistake there: float arithmetic in the pixel stage, which reproduces all" "$tmp/summary"
"$exe" --trace "$tmp/bi.txt"
"$exe" diff "$tmp/bi.txt" "$tmp/got.jsonl" >"$tmp/out" 2>&1; summary
check "diff-11.16 ... from a text EXPECTED too" \
    grep -qF "Likely mistake there: float arithmetic in the pixel stage, which reproduces all" "$tmp/summary"

# floor(x + 0.5) in a vertex record needs y_pp = 0.49999999999999994, which s3
# cannot produce (0.5 + w/2.001 * (y_ip + 1) is 0.5 or at least 2^-53 away):
# a hand-made pair of traces
"$exe" diff $data/floor-vertex-expected.jsonl $data/floor-vertex-actual.jsonl >"$tmp/out" 2>&1
check "diff-1.14 floor(x + 0.5) in a vertex record: exit 1" test $? = 1
# (int64_t)(y + 0.5) gives 1 there too: one vertex cannot tell them apart, and
# diff says so instead of naming one
awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
check "diff-1.15 ... floor(x + 0.5) and truncation both fit, and diff says it cannot tell" \
    grep -qF "cannot tell them apart: floor(x + 0.5) instead of Java's Math.round; truncation toward zero" "$tmp/summary"
check "diff-1.16 ... and names no single likely mistake" test "$(grep -c 'ikely mistake' "$tmp/out")" = 0

# the worked example of docs/teaching.md shows these two prepared traces
"$exe" $data/ties.scene --format jsonl --trace "$tmp/ties.jsonl"
mistaken s4_cround
"$tmp/sb/pipetrace" $data/ties.scene --format jsonl --trace "$tmp/ties-cround.jsonl"
check "diff-1.17 $data/ties.jsonl is today's reference trace (else: make, then $exe $data/ties.scene --format jsonl --trace $data/ties.jsonl)" \
    cmp "$tmp/ties.jsonl" $data/ties.jsonl
check "diff-1.18 $data/ties-cround.jsonl is today's student trace (else: make it again as docs/teaching.md says)" \
    cmp "$tmp/ties-cround.jsonl" $data/ties-cround.jsonl

# the stored traces of exercises 3 and 4 (docs/exercises/README.md says how
# they are made)
mistaken s3_two
"$tmp/sb/pipetrace" docs/exercises/03-pixel.scene --format jsonl --trace "$tmp/ex3.jsonl"
check "diff-1.19 docs/exercises/03-pixel-two.jsonl is today's student trace (else: make it again as docs/exercises/README.md says)" \
    cmp "$tmp/ex3.jsonl" docs/exercises/03-pixel-two.jsonl

# pipetrace step on a student build: says so, and shows where the student's
# stage leaves the formula (the reference stages', stages/pt_ref.h)
"$tmp/sb/pipetrace" step docs/examples/triangle.scene --vertex 1 >"$tmp/step.out" 2>&1
check "diff-10.1 step on a student build says so" \
    grep -qxF "student build: the pixel stage is yours (make STAGE_pixel=...)" "$tmp/step.out"
check "diff-10.2 ... and where the pixel stage differs from the formula" \
    sh -c "grep -A1 '^  here     x_pp = ' '$tmp/step.out' | tr '\n' '|' | grep -qxF '  here     x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313|           your stage gave x_pp = 5.5|'"
check "diff-10.3 ... in the pixel stage only" test "$(grep -c 'your stage gave' "$tmp/step.out")" = 2
check "diff-10.4 --version says so too" sh -c "'$tmp/sb/pipetrace' --version | grep -q 'student build: the pixel stage'"
"$exe" step docs/examples/triangle.scene --vertex 1 >"$tmp/step.out" 2>&1
check "diff-10.5 the reference build: no check line" test "$(grep -c 'your stage gave' "$tmp/step.out")" = 0
check "diff-10.6 ... and no student note" test "$(grep -c 'student build' "$tmp/step.out")" = 0
mistaken s4_cround
"$tmp/sb/pipetrace" docs/exercises/04-rounding.scene --format jsonl --trace "$tmp/ex4.jsonl"
check "diff-1.20 docs/exercises/04-rounding-cround.jsonl is today's student trace (else: make it again as docs/exercises/README.md says)" \
    cmp "$tmp/ex4.jsonl" docs/exercises/04-rounding-cround.jsonl

# ---- a student stage that reports nothing: said plainly, the next stage not blamed
"$exe" $data/offset.scene --format jsonl --trace "$tmp/want.jsonl"
mistaken s2_silent
"$tmp/sb/pipetrace" $data/offset.scene --format jsonl --trace "$tmp/got.jsonl"
"$tmp/sb/pipetrace" $data/offset.scene --trace "$tmp/got.txt"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
check "diff-8.1 a stage that does not report: exit 1" test $? = 1
check "diff-8.2 ... said plainly" grep -q "^ACTUAL has no image records: the stage did not report them" "$tmp/out"
check "diff-8.3 ... with the call it must make" grep -qF "pt_emit(sink, &r)" "$tmp/out"
check "diff-8.4 ... not as a stage left out on purpose" test "$(grep -c 'Not compared' "$tmp/out")" = 0
"$tmp/sb/pipetrace" step docs/examples/triangle.scene --vertex 1 --all >"$tmp/step.out" 2>&1
check "diff-8.4a step on it: all 7 stages, the index too" \
    test "$(grep -c '^stage [0-9] of 7:' "$tmp/step.out")" = 7
check "diff-8.4b ... the silent stage said plainly, no made-up numbers" \
    grep -q "^  here     none: the image stage did not report its record" "$tmp/step.out"
check "diff-8.4c ... and the pixel stage not blamed for it" \
    test "$(grep -c 'your stage gave' "$tmp/step.out")" = 0
"$tmp/sb/pipetrace" docs/examples/triangle.scene --vertex 1 --explain --all-stages >"$tmp/expl.out" 2>&1
check "diff-8.4d --explain: the index explained from the framebuffer's numbers" \
    grep -q "idx = y_fb \* W + x_fb = 7 \* 20 + 4 = 144" "$tmp/expl.out"
"$exe" diff "$tmp/got.txt" "$tmp/want.jsonl" >"$tmp/out" 2>&1
check "diff-8.5 ... on either side, in text too" grep -q "^EXPECTED has no image records: the stage did not report them" "$tmp/out"
sed 's|pt_emit(sink, &r);|(void)sink; (void)r;        /* no pt_emit: silent */|' \
    "$tmp/s2_divz.c" > "$tmp/s2_divz_silent.c"
student projection "$tmp/s2_divz_silent.c"
"$tmp/sb/pipetrace" $data/offset.scene --format jsonl --trace "$tmp/got.jsonl"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
check "diff-8.6 silent and wrong: the pixel records differ first ..." grep -q "^box v1: differs first at pixel" "$tmp/out"
check "diff-8.7 ... but the silent stage is named as the likely place" \
    grep -q "^    but ACTUAL has no image record: that stage did not report, and the difference may start there" "$tmp/out"
awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
check "diff-8.8 ... in the summary too" grep -qF "the mistake may be there, not in the pixel stage" "$tmp/summary"
"$exe" $data/offset.scene --stage pixel --stage viewport --format jsonl --trace "$tmp/some.jsonl"
"$exe" diff "$tmp/want.jsonl" "$tmp/some.jsonl" >"$tmp/out" 2>&1
check "diff-8.9 stages left out by --stage are not a silent stage: exit 0" test $? = 0
check "diff-8.10 ... but not compared" grep -q "^Not compared: model records are only in EXPECTED" "$tmp/out"

# ---- the documented student build, exactly: `make STAGE_projection=FILE`, no
# target, in a copy of the repository.  It must build build-student/pipetrace
# with FILE, and another choice must rebuild it.  (2024 audit: the first stage
# rule was the default goal, so only build-student/s1_model2camera.o was built.)
repo="$tmp/repo"
mkdir -p "$repo/docs/examples" "$repo/tests" "$repo/build-student"
cp -Rp Makefile src stages "$repo/"
cp -p docs/examples/builtin.scene "$repo/docs/examples/"
sh tests/teach/student.sh s2_divz "$repo/s2_divz.c"
sh tests/teach/student.sh s3_two "$repo/s3_two.c"
[ -n "$reuse" ] && cp -p "$bdir"/*.o "$bdir/builtin.c" "$repo/build-student/"
( cd "$repo" && MAKEFLAGS= MFLAGS= MAKELEVEL= make STAGE_projection=s2_divz.c ) \
    >"$tmp/make.log" 2>&1
check "diff-9.1 make STAGE_projection=FILE, no target: builds build-student/pipetrace" \
    test -x "$repo/build-student/pipetrace"
"$repo/build-student/pipetrace" $data/offset.scene --format jsonl --trace "$tmp/got.jsonl"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
check "diff-9.2 ... with FILE in it" grep -qF "likely mistake: projection divides by z_c" "$tmp/out"
( cd "$repo" && MAKEFLAGS= MFLAGS= MAKELEVEL= make STAGE_pixel=s3_two.c ) \
    >"$tmp/make.log" 2>&1
"$repo/build-student/pipetrace" $data/offset.scene --format jsonl --trace "$tmp/got.jsonl"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
check "diff-9.3 another choice rebuilds it: the new stage's mistake ..." grep -qF "likely mistake: 2 instead of 2.001" "$tmp/out"
check "diff-9.4 ... and the replaced stage is the reference again" test "$(grep -c 'likely mistake: projection' "$tmp/out")" = 0
( cd "$repo" && MAKEFLAGS= MFLAGS= MAKELEVEL= make clean ) >"$tmp/make.log" 2>&1
check "diff-9.5 make clean removes build-student/" test ! -e "$repo/build-student"

# ---- agreeing traces: exit 0
for s in offset ties floor; do
    "$exe" $data/$s.scene --format jsonl --trace "$tmp/$s.jsonl"
    "$exe" $data/$s.scene --trace "$tmp/$s.txt"
    "$exe" $data/$s.scene --all-stages --precision 3 --trace "$tmp/$s-all.txt"
done
"$exe" docs/examples/cube.scene --format jsonl --trace "$tmp/cube.jsonl"
"$exe" docs/examples/cube.scene --trace "$tmp/cube.txt"
"$exe" diff "$tmp/offset.jsonl" "$tmp/offset.jsonl" >"$tmp/out" 2>&1
check "diff-2.1 a trace against itself: exit 0" test $? = 0
check "diff-2.2 ... says they agree" grep -q "^The traces agree: 4 of 4 vertices" "$tmp/out"
for s in offset ties floor cube; do
    "$exe" diff "$tmp/$s.txt" "$tmp/$s.jsonl" >/dev/null 2>&1
    check "diff-2.3 $s: text against JSON Lines: exit 0" test $? = 0
    "$exe" diff "$tmp/$s.jsonl" "$tmp/$s.txt" >/dev/null 2>&1
    check "diff-2.4 $s: JSON Lines against text: exit 0" test $? = 0
done
"$exe" diff "$tmp/offset-all.txt" "$tmp/offset.jsonl" >"$tmp/out" 2>&1
check "diff-2.5 --all-stages --precision 3 against the default: exit 0" test $? = 0
"$exe" diff "$tmp/ties-all.txt" "$tmp/ties.jsonl" >"$tmp/out" 2>&1
check "diff-2.6 stages in one trace only are not compared, and said so" \
    grep -q "^Not compared: camera records are only in EXPECTED (3)" "$tmp/out"
"$exe" diff "$tmp/cube.txt" "$tmp/cube.jsonl" --rel 0 >/dev/null 2>&1
check "diff-2.7 --rel 0: text still agrees within its printed digits" test $? = 0

# ---- differences without a known mistake
"$exe" docs/examples/two-models.scene --format jsonl --trace "$tmp/two.jsonl"
"$exe" docs/examples/two-models.scene --format jsonl --model square --trace "$tmp/square.jsonl"
"$exe" diff "$tmp/two.jsonl" "$tmp/square.jsonl" >"$tmp/out" 2>&1
check "diff-3.1 a vertex in one trace only: exit 1" test $? = 1
check "diff-3.2 ... listed" grep -q "^only in EXPECTED: arrow v1, arrow v2" "$tmp/out"
grep -v '"model":"arrow","v":2,' "$tmp/two.jsonl" > "$tmp/less.jsonl"
"$exe" diff "$tmp/two.jsonl" "$tmp/less.jsonl" >"$tmp/out" 2>&1
awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
check "diff-3.2.1 one vertex only in EXPECTED: 'is', not 'are'" grep -qF ", 1 is only in EXPECTED." "$tmp/summary"
"$exe" docs/examples/lookat-near.scene --format jsonl --trace "$tmp/near.jsonl"
"$exe" diff "$tmp/near.jsonl" "$tmp/near.jsonl" >"$tmp/out" 2>&1
check "diff-3.2.2 clip points are counted apart from vertices" \
    grep -q "^The traces agree: 5 of 5 points (3 vertices, 2 clip points) at every stage" "$tmp/out"
sed 's/"x":1.25,/"x":1.2500001,/' "$tmp/offset.jsonl" > "$tmp/nudged.jsonl"
"$exe" diff "$tmp/offset.jsonl" "$tmp/nudged.jsonl" >"$tmp/out" 2>&1
check "diff-3.3 x_c off by 1e-7: exit 1" test $? = 1
check "diff-3.4 ... first differs at camera" grep -q "^box v2: differs first at camera" "$tmp/out"
awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/out" | tr '\n' ' ' >"$tmp/summary"
check "diff-3.5 ... no single mistake explains it" grep -qF "No single known mistake explains every vertex." "$tmp/summary"
check "diff-3.5a ... the offset that moves the agreeing vertices too is a partial candidate" \
    grep -qF "which do NOT explain the trace: a constant offset (1.0000000005838672e-07, 0, 0) (camera stage), which reproduces 2 of the 2 differing vertices and would change 2 of the 2 agreeing ones" "$tmp/summary"
check "diff-3.5b ... and no likely mistake" test "$(grep -c 'ikely mistake' "$tmp/out")" = 0
"$exe" diff "$tmp/offset.jsonl" "$tmp/nudged.jsonl" --tol 1e-6 >/dev/null 2>&1
check "diff-3.6 ... within --tol 1e-6: exit 0" test $? = 0
"$exe" diff "$tmp/offset.jsonl" "$tmp/nudged.jsonl" --rel 1e-6 >/dev/null 2>&1
check "diff-3.7 ... within --rel 1e-6: exit 0" test $? = 0

# ---- lit pixels against an independent count (sort and comm)
mistaken s3_two
"$tmp/sb/pipetrace" $data/offset.scene --format jsonl --trace "$tmp/got.jsonl"
"$exe" diff "$tmp/offset.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
for f in offset got; do
    grep '"type":"pixel"' "$tmp/$f.jsonl" | sed 's/.*"x":\([-0-9]*\),"y":\([-0-9]*\),"i":\([-0-9]*\).*/\1 \2 \3/' |
        sort -u > "$tmp/$f.px"
done
miss=$(comm -23 "$tmp/offset.px" "$tmp/got.px" | wc -l | tr -d ' ')
extra=$(comm -13 "$tmp/offset.px" "$tmp/got.px" | wc -l | tr -d ' ')
check "diff-4.1 missing pixels counted ($miss)" grep -q "^  missing in ACTUAL: $miss\$" "$tmp/out"
check "diff-4.2 extra pixels counted ($extra)" grep -q "^  extra in ACTUAL: $extra\$" "$tmp/out"

# ---- unreadable input: exit 2, FILE:LINE:COL: error:
head -2 "$tmp/offset.jsonl" > "$tmp/bad.jsonl"
echo '{"type":"vertex","model":"box","v":1,"stage":"pixel","x":1.5,"y":}' >> "$tmp/bad.jsonl"
"$exe" diff "$tmp/offset.jsonl" "$tmp/bad.jsonl" >"$tmp/out" 2>"$tmp/err"
check "diff-5.1 a malformed JSON line: exit 2" test $? = 2
check "diff-5.2 ... FILE:LINE:COL: error:" grep -q "^$tmp/bad.jsonl:3:66: error: " "$tmp/err"
sed '9s/x_c  =/x_c  = oops/' "$tmp/offset.txt" > "$tmp/bad.txt"
"$exe" diff "$tmp/bad.txt" "$tmp/offset.jsonl" >"$tmp/out" 2>"$tmp/err"
check "diff-5.3 a malformed text line: exit 2" test $? = 2
check "diff-5.4 ... FILE:LINE:COL: error:" grep -q "^$tmp/bad.txt:9:[0-9]*: error: " "$tmp/err"
"$exe" diff "$tmp/offset.jsonl" "$tmp/nosuch.jsonl" >/dev/null 2>"$tmp/err"
check "diff-5.5 a missing file: exit 2" test $? = 2
cat "$tmp/offset.jsonl" "$tmp/offset.jsonl" > "$tmp/twice.jsonl"
"$exe" diff "$tmp/offset.jsonl" "$tmp/twice.jsonl" >/dev/null 2>"$tmp/err"
check "diff-5.6 a record twice: exit 2" test $? = 2
"$exe" docs/examples/cube.scene --format csv --trace "$tmp/cube.csv"
"$exe" diff "$tmp/cube.csv" "$tmp/cube.jsonl" >/dev/null 2>"$tmp/err"
check "diff-5.7 CSV is refused: exit 2" test $? = 2
"$exe" diff "$tmp/offset.jsonl" >/dev/null 2>&1
check "diff-5.8 one file: usage error, exit 2 (as diff(1); 1 means different)" test $? = 2
# a text trace ends with its summary: cut anywhere before, it is refused
n=$(wc -l < "$tmp/offset.txt")
for cut in 4 12 $((n - 1)); do
    head -n $cut "$tmp/offset.txt" > "$tmp/cut.txt"
    "$exe" diff "$tmp/cut.txt" "$tmp/offset.jsonl" >/dev/null 2>"$tmp/err"
    check "diff-5.11 a text trace cut after line $cut: exit 2" test $? = 2
    check "diff-5.12 ... FILE:LINE:COL: error: ... cut short" \
        grep -q "^$tmp/cut.txt:$cut:[0-9]*: error: the trace ends .*: it was cut short" "$tmp/err"
done
head -c 100 "$tmp/offset.txt" > "$tmp/cut.txt"
"$exe" diff "$tmp/offset.jsonl" "$tmp/cut.txt" >/dev/null 2>"$tmp/err"
check "diff-5.13 a text trace cut inside a header line: exit 2" test $? = 2
printf 'hello\n' > "$tmp/hello.txt"
"$exe" diff "$tmp/hello.txt" "$tmp/offset.jsonl" >/dev/null 2>"$tmp/err"
check "diff-5.14 neither trace nor image: exit 2, naming what is read" \
    grep -qF "not a pipetrace trace (JSON Lines or text) nor an image (binary PPM (P6), plain PPM (P3), or PNG" "$tmp/err"
"$exe" diff "$tmp/offset.jsonl" "$tmp/offset.jsonl" --image-out "$tmp/x.ppm" >/dev/null 2>&1
check "diff-5.9 --image-out with traces: usage error, exit 2" test $? = 2
"$exe" diff --help >"$tmp/out" 2>&1
check "diff-5.10 --help" grep -q "^usage: pipetrace diff" "$tmp/out"

# ---- images: a 4 x 2 black image and one with 3 pixels changed
printf 'P6\n4 2\n255\n' > "$tmp/a.ppm"
printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0' >> "$tmp/a.ppm"
printf 'P6\n4 2\n255\n' > "$tmp/b.ppm"
printf '\0\0\0\377\377\377\0\0\0\0\0\0\0\0\0\0\0\0\0\0\1\0\0\0' >> "$tmp/b.ppm"
printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0' > "$tmp/zero"
check "diff-6.0 the test images are 35 bytes" test "$(wc -c < "$tmp/b.ppm")" = 35
"$exe" diff "$tmp/a.ppm" "$tmp/a.ppm" >/dev/null 2>&1
check "diff-6.1 an image against itself: exit 0" test $? = 0
"$exe" diff "$tmp/a.ppm" "$tmp/b.ppm" --image-out "$tmp/hl.ppm" >"$tmp/out" 2>&1
check "diff-6.2 two pixels differ: exit 1" test $? = 1
check "diff-6.3 ... counted, with their box" \
    grep -q "^2 of 8 pixels differ, all within the box (x, y) = (1, 0) .. (2, 1)\.\$" "$tmp/out"
check "diff-6.3a ... and never called the same" sh -c '! grep -q "images are the same" "$1"' _ "$tmp/out"
check "diff-6.4 ... listed with both colors" grep -q "^  (1, 0)  expected   0   0   0  actual 255 255 255\$" "$tmp/out"
check "diff-6.5 the highlight is a 4 x 2 PPM" test "$(head -c 11 "$tmp/hl.ppm" | tr '\n' ' ')" = "P6 4 2 255 "
check "diff-6.6 ... differing pixels red, the rest dimmed" \
    test "$(od -An -tu1 -j11 "$tmp/hl.ppm" | tr -s ' \n' '  ')" = " 0 0 0 255 0 0 0 0 0 0 0 0 0 0 0 0 0 0 255 0 0 0 0 0 "
printf 'P6\n5 2\n255\n' > "$tmp/c.ppm"
cat "$tmp/zero" "$tmp/zero" | head -c 30 >> "$tmp/c.ppm"
"$exe" diff "$tmp/a.ppm" "$tmp/c.ppm" >"$tmp/out" 2>&1
check "diff-6.7 different sizes: exit 1" test $? = 1
check "diff-6.8 ... the extra column counts as different" grep -q "^2 of 10 pixels differ" "$tmp/out"
check "diff-6.8a ... and the images are not called the same" sh -c '! grep -q "the same" "$1"' _ "$tmp/out"
head -c 20 "$tmp/a.ppm" > "$tmp/short.ppm"
"$exe" diff "$tmp/a.ppm" "$tmp/short.ppm" >/dev/null 2>"$tmp/err"
check "diff-6.9 a cut-short image: exit 2" test $? = 2
"$exe" diff "$tmp/a.ppm" "$tmp/offset.jsonl" >/dev/null 2>&1
check "diff-6.10 an image against a trace: exit 2" test $? = 2
"$exe" diff --tol x "$tmp/a.ppm" "$tmp/a.ppm" >/dev/null 2>&1
check "diff-6.10a a bad option value: exit 2" test $? = 2
"$exe" diff --nosuch "$tmp/a.ppm" "$tmp/a.ppm" >/dev/null 2>&1
check "diff-6.10b an unknown option: exit 2" test $? = 2

# ---- other images: plain PPM (P3) and PNG
printf 'P3\n4 2\n255\n0 0 0  255 255 255  0 0 0  0 0 0\n0 0 0 0 0 0 0 0 1 0 0 0\n' > "$tmp/b3.ppm"
"$exe" diff "$tmp/b.ppm" "$tmp/b3.ppm" >"$tmp/out" 2>&1
check "diff-6.11 P3 against the same P6: exit 0" test $? = 0
"$exe" diff "$tmp/a.ppm" "$tmp/b3.ppm" >"$tmp/out" 2>&1
check "diff-6.12 P3 against another P6: the same two pixels differ" \
    grep -q "^2 of 8 pixels differ, all within the box (x, y) = (1, 0) .. (2, 1)\.\$" "$tmp/out"
printf 'P3\n4 2\n255\n0 0 0 1\n' > "$tmp/short3.ppm"
"$exe" diff "$tmp/a.ppm" "$tmp/short3.ppm" >/dev/null 2>"$tmp/err"
check "diff-6.13 a cut-short P3: exit 2" test $? = 2
printf 'P3\n16384 16384\n255\n0 0 0\n' > "$tmp/huge3.ppm"
"$exe" diff "$tmp/a.ppm" "$tmp/huge3.ppm" >/dev/null 2>"$tmp/err"
check "diff-6.13a a P3 whose samples cannot fit in the file is refused before allocating" \
    grep -q "huge3.ppm:1:1: error: 805306368 samples cannot fit in the 6 bytes left" "$tmp/err"
"$exe" --image "$tmp/bi.png" 2>/dev/null
"$exe" --image "$tmp/bi.ppm" 2>/dev/null
"$exe" diff "$tmp/bi.png" "$tmp/bi.ppm" >"$tmp/out" 2>&1
check "diff-6.14 pipetrace's own PNG against its PPM: exit 0" test $? = 0
check "diff-6.15 ... read as PNG" grep -q "^EXPECTED .*(PNG, 400 x 300, maxval 255)\$" "$tmp/out"
"$exe" docs/examples/triangle.scene --image "$tmp/tri.png" 2>/dev/null
"$exe" diff "$tmp/bi.png" "$tmp/tri.png" >/dev/null 2>&1
check "diff-6.16 two different PNGs: exit 1" test $? = 1
# a 2 x 2 PNG with the Sub and Paeth row filters, stored; the same compressed
printf '\211PNG\r\n\032\n\000\000\000\015IHDR\000\000\000\002\000\000\000\002\010\002\000\000\000\375\324\232\163\000\000\000\031IDAT\170\001\001\016\000\361\377\001\012\024\036\036\036\036\004\074\074\074\036\036\036\012\126\001\252\374\332\162\222\000\000\000\000IEND\256\102\140\202' > "$tmp/f.png"
printf '\211PNG\r\n\032\n\000\000\000\015IHDR\000\000\000\002\000\000\000\002\010\002\000\000\000\375\324\232\163\000\000\000\023IDAT\170\332\143\344\022\221\003\002\026\033\033\033\040\005\000\012\126\001\252\246\214\223\060\000\000\000\000IEND\256\102\140\202' > "$tmp/z.png"
printf 'P6\n2 2\n255\n\012\024\036\050\062\074\106\120\132\144\156\170' > "$tmp/f.ppm"
"$exe" diff "$tmp/f.png" "$tmp/f.ppm" >"$tmp/out" 2>&1
check "diff-6.17 PNG row filters undone: the same as the PPM" test $? = 0
"$exe" diff "$tmp/z.png" "$tmp/f.ppm" >/dev/null 2>"$tmp/err"
check "diff-6.18 a compressed PNG: exit 2 ..." test $? = 2
check "diff-6.19 ... saying what is read and what to do" \
    grep -q "^$tmp/z.png:1:1: error: PNG: its image data is compressed; pipetrace diff reads only the uncompressed PNG that pipetrace writes (convert the image to P6 PPM" "$tmp/err"
head -c 60 "$tmp/bi.png" > "$tmp/cut.png"
"$exe" diff "$tmp/cut.png" "$tmp/bi.png" >/dev/null 2>"$tmp/err"
check "diff-6.20 a cut-short PNG: exit 2" test $? = 2

# ---- a consequence is claimed only when it is one: two mistakes, the index
# stage's (the vertices differ) and the viewport stage's floor(x + 0.5) (the
# rasterizer asks it each step: one step of data/floor.scene moves)
sh tests/teach/student.sh s6_xh "$tmp/s6_xh.c" >/dev/null 2>&1
sh tests/teach/student.sh s4_floor "$tmp/s4_floor.c" >/dev/null 2>&1
rm -f "$tmp/sb/pipetrace"
MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/sb" STAGE_index="$tmp/s6_xh.c" \
    STAGE_viewport="$tmp/s4_floor.c" "$tmp/sb/pipetrace" >"$tmp/make.log" 2>&1
"$exe" $data/floor.scene --format jsonl --trace "$tmp/want.jsonl"
"$tmp/sb/pipetrace" $data/floor.scene --format jsonl --trace "$tmp/got.jsonl"
"$exe" diff "$tmp/want.jsonl" "$tmp/got.jsonl" >"$tmp/out" 2>&1
summary
check "diff-13.1 two mistakes: the pixels are not called a consequence" \
    sh -c '! grep -qF ", as a consequence:" "$1" && grep -qF "and not only as a consequence" "$1"' _ "$tmp/summary"
check "diff-13.2 ... the second mistake said, where it starts" \
    grep -qF "so the rasterizer (or the viewport stage it asks each step) goes wrong there too: a second mistake." "$tmp/summary"

# ---- no verdict without evidence: PASS only when every stage and the pixels
# were compared (exit 3 and what was not, otherwise)
"$exe" docs/examples/triangle.scene --format kraft --trace "$tmp/v.log"
"$exe" diff --verdict "$tmp/v.log" "$tmp/v.log" >"$tmp/out" 2>&1; rc=$?
check "diff-12.1 a course log against itself: not proven, exit 3 ($rc)" \
    sh -c 'test "$1" = 3 && grep -q "^Verdict: NOT PROVEN" "$2" && ! grep -q PASS "$2"' _ "$rc" "$tmp/out"
check "diff-12.2 ... it names the stages and the pixels not compared" \
    sh -c 'tr "\n" " " < "$1" | grep -q "the viewport stage (in neither trace), the framebuffer stage (in neither trace), the index stage (in neither trace), the lit pixels (neither trace has raster records)"' _ "$tmp/out"
"$exe" docs/examples/triangle.scene --all-stages --format jsonl --trace "$tmp/v.jsonl"
"$exe" diff --verdict "$tmp/v.jsonl" "$tmp/v.jsonl" >"$tmp/out" 2>&1; rc=$?
check "diff-12.3 every stage, but the viewport at (0, 0): the offset is not proven (exit $rc)" \
    sh -c 'test "$1" = 3 && tr "\n" " " < "$2" | grep -q "the framebuffer stage.s offset"' _ "$rc" "$tmp/out"
"$exe" diff "$tmp/v.log" "$tmp/v.log" >/dev/null 2>&1; rc=$?
check "diff-12.4 without --verdict: agreement is exit 0, as diff(1)" test "$rc" = 0
"$exe" docs/examples/selfcheck.scene --format jsonl --trace "$tmp/v2.jsonl"
"$exe" diff --verdict "$tmp/v2.jsonl" "$tmp/v2.jsonl" >"$tmp/out" 2>&1; rc=$?
check "diff-12.5 the self-check scene exercises every stage: PASS, exit 0 ($rc)" \
    sh -c 'test "$1" = 0 && grep -q "^Verdict: PASS" "$2"' _ "$rc" "$tmp/out"
# ---- 14: --scene gives a trace without a header (the course's log) the scene's numbers
S=tests/reference/basic-two-models.scene
if mistaken s3_swapwh; then
    "$tmp/sb/pipetrace" $S --format kraft --trace "$tmp/swap.log"
    "$exe" diff --verdict tests/reference/kraftlog/basic-two-models.log "$tmp/swap.log" >"$tmp/out" 2>&1
    check "diff-14.1 a course log without pixel lines as EXPECTED, no --scene: no mistake named" \
        sh -c '! grep -q "Likely mistake" "$1"' _ "$tmp/out"
    "$exe" diff --verdict --scene $S tests/reference/kraftlog/basic-two-models.log "$tmp/swap.log" >"$tmp/out" 2>&1; rc=$?
    check "diff-14.2 ... with --scene: w and h swapped, named (exit $rc)" \
        sh -c 'test "$1" = 1 && tr "\n" " " < "$2" | grep -q "Likely mistake: w and h swapped:"' _ "$rc" "$tmp/out"
else
    check "diff-14.1 the s3_swapwh student build" false
fi
"$exe" diff --verdict --scene "$tmp/none.scene" tests/reference/kraftlog/basic-two-models.log "$tmp/swap.log" >"$tmp/out" 2>&1; rc=$?
check "diff-14.3 --scene of no file: exit 2, said" sh -c 'test "$1" = 2 && grep -q "none.scene" "$2"' _ "$rc" "$tmp/out"
"$exe" diff --verdict --scene tests/course79/r7-near-01.scene tests/reference/kraftlog/basic-two-models.log "$tmp/swap.log" >"$tmp/out" 2>&1; rc=$?
check "diff-14.4 --scene of a renderer 7 scene on renderer 4's logs: exit 2, said" \
    sh -c 'test "$1" = 2 && grep -q "renderer 7" "$2"' _ "$rc" "$tmp/out"

# ---- 15: the rasterizer's mistakes, seen only in the pixels: every vertex
# agrees (a course log has no viewport records; a JSON Lines trace of
# --stage pixel --stage raster neither), so diff replays the DDA from
# EXPECTED's rounded endpoints with each mistake and names the one that
# lights ACTUAL's pixels in every segment that differs
# rast ID EXPECTED ACTUAL NAME: diff names NAME there, and no other mistake
rast() {
    "$exe" diff --verdict "$2" "$3" >"$tmp/out" 2>&1; rc=$?
    summary
    check "$1 exit 1 ($rc)" test "$rc" = 1
    check "$1 names '$4'" grep -qxF "  likely mistake: $4" "$tmp/out"
    check "$1 ... and no other mistake" sh -c \
        'test "$(grep -E "^ *(likely mistake|partial|ambiguous):" "$1" | grep -cvF "$2")" = 0 &&
         ! grep -q "ambiguous" "$3"' _ "$tmp/out" "$4" "$tmp/flat"
    check "$1 ... in the summary and the verdict" \
        sh -c 'grep -qF "Likely mistake: $1" "$2" && grep -qF "Verdict: FAIL in the pixels" "$2"' _ "$4" "$tmp/flat"
    [ "$failed" -gt "$failed_before" ] && sed 's/^/  /' "$tmp/out" | tail -20
    failed_before=$failed
}
K=tests/reference/kraftlog/basic-two-models.pixels.log
# (a) x_vp = round(x_pp): the course's log of the student build, every pixel
# one to the right
if mistaken s4_nominus1; then
    "$tmp/sb/pipetrace" $S --format kraft-pixels --trace "$tmp/nominus1.log"
    rast diff-15.1 $K "$tmp/nominus1.log" "missing -1 in x_vp"
    check "diff-15.1a ... where it is made" grep -qF "missing -1 in x_vp in the viewport formula the rasterizer asks each step (s4)" "$tmp/flat"
    # a segment from the left edge, x_pp = 0 .. 5: x_vp = round(x_pp) lights
    # x_vp 0 .. 5, and so does the loop one step too long (0 is clipped):
    # both reproduce it, and diff names neither
    printf 'framebuffer 12 6\ncamera orthographic\nmodel e\nv -1.083375 0 0\nv -0.249625 0 0\nl 1 2\n' > "$tmp/edge.scene"
    "$exe" "$tmp/edge.scene" --format kraft-pixels --trace "$tmp/edge-want.log"
    "$tmp/sb/pipetrace" "$tmp/edge.scene" --format kraft-pixels --trace "$tmp/edge-got.log"
    "$exe" diff --verdict "$tmp/edge-want.log" "$tmp/edge-got.log" >"$tmp/out" 2>&1; rc=$?; summary
    check "diff-15.2 two mistakes reproduce a segment from the left edge: ambiguous (exit $rc)" \
        sh -c 'test "$1" = 1 && grep -qF "ambiguous: missing -1 in x_vp or DDA loop one step too long" "$2"' _ "$rc" "$tmp/flat"
    check "diff-15.2a ... and no likely mistake named alone" test "$(grep -c '^ *likely mistake' "$tmp/out")" = 0
else
    check "diff-15.1 the s4_nominus1 student build" false
fi
# (b) y_vp = round(y_pp) - 1: upside down
if mistaken s4_noflip; then
    "$tmp/sb/pipetrace" $S --format kraft-pixels --trace "$tmp/noflip.log"
    rast diff-15.3 $K "$tmp/noflip.log" "missing y flip"
else
    check "diff-15.3 the s4_noflip student build" false
fi
# (c) (int)(y + 0.5) draws the pixels floor(y + 0.5) draws (they differ only
# below -0.5, left of or below the viewport): the clip records of a segment
# that starts left of the viewport tell them apart.  Logical pixels (-3, 0)
# to (9, 1) in 12 x 4: y reaches 0.49999999999999994 at x = 3, and the first
# clipped step is x_vp -4 (Math.round, floor) or -3 (truncation)
printf 'framebuffer 12 4\ncamera orthographic\nmodel f\nv -1.583625 -1.250125 0\nv 0.417375 -0.749875 0\nl 1 2\n' > "$tmp/left.scene"
"$exe" "$tmp/left.scene" --format jsonl --stage pixel --stage raster --trace "$tmp/left-want.jsonl"
check "diff-15.4 (the first clipped step of the reference is x_vp -4)" grep -qF '"first":[-4,4]' "$tmp/left-want.jsonl"
"$exe" $data/floor.scene --format jsonl --trace "$tmp/floor-want.jsonl"
if mistaken s4_trunc; then
    "$tmp/sb/pipetrace" "$tmp/left.scene" --format jsonl --stage pixel --stage raster --trace "$tmp/left-got.jsonl"
    rast diff-15.5 "$tmp/left-want.jsonl" "$tmp/left-got.jsonl" "truncation toward zero instead of Java's Math.round"
    # where no step reaches below -0.5 the two light the same pixels: both
    # are said, neither named (naming floor(x + 0.5) would blame this
    # student for a mistake not made)
    "$tmp/sb/pipetrace" $data/floor.scene --format jsonl --trace "$tmp/floor-got.jsonl"
    "$exe" diff --verdict "$tmp/floor-want.jsonl" "$tmp/floor-got.jsonl" >"$tmp/out" 2>&1; rc=$?; summary
    check "diff-15.6 where no step tells truncation from floor(x + 0.5): ambiguous (exit $rc)" \
        sh -c 'test "$1" = 1 && grep -qF "ambiguous: floor(x + 0.5) instead of Java'"'"'s Math.round or truncation toward zero instead of Java'"'"'s Math.round" "$2"' _ "$rc" "$tmp/flat"
    check "diff-15.6a ... the two said to differ only left of or below the viewport" \
        grep -qF "floor(x + 0.5) instead of Java's Math.round and truncation toward zero instead of Java's Math.round light other pixels only at steps left of or below the viewport, which this trace does not tell apart." "$tmp/flat"
    check "diff-15.6b ... and no likely mistake named alone" test "$(grep -c '^ *likely mistake' "$tmp/out")" = 0
else
    check "diff-15.5 the s4_trunc student build" false
fi
if mistaken s4_floor; then
    "$tmp/sb/pipetrace" "$tmp/left.scene" --format jsonl --stage pixel --stage raster --trace "$tmp/left-got.jsonl"
    rast diff-15.7 "$tmp/left-want.jsonl" "$tmp/left-got.jsonl" "floor(x + 0.5) instead of Java's Math.round"
    check "diff-15.7a ... truncation not said to fit" sh -c '! grep -q "truncation" "$1"' _ "$tmp/out"
else
    check "diff-15.7 the s4_floor student build" false
fi
# (d) the loop bound off by one: no stage of a student build makes it, so the
# course's log is edited.  One step short: the last pixel line of each
# segment's run dropped (a run of one, a single pixel, is kept)
short='/^ *fb_\[/ { if (held != "") print held; held = $0; n++; next }
       { if (held != "" && n == 1) print held; held = ""; n = 0; print }
       END { if (held != "" && n == 1) print held }'
awk "$short" $K > "$tmp/short.log"
check "diff-15.8 (24 pixel lines fewer)" test $(($(grep -c 'fb_\[' $K) - $(grep -c 'fb_\[' "$tmp/short.log"))) = 24
rast diff-15.9 $K "$tmp/short.log" "DDA loop one step short"
# one step too long, on rows (m = 0, stepped left to right): after each
# segment's last pixel line the next step, x_pp and x_vp one more
printf 'framebuffer 30 20\nviewport 3 2 24 16\ncamera orthographic\nmodel h\nv -0.5 0.3 0\nv 0.5 0.3 0\nv -0.7 -0.4 0\nv 0.2 -0.4 0\nl 1 2\nl 4 3\n' > "$tmp/rows.scene"
"$exe" "$tmp/rows.scene" --format kraft-pixels --trace "$tmp/rows.log"
long='function bump(s, key,    v) {
         match(s, key "= *-?[0-9]+")
         v = substr(s, RSTART + length(key) + 1, RLENGTH - length(key) - 1) + 1
         return substr(s, 1, RSTART - 1) sprintf("%s=%4d", key, v) substr(s, RSTART + RLENGTH)
     }
     /^ *fb_\[/ { print; held = $0; next }
     held != "" { print bump(bump(held, "x_pp"), "x_vp"); held = "" }
     { print }
     END { if (held != "") print bump(bump(held, "x_pp"), "x_vp") }'
awk "$long" "$tmp/rows.log" > "$tmp/long.log"
check "diff-15.10 (2 pixel lines more)" test $(($(grep -c 'fb_\[' "$tmp/long.log") - $(grep -c 'fb_\[' "$tmp/rows.log"))) = 2
rast diff-15.11 "$tmp/rows.log" "$tmp/long.log" "DDA loop one step too long"
awk "$short" "$tmp/rows.log" > "$tmp/rows-short.log"
rast diff-15.12 "$tmp/rows.log" "$tmp/rows-short.log" "DDA loop one step short"
# (e) setPixelVP without (x_ul, y_ul): the course's log prints x_vp before
# setPixelVP, so only pipetrace's pixel records (framebuffer pixels) show it
"$exe" $S --format jsonl --stage pixel --stage raster --trace "$tmp/off-want.jsonl"
if mistaken s5_nooffset; then
    "$tmp/sb/pipetrace" $S --format jsonl --stage pixel --stage raster --trace "$tmp/off-got.jsonl"
    rast diff-15.13 "$tmp/off-want.jsonl" "$tmp/off-got.jsonl" "viewport offset (x_ul, y_ul) forgotten"
    check "diff-15.13a ... the pixels moved by (-10, -5)" grep -qF "all of them moved by (-10, -5)" "$tmp/flat"
else
    check "diff-15.13 the s5_nooffset student build" false
fi

# ---- 16: a clip record with a coordinate that has no integer value reads back
"$exe" tests/extreme/zdiv-zero.scene --format jsonl --trace "$tmp/z.jsonl" 2>/dev/null
"$exe" tests/extreme/zdiv-zero.scene --trace "$tmp/z.txt" 2>/dev/null
"$exe" diff "$tmp/z.jsonl" "$tmp/z.txt" >"$tmp/out" 2>&1; rc=$?
check "diff-16.1 clip records with null / none: both formats read, and agree (exit $rc)" test "$rc" = 0

# ---- 17: where several known mistakes explain everything, diff prints a
# scene made to tell them apart (src/tools/diff/dseparate.c), between two
# marker lines; it must render, and on it each student's trace must name
# that student's mistake and no other
# sepscene ID OUT: the scene between the markers of OUT into $tmp/sep.scene
sepscene() {
    sed -n '/^#---- begin separating scene ----$/,/^#---- end separating scene ----$/p' "$2" |
        sed '1d;$d' >"$tmp/sep.scene"
    check "$1 the separating scene is printed between its markers" test -s "$tmp/sep.scene"
    "$exe" "$tmp/sep.scene" --format jsonl --trace "$tmp/sep-want.jsonl" >"$tmp/sep.err" 2>&1; rc=$?
    check "$1 ... and it parses and renders (exit $rc)" test "$rc" = 0
}
# (a) floor(x + 0.5) or truncation in a vertex record (diff-1.15): on the
# scene, floor shows in the DDA's running y, truncation in a negative x_pp
"$exe" diff $data/floor-vertex-expected.jsonl $data/floor-vertex-actual.jsonl >"$tmp/out" 2>&1
sepscene diff-17.1 "$tmp/out"
check "diff-17.1a ... the summary points to it" sh -c 'tr "\n" " " < "$1" | grep -qF "The separating scene printed above tells them apart."' _ "$tmp/out"
check "diff-17.1b ... no longer to the self-check scene" sh -c '! grep -q "self-check scene tells" "$1"' _ "$tmp/out"
cp "$tmp/sep.scene" "$tmp/sep-a.scene"
if mistaken s4_floor; then
    mistake diff-17.2 "$tmp/sep-a.scene" jsonl "floor(x + 0.5) instead of Java's Math.round" ""
else
    check "diff-17.2 the s4_floor student build" false
fi
if mistaken s4_trunc; then
    mistake diff-17.3 "$tmp/sep-a.scene" jsonl "truncation toward zero instead of Java's Math.round"
else
    check "diff-17.3 the s4_trunc student build" false
fi
# --separating-scene FILE writes the same lines; never over an input
"$exe" diff $data/floor-vertex-expected.jsonl $data/floor-vertex-actual.jsonl --separating-scene "$tmp/sep-file.scene" >/dev/null 2>&1; rc=$?
check "diff-17.4 --separating-scene FILE: exit 1 as before ($rc), FILE the printed scene" \
    sh -c 'test "$1" = 1 && cmp -s "$2" "$3"' _ "$rc" "$tmp/sep-file.scene" "$tmp/sep-a.scene"
cp $data/floor-vertex-actual.jsonl "$tmp/act.jsonl"
"$exe" diff $data/floor-vertex-expected.jsonl "$tmp/act.jsonl" --separating-scene "$tmp/act.jsonl" >"$tmp/out" 2>&1; rc=$?
check "diff-17.5 --separating-scene over ACTUAL: refused, exit 2 ($rc), ACTUAL kept" \
    sh -c 'test "$1" = 2 && grep -qF "names ACTUAL" "$2" && cmp -s "$3" "$4"' _ "$rc" "$tmp/out" "$tmp/act.jsonl" $data/floor-vertex-actual.jsonl
rm -f "$tmp/none.scene"
"$exe" diff $data/ties.jsonl $data/ties-cround.jsonl --separating-scene "$tmp/none.scene" >"$tmp/out" 2>&1; rc=$?
check "diff-17.6 nothing ambiguous: no scene printed or written, said on stderr (exit $rc)" \
    sh -c 'test "$1" = 1 && ! test -e "$2" && ! grep -q "begin separating scene" "$3" && grep -qF "no separating scene" "$3"' _ "$rc" "$tmp/none.scene" "$tmp/out"
# (b) the rasterizer: missing -1 in x_vp or the loop one step too long on a
# segment from the viewport's left edge (diff-15.2), in the course's logs
if mistaken s4_nominus1; then
    "$exe" "$tmp/edge.scene" --format kraft-pixels --trace "$tmp/edge-want.log"
    "$tmp/sb/pipetrace" "$tmp/edge.scene" --format kraft-pixels --trace "$tmp/edge-got.log"
    "$exe" diff --verdict "$tmp/edge-want.log" "$tmp/edge-got.log" >"$tmp/out" 2>&1
    sepscene diff-17.7 "$tmp/out"
    check "diff-17.7a ... for the course's logs with pixels" grep -qF "kraft-pixels" "$tmp/sep.scene"
    check "diff-17.7b ... the summary points to it" \
        sh -c 'tr "\n" " " < "$1" | tr -s " " | grep -qF "The separating scene printed above tells them apart."' _ "$tmp/out"
    "$exe" "$tmp/sep.scene" --format kraft-pixels --trace "$tmp/sep-want.log"
    "$tmp/sb/pipetrace" "$tmp/sep.scene" --format kraft-pixels --trace "$tmp/sep-got.log"
    rast diff-17.8 "$tmp/sep-want.log" "$tmp/sep-got.log" "missing -1 in x_vp"
    awk "$long" "$tmp/sep-want.log" > "$tmp/sep-long.log"
    rast diff-17.9 "$tmp/sep-want.log" "$tmp/sep-long.log" "DDA loop one step too long"
else
    check "diff-17.7 the s4_nominus1 student build" false
fi

# ---- 19: two images, the viewport's corner forgotten in setPixelVP (the
# course's log prints x_vp before it: only the image shows it).  The scene with
# its viewport at (0, 0) draws the picture of offset.scene moved by (-5, -3),
# as setPixelVP without (x_ul, y_ul) does; at (1, 0) it moves by (-4, -3).
"$exe" $data/offset.scene --image "$tmp/ul-want.ppm" >/dev/null
for c in "0 0" "1 0"; do
    sed "s/^viewport 5 3 /viewport $c /" $data/offset.scene > "$tmp/ul.scene"
    "$exe" "$tmp/ul.scene" --image "$tmp/ul-$(echo $c | tr -d ' ').ppm" >/dev/null
done
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-00.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
summary
check "diff-19.1 images moved by the scene's (-x_ul, -y_ul): exit 1 ($rc)" test "$rc" = 1
check "diff-19.1a ... the forgotten corner named" grep -qF "The shift is the viewport's corner (x_ul, y_ul) = (5, 3) of $data/offset.scene taken off every pixel. Likely mistake: viewport offset (x_ul, y_ul) forgotten: in setPixelVP," "$tmp/flat"
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-00.ppm" >"$tmp/out" 2>&1; summary
check "diff-19.2 ... without --scene: the shift said, nothing named" \
    sh -c 'grep -qF "moved by (-5, -3): the same picture, shifted. With --scene SCENE, diff tells whether" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat"
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-10.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; summary
check "diff-19.3 a shift by something else, (-4, -3): said, nothing named" \
    sh -c 'grep -qF "moved by (-4, -3): the same picture, shifted. ACTUAL is not EXPECTED moved by (-5, -3), the viewport'"'"'s corner (x_ul, y_ul) = (5, 3) of" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat"
# one lit pixel of EXPECTED left where it was: not every pixel moved
xy=$("$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-00.ppm" --show 1000 | awk '/actual   0   0   0$/ { gsub(/[(),]/, ""); print $1, $2; exit }')
cp "$tmp/ul-00.ppm" "$tmp/ul-part.ppm"
printf '\377\377\377' | dd of="$tmp/ul-part.ppm" bs=1 seek=$((13 + 3 * (${xy% *} + 40 * ${xy#* }))) conv=notrunc 2>/dev/null
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-part.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
summary
check "diff-19.4 all but one pixel moved by (-5, -3) (pixel $xy stayed): exit 1, not moved, nothing named" \
    sh -c 'test "$2" = 1 && grep -qF "ACTUAL is not EXPECTED moved by (-5, -3), the viewport'"'"'s corner" "$1" && ! grep -q "shifted" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat" "$rc"
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-00.ppm" --scene docs/examples/triangle.scene >"$tmp/out" 2>&1; summary
check "diff-19.5 --scene of a viewport at (0, 0): nothing named" \
    sh -c 'grep -qF "corner (x_ul, y_ul) of docs/examples/triangle.scene is (0, 0): forgetting it moves nothing" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat"
"$exe" diff "$tmp/ul-want.ppm" "$tmp/ul-00.ppm" --scene "$tmp/none.scene" >"$tmp/out" 2>&1
check "diff-19.6 --scene unreadable: exit 2" test $? = 2


# ---- 20: a rasterizer's mistake behind a vertex stage's: the course's
# renderer 4 with 2 for 2.001 and without the y flip (tests/data/students/),
# its pixels replayed from its own end pixels with each viewport stage the
# DDA asks
"$exe" $data/offset.scene --all-stages --format jsonl --trace "$tmp/two-want.jsonl"
for who in j-two-noflip j-twoint-nominus1 j-two; do
    gzip -dc tests/data/students/offset/$who.log.gz > "$tmp/$who.log"
done
"$exe" diff --verdict "$tmp/two-want.jsonl" "$tmp/j-two-noflip.log" >"$tmp/out" 2>&1; rc=$?
tr '\n' ' ' < "$tmp/out" | tr -s ' ' > "$tmp/flat"
check "diff-20.1 2 for 2.001 and no y flip: exit 1 ($rc), the flip named as the second mistake" \
    sh -c 'test "$2" = 1 && grep -qF "a second mistake. Likely second mistake: missing y flip in the viewport formula the rasterizer asks each step (s4), which from ACTUAL'"'"'s own end pixels draws ACTUAL'"'"'s pixels in every segment." "$1"' _ "$tmp/flat" "$rc"
check "diff-20.1a ... the first mistake named in the verdict" grep -qF "Likely mistake: 2 instead of 2.001:" "$tmp/flat"
for who in j-twoint-nominus1 j-two; do
    "$exe" diff --verdict "$tmp/two-want.jsonl" "$tmp/$who.log" >"$tmp/out" 2>&1
    check "diff-20.2 $who: its pixels a consequence of its vertices, no second mistake named" \
        sh -c '! grep -q "second mistake" "$1"' _ "$tmp/out"
done


# ---- 21: a student's own log against the image the same program wrote: the
# corner forgotten behind another mistake (the longer DDA loop, w and h
# swapped): the image is not the reference's moved, but the student's own
# logged pixels at their viewport coordinates (x_vp, y_vp)
for who in j-long-setpixel j-swapwh-setpixel j-right; do
    for e in log ppm; do
        gzip -dc tests/data/students/offset/$who.$e.gz > "$tmp/own-$who.$e"
    done
done
for who in j-long-setpixel j-swapwh-setpixel; do
    "$exe" diff "$tmp/own-$who.log" "$tmp/own-$who.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
    summary
    check "diff-21.1 $who's log and image: exit 1 ($rc), the corner (5, 3) forgotten named" \
        sh -c 'test "$2" = 1 && grep -qF "the viewport'"'"'s corner (x_ul, y_ul) = (5, 3) taken off every pixel. Likely mistake: viewport offset (x_ul, y_ul) forgotten:" "$1"' _ "$tmp/flat" "$rc"
    "$exe" diff "$tmp/ul-want.ppm" "$tmp/own-$who.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1
    check "diff-21.2 ... which its image against the reference's cannot name" \
        sh -c '! grep -qi "likely mistake" "$1"' _ "$tmp/out"
done
"$exe" diff "$tmp/own-j-right.log" "$tmp/own-j-right.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
summary
check "diff-21.3 a right student's log and image: exit 0 ($rc), the image is what the log drew, nothing named" \
    sh -c 'test "$2" = 0 && grep -qF "The image is what the log drew" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat" "$rc"
"$exe" diff "$tmp/own-j-right.log" "$tmp/ul-10.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
summary
check "diff-21.4 its log with its picture moved by (-4, -3), not the corner: exit 1 ($rc), nothing named" \
    sh -c 'test "$2" = 1 && grep -qF "neither the logged framebuffer pixels nor the logged viewport pixels" "$1" && ! grep -qi "likely mistake" "$1"' _ "$tmp/flat" "$rc"
"$exe" diff "$tmp/own-j-right.log" "$tmp/ul-00.ppm" --scene $data/offset.scene >"$tmp/out" 2>&1; rc=$?
summary
check "diff-21.5 ... moved by (-5, -3), the corner: exit 1 ($rc), named" \
    sh -c 'test "$2" = 1 && grep -qF "Likely mistake: viewport offset (x_ul, y_ul) forgotten:" "$1"' _ "$tmp/flat" "$rc"
"$exe" diff "$tmp/own-j-right.log" "$tmp/ul-00.ppm" >"$tmp/out" 2>&1; rc=$?
check "diff-21.6 a log and an image without --scene: a usage error, exit 2 ($rc)" test "$rc" = 2
"$exe" diff "$tmp/own-j-right.log" "$tmp/own-j-right.ppm" --scene "$tmp/none.scene" >"$tmp/out" 2>&1; rc=$?
check "diff-21.7 --scene unreadable: exit 2 ($rc)" test "$rc" = 2

report
