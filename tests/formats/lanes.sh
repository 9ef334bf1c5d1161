#!/bin/sh
# tests/formats/lanes.sh -- the trace on two threads (--threads 2, src/io/tlanes.c) is
# the trace on one
# See LICENSE for copyright and license.
#
# Usage: sh tests/formats/lanes.sh BUILD_DIR.  Run from the repository root.
# $B/test_lanes compares the two ways in process, with pieces of every size,
# for every scene of the repository that loads and for a benchmark scene of
# 20,000 vertices (tests/bench/benchgen.c: many pieces of the default size); its
# count is added to this script's.  Then the command line: --threads 1 and 2
# give the same bytes and images, a write error is reported alike, and a bad
# --threads is a usage error.
B=$1
exe=$B/pipetrace
. tests/lib/testlib.sh

# ---- in process: every scene that loads
"$B/benchgen" 2500 > "$tmp/bench.scene"
scenes=$(for s in docs/examples/*.scene docs/examples/shapes/*.scene docs/exercises/*.scene \
                  tests/data/*.scene tests/extreme/*.scene tests/reference/*.scene; do
             "$exe" "$s" --trace /dev/null --threads 1 >/dev/null 2>&1 && echo "$s"
         done)
# shellcheck disable=SC2086 # one argument a scene
"$B/test_lanes" $scenes "$tmp/bench.scene" > "$tmp/lanes" 2>&1
add_counts "$tmp/lanes" test_lanes
check "lanes-1.1 some 100 scenes load" test "$(echo "$scenes" | wc -l)" -ge 100

# ---- the command line: the same bytes on one thread and on two
for fmt in jsonl text csv; do
    for t in 1 2; do
        "$exe" "$tmp/bench.scene" --format "$fmt" --trace "$tmp/$fmt-$t" --image "$tmp/$fmt-$t.ppm" \
            --threads "$t" 2>"$tmp/err-$t"
        echo $? > "$tmp/rc-$t"
    done
    check "lanes-2.1 $fmt: exit 0 on both" test "$(cat "$tmp/rc-1")$(cat "$tmp/rc-2")" = 00
    check "lanes-2.2 $fmt: the same trace" cmp "$tmp/$fmt-1" "$tmp/$fmt-2"
    check "lanes-2.3 $fmt: the same image" cmp "$tmp/$fmt-1.ppm" "$tmp/$fmt-2.ppm"
done
run "$tmp/bench.scene" --format jsonl --trace - --explain --threads 2
check "lanes-2.4 --explain to standard output: as on one thread" \
    sh -c '"$1" "$2" --format jsonl --trace - --explain --threads 1 | cmp - "$3"' \
    sh "$exe" "$tmp/bench.scene" "$tmp/out"
run docs/examples/triangle.scene --trace - --threads 2
check "lanes-2.5 the default text trace to standard output" \
    sh -c '"$1" docs/examples/triangle.scene --trace - --threads 1 | cmp - "$2"' sh "$exe" "$tmp/out"

# ---- a write that fails: reported as on one thread
if [ -w /dev/full ]; then
    run "$tmp/bench.scene" --format jsonl --trace /dev/full --threads 2
    rc2=$rc err2=$err
    run "$tmp/bench.scene" --format jsonl --trace /dev/full --threads 1
    check "lanes-3.1 /dev/full: exit 2" test "$rc2" = 2
    check "lanes-3.2 /dev/full: the message of one thread" test "$err2" = "$err"
else
    echo "  skipped: no /dev/full to fail a write"
fi

# ---- --threads takes 1 or 2
for bad in 0 3 x ""; do
    run docs/examples/triangle.scene --trace - --threads "$bad"
    check "lanes-4.1 --threads '$bad': a usage error" test "$rc" = 1
done
run docs/examples/triangle.scene --trace - --threads 3
check "lanes-4.2 ... that says what it takes" \
    sh -c 'grep -q "takes 1 or 2, not .3." "$1"' sh "$tmp/err"

report
