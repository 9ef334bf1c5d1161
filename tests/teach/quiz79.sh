#!/bin/sh
# tests/teach/quiz79.sh -- pipetrace quiz on scenes of the course's renderers 7 and 9
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/quiz79.sh PIPETRACE.  Run from the repository root.
# The answer keys are the quiz's own "go on with" lines for a sheet of zeros;
# each check then changes one answer, or moves a vertex in a copy of the scene
# to make the answers a slip carries forward.
exe=$1
. tests/lib/testlib.sh
near=tests/course79/r7-near-01.scene
corner=docs/exercises/13-corner.scene
r9=docs/exercises/16-r9-whole.scene

key() {     # key FILE ARGS...: the right answers, one a line, into FILE
    f=$1; shift
    yes 0 | head -20 | "$exe" quiz "$@" 2>/dev/null | sed -n 's/^  go on with [^=]*= //p' > "$f"
}

# ---- a right sheet scores full, on standard input and graded
key "$tmp/near7" $near --vertex 7
check "quiz79-1.1 renderer 7, vertex 7: nine questions" test "$(wc -l < "$tmp/near7")" = 9
feed "$(cat "$tmp/near7")\n" quiz $near --vertex 7
check "quiz79-1.2 the key on standard input: exit 0" test "$rc" = 0
check "quiz79-1.3 ... score 9/9" grep -qx "score: 9/9" "$tmp/out"
check "quiz79-1.4 ... the near clip's t and point" grep -qx "  correct: 0.9259114139691406 0.057315176907822764 0.3276442556526084 -0.1" "$tmp/out"
check "quiz79-1.5 ... the clip's edge" grep -qx "  correct: y=+1 0.6788668532392984 0.3014224170801599 1" "$tmp/out"
check "quiz79-1.6 ... the colour is the trace's pixel there" \
    sh -c "\"$exe\" $near | grep -q 'x_fb = 40  y_fb = 0  rgb = 182 145 213'"
check "quiz79-1.7 ... and the quiz's" grep -qx "  correct: 182 145 213" "$tmp/out"
mkdir "$tmp/g1"
cp "$tmp/near7" "$tmp/g1/right.txt"
run quiz $near --vertex 7 --grade "$tmp/g1"
check "quiz79-1.8 graded: full score, exit 0" test "$rc" = 0
check "quiz79-1.9 ... the row" grep -qx "right.txt,1,1,1,1,1,1,1,1,1,9,9," "$tmp/out"
check "quiz79-1.10 ... the header names the stages" grep -qx "sheet,model,view,camera,nearclip,image,clip,pixel,viewport,color,right,of,note" "$tmp/out"

# ---- each wrong answer costs its stage, and only it
mkdir "$tmp/g2"
i=1
while [ $i -le 9 ]; do
    awk -v k=$i 'NR == k { if ($1 ~ /^[xy]=/) $1 = ($1 == "x=+1" ? "x=-1" : "x=+1"); else $NF = $NF + 3 } { print }' "$tmp/near7" > "$tmp/g2/wrong$i.txt"
    i=$((i + 1))
done
run quiz $near --vertex 7 --grade "$tmp/g2"
check "quiz79-2.1 one wrong answer a sheet: exit 1" test "$rc" = 1
i=1; ok=1
while [ $i -le 9 ]; do
    row=$(grep "^wrong$i.txt," "$tmp/out")
    want=$(awk -v k=$i 'BEGIN { s = ""; for (j = 1; j <= 9; j++) s = s "," (j == k ? "0" : "1"); print s ",8,9," }')
    [ "$row" = "wrong$i.txt$want" ] || { ok=0; echo "  $row"; }
    i=$((i + 1))
done
check "quiz79-2.2 ... each costs its own stage: 8 of 9" test $ok = 1

# ---- follows: a slip carried forward costs one stage
sed 's/^v 0.01524416825611219 /v 0.02 /' $near > "$tmp/slip.scene"
key "$tmp/slip" "$tmp/slip.scene" --vertex 7
mkdir "$tmp/g3"
{ sed -n 1,2p "$tmp/near7"; sed -n 3,9p "$tmp/slip"; } > "$tmp/g3/slip.txt"
run quiz $near --vertex 7 --grade "$tmp/g3"
check "quiz79-3.1 a slip at camera: nearclip, image, clip and pixel follow" \
    grep -qx "slip.txt,1,1,0,follows,follows,follows,follows,1,1,8,9," "$tmp/out"
key "$tmp/r9" $r9 --vertex 1
check "quiz79-3.2 renderer 9: ten questions, world first" test "$(wc -l < "$tmp/r9")" = 10
sed 's/^matrix translate 0 0.25 -3$/matrix translate 0 0.5 -3/' $r9 > "$tmp/slip9.scene"
key "$tmp/slip9" "$tmp/slip9.scene" --vertex 1
mkdir "$tmp/g4"
{ sed -n 1p "$tmp/r9"; sed -n 2,5p "$tmp/slip9"; } > "$tmp/g4/world.txt"
run quiz $r9 --vertex 1 --grade "$tmp/g4"
check "quiz79-3.3 renderer 9: a slip at world, view and camera follow" \
    grep -qx "world.txt,1,0,follows,follows,1,,,,,,4,10," "$tmp/out"
mkdir "$tmp/g5"
awk 'NR == 8 { $1 = $1 + 0.6 } NR == 9 { $1 = $1 + 1 } { print }' "$tmp/r9" > "$tmp/g5/pixel.txt"
run quiz $r9 --vertex 1 --grade "$tmp/g5"
check "quiz79-3.4 a slip at pixel: the viewport follows by Java's rounding" \
    grep -qx "pixel.txt,1,1,1,1,1,1,1,0,follows,1,9,10," "$tmp/out"
key "$tmp/end" $r9 --vertex 2
"$exe" $r9 | grep ' pixel ' | tail -1 > "$tmp/last"
check "quiz79-3.5 the viewport (the reference pixel stage's rounding) is the rasterizer's end pixel" \
    test "$(sed -n 9p "$tmp/end")" = "39 27" -a -n "$(grep -F 'x_fb = 43  y_fb = 30  rgb = 144 144 128' "$tmp/last")"
check "quiz79-3.6 ... with the raw colour the quiz gives" test "$(sed -n 10p "$tmp/end")" = "144 144 128"

# ---- a corner: two cuts, two questions; near clip: dropped; none
key "$tmp/corner" $corner --vertex 2
check "quiz79-4.1 a corner: clip at x=+1" grep -qx "x=+1 0.3333333333333333 1 1.2000000000000002" "$tmp/corner"
check "quiz79-4.2 ... then clip2 at y=+1" grep -q "^y=+1 0.16666666666666" "$tmp/corner"
run quiz $corner --vertex 2 --grade "$tmp/g1"
check "quiz79-4.3 ... its header has clip2" grep -q "^sheet,model,view,camera,nearclip,image,clip,clip2,pixel," "$tmp/out"
key "$tmp/drop" $near --vertex 3
check "quiz79-4.4 a segment behind the near plane: dropped, and no more questions" \
    test "$(tail -1 "$tmp/drop")" = dropped -a "$(wc -l < "$tmp/drop")" = 4
key "$tmp/none" $corner --vertex 1
check "quiz79-4.5 an end the cuts leave: none" test "$(sed -n 4p "$tmp/none")" = none
feed "$(cat "$tmp/corner")\n" quiz $corner --vertex 2 --json
check "quiz79-4.6 --json" grep -q '"stage":"clip2","score":1}.*"right":10,"answered":10,"of":10}' "$tmp/out"
feed "$(sed -n 6p "$tmp/corner")\n" quiz $corner --vertex 2 --stage clip2
check "quiz79-4.7 --stage clip2, given clip" grep -q "^given: clip: edge t x y = x=+1 " "$tmp/out"
check "quiz79-4.8 ... wrong answer: exit 1" test "$rc" = 1
run quiz $corner --vertex 2 --stage index
check "quiz79-4.9 --stage of renderer 4 on renderer 7: its questions listed" \
    grep -q "no such question.*(its questions: model, view, camera, nearclip, image, clip, clip2, pixel, viewport, color)" "$tmp/err"
run quiz docs/examples/triangle.scene --vertex 1 --stage nearclip
check "quiz79-4.10 --stage nearclip on renderer 4: usage error" test "$rc" = 1

# ---- bad sheets: FILE:LINE:COL
mkdir "$tmp/g6"
printf '# my answers\n\n%s\n  %s\n0 0 zero\n' "$(sed -n 1p "$tmp/near7")" "$(sed -n 2p "$tmp/near7")" > "$tmp/g6/bad.txt"
run quiz $near --vertex 7 --grade "$tmp/g6"
check "quiz79-5.1 an unreadable answer: exit 2" test "$rc" = 2
check "quiz79-5.2 ... FILE:LINE:COL: error" grep -qx "$tmp/g6/bad.txt:5:5: error: camera (x_c y_c z_c): not a number" "$tmp/err"
check "quiz79-5.3 ... the row, with the note" grep -qx "bad.txt,1,1,0,,,,,,,2,9,line 5: camera (x_c y_c z_c): not a number" "$tmp/out"
rm "$tmp/g6/bad.txt"
{ cat "$tmp/corner"; echo "1 2 3"; } > "$tmp/g6/long.txt"
printf 'x=+1 1 2\n' > "$tmp/g6/short.txt"
run quiz $corner --vertex 2 --grade "$tmp/g6"
check "quiz79-5.4 too many answers: said at the extra line" grep -q "long.txt:11:1: error: more answers than the quiz's 10 questions" "$tmp/err"
check "quiz79-5.5 an edge where a number goes" grep -q "short.txt:1:1: error: model (x_m y_m z_m): not a number" "$tmp/err"
mkdir "$tmp/g7"
printf '%s\n' "$(sed -n 6p "$tmp/corner" | cut -d' ' -f1-3)" > "$tmp/g7/few.txt"
run quiz $corner --vertex 2 --stage clip --grade "$tmp/g7"
check "quiz79-5.6 too few values: the column after the last" grep -q "few.txt:1:.*: error: clip (edge t x y): fewer values than the stage has" "$tmp/err"

# ---- a sheet of renderer 4's quiz on a renderer 9 scene
mkdir "$tmp/g8"
printf -- '-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.4975 2.9988\n4 7\n4 7\n144\n' > "$tmp/g8/r4.txt"
run quiz $r9 --vertex 1 --grade "$tmp/g8"
check "quiz79-6.1 a renderer 4 sheet on a renderer 9 scene: exit 2" test "$rc" = 2
check "quiz79-6.2 ... told clearly" grep -q "r4.txt: error: a sheet of renderer 4's quiz (model, camera, image, pixel, viewport, framebuffer, index); this scene is the course's renderer 9, whose quiz asks model, world, view," "$tmp/err"
check "quiz79-6.3 ... its row scores nothing" grep -q "^r4.txt,,,,,,,,,,,0,10," "$tmp/out"

# ---- what stays: renderer 4's quiz, an unused vertex, a hidden model
printf 'renderer 7\nframebuffer 10 10\nmodel m\nv 0 0 -1\nv 1 0 -1\nv 0 1 -1\nsegment 1 2\n' > "$tmp/u.scene"
key "$tmp/u" "$tmp/u.scene" --vertex 3
check "quiz79-7.1 a vertex no segment uses: model to image, four questions" test "$(wc -l < "$tmp/u")" = 4
printf 'renderer 7\nframebuffer 10 10\nmodel m\nhidden-model\nv 0 0 -1\nv 1 0 -1\nsegment 1 2\n' > "$tmp/h.scene"
run quiz "$tmp/h.scene" --vertex 1
check "quiz79-7.2 a hidden model: said, exit 2" test "$rc" = 2 -a -n "$(grep 'is hidden' "$tmp/err")"
feed '\n' quiz $near --seed 5
check "quiz79-7.3 --seed picks a vertex of renderer 7" grep -q "(picked with --seed 5)" "$tmp/out"

feed 'banana\n1.5 1.8 0\n' quiz $corner --vertex 2 --interactive
check "quiz79-7.4 --interactive: an unreadable answer is asked again, with its column" \
    grep -q "(not read: column 1: not a number; write x_m y_m z_m," "$tmp/out"
check "quiz79-7.5 ... and costs nothing" grep -qx "score: 1/1 (input ended after 1 of 10 stages)" "$tmp/out"
feed '1.5 1.8 0\n1 1 1 1\n' quiz $corner --vertex 2
check "quiz79-7.6 from a file: an unreadable answer is wrong for its stage, with its column" \
    grep -qx "  wrong: column 7: more values than the stage has" "$tmp/out"

# ---- a wrong answer shows its stage's formula with the numbers put in, as
# pipetrace step does; each worked line evaluates (awk, in double) to the key
# worked QUESTION NAME KEY: in $tmp/out's answer to QUESTION, the line
# "NAME = FORMULA = EXPR = RESULT" with EXPR numbers only, EXPR == RESULT == KEY
worked() {
    line=$(sed -n "/^$1: /,/^  go on with/p" "$tmp/out" | grep -m1 "^    $2 = ") || return 1
    expr=$(printf '%s\n' "$line" | awk -F ' = ' '{ print $(NF - 1) }')
    res=$(printf '%s\n' "$line" | awk -F ' = ' '{ print $NF }')
    case $expr in *[!-0-9.e+*/\(\)\ ]*|'') return 1 ;; esac
    awk "BEGIN { v = $expr; exit !(v == $res && $res == $3) }"
}
kv() { sed -n "$2p" "$1" | cut -d' ' -f"$3"; }     # kv KEYFILE LINE FIELD
yes '0 0 0' | head -9 > "$tmp/zeros"
feed "$(cat "$tmp/zeros")\n" quiz $near --vertex 7
check "quiz79-8.1 a wrong camera: x_c worked out, = the key" worked camera x_c "$(kv "$tmp/near7" 3 1)"
check "quiz79-8.2 ... y_c" worked camera y_c "$(kv "$tmp/near7" 3 2)"
check "quiz79-8.3 a wrong nearclip: its t" worked nearclip t "$(kv "$tmp/near7" 4 1)"
check "quiz79-8.4 ... the new point's x" worked nearclip x "$(kv "$tmp/near7" 4 2)"
check "quiz79-8.5 a wrong image: x_p" worked image x_p "$(kv "$tmp/near7" 5 1)"
check "quiz79-8.6 a wrong clip: its t" worked clip t "$(kv "$tmp/near7" 6 2)"
check "quiz79-8.7 ... the new point's x" worked clip x "$(kv "$tmp/near7" 6 3)"
check "quiz79-8.8 a wrong pixel: x_pp" worked pixel x_pp "$(kv "$tmp/near7" 7 1)"
check "quiz79-8.9 ... y_pp" worked pixel y_pp "$(kv "$tmp/near7" 7 2)"
check "quiz79-8.10 a wrong viewport: x_vp" worked viewport x_vp "$(kv "$tmp/near7" 8 1)"
check "quiz79-8.11 the model: the scene gives it" \
    test "$(sed -n '/^model: /,/^  go on/p' "$tmp/out" | sed -n 3p)" = "  the scene gives:"
step_formula=$("$exe" step $near --vertex 7 --all | sed -n '/^stage 5 of 9: image/,/formula/s/^  formula  //p')
check "quiz79-8.12 the image's formula line is step's" \
    grep -qxF "  $step_formula" "$tmp/out"
check "quiz79-8.13 the colour: its formula, then the write that left it" \
    test "$(sed -n '/^color: /,/^  go on/p' "$tmp/out" | sed -n 3,4p | cut -c1-21)" = "$(printf '  c = (float)|c0 + sl\n    the only write at')"
r4_formula=$("$exe" step docs/examples/triangle.scene --vertex 1 --all | sed -n 's/^  formula  \(x_pp = .*\)/\1/p')
check "quiz79-8.18 the pixel formula is the stage table's (renderer 4's step), x_ip named x_p" \
    grep -qxF "  $(printf '%s\n' "$r4_formula" | sed 's/\([xy]\)_ip/\1_p/g')" "$tmp/out"
feed "$(cat "$tmp/near7")\n" quiz $near --vertex 7
check "quiz79-8.14 a right answer: no worked lines" test "$(grep -c '^    ' "$tmp/out")" = 0
feed "$(cat "$tmp/zeros")\n" quiz $r9 --vertex 1
check "quiz79-8.15 renderer 9, a wrong world: x_w = M times v_m" worked world x_w "$(kv "$tmp/r9" 2 1)"
check "quiz79-8.16 ... z_w" worked world z_w "$(kv "$tmp/r9" 2 3)"
check "quiz79-8.17 ... view subtracts the view vector" worked view x_v "$(kv "$tmp/r9" 3 1)"

# ---- the colour's numbers: the last write at the vertex's pixel in the
# whole render, each equation evaluated again (quiz79_color.py) to the key,
# the write it names the trace's last pixel record there
# colour SCENE VERTEX: a sheet of zeros; the quiz's output in $tmp/out, the
# key in $tmp/ckey, the scene's trace in $tmp/c.jsonl
colour() {
    yes '0 0 0' | head -12 | "$exe" quiz "$1" --vertex "$2" > "$tmp/out" 2>/dev/null
    sed -n '/^color: /,$s/^  go on with r g b = //p' "$tmp/out" > "$tmp/ckey"
    "$exe" "$1" --format jsonl > "$tmp/c.jsonl"
}
cworked() { python3 tests/teach/quiz79_color.py "$tmp/out" "$(cat "$tmp/ckey")" "$tmp/c.jsonl"; }
cline() { sed -n '/^color: /,/^  go on/p' "$tmp/out" | grep -q -e "$1"; }
ppmkey() {  # ppmkey FILE.ppm.gz INDEX: the bytes of pixel INDEX of the course's image
    python3 -c '
import gzip, re, sys
d = gzip.open(sys.argv[1]).read()
m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", d)
i = m.end() + 3 * int(sys.argv[2])
print(*d[i:i + 3])' "$1" "$2"
}
fbat() {    # the (x_fb, y_fb) the colour's first worked line names, as "x y"
    sed -n '/^color: /,/^  go on/p' "$tmp/out" | sed -n 's/^    the .* at (x_fb, y_fb) = (\(-*[0-9]*\), \(-*[0-9]*\)).*/\1 \2/p'
}
cube=tests/course79/r7-basic-cube-viewport.scene
colour $cube 1
check "quiz79-9.1 renderer 7, anti-aliasing off, gamma on: the worked colour evaluates to the key, the trace's last write" cworked
check "quiz79-9.2 ... overwritten: the last of 3 writes, by a later segment (v1 to v5), not the vertex's own first (v1 to v2)" \
    sh -c "grep -q 'first segment, from vertex 1 to vertex 2' '$tmp/out' && sed -n '/^color: /,/^  go on/p' '$tmp/out' | grep -q 'the last of 3 writes.*primitive 9 of the rasterizer, a segment from vertex 1 to vertex 5, its step k'"
check "quiz79-9.3 ... a step without anti-aliasing" cline "anti-aliasing off: the pixel Math.round"
set -- $(fbat)
check "quiz79-9.4 ... the key is the course's image there" \
    test "$(ppmkey tests/course79/r7-basic-cube-viewport.ppm.gz $(($2 * 300 + $1)))" = "$(cat "$tmp/ckey")"
colour tests/course79/r7-aa-00.scene 2
check "quiz79-9.5 renderer 7, anti-aliasing on: evaluates, the trace's last write" cworked
check "quiz79-9.6 ... a step's weight and blend, gamma" \
    sh -c "sed -n '/^color: /,/^  go on/p' '$tmp/out' | grep -q 'its step k = x - x0 = 61 - 3 = 58' && sed -n '/^color: /,/^  go on/p' '$tmp/out' | grep -q \"^    gamma: r' = \""
colour tests/course79/r9-aa-04.scene 3
check "quiz79-9.7 renderer 9, anti-aliasing on, a steep segment: evaluates, the trace's last write" cworked
check "quiz79-9.8 ... its DDA steps y" cline "its step k = y - y0 = .*(transposed"
colour tests/course/r9/aa-00.scene 5
check "quiz79-9.9 renderer 9, anti-aliasing on, gamma off: evaluates, the trace's last write" cworked
check "quiz79-9.10 ... gamma off said" cline "gamma off: the colour is written as it is"
colour tests/course79/r9-basic-two-models.scene 1
check "quiz79-9.11 renderer 9, anti-aliasing off: evaluates, the trace's last write" cworked
colour $near 7
check "quiz79-9.12 a segment's last pixel: evaluates, the trace's last write" cworked
check "quiz79-9.13 ... its raw colour" cline "its last pixel, coverage 1, in that end's colour as it is"
colour tests/course/r7/aa-04.scene 1
check "quiz79-9.14 a pixel left the viewport's background (an anti-aliased pair on the top row, coverage 0): evaluates, the trace's last write" cworked
check "quiz79-9.15 ... the key is the viewport's background" \
    test "$(cat "$tmp/ckey")" = "$(sed -n 's/^viewport-background //p' tests/course/r7/aa-04.scene)" -a -n "$(grep -e 'coverage 0: the write leaves the viewport' "$tmp/out")"
colour tests/course/r7/vpout-01.scene 5
set -- $(fbat)
check "quiz79-9.16 a viewport sticking out: the pixel lies right of the framebuffer (x_fb >= W)" test "$1" -ge 20
check "quiz79-9.17 ... the key is the course's image at the wrapped index y_fb*W + x_fb" \
    test "$(ppmkey tests/course/r7/vpout-01.ppm.gz $(($2 * 20 + $1)))" = "$(cat "$tmp/ckey")"
check "quiz79-9.18 ... the worked numbers evaluate to it" \
    python3 tests/teach/quiz79_color.py "$tmp/out" "$(cat "$tmp/ckey")"
check "quiz79-9.19 ... the pixel written named" cline "the pixel written is ($(($1 - 20)), $(($2 + 1))) of the array"
colour tests/course/r7/vpout-02.scene 1
check "quiz79-9.20 a pixel the course drops: none" test "$(cat "$tmp/ckey")" = none
check "quiz79-9.21 ... said as the course's log says it" \
    sh -c "line=\$(sed -n '/^color: /,/^  go on/p' '$tmp/out' | grep -o 'FrameBuffer: Bad pixel coordinate ([-0-9]*, [-0-9]*) \[w=20, h=16\]') && gzip -dc tests/course/r7/vpout-02.log.gz | grep -qF \"\$line\""
check "quiz79-9.22 ... and evaluates" python3 tests/teach/quiz79_color.py "$tmp/out" none
colour tests/course79/r9-pipe2-two-models.scene 3
check "quiz79-9.25 renderer 9's Pipeline2 (each stage over every position): evaluates, the trace's last write" cworked
colour $near 7
raster_formula=$("$exe" step $near --vertex 7 --all | sed -n '/^stage 9 of 9: raster/,/formula/s/^  formula  //p')
check "quiz79-9.23 the colour's formula line is step's raster formula" \
    test -n "$raster_formula" -a "$(sed -n '/^color: /,/^  go on/p' "$tmp/out" | sed -n 3p)" = "  $raster_formula"
check "quiz79-9.24 ... which states the step's colour, anti-aliasing, gamma and the bytes" \
    sh -c "printf '%s\n' \"\$1\" | grep -q 'c = (float)|c0 + slope\*(x - x0)|.*f\*c + (1 - f)\*bg.*Math.pow(c, 1/2.2).*255f' " - "$raster_formula"

report
