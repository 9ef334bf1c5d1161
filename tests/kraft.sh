#!/bin/sh
# tests/kraft.sh -- the course renderer's debug log: --format kraft, kraft-pixels
# See LICENSE for copyright and license.
#
# Usage: sh tests/kraft.sh PIPETRACE [REFERENCE_DIR].  Run from the repository
# root.  REFERENCE_DIR (default tests/reference) holds the 39 reference scenes
# and kraftlog/, the course renderer's own logs of them (kraftlog/README.md):
# every log must come out byte for byte.
exe=$1
ref=${2:-tests/reference}
. tests/testlib.sh

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

report
