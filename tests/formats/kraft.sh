#!/bin/sh
# tests/formats/kraft.sh -- the course renderer's debug log: --format kraft, kraft-pixels
# See LICENSE for copyright and license.
#
# Usage: sh tests/formats/kraft.sh PIPETRACE.  Run from the repository
# root.  tests/reference holds the 39 reference scenes
# and kraftlog/, the course renderer's own logs of them (kraftlog/README.md):
# every log must come out byte for byte.
exe=$1
ref=tests/reference          # the logs of this version (a second argument, an older
                             # copy of the reference cases, is not used)
. tests/lib/testlib.sh

# ---- kraft-1: the course's logs, byte for byte
n=0
for log in "$ref"/kraftlog/*.log; do
    b=${log##*/}
    name=${b%%.*}
    fmt=kraft
    [ "${b%.pixels.log}" != "$b" ] && fmt=kraft-pixels
    run "$ref/$name.scene" --format $fmt
    check "kraft-1.1 $b: exit 0" test "$rc" = 0
    check "kraft-1.2 $b: byte for byte" cmp -s "$tmp/out" "$log"
    n=$((n + 1))
done
check "kraft-1.3 51 logs (39 scenes, 12 with pixels)" test "$n" = 51

# ---- kraft-2: the log's pixels are the pixels pt_run draws (the log's DDA
# is written out again to print each step: tie it to src/core/raster.c)
logpix() {    # the framebuffer pixels of a pixel log's lines that are not clipped
    sed -n 's/^      fb_.*vp_\[x= *\(-*[0-9]*\), y= *\(-*[0-9]*\),.*(x_vp= *\(-*[0-9]*\), y_vp= *\(-*[0-9]*\)).*/\1 \2 \3 \4/p' "$1" |
        awk '{ print $1 + $3, $2 + $4 }'
}
for log in "$ref"/kraftlog/*.pixels.log; do
    b=${log##*/}
    name=${b%%.*}
    run "$ref/$name.scene"
    grep '^[^ ]* s[0-9]* *pixel ' "$tmp/out" | awk '{ print $6, $9 }' > "$tmp/trace.pix"
    logpix "$log" > "$tmp/log.pix"
    check "kraft-2.1 $name: the log's pixels are the trace's, in order" cmp -s "$tmp/trace.pix" "$tmp/log.pix"
done
check "kraft-2.2 ... and there are some" test -s "$tmp/trace.pix"

# ---- kraft-3: what the log cannot show
printf 'camera lookat 0 0 5 0 0 -1 0 1 0\nprojection perspective 60 auto 0.1 100\nmodel m\nv 0 0 0\nv 1 1 0\nl 1 2\n' > "$tmp/matrix.scene"
run "$tmp/matrix.scene" --format kraft
check "kraft-3.1 matrix camera: exit 2" test "$rc" = 2
check "kraft-3.2 ... saying the course's renderer has no matrix camera" grep -q "$tmp/matrix.scene: error: the course's renderer has no matrix camera" "$tmp/err"
check "kraft-3.3 ... and writing nothing" test ! -s "$tmp/out"
run "$tmp/matrix.scene" --format kraft-pixels --trace "$tmp/m.log"
check "kraft-3.4 ... nor a file" test "$rc" = 2 -a ! -e "$tmp/m.log"
run "$ref/basic-cube.scene" --format kraft --vertex 1
check "kraft-3.5 --vertex with kraft: usage error" test "$rc" = 1
check "kraft-3.6 ... naming what it cannot filter" grep -q "logs the whole scene" "$tmp/err"
printf 'framebuffer 20 20\ncamera orthographic\nmodel m\nv -1 0 0\nv 1e7 0 0\nl 1 2\n' > "$tmp/long.scene"
run "$tmp/long.scene" --format kraft-pixels
check "kraft-3.7 a segment of 10^8 steps: exit 2, nothing written" test "$rc" = 2 -a ! -s "$tmp/out"
check "kraft-3.8 ... saying which segment" grep -q "model 'm', segment 1: .* steps, more than" "$tmp/err"
run "$tmp/long.scene" --format kraft
check "kraft-3.9 ... without pixels it logs" test "$rc" = 0 -a -s "$tmp/out"

# ---- kraft-4: a coloured model: its colour, and the gamma of the pixel lines
printf 'framebuffer 4 3\ncamera orthographic\nmodel m\ncolor 255 128 0\nv -0.9 0 0\nv 0.9 0.5 0\nl 1 2\n' > "$tmp/color.scene"
run "$tmp/color.scene" --format kraft-pixels
check "kraft-4.1 colour list: java.awt.Color" grep -q '^3. Pixel-plane: cIndex =   0, java.awt.Color\[r=255,g=128,b=0\]$' "$tmp/out"
# 128/255f = 0.5019608f; its gamma (1/2.2) 0.73103946f, as the course prints it
check "kraft-4.2 pixel lines: r g b after gamma" grep -q 'r=1.0000 g=0.7310 b=0.0000$' "$tmp/out"
check "kraft-4.3 colour slopes of one colour: 0.0" test "$(grep -c '^Slope m... = 0.0$' "$tmp/out")" = 3

# ---- kraft-5: diff reads the logs, as EXPECTED or ACTUAL: each agrees with
# pipetrace's own trace of its scene (vIndex 0-based is vertex v + 1; the
# log's five decimals get half a unit of tolerance; its pixels are compared)
n=0
for log in "$ref"/kraftlog/*.log; do
    b=${log##*/}
    name=${b%%.*}
    "$exe" "$ref/$name.scene" --trace "$tmp/t.txt"
    "$exe" "$ref/$name.scene" --format jsonl --trace "$tmp/t.jsonl"
    run diff "$tmp/t.txt" "$log"
    check "kraft-5.1 $b as ACTUAL: agrees with the text trace" test "$rc" = 0
    run diff "$log" "$tmp/t.jsonl"
    check "kraft-5.2 $b as EXPECTED: agrees with the JSON Lines trace" test "$rc" = 0
    n=$((n + 1))
done
check "kraft-5.3 all 51 logs read" test "$n" = 51
"$exe" "$ref/basic-two-models.scene" --trace "$tmp/t.txt"
run diff "$tmp/t.txt" "$ref/kraftlog/basic-two-models.pixels.log"
check "kraft-5.4 diff says what it read" grep -q "(the course's debug log, 5 decimals: 64 vertex, 338 pixel records)" "$tmp/out"
check "kraft-5.5 ... and compares the pixels" grep -q "the same 279" "$tmp/out"
"$exe" "$ref/basic-unused-vertex.scene" --trace "$tmp/t.txt"
run diff "$tmp/t.txt" "$ref/kraftlog/basic-unused-vertex.log"
check "kraft-5.6 a vertex no segment uses is not compared (the trace has none)" test "$rc" = 0

# ---- kraft-6: a log with a known mistake is found at the right stage.  The
# course's Viewport stage (pipetrace's pixel stage) of a student who wrote
# w/2 for w/2.001: a student build (tests/teach/student.sh s3_two) writes the log
scene=$ref/basic-two-models.scene                   # viewport 100 x 80
"$exe" "$scene" --trace "$tmp/want.txt"
. tests/lib/studentlib.sh
mistaken s3_two
"$tmp/sb/pipetrace" "$scene" --format kraft > "$tmp/student.log"
check "kraft-6.1 the edit changed the pixel plane" test "$(cmp -l "$tmp/student.log" "$ref/kraftlog/basic-two-models.log" | wc -l)" -gt 0
run diff "$tmp/want.txt" "$tmp/student.log"
check "kraft-6.2 exit 1" test "$rc" = 1
check "kraft-6.3 first wrong stage: pixel" grep -q "^a v1: differs first at pixel" "$tmp/out"
check "kraft-6.4 the mistake named" grep -q "likely mistake: 2 instead of 2.001" "$tmp/out"
check "kraft-6.5 ... and no other" test "$(grep 'likely mistake' "$tmp/out" | grep -cv '2 instead of 2.001')" = 0
run diff "$tmp/student.log" "$tmp/want.txt"
check "kraft-6.6 as EXPECTED, a log without pixels has no header: no mistake checked" \
    grep -q "no known mistake checked: EXPECTED has no header" "$tmp/out"
# the rasterizer's lines: every pixel one row higher
awk '/^      fb_/ { i = index($0, "y_vp="); n = substr($0, i + 5, 4) + 0
                   $0 = substr($0, 1, i + 4) sprintf("%4d", n - 1) substr($0, i + 9) } { print }' \
    "$ref/kraftlog/basic-two-models.pixels.log" > "$tmp/student.log"
run diff "$tmp/want.txt" "$tmp/student.log"
check "kraft-6.7 pixels one row up: exit 1" test "$rc" = 1
check "kraft-6.8 ... every vertex agrees, the pixels differ" grep -q "16 of 16 vertices agree. But the lit pixels differ" "$tmp/out"

# ---- kraft-7: a log that is not one
printf '\n== Begin Rendering of Scene:  ==\nperspective = maybe\n' > "$tmp/bad.log"
run diff "$tmp/bad.log" "$tmp/want.txt"
check "kraft-7.1 a bad line: exit 2" test "$rc" = 2
check "kraft-7.2 ... FILE:LINE:COL: error" grep -q "^$tmp/bad.log:3:15: error: expected 'true' or 'false'" "$tmp/err"
head -20 "$ref/kraftlog/basic-two-models.log" > "$tmp/cut.log"
run diff "$tmp/cut.log" "$tmp/want.txt"
check "kraft-7.3 a log cut short: exit 2" test "$rc" = 2 -a -n "$(grep 'ends before' "$tmp/err")"
# a log as a student's program prints it: its own lines, the renderer's
# messages, lines after the end are passed over and counted, never refused
sed -e '5i hello from my renderer' -e '$a done, 16 vertices' "$ref/kraftlog/basic-two-models.log" |
    sed '7i FrameBuffer: Bad pixel coordinate (-1, 5) [w=20, h=10]' > "$tmp/chatty.log"
run diff "$tmp/chatty.log" "$tmp/want.txt"
check "kraft-7.4 a student's own lines in the log: read, exit 0 ($rc)" test "$rc" = 0
check "kraft-7.5 ... the lines passed over counted in a note, with the first one's number" \
    grep -q "^Note: 2 lines of EXPECTED (the first: line 5) are not a kind of line diff reads" "$tmp/out"
check "kraft-7.6 ... the renderer's own message is understood, not counted" \
    sh -c '! grep -q "Note: 3 lines" "$1"' _ "$tmp/out"

# ---- kraft-8: a log cut anywhere is refused with a message, never a crash
log=$ref/kraftlog/basic-clip-edges.pixels.log
"$exe" "$ref/basic-clip-edges.scene" --trace "$tmp/want.txt"
size=$(wc -c < "$log")
cuts=0 crashed=0 accepted=0
i=1
while [ "$i" -lt "$size" ]; do
    head -c "$i" "$log" > "$tmp/cut.log"
    "$exe" diff "$tmp/want.txt" "$tmp/cut.log" >/dev/null 2>&1; rc=$?
    [ "$rc" -gt 2 ] && crashed=$((crashed + 1))
    [ "$rc" -ne 2 ] && accepted=$((accepted + 1))
    cuts=$((cuts + 1))
    i=$((i + 211))
done
check "kraft-8.1 $cuts cuts of a pixel log: none crashes" test "$crashed" = 0
check "kraft-8.2 ... each is an error (exit 2)" test "$accepted" = 0

# ---- kraft-9: a viewport that sticks out of the framebuffer (left and below):
# the framebuffer's "Bad pixel coordinate" lines, as the course's jar printed
# them (tests/data/vpout/README.md), whatever the debug switches: the
# clearing's first, then each after its pixel's line
vd=tests/data/vpout
for dbg in none scene all; do
    run "$vd/r4-bad.scene" --format kraft --kraft-debug $dbg
    check "kraft-9.1 --kraft-debug $dbg: the course's log byte for byte" cmp -s "$tmp/out" "$vd/r4-bad.$dbg.log"
done
check "kraft-9.2 ... which has Bad pixel lines of the clearing and of the drawing" \
    test "$(grep -c 'Bad pixel' "$vd/r4-bad.none.log")" -gt "$(awk '/Bad/ { n++ } /WARNING/ { exit } END { print n }' "$vd/r4-bad.none.log")"
run "$vd/r4-bad.scene" --image "$tmp/bad.ppm"
check "kraft-9.3 the image, rows wrapped, byte for byte" cmp -s "$tmp/bad.ppm" "$vd/r4-bad.ppm"
run "$vd/r4-bad.scene"
check "kraft-9.4 a dropped pixel's record says idx = -1, one per Bad pixel line of the drawing" \
    test "$(grep -c ' pixel .*idx = -1$' "$tmp/out")" = "$(awk '/== Begin/ { b = 1 } b && /Bad pixel/' "$vd/r4-bad.all.log" | wc -l)"
check "kraft-9.5 ... and a wrapped one its index y_fb * W + x_fb" grep -q 'x_fb = *-3  y_fb = *5  idx = 47$' "$tmp/out"
"$exe" "$vd/r4-bad.scene" --format jsonl --trace "$tmp/bad.jsonl"
run diff "$vd/r4-bad.all.log" "$tmp/bad.jsonl"
check "kraft-9.6 diff reads the log (Bad pixel lines first) and agrees with the trace" \
    grep -q "every stage both hold, and the same 16" "$tmp/out"
"$exe" "$vd/r4-bad.scene" --trace "$tmp/bad.txt"
run diff "$tmp/bad.txt" "$tmp/bad.jsonl"
check "kraft-9.9 the text trace's negative viewport corner reads back: it agrees with the JSON Lines" \
    test "$rc" = 0
# renderers 7 and 9 print the clearing's lines first as well
for r in r7 r9; do
    gzip -dc tests/course/$r/vpout-04.log.gz > "$tmp/c79.log"
    "$exe" tests/course/$r/vpout-04.scene --format jsonl --trace "$tmp/c79.jsonl"
    run diff "$tmp/c79.log" "$tmp/c79.jsonl"
    check "kraft-9.7 $r: diff reads a log that begins with Bad pixel lines, and agrees" \
        test "$rc" = 0 -a "$(head -c 33 "$tmp/c79.log")" = "FrameBuffer: Bad pixel coordinate"
    check "kraft-9.8 ... reading every line" sh -c '! grep -q "not read" "$1"' _ "$tmp/out"
done

report
