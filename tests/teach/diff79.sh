#!/bin/sh
# tests/teach/diff79.sh -- pipetrace diff on renderers 7 and 9: students' logs, each mistake named
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/diff79.sh PIPETRACE.  Run from the repository root.
# tests/data/diff79/ holds, per scene (SCENE.scene, and SCENE.case for the
# course's harness), the logs the course's renderer printed for it, right
# (SCENE.right.log.gz) and with one mistake made in a copy of its Java source
# (SCENE.MISTAKE.log.gz; README.md there says which).  EXPECTED is pipetrace's
# own trace of the scene, made here in JSON Lines and text, or the right log;
# each student's log must be named with its mistake and no other, the right
# logs pass, a log without the rasterizer's lines is not proven, two mistakes
# that give the same log are "ambiguous", with a scene printed that tells
# them apart (SCENE-sep of each ambiguous SCENE: the near clip's, the
# camera's, the clip's, the world's; their students' logs are stored too).
exe=$1
. tests/lib/testlib.sh
data=tests/data/diff79

unz() { gzip -dc "$data/$1.log.gz" > "$tmp/$1.log"; }

# expect ID EXPECTED ACTUAL STATUS LINE: `diff --verdict` exits STATUS and
# prints LINE (a fixed string), and names no mistake LINE does not.
expect() {
    id=$1 want=$2 got=$3 st=$4 line=$5
    "$exe" diff "$want" "$got" --verdict >"$tmp/out" 2>&1; rc=$?
    check "$id exit $st" test "$rc" = "$st"
    check "$id says '$line'" grep -qF "$line" "$tmp/out"
    check "$id ... and one Mistake line at most" test "$(grep -c '^Mistake:' "$tmp/out")" -le 1
    case $line in
    Mistake:*) check "$id ... that one" test "$(grep '^Mistake:' "$tmp/out" | grep -cvF "$line")" = 0 ;;
    *) check "$id ... no mistake named" test "$(grep -c '^Mistake: [^u]' "$tmp/out")" = 0 ;;
    esac
    [ "$failed" -gt "$failed_before" ] && sed 's/^/  /' "$tmp/out" | head -30
    failed_before=$failed
}
failed_before=0

# mistake SCENE MISTAKE NAME: the student's log against EXPECTED three ways
mistake() {
    scene=$1 m=$2 name=$3
    unz "$scene.$m"
    for want in "$tmp/$scene.jsonl" "$tmp/$scene.txt" "$tmp/$scene.right.log"; do
        expect "$scene.$m vs ${want##*.}" "$want" "$tmp/$scene.$m.log" 1 "Mistake: $name"
    done
}

for scene in r7-skew-aa r7-near r7-near-amb r7-near-amb-sep r7-clip1 r7-clip2 r9-view-skew r9-order r9-order3 \
             r7-cam-amb1 r7-cam-amb1-sep r7-cam-amb2 r7-cam-amb2-sep r7-clip-amb r7-clip-amb-sep \
             r7-cam-amb3 r7-cam-amb3-sep r7-cam-amb4 r7-cam-amb4-sep r7-near-amb-col r7-near-amb-col-sep \
             r9-cam-amb r9-cam-amb-sep r9-world-amb r9-world-amb-sep r7-cam-amb-ortho r7-cam-amb-ortho-sep; do
    "$exe" "$data/$scene.scene" --format jsonl --trace "$tmp/$scene.jsonl"
    "$exe" "$data/$scene.scene" --trace "$tmp/$scene.txt"
    unz "$scene.right"
    # ---- the right logs pass, against pipetrace's traces and its own log
    expect "$scene right vs jsonl" "$tmp/$scene.jsonl" "$tmp/$scene.right.log" 0 "Verdict: PASS"
    expect "$scene right vs text" "$tmp/$scene.txt" "$tmp/$scene.right.log" 0 "Verdict: PASS"
    "$exe" "$data/$scene.scene" --format kraft --kraft-debug all --trace "$tmp/$scene.kraft.log"
    check "$scene: --format kraft writes the course's log" cmp -s "$tmp/$scene.kraft.log" "$tmp/$scene.right.log"
    expect "$scene kraft vs jsonl" "$tmp/$scene.jsonl" "$tmp/$scene.kraft.log" 0 "Verdict: PASS"
    expect "$scene jsonl vs text" "$tmp/$scene.jsonl" "$tmp/$scene.txt" 0 "Verdict: PASS"
done

# ---- each mistake named on the scene that separates it
mistake r7-skew-aa skew0 "the skew forgotten"
mistake r7-skew-aa skewneg "the skew's sign wrong"
mistake r7-skew-aa halfsize "scaled by the width, not the half-width"
mistake r7-skew-aa doublesize "scaled by the half-width twice"
mistake r7-skew-aa gamma0 "gamma not applied"
mistake r7-skew-aa gamma2 "gamma applied twice"
mistake r7-skew-aa aaswap "the anti-aliasing weights swapped"
mistake r7-near nearsign "the near plane's sign wrong"
mistake r7-near nearoff "the near plane ignored"
mistake r7-near nearkept "the near clip's colour not interpolated"
mistake r7-near nearbytes "the near clip's colour interpolated in bytes"
mistake r7-near clipkept "the clip's colour not interpolated"
mistake r7-near clipbytes "the clip's colour interpolated in bytes"
mistake r7-near neart "the near clip's t from y"
mistake r7-clip1 clipt "the clip's t from the other coordinate"
mistake r7-clip1 clipswap "the clip's edges swapped"
# segments cut twice (entering and leaving, a corner, a corner missed): the
# student's loop follows its own wrong first cut
mistake r7-clip2 clipt "the clip's t from the other coordinate"
mistake r7-clip2 clipswap "the clip's edges swapped"
mistake r9-view-skew viewadd "the camera translation added"
mistake r9-view-skew skewneg "the skew's sign wrong"
# matrices that do not commute: rotate then translate, translate then rotate
mistake r9-order matswap "the matrices multiplied in the wrong order"
mistake r9-order mattrans "the matrix-vector product transposed"
# three lines, one a scaling that is not uniform: the transposed product is
# named; composed backwards, the matrix is neither [A | A t] nor [A | A^-1 t]
mistake r9-order3 mattrans "the matrix-vector product transposed"
unz r9-order3.matswap
expect "r9-order3 matswap: three lines backwards" "$tmp/r9-order3.jsonl" "$tmp/r9-order3.matswap.log" 1 "Mistake: unknown"

# ---- the new names on no other log: every student's log of every scene
# against its scene's right log names neither world mistake nor, but on
# r7-clip1 and r7-clip2, the clip's t or edges
for f in "$data"/*.*.log.gz; do
    b=$(basename "$f" .log.gz); sc=${b%%.*}; m=${b#*.}
    [ "$m" = right ] && continue
    gzip -dc "$f" >"$tmp/s.log"
    "$exe" diff "$tmp/$sc.right.log" "$tmp/s.log" >"$tmp/out" 2>&1
    case $b in
    r9-order.*|r9-order3.mattrans|r9-world-amb*) ;;
    *) check "$b: no world mistake named" test "$(grep -c 'multiplied in the wrong order\|product transposed' "$tmp/out")" = 0 ;;
    esac
    case $b in
    r7-clip1.*|r7-clip2.*|r7-clip-amb-sep.clipt|r7-clip-amb-sep.clipswap) ;;
    *) check "$b: no clip t or edge mistake named" test "$(grep -c "clip's t from the other\|clip's edges swapped" "$tmp/out")" = 0 ;;
    esac
done

# ---- the world stage: first to differ, every vertex of both positions
"$exe" diff "$tmp/r9-order.jsonl" "$tmp/r9-order.matswap.log" >"$tmp/out" 2>&1
check "r9-order matswap: world, 16 of 16" grep -qF "First stage that differs: world (16 of 16 vertices)." "$tmp/out"
check "... the model stage agrees" grep -qE "^  model +16 compared, 0 differ$" "$tmp/out"
# every vertex must fit: one world vertex moved, and no mistake is named
awk '/^1\. World +: vIndex = +5,/ && !done { sub(/\(x,y,z,w\)=\( +/, "&1"); done = 1 } { print }' \
    "$tmp/r9-order.matswap.log" >"$tmp/moved.log"
check "... (one vertex moved)" test "$(cmp "$tmp/moved.log" "$tmp/r9-order.matswap.log" 2>&1 | wc -l)" = 1
expect "r9-order matswap, one vertex moved" "$tmp/r9-order.jsonl" "$tmp/moved.log" 1 "Mistake: unknown"

# ---- where nothing separates two mistakes: ambiguous, on both logs
for m in nearsign nearoff; do
    mistake r7-near-amb $m "ambiguous: the near plane's sign wrong or the near plane ignored"
done

# ---- ... and the scene diff prints to tell them apart (dseparate.c): it is
# r7-near-amb-sep.scene, made once, whose logs the course's renderer printed
# with each student's Java (README.md); on it each student is named alone
for m in nearsign nearoff; do
    "$exe" diff "$tmp/r7-near-amb.jsonl" "$tmp/r7-near-amb.$m.log" >"$tmp/out" 2>&1
    sed -n '/^#---- begin separating scene ----$/,/^#---- end separating scene ----$/p' "$tmp/out" |
        sed '1d;$d' >"$tmp/sep.scene"
    check "sep-1 r7-near-amb $m: a separating scene printed between its markers" test -s "$tmp/sep.scene"
    check "sep-2 ... $data/r7-near-amb-sep.scene is that scene (else store it again and remake its logs: README.md)" \
        cmp -s "$tmp/sep.scene" "$data/r7-near-amb-sep.scene"
    "$exe" diff "$tmp/r7-near-amb.jsonl" "$tmp/r7-near-amb.$m.log" --separating-scene "$tmp/sep-file.scene" >/dev/null 2>&1
    check "sep-3 ... --separating-scene FILE writes it" cmp -s "$tmp/sep-file.scene" "$data/r7-near-amb-sep.scene"
done
mistake r7-near-amb-sep nearsign "the near plane's sign wrong"
mistake r7-near-amb-sep nearoff "the near plane ignored"
"$exe" diff "$tmp/r7-near-amb.jsonl" "$tmp/r7-near-amb.nearoff.log" --separating-scene "$tmp/r7-near-amb.jsonl" >"$tmp/out" 2>&1; rc=$?
check "sep-4 --separating-scene over EXPECTED: refused, exit 2 ($rc)" \
    sh -c 'test "$1" = 2 && grep -qF "names EXPECTED" "$2" && head -c 1 "$3" | grep -q "{"' _ "$rc" "$tmp/out" "$tmp/r7-near-amb.jsonl"

# ---- every other ambiguity of the catalogue the course's students can
# make: two mistakes of one stage that give the same log on a scene made for
# it (README.md says how), and the separating scene diff prints for them,
# stored with the logs each student's Java printed for it.  On it each
# student is named alone; the right log passes (the loop above).
#   sepcase ID AMB M1 M2 NAME1 NAME2: AMB's logs of M1 and M2 both give
#   "ambiguous: NAME1 or NAME2" and print AMB-sep.scene; on AMB-sep each is
#   named with its own mistake.
sepcase() {
    sid=$1 amb=$2 m1=$3 m2=$4 n1=$5 n2=$6
    for m in $m1 $m2; do
        mistake "$amb" "$m" "ambiguous: $n1 or $n2"
        "$exe" diff "$tmp/$amb.jsonl" "$tmp/$amb.$m.log" >"$tmp/out" 2>&1
        check "$sid-1 $amb $m: no 'No separating scene'" test "$(grep -c '^No separating scene' "$tmp/out")" = 0
        sed -n '/^#---- begin separating scene ----$/,/^#---- end separating scene ----$/p' "$tmp/out" |
            sed '1d;$d' >"$tmp/sep.scene"
        check "$sid-2 ... $data/$amb-sep.scene is the scene printed (else store it again and remake its logs: README.md)" \
            cmp -s "$tmp/sep.scene" "$data/$amb-sep.scene"
        "$exe" "$tmp/sep.scene" --format kraft --kraft-debug all --trace "$tmp/sep.log" >/dev/null 2>&1
        check "$sid-3 ... it parses and renders as the course's renderer does" \
            cmp -s "$tmp/sep.log" "$tmp/$amb-sep.right.log"
    done
    mistake "$amb-sep" "$m1" "$n1"
    mistake "$amb-sep" "$m2" "$n2"
    check "$sid-4 $amb-sep $m1 against $m2's log: they differ (exit 1)" \
        sh -c '"$1" diff "$2" "$3" >/dev/null 2>&1; test $? = 1' _ "$exe" "$tmp/$amb-sep.$m1.log" "$tmp/$amb-sep.$m2.log"
}
# the camera: every vertex on one line through the eye where a skew mistake
# and a size mistake agree; the scene keeps the asymmetric rectangle
sepcase sep-5 r7-cam-amb1 skew0 halfsize "the skew forgotten" "scaled by the width, not the half-width"
sepcase sep-6 r7-cam-amb2 skewneg doublesize "the skew's sign wrong" "scaled by the half-width twice"
sepcase sep-7 r7-cam-amb3 skew0 doublesize "the skew forgotten" "scaled by the half-width twice"
sepcase sep-8 r7-cam-amb4 skewneg halfsize "the skew's sign wrong" "scaled by the width, not the half-width"
# orthographic: the line is parallel to the z axis
sepcase sep-9 r7-cam-amb-ortho skew0 halfsize "the skew forgotten" "scaled by the width, not the half-width"
# renderer 9: the same, with its normalization matrix
sepcase sep-10 r9-cam-amb skew0 halfsize "the skew forgotten" "scaled by the width, not the half-width"
# the clip's and the near clip's colours: one byte apart, cut where the
# inside (kept) end's colour and the bytes truncated agree
sepcase sep-11 r7-clip-amb clipkept clipbytes "the clip's colour not interpolated" "the clip's colour interpolated in bytes"
# ... and the separating scenes tell the listed mistakes from the stage's
# others too: the other camera and clip students, each named alone on them
mistake r7-cam-amb1-sep skewneg "the skew's sign wrong"
mistake r7-cam-amb1-sep doublesize "scaled by the half-width twice"
mistake r7-clip-amb-sep clipt "the clip's t from the other coordinate"
mistake r7-clip-amb-sep clipswap "the clip's edges swapped"
sepcase sep-12 r7-near-amb-col nearkept nearbytes "the near clip's colour not interpolated" "the near clip's colour interpolated in bytes"
# its scene is r7-near-amb-sep's (one segment from z = -2.1 to 0.5): the near
# clip's other students on it, each named alone
mistake r7-near-amb-col-sep nearsign "the near plane's sign wrong"
mistake r7-near-amb-col-sep nearoff "the near plane ignored"
mistake r7-near-amb-col-sep neart "the near clip's t from y"

# the world stage: a half turn (its own transpose) and a translation of
# 0.00004, which a log's 5 decimals nearly hide: against the right log both
# world mistakes fit (against pipetrace's exact traces each is named alone);
# the scene printed has a rotation and a translation of a few units
wa="the matrices multiplied in the wrong order" wb="the matrix-vector product transposed"
for m in matswap mattrans; do
    unz r9-world-amb.$m
    expect "sep-13 r9-world-amb $m vs the right log" "$tmp/r9-world-amb.right.log" "$tmp/r9-world-amb.$m.log" 1 "Mistake: ambiguous: $wa or $wb"
    "$exe" diff "$tmp/r9-world-amb.right.log" "$tmp/r9-world-amb.$m.log" >"$tmp/out" 2>&1
    sed -n '/^#---- begin separating scene ----$/,/^#---- end separating scene ----$/p' "$tmp/out" |
        sed '1d;$d' >"$tmp/sep.scene"
    check "sep-13.2 ... $data/r9-world-amb-sep.scene is the scene printed" cmp -s "$tmp/sep.scene" "$data/r9-world-amb-sep.scene"
    "$exe" "$tmp/sep.scene" --format kraft --kraft-debug all --trace "$tmp/sep.log" >/dev/null 2>&1
    check "sep-13.3 ... it parses and renders as the course's renderer does" cmp -s "$tmp/sep.log" "$tmp/r9-world-amb-sep.right.log"
done
expect "sep-13.4 r9-world-amb matswap vs jsonl: named alone" "$tmp/r9-world-amb.jsonl" "$tmp/r9-world-amb.matswap.log" 1 "Mistake: $wa"
expect "sep-13.5 r9-world-amb mattrans vs jsonl: named alone" "$tmp/r9-world-amb.jsonl" "$tmp/r9-world-amb.mattrans.log" 1 "Mistake: $wb"
mistake r9-world-amb-sep matswap "$wa"
mistake r9-world-amb-sep mattrans "$wb"

# ---- the first stage that differs, and its counts
"$exe" diff "$tmp/r7-skew-aa.jsonl" "$tmp/r7-skew-aa.skew0.log" >"$tmp/out" 2>&1
check "first stage: camera, 8 of 8" grep -qF "First stage that differs: camera (8 of 8 vertices)." "$tmp/out"
check "the view stage agrees" grep -qE "^  view +8 compared, 0 differ$" "$tmp/out"
"$exe" diff "$tmp/r7-near.jsonl" "$tmp/r7-near.clipkept.log" >"$tmp/out" 2>&1
check "first stage: clip, its new vertices" grep -qF "First stage that differs: clip (4 of 4 vertices)." "$tmp/out"
check "... numbered old count + k (v11)" grep -qE "^  near v11 clip: +rgb" "$tmp/out"
"$exe" diff "$tmp/r7-near.jsonl" "$tmp/r7-near.nearoff.log" >"$tmp/out" 2>&1
check "nearclip: made only in EXPECTED" grep -qE "^  nearclip +0 compared, 0 differ; 2 only in EXPECTED, 0 only in ACTUAL$" "$tmp/out"
"$exe" diff "$tmp/r7-skew-aa.jsonl" "$tmp/r7-skew-aa.gamma0.log" >"$tmp/out" 2>&1
check "the pixels: 0 vertices differ, the colours do" grep -qF "First stage that differs: the pixels (every vertex agrees)." "$tmp/out"

# ---- no pixels on one side: NOT PROVEN, exit 3 (0 without --verdict)
unz r7-skew-aa.nopixels
expect "no pixel lines" "$tmp/r7-skew-aa.jsonl" "$tmp/r7-skew-aa.nopixels.log" 3 "Verdict: NOT PROVEN"
check "... says the pixels were not compared" grep -qF "Not compared: the pixels (ACTUAL has no rasterizer lines)." "$tmp/out"
"$exe" diff "$tmp/r7-skew-aa.nopixels.log" "$tmp/r7-skew-aa.nopixels.log" >"$tmp/out" 2>&1
check "... neither side with pixel lines: said so" grep -qF "Not compared: the pixels (neither has rasterizer lines)." "$tmp/out"
"$exe" diff "$tmp/r7-skew-aa.jsonl" "$tmp/r7-skew-aa.nopixels.log" >/dev/null 2>&1
check "... exit 0 without --verdict" test $? = 0
"$exe" diff "$tmp/r7-skew-aa.jsonl" "$tmp/r7-skew-aa.skew0.log" >/dev/null 2>&1
check "a difference: exit 1 without --verdict" test $? = 1
"$exe" "$data/r7-skew-aa.scene" --format csv --trace "$tmp/r7.csv"
expect "CSV (no pixels)" "$tmp/r7-skew-aa.jsonl" "$tmp/r7.csv" 3 "Verdict: NOT PROVEN"

# ---- lines diff does not know: skipped and counted
{ echo "student: hello"; cat "$tmp/r7-skew-aa.right.log"; echo "student: bye"; } >"$tmp/chatty.log"
expect "a student's own lines" "$tmp/r7-skew-aa.jsonl" "$tmp/chatty.log" 0 "Verdict: PASS"
check "... counted in a note" grep -qF "Note: 2 lines of ACTUAL not read (the first: line 1)." "$tmp/out"

# ---- a log against a log: the stage values at 5 decimals
expect "log vs log" "$tmp/r9-view-skew.right.log" "$tmp/r9-view-skew.right.log" 0 "Verdict: PASS"

# ---- the course's own logs of tests/course79 (the jar's, every debug level,
# renderer 9's Pipeline2): each agrees with pipetrace's trace of its scene
for sc in tests/course79/*.scene; do
    n=$(basename "$sc" .scene)
    "$exe" "$sc" --format jsonl --trace "$tmp/c.jsonl" 2>/dev/null
    gzip -dc "tests/course79/$n.log.gz" >"$tmp/c.log"
    "$exe" diff --verdict "$tmp/c.jsonl" "$tmp/c.log" >"$tmp/out" 2>&1; rc=$?
    case $n in
    *deflog*|*posclip|*pipe2-two-models-pos) check "course79 $n: NOT PROVEN, no pixel lines (exit $rc)" test "$rc" = 3 ;;
    *) check "course79 $n: PASS (exit $rc)" test "$rc" = 0 ;;
    esac
done

# ---- trouble: renderers that do not match, a renderer 4 trace, bad lines
run diff "$tmp/r7-skew-aa.jsonl" "$tmp/r9-view-skew.jsonl"
check "renderer 7 against 9: exit 2" test "$rc" = 2
check "... says so" grep -qF "EXPECTED is of renderer 7, ACTUAL of renderer 9" "$tmp/err"
"$exe" tests/data/tri.obj >/dev/null 2>&1
"$exe" --format jsonl --trace "$tmp/r4.jsonl" >/dev/null 2>&1
run diff "$tmp/r4.jsonl" "$tmp/r7-skew-aa.jsonl"
check "renderer 4 against 7: exit 2" test "$rc" = 2
sed '5s/"v":[0-9]*,//' "$tmp/r7-skew-aa.jsonl" >"$tmp/bad.jsonl"
run diff "$tmp/r7-skew-aa.jsonl" "$tmp/bad.jsonl"
check "a vertex record without v: exit 2" test "$rc" = 2
check "... FILE:LINE:COL: error:" grep -qF "bad.jsonl:5:1: error: a vertex record without its number v" "$tmp/err"
sed 's/^\(1\. View *: vIndex = *3, \).*/\1(x,y,z) = (/' "$tmp/r7-skew-aa.right.log" >"$tmp/bad.log"
run diff "$tmp/r7-skew-aa.jsonl" "$tmp/bad.log"
check "a log's vertex without numbers: exit 2" test "$rc" = 2
check "... FILE:LINE:COL: error:" grep -qE "bad.log:[0-9]+:1: error: a vIndex line without x, y and z" "$tmp/err"

# ---- images beside: the student's PPM against pipetrace's image
"$exe" "$data/r7-skew-aa.scene" --image "$tmp/want.ppm" >/dev/null
gzip -dc "$data/r7-skew-aa.gamma0.ppm.gz" >"$tmp/got.ppm"
run diff "$tmp/want.ppm" "$tmp/got.ppm"
check "images: the gamma student's differs (exit 1)" test "$rc" = 1
run diff "$tmp/want.ppm" "$tmp/want.ppm"
check "images: the same (exit 0)" test "$rc" = 0

report
