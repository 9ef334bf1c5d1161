#!/bin/sh
# tests/run.sh -- run every test program and script; add up their counts.
# See LICENSE for copyright and license.
#
# Usage: sh tests/run.sh BUILD_DIR.  Each test prints "N passed, N failed" as its
# last line; this script prints the sum as its own last line and exits 1 when
# anything failed (or a test crashed without printing its count).
B=${1:-build}
ref=tests/reference
[ -d ../shared/reference ] && ref=../shared/reference
passed=0
failed=0

one() {     # one NAME COMMAND...: run, show failures, add the counts
    name=$1; shift
    out=$("$@" 2>&1); rc=$?
    last=$(printf '%s\n' "$out" | grep -E '^[0-9]+ passed, [0-9]+ failed$' | tail -1)
    if [ -z "$last" ]; then
        printf '%s\n' "$out" | tail -20
        echo "$name: crashed or printed no count (exit $rc)"
        failed=$((failed + 1))
        return
    fi
    p=${last%% passed*}; f=${last#*, }; f=${f%% failed*}
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    printf '%s\n' "$out" | grep -E '^(FAIL|  )' | head -40
    printf '%-16s %s\n' "$name" "$last"
    passed=$((passed + p)); failed=$((failed + f))
}

one stages     "$B/test_stages"
one numfmt     "$B/test_numfmt"
one raster     "$B/test_raster"
one matrix     "$B/test_matrix"
one scene      "$B/test_scene"
one reference  "$B/test_reference" "$ref"
one fuzz       "$B/test_fuzz"
one explain    "$B/test_explain"
one png        "$B/test_png"
one golden     sh tests/golden.sh "$B/pipetrace"
one cli        sh tests/cli.sh "$B/pipetrace"
one diff       sh tests/diff.sh "$B/pipetrace"
one extreme    sh tests/extreme.sh "$B/pipetrace"
one teach      sh tests/teach.sh "$B/pipetrace"
one accuracy   sh tests/accuracy.sh "$B/pipetrace"
one journey    sh tests/journey.sh "$B/pipetrace"
one browser    sh tests/journey_browser.sh "$B/pipetrace"
one docs       sh tests/docs.sh "$B/pipetrace"
one valgrind   sh tests/valgrind.sh "$B/pipetrace"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
