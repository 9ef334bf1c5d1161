#!/bin/sh
# tests/valgrind.sh -- every command under valgrind's memcheck
# See LICENSE for copyright and license.
#
# Usage: sh tests/valgrind.sh PIPETRACE (part of `make test`).  Each command
# must exit as it would without valgrind, with no invalid read or write, no use
# of an uninitialised value and no leak.  Without valgrind, or for a binary
# built with AddressSanitizer (`make sanitize`: the two cannot run together),
# it skips: "0 passed, 0 failed".
exe=$1
. tests/testlib.sh
if ! command -v valgrind >/dev/null 2>&1; then
    echo "  skipped: valgrind not installed"
    report
    exit 0
fi
if grep -qa __asan_init "$exe"; then
    echo "  skipped: built with AddressSanitizer"
    report
    exit 0
fi

vg() {      # vg DESCRIPTION EXIT ARGS...: ARGS under memcheck, exit status EXIT
    d=$1; want=$2; shift 2
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
        "$exe" "$@" </dev/null >"$tmp/out" 2>"$tmp/err"
    rc=$?
    check "$d (exit $rc, want $want)" test "$rc" = "$want"
    grep -q '^==' "$tmp/err" && sed -n '1,12p' "$tmp/err"
}

vg "vg-1 the built-in scene, image and text trace" 0 --image "$tmp/b.png" --trace "$tmp/b.txt"
vg "vg-2 a scene with an obj include, JSONL" 0 tests/data/include.scene --format jsonl
vg "vg-3 a plain .obj file, CSV, every stage" 0 docs/examples/tetra.obj --format csv --all-stages
vg "vg-4 the matrix camera, clipping, --explain" 0 docs/examples/lookat-near.scene --explain
vg "vg-5 extreme: 2 * 10^14 steps fast-forwarded" 0 tests/extreme/far-away-1e15.scene --format jsonl
vg "vg-6 extreme: non-finite endpoints" 0 tests/extreme/zdiv-zero.scene --format jsonl
vg "vg-7 an obj include with an error" 2 tests/data/bad_include.scene
vg "vg-8 step through every stage" 0 step --vertex 3 --all
vg "vg-9 step, both cameras side by side" 0 step docs/examples/compare-matrix.scene --compare-cameras
vg "vg-10 why is a pixel lit" 0 why 133 165
vg "vg-11 quiz with no answers" 0 quiz --seed 7
vg "vg-12 accuracy, classic camera" 0 accuracy docs/examples/triangle.scene --no-time
vg "vg-13 accuracy, matrix camera" 0 accuracy docs/examples/lookat-near.scene --no-time
vg "vg-14 journey: SVG and HTML" 0 journey --vertex 1 --svg "$tmp/j.svg" --html "$tmp/j.html"
"$exe" docs/examples/cube.scene --format jsonl > "$tmp/a.jsonl"
"$exe" docs/examples/cube.scene > "$tmp/a.txt"
vg "vg-15 diff: JSONL against text" 0 diff "$tmp/a.jsonl" "$tmp/a.txt"
"$exe" --image "$tmp/c.ppm"
vg "vg-16 diff: two images" 0 diff "$tmp/c.ppm" "$tmp/c.ppm"
vg "vg-16a diff: every mistake tested on every vertex, the verdict" 1 diff --verdict \
    tests/data/diff/selfcheck.jsonl tests/data/diff/selfcheck-trunc.jsonl
report
