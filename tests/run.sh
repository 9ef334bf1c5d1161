#!/bin/sh
# tests/run.sh -- run every test program and script; add up their counts.
# See LICENSE for copyright and license.
#
# Usage: sh tests/run.sh BUILD_DIR.  Each test prints "N passed, N failed" as its
# last line; this script prints the sum as its own last line and exits 1 when
# anything failed (or a test crashed without printing its count).  A group that
# cannot run for want of a tool prints "  skipped: WHY" (each such line is one
# skip); then the line before the sum says "N skipped (GROUP: WHY, ...)".  The
# groups run in two lanes at once (CI has two cores), the slowest ones split
# between them; their reports are printed afterwards in the order listed below.
# PT_RUN_GROUPS, when set, replaces the list (tests/runner.sh tests this script).
B=${1:-build}
ref=tests/reference
[ -d ../shared/reference ] && ref=../shared/reference
unset COLUMNS                   # step and why wrap to it (src/tools/cli.h)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0
failed=0
skipped=0
why=

# NAME LANE COMMAND...: the groups, in report order
groups=${PT_RUN_GROUPS:-"stages      1 $B/test_stages
numfmt      2 $B/test_numfmt
numfmt-portable 1 $B/test_numfmt_portable
jnum        2 $B/test_jnum
raster      1 $B/test_raster
pipelines   2 $B/test_pipelines
matrix      1 $B/test_matrix
scene       1 $B/test_scene
nameset     2 $B/test_nameset
numparse    2 $B/test_numparse
baseline    2 sh tests/baseline.sh $B
stream      2 sh tests/stream.sh $B/pipetrace
hostile     1 sh tests/hostile.sh $B/pipetrace
shapes      1 $B/test_shapes
reference   1 $B/test_reference $ref
catalogue   1 $B/test_catalogue $ref
fuzz        1 $B/test_fuzz
tread       2 $B/test_tread
trace       1 $B/test_trace
lanes       2 sh tests/lanes.sh $B
explain     1 $B/test_explain
png         1 $B/test_png
layers      1 sh tests/layers.sh
runner      2 sh tests/runner.sh $B
golden      1 sh tests/golden.sh $B/pipetrace
shapes-cli  2 sh tests/shapes.sh $B/pipetrace
install     2 sh tests/install.sh $B/pipetrace
export      2 sh tests/export.sh $B/pipetrace
cli         1 sh tests/cli.sh $B/pipetrace
outputs     2 sh tests/outputs.sh $B/pipetrace
diff        1 sh tests/diff.sh $B/pipetrace
kraft       2 sh tests/kraft.sh $B/pipetrace $ref
selfcheck   2 sh tests/selfcheck.sh $B/pipetrace
extreme     1 sh tests/extreme.sh $B/pipetrace
teach       1 sh tests/teach.sh $B/pipetrace
classroom   2 sh tests/classroom.sh $B/pipetrace
term        2 sh tests/term.sh $B/pipetrace
accuracy    1 sh tests/accuracy.sh $B/pipetrace
journey     1 sh tests/journey.sh $B/pipetrace
browser     2 sh tests/journey_browser.sh $B/pipetrace
wasm        1 sh tests/journey_wasm.sh $B/pipetrace
wasm-libm   1 $B/test_wasm_libm
docs        1 sh tests/docs.sh $B/pipetrace
valgrind    1 sh tests/valgrind.sh $B/pipetrace"}

lane() {    # lane N: run lane N's groups one after another, each into $out/NAME
    printf '%s\n' "$groups" | while read -r name l cmd; do
        [ "$l" = "$1" ] || continue
        $cmd > "$out/$name" 2>&1 < /dev/null   # (stdin is the list)
        echo $? > "$out/$name.rc"
    done
}

report() {  # report NAME: show failures, add the counts
    name=$1
    rc=$(cat "$out/$name.rc" 2>/dev/null || echo 1)
    last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$out/$name" | tail -1)
    if [ -z "$last" ]; then
        tail -20 "$out/$name"
        echo "$name: crashed or printed no count (exit $rc)"
        failed=$((failed + 1))
        return
    fi
    p=${last%% passed*}; f=${last#*, }; f=${f%% failed*}
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    grep -E '^(FAIL|  )' "$out/$name" | head -40
    s=$(grep -c '^  skipped: ' "$out/$name")
    if [ "$s" -gt 0 ]; then
        skipped=$((skipped + s))
        why="${why:+$why, }$(awk -v g="$name" '/^  skipped: / { sub(/^  skipped: /, "");
            printf "%s%s: %s", k++ ? ", " : "", g, $0 }' "$out/$name")"
    fi
    printf '%-16s %s\n' "$name" "$last"
    passed=$((passed + p)); failed=$((failed + f))
}

lane 1 &
lane 2
wait
for name in $(printf '%s\n' "$groups" | cut -d' ' -f1); do report "$name"; done
[ "$skipped" -gt 0 ] && echo "$skipped skipped ($why)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
