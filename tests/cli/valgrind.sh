#!/bin/sh
# tests/cli/valgrind.sh -- every command under valgrind's memcheck
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/valgrind.sh PIPETRACE (part of `make test`).  Each command
# must exit as it would without valgrind, with no invalid read or write, no use
# of an uninitialised value and no leak.  Without valgrind, or for a binary
# built with AddressSanitizer (`make sanitize`: the two cannot run together),
# or one that uses an instruction valgrind does not know, it skips: "0
# passed, 0 failed".
exe=$1
. tests/lib/testlib.sh
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

# valgrind must know every instruction the binary uses: one built for this
# CPU (-march=native) may use some it does not emulate (AVX-512), and then
# every command would die of SIGILL under it; that is valgrind's limit, not
# the binary's, so the group says so and stops
valgrind -q "$exe" --version >/dev/null 2>"$tmp/err"
if [ $? -ge 128 ] && grep -q 'unhandled instruction\|Illegal instruction\|SIGILL' "$tmp/err"; then
    echo "  skipped: valgrind cannot run $exe (an instruction it does not know: built with -march=native?)"
    report
    exit 0
fi

# valgrind must read the binary's debug information (clang 14's default DWARF
# 5 it cannot: the Makefile asks for DWARF 4), or its reports lose their lines.
valgrind -q "$exe" --version >/dev/null 2>"$tmp/err"
check "vg-0 valgrind reads the debug information of $exe" test ! -s "$tmp/err"
sed -n '1,3p' "$tmp/err"

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
vg "vg-11 quiz with no answers (1: not all right)" 1 quiz --seed 7
vg "vg-12 accuracy, classic camera" 0 accuracy docs/examples/triangle.scene --no-time
vg "vg-13 accuracy, matrix camera" 0 accuracy docs/examples/lookat-near.scene --no-time
vg "vg-14 journey: SVG and HTML" 0 journey --vertex 1 --svg "$tmp/j.svg" --html "$tmp/j.html"
"$exe" docs/examples/cube.scene --format jsonl > "$tmp/a.jsonl"
"$exe" docs/examples/cube.scene > "$tmp/a.txt"
vg "vg-15 diff: JSONL against text" 0 diff "$tmp/a.jsonl" "$tmp/a.txt"
"$exe" --image "$tmp/c.ppm"
vg "vg-16 diff: two images" 0 diff "$tmp/c.ppm" "$tmp/c.ppm"
vg "vg-17 the course's debug log with pixels" 0 tests/reference/basic-clip-edges.scene --format kraft-pixels
"$exe" tests/reference/basic-clip-edges.scene > "$tmp/e.txt"
vg "vg-18 diff reads the course's log" 0 diff tests/reference/kraftlog/basic-clip-edges.pixels.log "$tmp/e.txt"
vg "vg-19 diff: /dev/zero is refused at once, nothing leaks" 2 diff /dev/zero /dev/zero
vg "vg-20 shape lines mixed with v and l" 0 docs/examples/shapes/mixed.scene --image "$tmp/s.ppm"
printf 'model m\nshape torus 1e308 1e308 3 3\n' > "$tmp/inf.scene"
vg "vg-21 a shape whose coordinates overflow" 2 "$tmp/inf.scene"
vg "vg-22 the list of shapes" 0 shapes
vg "vg-23 export java" 0 export java docs/examples/shapes/mixed.scene -o "$tmp/Mixed.java" --pixels
vg "vg-24 diff: every mistake tested on every vertex, the verdict" 1 diff --verdict \
    tests/data/diff/selfcheck.jsonl tests/data/diff/selfcheck-trunc.jsonl
# A scene of 2,400 vertices on two threads (tests/bench/benchgen.c: a few pieces each
# way); helgrind too, for races between them and locks out of order.
b=${exe%/*}/benchgen
if [ -x "$b" ]; then
    "$b" 300 > "$tmp/b300.scene"
    vg "vg-25 the trace on two threads, JSONL, image" 0 "$tmp/b300.scene" --format jsonl \
        --threads 2 --image "$tmp/b300.ppm"
    valgrind -q --tool=helgrind --error-exitcode=99 "$exe" "$tmp/b300.scene" --format jsonl \
        --threads 2 --trace /dev/null </dev/null >/dev/null 2>"$tmp/err"
    rc=$?
    check "vg-26 helgrind: the two threads race for nothing (exit $rc)" test "$rc" = 0
    grep -q '^==' "$tmp/err" && sed -n '1,12p' "$tmp/err"
    # the course's renderer 9 with anti-aliasing: its lanes (src/io/trace_course.c)
    "$b" 300 1000 9 aa > "$tmp/b9.scene"
    vg "vg-27 renderer 9's trace on two threads, JSONL, image" 0 "$tmp/b9.scene" --format jsonl \
        --threads 2 --image "$tmp/b9.ppm"
    valgrind -q --tool=helgrind --error-exitcode=99 "$exe" "$tmp/b9.scene" --format kraft \
        --threads 2 --trace /dev/null </dev/null >/dev/null 2>"$tmp/err"
    rc=$?
    check "vg-28 helgrind: renderer 9's two lanes, the course's log, race for nothing (exit $rc)" \
        test "$rc" = 0
    grep -q '^==' "$tmp/err" && sed -n '1,12p' "$tmp/err"
else
    echo "  skipped: no $b to make a scene of several pieces"
fi
report
