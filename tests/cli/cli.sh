#!/bin/sh
# tests/cli/cli.sh -- the command line: exit codes, messages, outputs, formats
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/cli.sh PIPETRACE.  Run from the repository root.
exe=$1
. tests/lib/testlib.sh



# ---- exit codes and messages
run --help
check "cli-1.1 --help exits 0 and shows usage" test "$rc" = 0 -a -n "$(echo "$out" | grep 'usage: pipetrace')"
run --version
check "cli-1.2 --version" test "$rc" = 0 -a "${out%% *}" = pipetrace
run --frobnicate
check "cli-1.3 unknown option: exit 1" test "$rc" = 1
check "cli-1.4 ... with a message on stderr" grep -q "unknown option '--frobnicate'" "$tmp/err"
run --format xml
check "cli-1.5 unknown format: exit 1" test "$rc" = 1
run --vertex 0
check "cli-1.6 --vertex 0: exit 1" test "$rc" = 1
run a.scene b.scene
check "cli-1.7 two scenes: exit 1" test "$rc" = 1
run --trace
check "cli-1.8 missing option value: exit 1" test "$rc" = 1
printf 'framebuffer 10 10\nmodel m\nv 1 2\n' > "$tmp/bad.scene"
run "$tmp/bad.scene"
check "cli-2.1 bad scene: exit 2" test "$rc" = 2
check "cli-2.2 ... FILE:LINE:COL: error: message" grep -q "^$tmp/bad.scene:3:[0-9]*: error: " "$tmp/err"
check "cli-2.3 ... and nothing on stdout" test -z "$out"
run "$tmp/missing.scene"
check "cli-2.4 missing scene file: exit 2" test "$rc" = 2
run docs/examples/triangle.scene --model nosuch
check "cli-2.5 --model of no model: exit 2" test "$rc" = 2
run docs/examples/triangle.scene --vertex 99
check "cli-2.6 --vertex past every model: exit 2" test "$rc" = 2

# ---- outputs appear whole or not at all
echo "keep me" > "$tmp/old.ppm"
run "$tmp/bad.scene"; ls -A "$tmp" > "$tmp/before.ls"
run "$tmp/bad.scene" --image "$tmp/old.ppm" --trace "$tmp/new.trace"
check "cli-3.1 bad input leaves an existing output untouched" grep -q "keep me" "$tmp/old.ppm"
check "cli-3.2 ... and creates no new output" test ! -e "$tmp/new.trace"
check "cli-3.3 ... and no temporary files: the folder holds what it held" sh -c 'ls -A "$1" | cmp -s "$1/before.ls" -' _ "$tmp"
run docs/examples/triangle.scene --trace "$tmp/nodir/x.trace"
check "cli-3.4 unwritable trace path: exit 2" test "$rc" = 2
run docs/examples/triangle.scene --image "$tmp/t.ppm"
check "cli-3.5 --image alone writes the image and no trace" test "$rc" = 0 -a -z "$out" -a -s "$tmp/t.ppm"
check "cli-3.6 PPM header P6 20 10 255" test "$(head -c 13 "$tmp/t.ppm" | tr '\n' ' ')" = "P6 20 10 255 "
check "cli-3.7 PPM size is header + 3*20*10" test "$(wc -c < "$tmp/t.ppm")" = $((13 + 600))
ls "$tmp" > "$tmp/listing"
check "cli-3.8 no temporary file left after success" test "$(grep -c '\.ppm\.' "$tmp/listing")" = 0
mkdir "$tmp/dest"
mkfifo "$tmp/dest/fifo"
timeout 10 cat "$tmp/dest/fifo" > "$tmp/dest/from-fifo" &   # (no hang if the FIFO is replaced)
run docs/examples/triangle.scene --trace "$tmp/dest/fifo"
wait
check "cli-3.9 a FIFO as --trace is written to, not replaced" test "$rc" = 0 -a -p "$tmp/dest/fifo"
check "cli-3.10 ... and the reader gets the whole trace" grep -q "^# pipetrace trace" "$tmp/dest/from-fifo"
ln -s real.ppm "$tmp/dest/link.ppm"
run docs/examples/triangle.scene --image "$tmp/dest/link.ppm"
check "cli-3.11 a symbolic link as --image stays a link" test "$rc" = 0 -a -L "$tmp/dest/link.ppm"
check "cli-3.12 ... and the file it names is written" test "$(wc -c < "$tmp/dest/real.ppm")" = $((13 + 600))
check "cli-3.13 ... with no temporary file left" test "$(ls "$tmp/dest" | wc -l)" = 4

# ---- trace destinations and formats
run docs/examples/triangle.scene
cp "$tmp/out" "$tmp/default.txt"
run docs/examples/triangle.scene --trace -
check "cli-4.1 default output is the text trace on stdout" cmp -s "$tmp/out" "$tmp/default.txt"
run docs/examples/triangle.scene --trace "$tmp/t.trace"
check "cli-4.2 --trace FILE holds the same text" cmp -s "$tmp/t.trace" "$tmp/default.txt"
run docs/examples/cube.scene --format jsonl
check "cli-4.3 jsonl: first record is the header" test "$(echo "$out" | head -1 | cut -c1-28)" = '{"type":"header","version":1'
check "cli-4.4 jsonl: last record is the summary" test "$(echo "$out" | tail -1 | cut -c1-18)" = '{"type":"summary",'
if command -v python3 >/dev/null 2>&1; then
    check "cli-4.5 jsonl: every line is a JSON object" python3 -c '
import json, sys
for line in open(sys.argv[1]):
    assert isinstance(json.loads(line), dict)' "$tmp/out"
fi
n_vertex=$(grep -c '"type":"vertex"' "$tmp/out")
run docs/examples/cube.scene --format csv
check "cli-4.6 csv: one row per vertex record, plus a header row" test "$(echo "$out" | wc -l)" = $((n_vertex + 1))
check "cli-4.7 csv header" test "$(echo "$out" | head -1)" = "model,v,stage,x,y,z,inside,behind,i,warning,digits_lost"
run docs/examples/lookat-near.scene --format jsonl
n_matrix=$(grep -c '"type":"vertex"\|"type":"clipvertex"' "$tmp/out")
run docs/examples/lookat-near.scene --format csv
check "cli-4.7a matrix camera csv: a row per vertex and clipvertex record, every stage" test "$(echo "$out" | wc -l)" = $((n_matrix + 1)) -a "$(echo "$out" | cut -d, -f3 | sort -u | tr '\n' ' ')" = "clip cvv index model ndc screen stage viewport "
check "cli-4.7b ... its header has w, code, planes, segment and t" test "$(echo "$out" | head -1)" = "model,v,stage,x,y,z,w,code,planes,inside,i,segment,t,warning,digits_lost"
check "cli-4.7c ... every row has the header's 15 fields" test "$(echo "$out" | awk -F, '{print NF}' | sort -u)" = 15
check "cli-4.7d ... the cvv row has its code and planes" grep -qx 'stick,2,cvv,,,,,61,near|left|right|bottom|top,,,,,,' "$tmp/out"
check "cli-4.7e ... a point clipping made has its segment and t, and no v" grep -qx 'stick,,ndc,0.375,0.25,0,,,,,,1,0.375,,' "$tmp/out"
run tests/extreme/cancel-translate.scene --format csv
check "cli-4.7g csv: a warning's digits lost in the last column" grep -q ',cancellation,9$' "$tmp/out"
cp docs/examples/triangle.scene "$tmp/bad$(printf '\377')name.scene"
run "$tmp/bad$(printf '\377')name.scene" --format jsonl
check "cli-4.7f a scene path that is not UTF-8 is written with U+FFFD, so the JSON stays valid" grep -q '"scene":"[^"]*bad\\ufffdname.scene"' "$tmp/out"
run docs/examples/triangle.scene --format jsonl
check "cli-4.8 exact values in jsonl: x_pp of vertex 1" grep -q '"v":1,"stage":"pixel","x":5.497501249375313,"y":2.9987506246876565' "$tmp/out"
run docs/examples/triangle.scene --precision 2
check "cli-4.9 --precision 2 shows 2 decimals" grep -q 'x_pp = *5.50  y_pp = *3.00$' "$tmp/out"

# ---- leaving out what a scene does not need
run docs/examples/triangle.scene --format jsonl
check "cli-5.1 viewport at 0,0: framebuffer stage left out" test "$(grep -c '"type":"vertex".*"stage":"framebuffer"' "$tmp/out")" = 0
check "cli-5.2 ... and the header says why" grep -q '"left_out":\[{"stage":"framebuffer","why":"identity: viewport at 0,0"}\]' "$tmp/out"
run docs/examples/triangle.scene --format jsonl --all-stages
check "cli-5.3 --all-stages puts it back" test "$(grep -c '"stage":"framebuffer"' "$tmp/out")" = 3
run docs/examples/ortho.scene --format jsonl --model far
check "cli-5.4 --model traces one model's vertices" test "$(grep -c '"type":"vertex","model":"far","v":' "$tmp/out")" -gt 0 -a "$(grep '"type":"vertex"' "$tmp/out" | grep -vc '"model":"far"')" = 0
check "cli-5.5 unused vertices are not traced: far's v1 and v3 are, v2 and v4 not" test "$(grep '"type":"vertex"' "$tmp/out" | grep -o '"v":[0-9]*' | sort -u | tr '\n' ' ')" = '"v":1 "v":3 '
run docs/examples/cube.scene --format jsonl --vertex 3
check "cli-5.6 --vertex 3: one journey" test "$(grep -c '"type":"vertex","model":"cube","v":3,' "$tmp/out")" -gt 0 -a "$(grep '"type":"vertex"' "$tmp/out" | grep -vc '"v":3,')" = 0
check "cli-5.7 --vertex without --image: no raster records, a summary" test "$(grep -c '"type":"pixel"' "$tmp/out")" = 0 -a "$(grep -c '"type":"summary"' "$tmp/out")" = 1
run docs/examples/cube.scene --format jsonl --stage pixel --stage index
check "cli-5.8 --stage keeps only the stages named, and keeps them" \
    test "$(grep '"type":"vertex"' "$tmp/out" | grep -Evc '"stage":"(pixel|index)"')" = 0 \
    -a "$(grep -c '"type":"vertex",.*"stage":"pixel"' "$tmp/out")" -gt 0 \
    -a "$(grep -c '"type":"vertex",.*"stage":"index"' "$tmp/out")" -gt 0
run docs/examples/behind.scene --format jsonl
check "cli-5.9 a vertex behind the camera is flagged" grep -q '"v":2,"stage":"image",.*"behind":true' "$tmp/out"
run docs/examples/behind.scene
check "cli-5.10 ... in the text trace too" grep -q 'behind the camera' "$tmp/out"

# ---- the same output every time, whatever the locale: pipetrace never calls
# setlocale(), so the C library formats and reads numbers in the "C" locale
# whatever LC_ALL says; a call to it would be seen in the binary's symbols.
run docs/examples/two-models.scene --format jsonl
cp "$tmp/out" "$tmp/a"
LC_ALL=de_DE.UTF-8 LANG=de_DE.UTF-8 "$exe" docs/examples/two-models.scene --format jsonl > "$tmp/b" 2>/dev/null
check "cli-6.1 byte-identical across runs" sh -c 'grep -q "\"type\":\"vertex\"" "$1" && cmp -s "$1" "$2"' _ "$tmp/a" "$tmp/b"
check "cli-6.1a ... and no locale can change a number: the binary never calls setlocale" sh -c '! grep -qa setlocale "$1"' _ "$exe"

# ---- the built-in scene and plain OBJ files
run --image "$tmp/b.ppm" --trace -
check "cli-7.1 built-in scene renders" test "$rc" = 0 -a -s "$tmp/b.ppm"
check "cli-7.2 its viewport is not the whole framebuffer" grep -q 'viewport     320 x 240 at (x_ul, y_ul) = (40, 30)' "$tmp/out"
run docs/examples/tetra.obj --format jsonl
check "cli-7.3 a plain .obj is wrapped and placed; the header says where" grep -q '"obj_translate":\[' "$tmp/out"

# ---- the matrix camera
mcam() {    # mcam NAME CAMERA-LINE PROJECTION-LINE EXPECTED-MESSAGE-PART
    printf '%s\n%s\nmodel m\nv 0 0 5\nv 1 0 5\nl 1 2\n' "$2" "$3" > "$tmp/m.scene"
    run "$tmp/m.scene"
    check "$1" test "$rc" = 2 -a -n "$(echo "$err" | grep -F -- "$4")"
}
mcam "cli-8.1 zero direction is named" "camera lookat 0 0 0 0 0 0 0 1 0" "projection perspective 60 1 1 10" ":1:8: error: camera: direction has length 0"
mcam "cli-8.2 up parallel to direction is named" "camera lookat 0 0 0 0 0 1 0 0 -3" "projection perspective 60 1 1 10" ":1:8: error: camera: up is parallel to direction"
mcam "cli-8.3 fov >= 180 points at the fov" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 180 1 1 10" ":2:24: error: projection: field of view"
mcam "cli-8.4 fov <= 0" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 0 1 1 10" ":2:24: error: projection: field of view"
mcam "cli-8.5 near <= 0 points at near" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 60 1 0 10" ":2:29: error: projection: near must be > 0"
mcam "cli-8.6 near >= far points at far" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 60 1 10 10" ":2:32: error: projection: near must be < far"
mcam "cli-8.7 aspect <= 0" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 60 -2 1 10" ":2:27: error: projection: aspect ratio must be > 0"
mcam "cli-8.8 lookat without projection" "camera lookat 0 0 0 0 0 1 0 1 0" "" "needs a 'projection perspective' line"
mcam "cli-8.8a fov 1e-320: cot(fov/2) overflows, never a matrix of infinities" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 1e-320 1 1 10" ":2:24: error: projection: field of view too close to 0"
mcam "cli-8.8b aspect 1e-320 points at the aspect" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 60 1e-320 1 10" ":2:27: error: projection: aspect ratio too extreme"
mcam "cli-8.8c near 1e300, far 1e308: f*n/(n-f) overflows" "camera lookat 0 0 0 0 0 1 0 1 0" "projection perspective 90 1 1e300 1e308" ":2:35: error: projection: near and far too extreme"
mcam "cli-8.8d an eye whose -eye.d overflows is named" "camera lookat 1.5e308 0 1.5e308 1 0 1 0 1 0" "projection perspective 60 1 1 10" ":1:8: error: camera: position too far from the origin"
printf 'camera lookat 0 0 0 1e200 0 1e200 0 1e-310 0\nprojection perspective 60 1 1 10\nmodel m\nv 0 0 5\nv 1 0 5\nl 1 2\n' > "$tmp/m.scene"
run "$tmp/m.scene" --format jsonl
check "cli-8.8e a direction of 1e200 and an up of 1e-310 are not 'length 0'" test "$rc" = 0 -a -n "$(grep -F '"view":[[0.7071067811865476,' "$tmp/out")"
mcam "cli-8.8f a world matrix that overflows is named" "camera lookat 0 0 0 0 0 1 0 1 0
projection perspective 60 1 1 10
model w
world scale 1e200
world scale 1e200" "" ":5:1: error: the world matrix overflows"
printf 'framebuffer 10 10\nmodel m\nworld scale 2\nv 0 0 -1\n' > "$tmp/w.scene"
run "$tmp/w.scene"
check "cli-8.8g 'world' under the classic camera is an error, not ignored" test "$rc" = 2 -a -n "$(echo "$err" | grep -F ":3:1: error: 'world' needs the matrix camera")"
run docs/examples/triangle.scene --raw-lookat
check "cli-8.8h --raw-lookat on a classic scene says it changes nothing" test "$rc" = 0 -a -n "$(echo "$err" | grep -F 'note: --raw-lookat changes nothing')"
run docs/examples/lookat-near.scene --format jsonl
check "cli-8.9 near-plane crossing: the clipped point is traced with its t" grep -q '"type":"clipvertex","model":"stick","segment":1,"from":1,"to":2,"t":0.375,"stage":"ndc","x":0.375,"y":0.25,"z":0}' "$tmp/out"
check "cli-8.10 a vertex behind the eye stops at the cvv" grep -q '"v":2,"stage":"cvv","code":61,"planes":\["near","left","right","bottom","top"\]}' "$tmp/out"
check "cli-8.11 ... and is never divided (v1 is)" test "$(grep -c '"v":2,"stage":"ndc"' "$tmp/out")" = 0 -a "$(grep -c '"v":1,"stage":"ndc"' "$tmp/out")" = 1
check "cli-8.12 the header holds the matrices" grep -q '"projection_matrix":\[\[0.75,0,0,0\],\[0,1,0,0\],\[0,0,1.0101010101010102,1\],\[0,0,-1.0101010101010102,0\]\]' "$tmp/out"
printf 'framebuffer 10 10\ncamera lookat 0 0 0 0 0 1 0 1 0\nprojection perspective 90 1 1 10\nmodel m\nv -5 0 2\nv -9 0 3\nl 1 2\n' > "$tmp/cull.scene"
run "$tmp/cull.scene" --format jsonl
check "cli-8.13 a segment wholly outside is culled" grep -q '{"type":"skip","model":"m","segment":1,"why":"outside the view volume"}' "$tmp/out"
check "cli-8.14 ... and counted" grep -q '"segments_culled":1' "$tmp/out"
run docs/examples/lookat-world.scene --format jsonl
cp "$tmp/out" "$tmp/adjusted"
check "cli-8.15 a skewed up vector is re-derived, and the header says so" grep -q '"up_adjusted":true' "$tmp/out"
run docs/examples/lookat-world.scene --format jsonl --raw-lookat
check "cli-8.16 --raw-lookat keeps the seed's matrix: other view values" sh -c 'test "$1" = 0 && grep -q "\"up_adjusted\":false" "$2" && ! cmp -s "$2" "$3"' _ "$rc" "$tmp/out" "$tmp/adjusted"
check "cli-8.16a ... and the header still says up is not perpendicular" grep -q '"up_perpendicular":false,"up_adjusted":false' "$tmp/out"
check "cli-8.17 --raw-lookat: columns u = (0, .7071, .7071) and d = (0, 0, 1) are not orthogonal" grep -q '"view":\[\[1,0,0,0\],\[0,0.7071067811865475,0,0\],\[0,0.7071067811865475,1,0\]' "$tmp/out"
run docs/examples/lookat-cube.scene --format jsonl --stage cvv --stage screen
check "cli-8.18 --stage takes the matrix camera's stages" test "$(grep '"type":"vertex"' "$tmp/out" | grep -Evc '"stage":"(cvv|screen)"')" = 0 -a "$(grep -c '"type":"vertex"' "$tmp/out")" = 16


# ---- pipetrace stages: the table of stages/pt_stage.c
run stages
check "cli-9.1 stages: exit 0" test "$rc" = 0
check "cli-9.2 ... every stage once, the viewport once per camera" \
    test "$(grep -c '^[a-z]' "$tmp/out")" = 14 -a "$(grep -c '^viewport ' "$tmp/out")" = 2
check "cli-9.3 ... with the pixel stage's formula and values" \
    grep -q '^  formula  x_pp = 0.5 + w/2.001 \* (x_ip + 1)' "$tmp/out"
check "cli-9.4 ... value names and JSON keys" grep -q '^  values   x_vp (x), y_vp (y): integers' "$tmp/out"
run stages extra
check "cli-9.5 stages: an unknown argument is a usage error" test "$rc" = 1 -a -n "$(grep "Try 'pipetrace stages --help'" "$tmp/err")"
run stages --camera matrix
check "cli-9.6 --camera matrix: its 10 stages, the classic viewport not among them" \
    test "$(grep -c '^[a-z]' "$tmp/out")" = 10 -a -z "$(grep 'round(x_pp)' "$tmp/out")"
run stages --camera pinhole
check "cli-9.7 --camera takes classic or matrix" test "$rc" = 1

report
