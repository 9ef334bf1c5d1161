#!/bin/sh
# tests/teach/teach.sh -- the teaching commands: step, why, quiz, and --explain
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/teach.sh PIPETRACE.  Run from the repository root.
exe=$1
. tests/lib/testlib.sh
tri=docs/examples/triangle.scene




has() {     # has LINE: $tmp/out holds exactly this line
    grep -Fxq -- "$1" "$tmp/out"
}

# ---- step: every stage at once
run step $tri --vertex 1 --all
check "teach-1.1 step --all: exit 0" test "$rc" = 0
check "teach-1.2 ... seven stages" test "$(grep -c '^stage [1-7] of 7: ' "$tmp/out")" = 7
check "teach-1.3 ... name and spaces" has "stage 4 of 7: pixel (image plane -> pixel plane)"
check "teach-1.4 ... the formula" has "  formula  x_pp = 0.5 + w/2.001 * (x_ip + 1), y_pp = 0.5 + h/2.001 * (y_ip + 1)"
check "teach-1.5 ... x_pp substituted, exact" has "  here     x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313"
check "teach-1.6 ... y_pp substituted, exact" has "           y_pp = 0.5 + h/2.001 * (y_ip + 1) = 0.5 + 10/2.001 * (-0.5 + 1) = 2.9987506246876565"
check "teach-1.7 ... camera, negative in parentheses" has "           z_c = z_m + z_t = 0 + (-2) = -2"
check "teach-1.8 ... image" has "  here     x_ip = x_c / -z_c = -1 / -(-2) = -0.5"
check "teach-1.9 ... viewport" has "           y_vp = h - round(y_pp) = 10 - round(2.9987506246876565) = 10 - 3 = 7"
check "teach-1.10 ... index" has "  here     idx = y_fb * W + x_fb = 7 * 20 + 4 = 144"
check "teach-1.11 ... note for the next stage" has "  next     inside the viewport: the rasterizer writes the pixels of its segments here"
cp "$tmp/out" "$tmp/all"
run step $tri --vertex 1
check "teach-1.12 not on a terminal: every stage at once, same bytes" cmp -s "$tmp/out" "$tmp/all"
run step docs/examples/clip.scene --vertex 1 --all
check "teach-1.13 outside: clipped note" has "  next     outside the viewport: its pixel is clipped (the rasterizer steps there but writes nothing)"
check "teach-1.14 ... no index" has "  here     idx = y_fb * W + x_fb: none, (x_fb, y_fb) = (-2, 4) lies outside the 12 x 8 framebuffer"
check "teach-1.15 ... view rectangle" has "  next     outside the view rectangle [-1, 1] x [-1, 1]: the point lies outside the viewport"
run step docs/examples/behind.scene --vertex 2 --all
check "teach-1.16 behind the camera" grep -q "^  next     behind the camera (z_c > 0): projected mirrored" "$tmp/out"
run step --vertex 3 --model floor --all
check "teach-1.17 built-in scene, unused vertex: still shown" test "$rc" = 0 -a "$(grep -c '^stage' "$tmp/out")" = 7
check "teach-1.18 ... with a note" grep -q "no segment uses vertex 3, so the renderer does not transform it" "$tmp/out"
run step docs/examples/two-models.scene --vertex 1 --all
check "teach-1.19 default model: the first with that vertex" grep -q "^pipetrace step: vertex 1 of model square in" "$tmp/out"

# ---- step: one stage at a time (--interactive forces the loop through a pipe)
feed '\n\nb\nq\n' step $tri --vertex 1 --interactive
check "teach-2.1 interactive: exit 0" test "$rc" = 0
check "teach-2.2 Enter, Enter, b, q: stages 1 2 3 2" test "$(grep '^stage' "$tmp/out" | cut -c7 | tr -d '\n')" = 1232
check "teach-2.3 ... a prompt per stage shown" test "$(grep -c 'b back, q quit: ' "$tmp/out")" = 4
feed '\n\n\n\n\n\n\n' step $tri --vertex 1 --interactive
check "teach-2.4 Enter after the last stage ends" test "$rc" = 0 -a "$(grep -c '^stage' "$tmp/out")" = 7
feed 'x\n' step $tri --vertex 1 --interactive
check "teach-2.5 other input: help, then end of input ends" test "$rc" = 0 -a "$(grep -c '^(Enter: next stage, 1-7: that stage, b: back, q: quit)' "$tmp/out")" = 1

# ---- step: errors
run step --vertex 0
check "teach-3.1 --vertex 0: exit 1" test "$rc" = 1
run step --all --interactive
check "teach-3.2 --all with --interactive: exit 1" test "$rc" = 1
run step $tri --vertex 9
check "teach-3.3 no such vertex: exit 2" test "$rc" = 2
check "teach-3.3.1 ... the message names --vertex" grep -q "^pipetrace step: --vertex 9: no model of $tri has a vertex 9 (the largest has 3)" "$tmp/err"
run step --vertex 7 --model pyramid
check "teach-3.3.2 the named model has no such vertex: said so" \
    test "$rc" = 2 -a -n "$(grep '^pipetrace step: --vertex 7: model pyramid of <builtin> has no vertex 7 (it has 5)' "$tmp/err")"
run step $tri --model nosuch
check "teach-3.4 no such model: exit 2" test "$rc" = 2
check "teach-3.4.1 ... the message names --model" grep -q "^pipetrace step: --model nosuch: $tri has no model 'nosuch' (its models: tri)" "$tmp/err"
printf 'framebuffer 20 10\nmodel m\ntranslate 0 0 -2\nv 1e300 0 0\nv 0 0 0\nl 1 2\n' > "$tmp/far.scene"
run step "$tmp/far.scene" --vertex 1 --all
check "teach-3.6 x_pp beyond 2^62: y_vp computed, and x_vp named as the one without a value" \
    has "           y_vp = h - round(y_pp) = 10 - round(5.497501249375313) = 10 - 5 = 5, but the viewport pixel has no value: x_vp has none (x_pp is beyond 2^62)"
printf 'model m\nv 1 2\n' > "$tmp/bad.scene"
run step "$tmp/bad.scene"
check "teach-3.5 bad scene: exit 2 with FILE:LINE:COL" test "$rc" = 2 -a -n "$(grep "^$tmp/bad.scene:2:" "$tmp/err")"

# ---- quiz
feed '-1 -1 0\n-1, -1, -2\n0.5 -0.5 -1\n5.4975012 2.9987506\n4.0 7\n4 7\n144\n' quiz $tri --vertex 1
check "teach-4.1 quiz with one answer wrong: exit 1" test "$rc" = 1
check "teach-4.2 ... prompt line" grep -q "^camera: x_c y_c z_c = ? -1, -1, -2$" "$tmp/out"
check "teach-4.3 ... states the tolerance" grep -q "within 1e-6 absolute or 1e-6 relative" "$tmp/out"
check "teach-4.4 ... six right" test "$(grep -c '^  correct: ' "$tmp/out")" = 6
check "teach-4.5 ... one wrong, explained" has "    x_ip = x_c / -z_c = -1 / -(-2) = -0.5"
check "teach-4.6 ... and the quiz goes on from the right value" has "  go on with (x_ip, y_ip, z_ip) = (-0.5, -0.5, -1)"
check "teach-4.7 ... score" has "score: 6/7"
feed '1 1 1\n4.4 7\n' quiz $tri --vertex 1
check "teach-4.8 end of input: the score so far" has "score: 0/2 (input ended after 2 of 7 stages)"
feed '-2 0 0\n-2 0 0\n-2 0 0\n-3.49800099950025 2.499000499750125\n-4 2\n-2 4\nnone\n' quiz docs/examples/clip.scene --vertex 1
check "teach-4.9 'none' answers a missing index" test "$(grep -c '^  correct: ' "$tmp/out")" = 7
check "teach-4.10 ... score 7/7, exit 0" test "$rc" = 0 -a -n "$(grep -x "score: 7/7" "$tmp/out")"
feed '1 2\n' quiz $tri --vertex 1
check "teach-4.11 wrong count of numbers: wrong" grep -q "^  wrong: expected 3 numbers" "$tmp/out"
feed '' quiz --seed 7
cp "$tmp/out" "$tmp/seed7"
check "teach-4.12 --seed picks a used vertex" grep -q "^pipetrace quiz: vertex [0-9]* of model [a-z]* in <builtin> (picked with --seed 7)$" "$tmp/out"
feed '' quiz --seed 7
check "teach-4.13 ... the same one every time" cmp -s "$tmp/out" "$tmp/seed7"
run quiz --seed 7 --vertex 1
check "teach-4.14 --seed with --vertex: exit 1" test "$rc" = 1
run quiz $tri --vertex 4
check "teach-4.15 no such vertex: exit 2" test "$rc" = 2
check "teach-4.16 ... naming --vertex" grep -q "^pipetrace quiz: --vertex 4: no model of $tri has a vertex 4" "$tmp/err"
run quiz $tri --model nosuch
check "teach-4.17 no such model: exit 2, naming --model" test "$rc" = 2 -a -n "$(grep "^pipetrace quiz: --model nosuch: " "$tmp/err")"
feed 'x\n' quiz $tri --vertex 1
check "teach-4.18 not numbers at the model stage: no 'or none' (it always has values)" has "  wrong: expected 3 numbers"
feed '-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.5 3\nx\n' quiz $tri --vertex 1
check "teach-4.19 ... at the viewport stage 'none' is an answer" has "  wrong: expected 2 numbers, or none"

# ---- why
run why $tri 4 7
check "teach-5.1 why, lit pixel: exit 0" test "$rc" = 0
check "teach-5.2 ... both segments through it" test "$(grep -c '^  tri s[13] (v' "$tmp/out")" = 2
check "teach-5.3 ... each vertex's journey, model to index" has "    v1  model (-1, -1, 0) -> camera (-1, -1, -2) -> image (-0.5, -0.5, -1)"
check "teach-5.3.1 ... on to the pixel plane and the viewport" has "        -> pixel (5.497501249375313, 2.9987506246876565) -> viewport (4, 7)"
check "teach-5.3.2 ... and to the index" has "        -> framebuffer (4, 7) -> index 144"
check "teach-5.3.3 ... both vertices of both segments" test "$(grep -c '^        -> framebuffer' "$tmp/out")" = 4
check "teach-5.4 ... the color and who set it" has "color 255 255 255: tri s3 is the last segment drawn there"
run why $tri 10 2
check "teach-5.5 unlit: endpoints rounded elsewhere" grep -q "^    lost at raster: endpoints rounded elsewhere: .* (x_fb, y_fb) = (9, 2)$" "$tmp/out"
run why docs/examples/clip.scene 1 4
check "teach-5.6 clipped by the viewport (exact step)" grep -q "^    lost at viewport: clipped by the viewport: one of its steps lands on this pixel, (x_vp, y_vp) = (-1, 2)" "$tmp/out"
run why docs/examples/clip.scene 0 0
check "teach-5.7 outside the viewport" grep -q "^    lost at viewport: outside the viewport" "$tmp/out"
run why docs/examples/behind.scene 12 6
check "teach-5.8 behind the camera" grep -q "^    lost at image: behind the camera: v2 has z_c = 2 > 0" "$tmp/out"
printf 'framebuffer 20 10\nmodel d\ntranslate 0 0 -2\nv 0 0 0\nv 0.0001 0 0\nl 1 2\nmodel s\nv 1 1 0\nv 0 0 -2\nl 1 2\n' > "$tmp/odd.scene"
run why "$tmp/odd.scene" 0 0
check "teach-5.9 degenerate" grep -q "^    lost at raster: degenerate: .* at (x_fb, y_fb) = (9, 5)$" "$tmp/out"
check "teach-5.10 an end at -inf (renderer 4 rounds it to -2^63 and steps from INT_MIN): all clipped" grep -q "^    lost at viewport: clipped by the viewport: all 2147483659 of its steps lie outside the viewport" "$tmp/out"
run why $tri 20 0
check "teach-5.11 pixel outside the framebuffer: exit 2" test "$rc" = 2
run why $tri x 0
check "teach-5.12 not a number: exit 1" test "$rc" = 1
run why 200 150
check "teach-5.13 built-in scene" test "$rc" = 0
# Every pixel of the triangle: why says "lit" exactly where the renderer draws.
"$exe" $tri --format jsonl --stage raster | grep '"type":"pixel"' |
    sed 's/.*"x":\([0-9]*\),"y":\([0-9]*\).*/\1 \2/' | sort -u > "$tmp/drawn"
: > "$tmp/lit"
y=0
while [ $y -lt 10 ]; do
    x=0
    while [ $x -lt 20 ]; do
        "$exe" why $tri $x $y | grep -q '^lit by:' && echo "$x $y" >> "$tmp/lit"
        x=$((x + 1))
    done
    y=$((y + 1))
done
sort -u "$tmp/lit" -o "$tmp/lit"
check "teach-5.14 lit pixels = the renderer's pixels, all 200" cmp -s "$tmp/lit" "$tmp/drawn"
run why 400 300
check "teach-5.15 outside the framebuffer: the message names X_FB Y_FB" \
    test "$rc" = 2 -a -n "$(grep '^pipetrace why: X_FB Y_FB = 400 300: the pixel lies outside the 400 x 300 framebuffer' "$tmp/err")"

# ---- why: its model left out (--model, as the render command leaves models out)
# (226, 168) of the built-in scene: the pyramid lights it, the cube does not
"$exe" --model cube --stage raster | grep -c ' x_fb = *226 *y_fb = *168 ' > "$tmp/n"
check "teach-5.16 (the render command: --model cube traces no pixel record there)" test "$(cat "$tmp/n")" = 0
run why --model pyramid 226 168
check "teach-5.17 why --model pyramid: lit by the pyramid" test "$rc" = 0 -a -n "$(grep '^lit by:' "$tmp/out")"
run why 226 168 --model cube
check "teach-5.18 why --model cube: not lit in that trace" grep -q "^not lit in the trace of --model cube: none of its segments writes this pixel" "$tmp/out"
check "teach-5.19 ... the pyramid's segment: its model left out" \
    grep -q "^    lost at model: its model left out: --model cube traces the records of model cube only; model pyramid is drawn into the image but not traced" "$tmp/out"
check "teach-5.20 ... and in the image it lights the pixel" has "    in the image, it lights this pixel"
check "teach-5.21 ... the cube's own nearest segment is listed too" grep -q "^  cube s[0-9]* (v" "$tmp/out"
"$exe" --image "$tmp/builtin.ppm" >/dev/null 2>&1
px=$(python3 -c '
import re, sys
d = open(sys.argv[1], "rb").read()
m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", d)
i = m.end() + 3 * (168 * int(m.group(1)) + 226)
print(*d[i:i + 3])' "$tmp/builtin.ppm")
check "teach-5.22 ... the image's color (gamma-encoded, not the model's 80 200 255), from the pyramid" \
    grep -q "^color ${px:-none} in the image: pyramid s[0-9]* is the last segment drawn there" "$tmp/out"
run why --model nope 226 168
check "teach-5.23 --model with no such model: exit 2, naming the argument" \
    test "$rc" = 2 -a -n "$(grep "^pipetrace why: --model nope: <builtin> has no model 'nope' (its models: cube, pyramid, floor)" "$tmp/err")"
printf 'framebuffer 20 10\nmodel dots\ntranslate 0 0 -2\nv 0 0 0\nv 1 1 0\nmodel line\ntranslate 0 0 -2\nv -1 -1 0\nv 1 -1 0\nl 1 2\n' > "$tmp/dots.scene"
run why "$tmp/dots.scene" 9 5
check "teach-5.24 a model without segments: left out of the drawing" \
    grep -q "^models without segments (left out: the renderer draws nothing of a model without segments):" "$tmp/out"
check "teach-5.25 ... with the vertex of it that lands nearest" \
    has "  dots: 2 vertices; the nearest, v1, would be 0.70 pixels away, at (x_fb, y_fb) = (9, 5)"
run why "$tmp/dots.scene" 9 5 --model dots
check "teach-5.26 --model of a model without segments: said so" has "model dots has no segments: the renderer draws nothing of it (below)"

# ---- why against the trace's records, in a viewport off the framebuffer's
# corner (6,4), 19 x 9 in 31 x 17: its pixel, index and viewport pixel, and
# the distance from a pixel-plane point (cmd_why.c, pp_in_fb: the viewport and
# framebuffer stages without rounding) to the centre of its own framebuffer
# pixel, which is hypot(x_pp - round(x_pp), y_pp - round(y_pp)) when the two
# agree.  p's segments are points (v1 = v2, ...); --model a leaves them out,
# so why lists them with their distances.
printf 'framebuffer 31 17\nviewport 6 4 19 9\ncamera orthographic\nmodel a\nv -0.9 -0.9 0\nv -0.8 -0.9 0\nl 1 2\nmodel p\nv 0.3 0.2 0\nv 0.3 0.2 0\nv -0.41 0.77 0\nv -0.41 0.77 0\nv 0.66 -0.52 0\nv 0.66 -0.52 0\nl 1 2\nl 3 4\nl 5 6\n' > "$tmp/vpoff.scene"
"$exe" "$tmp/vpoff.scene" --model p --format jsonl > "$tmp/vpoff.jsonl"
# v X_FB Y_FB IDX X_VP Y_VP D for v1, v3, v5 (D: the distance, 2 decimals)
awk -F'[:,]' '/"type":"vertex"/ {
        v = $6; for (k = 1; k <= NF; k++) if ($k == "\"stage\"") st = $(k + 1)
        for (k = 1; k <= NF; k++) { if ($k == "\"x\"") x = $(k + 1); if ($k == "\"y\"") y = $(k + 1); if ($k == "\"i\"") i = $(k + 1) }
        if (v % 2 == 0) next
        if (st == "\"pixel\"") { fx = x - int(x + 0.5); fy = y - int(y + 0.5); d[v] = sprintf("%.2f", sqrt(fx * fx + fy * fy)) }
        if (st == "\"viewport\"") { vx[v] = x; vy[v] = y + 0 }
        if (st == "\"framebuffer\"") { bx[v] = x; by[v] = y + 0 }
        if (st == "\"index\"") { gsub(/}/, "", i); ix[v] = i }
    }
    END { for (v = 1; v <= 5; v += 2) print v, bx[v], by[v], ix[v], vx[v], vy[v], d[v] }' "$tmp/vpoff.jsonl" > "$tmp/vpoff.rec"
check "teach-5.27 (the trace gives three points)" test "$(wc -l < "$tmp/vpoff.rec")" = 3
while read -r v X Y I VX VY D; do
    run why "$tmp/vpoff.scene" --model a "$X" "$Y"
    check "teach-5.28 why at p v$v's pixel ($X, $Y): the trace's index and viewport pixel" \
        grep -qxF "pixel (x_fb, y_fb) = ($X, $Y) of $tmp/vpoff.scene: idx = $I, inside the viewport at (x_vp, y_vp) = ($VX, $VY)" "$tmp/out"
    check "teach-5.29 ... v$v's point is $D pixels from the pixel's centre" \
        grep -qxF "  p s$(((v + 1) / 2)) (v$v -> v$((v + 1))): $D pixels away" "$tmp/out"
done < "$tmp/vpoff.rec"
run why "$tmp/vpoff.scene" --model a 21 9
check "teach-5.30 the pixel a degenerate segment drew: the trace's framebuffer pixel of v5" \
    grep -qF "drew that one pixel elsewhere, at (x_fb, y_fb) = ($(awk '$1 == 5 { print $2 ", " $3 }' "$tmp/vpoff.rec"))" "$tmp/out"
run why "$tmp/vpoff.scene" 25 3
check "teach-5.31 outside the viewport: its framebuffer pixels 6..24 x 4..12" \
    grep -qF "outside the viewport (x_fb 6..24, y_fb 4..12): nothing is ever drawn there" "$tmp/out"

# ---- --explain on the render command
run $tri --vertex 1 --explain
check "teach-6.1 --explain text: exit 0" test "$rc" = 0
check "teach-6.2 ... an indented line under the record" has "              x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313; y_pp = 0.5 + h/2.001 * (y_ip + 1) = 0.5 + 10/2.001 * (-0.5 + 1) = 2.9987506246876565"
check "teach-6.3 ... framebuffer left out, index still uses the real y_fb" has "              idx = y_fb * W + x_fb = 7 * 20 + 4 = 144"
check "teach-6.4 ... one line per record" test "$(grep -c '^tri v1 ' "$tmp/out")" = "$(grep -c '^              [a-z]' "$tmp/out")"
run docs/examples/behind.scene --vertex 1 --explain
check "teach-6.5 camera left out, image uses the real x_c" has "              x_ip = x_c / -z_c = 0.5 / -(-2) = 0.25; y_ip = y_c / -z_c = 0.25 / -(-2) = 0.125; z_ip = -1 (the image plane)"
run $tri --vertex 1 --explain --format jsonl
check "teach-6.6 --explain jsonl: a last field on vertex records" grep -q '"stage":"index","i":144,"explain":"idx = y_fb \* W + x_fb = 7 \* 20 + 4 = 144"}$' "$tmp/out"
check "teach-6.7 ... on every vertex record" test "$(grep -c '"type":"vertex"' "$tmp/out")" = "$(grep -c '"explain":"' "$tmp/out")"
if command -v python3 >/dev/null 2>&1; then
    check "teach-6.8 ... still JSON" python3 -c '
import json, sys
for line in open(sys.argv[1]):
    json.loads(line)' "$tmp/out"
fi
run docs/examples/lookat-near.scene --explain --format jsonl
check "teach-6.8a matrix camera: every vertex and clipvertex record explained" test "$(grep -c '"type":"\(vertex\|clipvertex\)"' "$tmp/out")" = "$(grep -c '"explain":"' "$tmp/out")"
check "teach-6.8b ... a clip point's divide, from its clip coordinates" grep -q '"type":"clipvertex","model":"stick","segment":1,"from":1,"to":2,"t":0.375,"stage":"ndc",.*"explain":"x_n = x_k / w_k = 0.375 / 1 = 0.375; ' "$tmp/out"
run $tri --explain --format csv
check "teach-6.9 --explain with csv: exit 1" test "$rc" = 1
run $tri
cp "$tmp/out" "$tmp/plain"
run $tri --explain
check "teach-6.10 without the explain lines, the trace is unchanged" test "$(grep -v '^              [a-z]' "$tmp/out")" = "$(cat "$tmp/plain")"


# ---- the matrix camera in step, quiz and --explain; --compare-cameras
run step docs/examples/lookat-near.scene --vertex 1 --all
check "teach-8.1 step under the matrix camera: ten stages" test "$(grep -c '^stage [0-9]* of 10: ' "$tmp/out")" = 10
check "teach-8.2 ... the divide, substituted" has "  here     x_n = x_k / w_k = 0.375 / 4 = 0.09375"
run step docs/examples/lookat-near.scene --vertex 2 --all
check "teach-8.3 a vertex behind the eye stops at the cvv" test "$(grep -c '^stage [0-9]* of 5: ' "$tmp/out")" = 5
check "teach-8.4 ... and says so" has "(the journey ends at the cvv: the vertex is outside the view volume)"
feed '0.5 0.25 4\n0.5 0.25 4 1\n0.5 0.25 4 1\n0.375 0.25 3.0303030303 4\n0\n0.09375 0.0625 0.7575757576\n21.875 14.0625 0.7575757576\n21 14\n21 14\n581\n' quiz docs/examples/lookat-near.scene --vertex 1
check "teach-8.5 quiz under the matrix camera: all ten right" has "score: 10/10"
run docs/examples/lookat-near.scene --vertex 1 --explain
check "teach-8.6 --explain under the matrix camera" has "              x_vp = floor(x_s) = floor(21.875) = 21; y_vp = floor(y_s) = floor(14.0625) = 14"
run step docs/examples/compare-classic.scene --vertex 1 --compare-cameras
check "teach-8.7 --compare-cameras: exit 0" test "$rc" = 0
check "teach-8.8 ... the image point and the NDC point agree bit for bit" has "(x_ip, y_ip) and (x_n, y_n) are equal, bit for bit: both cameras put the vertex at the same point of the view rectangle"
check "teach-8.9 ... both columns" grep -q '^projected  *image     (x_ip, y_ip, z_ip) = (0.5, -0.5, -1)  *| clip      (x_k, y_k, z_k, w_k) = (1, -1, ' "$tmp/out"
check "teach-8.10 ... the pixels differ by the rounding conventions" has "the pixels differ: the classic camera rounds x_pp = 0.5 + w/2.001 * (x_ip + 1)"
run step docs/examples/lookat-world.scene --vertex 1 --compare-cameras
check "teach-8.11 --compare-cameras on a matrix scene" test "$rc" = 0 -a -n "$(grep 'matrix camera:  this scene' "$tmp/out")"

# ---- why --model: the other models that light the pixel are named
printf 'framebuffer 20 10\ncamera orthographic\nmodel a\nv -0.5 0 0\nv 0.5 0 0\nl 1 2\nmodel b\nv -0.5 0 0\nv 0.5 0 0\nl 1 2\nl 1 2\n' > "$tmp/ov.scene"
run why "$tmp/ov.scene" --model a 8 5
check "teach-8.12 why --model a: b's two segments also light the pixel" has "also lit in the image by segments that --model a leaves out of the trace: b s1, b s2"

# ---- x_ip = 1.0005: outside the view rectangle, yet the pixel stage's divisor keeps it in
printf 'framebuffer 40 30\nviewport 0 0 40 30\nmodel m\nv 2.001 0 -2\nv 0 0 -2\nl 1 2\n' > "$tmp/room.scene"
run step "$tmp/room.scene" --vertex 1
check "teach-8.13 step: just outside the view rectangle, but 2.001 leaves room" \
    grep -qF -- "but the pixel stage's 2.001 leaves room: it still rounds to a pixel inside the viewport" "$tmp/out"

# ---- where the Java renderer's 32-bit int parts from pipetrace, step says what Java holds
run step tests/extreme/huge-coordinates.scene --vertex 1 --all
check "teach-9.1 no pixel for 1e301, and Java's (int)Math.round gives -1" grep -qF -- "round(9.995002498750627e+300) - 1: none, it is beyond 2^62 (the Java renderer's (int)Math.round(x_pp) gives -1 here)" "$tmp/out"
printf 'framebuffer 20 10\ncamera orthographic\nmodel m\nv 0 0 0\nv 300000000 0 0\nl 1 2\n' > "$tmp/j3.scene"
run step "$tmp/j3.scene" --vertex 2 --all
check "teach-9.2 a pixel past 2^31: pipetrace's 64-bit value, and Java's wrapped one" grep -qF -- "= 2998500760 - 1 = 2998500759 (the Java renderer's (int)Math.round(x_pp) gives -1296466536 here)" "$tmp/out"

# ---- why on a viewport that sticks out of the framebuffer (renderer 4: the
# course's vpout-* scenes): the viewport pixels that land on a pixel, each
# explained, and the last write, against the trace's pixel records (their
# index) and the image (tests/teach/why_vpout.py says what it checks)
why_vpout() {   # why_vpout ID SCENE [every] [lit2]
    id=$1; s=$2; shift 2
    python3 tests/teach/why_vpout.py "$exe" "$s" "$id" "$@" > "$tmp/py" 2>&1
    check "$id why on $(basename "$s") (viewport sticking out): every viewport pixel, against the trace ($(tail -1 "$tmp/py"))" test $? = 0
    grep '^FAIL\|^  \|Error' "$tmp/py" | head -10
}
if command -v python3 >/dev/null 2>&1; then
    why_vpout teach-10.1 tests/course/r4/vpout-12.scene every lit2
    why_vpout teach-10.2 tests/course/r4/vpout-13.scene
    why_vpout teach-10.3 tests/course/r4/vpout-01.scene
fi
run why tests/course/r4/vpout-12.scene 23 0
check "teach-10.4 two viewport pixels, one wrapped from the row below: said" \
    has "viewport pixel (x_vp, y_vp) = (0, 1) -> framebuffer (x_fb, y_fb) = (-1, 1) -> index y_fb * W + x_fb = 1 * 24 + (-1) = 23 -> shown at (x_fb, y_fb) = (23, 0): x_fb = -1 lies left of the framebuffer, so the index falls 1 row up"
check "teach-10.5 ... exit 0, two listed" test "$rc" = 0 -a "$(grep -c '^viewport pixel (x_vp, y_vp) = ' "$tmp/out")" = 2
run why tests/course/r4/vpout-12.scene 23 17
check "teach-10.6 reached by none: said, and today's report on a pixel outside the viewport" \
    test "$rc" = 0 -a -n "$(grep '^no viewport pixel lands on index 431: nothing is ever drawn there$' "$tmp/out")" -a -n "$(grep 'idx = 431, outside the viewport (x_fb -1..33, y_fb 0..15): nothing is ever drawn there$' "$tmp/out")"
# (6, 7): the cube's s5 and s6 from (7, 7), pts p1 from (31, 6), then pts p4 from (7, 7)
run why tests/course/r4/vpout-12.scene 6 7 --model cube
check "teach-10.7 --model cube on such a scene: the cube's segments lit it, no point listed" \
    test "$rc" = 0 -a "$(grep -c '^  cube s[56] (v' "$tmp/out")" = 2 -a "$(grep -c '^  pts p' "$tmp/out")" = 0
check "teach-10.8 ... the last write, a point of the model left out, in the image" \
    grep -q '^color [0-9 ]* in the image: the last write, by pts p4, from viewport pixel (x_vp, y_vp) = (7, 7)$' "$tmp/out"
# a viewport 100 wide in a framebuffer 1 wide: 100 viewport pixels land on
# index 99, (99 - k, k) for k = 0 .. 99; the line y = 0 lights (49, 50)
printf 'renderer 4\nframebuffer 1 100\nviewport 0 0 100 100\ncamera orthographic\nmodel m\nv -1 0 0\nv 1 0 0\nl 1 2\n' > "$tmp/thin.scene"
run why "$tmp/thin.scene" 0 99
check "teach-10.9 100 viewport pixels on one index: all listed, the first 64 explained" \
    test "$rc" = 0 -a "$(grep -c '^viewport pixel (x_vp, y_vp) = ' "$tmp/out")" = 100 -a "$(grep -c '^not lit from there\|^lit by:' "$tmp/out")" = 64 \
    -a -n "$(grep -Fx '(the 36 viewport pixels after the first 64 are listed, not explained)' "$tmp/out")"
check "teach-10.10 ... the one lit, and the last write" \
    test -n "$(grep -A1 '^viewport pixel (x_vp, y_vp) = (49, 50) ' "$tmp/out" | grep '^lit by:')" \
    -a -n "$(grep -Fx 'color 255 255 255: the last write, by m s1, from viewport pixel (x_vp, y_vp) = (49, 50)' "$tmp/out")"

# The colour why names is the one written: per-vertex colours, anti-aliasing
# and gamma make it differ from the model's colour.  Every 7th pixel of the
# course's image that a segment lit (neither background), asked of why, must
# say the image's bytes.
why_colours() {  # why_colours SCENE: "ok", or the first pixel whose colour differs
    python3 - "$exe" "$1" "${1%.scene}.ppm.gz" <<'PY'
import gzip, re, subprocess, sys
exe, scene, ppm = sys.argv[1:4]
d = gzip.open(ppm).read()
m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", d)
w, h, o = int(m.group(1)), int(m.group(2)), m.end()
bg = {(0, 0, 0)}                  # the course's default background
for line in open(scene):
    f = line.split()
    if f and f[0] in ("background", "viewport-background"): bg.add(tuple(map(int, f[1:4])))
lit = [(x, y) for y in range(h) for x in range(w)
       if tuple(d[o + 3 * (y * w + x):o + 3 * (y * w + x) + 3]) not in bg][::7]
for x, y in lit[:40]:
    out = subprocess.run([exe, "why", scene, str(x), str(y)], capture_output=True, text=True).stdout
    got = re.search(r"^color (\d+) (\d+) (\d+)", out, re.M)
    want = list(d[o + 3 * (y * w + x):o + 3 * (y * w + x) + 3])
    if not got or list(map(int, got.groups())) != want:
        print("pixel", x, y, "why:", got and got.groups(), "image:", want); sys.exit()
print("ok" if lit else "no lit pixel")
PY
}
check "teach-11.1 why's colour is the one written: per-vertex colours, gamma (the course's image)" \
    test "$(why_colours tests/course/r4/vp-00.scene)" = ok
check "teach-11.2 ... with anti-aliasing" test "$(why_colours tests/course/r4/aa-00.scene)" = ok
check "teach-11.3 ... another anti-aliased scene" test "$(why_colours tests/course/r4/aa-03.scene)" = ok

report
