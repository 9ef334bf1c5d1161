#!/bin/sh
# tests/formats/lanes79.sh -- renderers 7 and 9: the trace and the course's log on two
# threads (--threads 2, src/io/tlanes.c) are the ones on one
# See LICENSE for copyright and license.
#
# Usage: sh tests/formats/lanes79.sh BUILD_DIR.  Run from the repository root.
# $B/test_lanes79 compares the two ways in process, in every format, with the
# driver's pieces of every size, for the course's scenes of tests/course79/ and
# tests/course/ that load, and for two benchmark scenes of 4,000 vertices
# (tests/bench/benchgen.c: renderer 9 with anti-aliasing, renderer 7), whose
# pieces must go to both threads; it also checks that the second thread runs
# the rasterizer on its own pieces' primitives only, and that the pixel lines
# the cuts count (pt_rv_raster_steps) are those drawn; its count is added to
# this script's.  Then
# the command line: --threads 1 and 2 give the same bytes and images, the
# default takes two threads on two CPUs and gives the same bytes, and a write
# error is reported alike.
B=$1
exe=$B/pipetrace
. tests/lib/testlib.sh

# ---- in process: the benchmark scenes (pieces on both threads), every course scene
"$B/benchgen" 500 1000 9 aa > "$tmp/r9aa.scene"
"$B/benchgen" 500 1000 7 > "$tmp/r7.scene"
scenes=$(for s in tests/course79/*.scene tests/course/r7/*.scene tests/course/r9/*.scene; do
             "$exe" "$s" --trace /dev/null --threads 1 >/dev/null 2>&1 && echo "$s"
         done)
# shellcheck disable=SC2086 # one argument a scene
"$B/test_lanes79" --both 2 "$tmp/r9aa.scene" "$tmp/r7.scene" $scenes > "$tmp/lanes" 2>&1
add_counts "$tmp/lanes" test_lanes79
check "lanes79-4.1 some 500 course scenes load" test "$(echo "$scenes" | wc -l)" -ge 500

# ---- the command line: the same bytes on one thread and on two
for sc in r9aa r7; do
    for fmt in jsonl text csv kraft kraft-pixels; do
        for t in 1 2; do
            "$exe" "$tmp/$sc.scene" --format "$fmt" --trace "$tmp/$fmt-$t" \
                --image "$tmp/$fmt-$t.ppm" --threads "$t" 2>"$tmp/err-$t"
            echo $? > "$tmp/rc-$t"
        done
        check "lanes79-5.1 $sc $fmt: exit 0 on both" test "$(cat "$tmp/rc-1")$(cat "$tmp/rc-2")" = 00
        check "lanes79-5.2 $sc $fmt: the same trace" cmp "$tmp/$fmt-1" "$tmp/$fmt-2"
        check "lanes79-5.3 $sc $fmt: the same image" cmp "$tmp/$fmt-1.ppm" "$tmp/$fmt-2.ppm"
    done
done
run "$tmp/r9aa.scene" --format jsonl --trace - --explain --threads 2
check "lanes79-5.4 --explain to standard output: as on one thread" \
    sh -c '"$1" "$2" --format jsonl --trace - --explain --threads 1 | cmp - "$3"' \
    sh "$exe" "$tmp/r9aa.scene" "$tmp/out"
run "$tmp/r9aa.scene" --format text --trace -
check "lanes79-5.5 the default (two threads with two CPUs): as on one thread" \
    sh -c '"$1" "$2" --format text --trace - --threads 1 | cmp - "$3"' \
    sh "$exe" "$tmp/r9aa.scene" "$tmp/out"

# ---- a write that fails: reported as on one thread
if [ -w /dev/full ]; then
    for fmt in jsonl kraft; do
        run "$tmp/r9aa.scene" --format "$fmt" --trace /dev/full --threads 2
        rc2=$rc err2=$err
        run "$tmp/r9aa.scene" --format "$fmt" --trace /dev/full --threads 1
        check "lanes79-6.1 $fmt to /dev/full: exit 2" test "$rc2" = 2
        check "lanes79-6.2 $fmt to /dev/full: the message of one thread" test "$err2" = "$err"
        check "lanes79-6.3 ... which says the trace was not written" \
            sh -c 'echo "$1" | grep -q "cannot write the trace"' sh "$err2"
        check "lanes79-6.4 ... and why, as the system said it (ENOSPC), not 'a write failed'" \
            sh -c 'echo "$1" | grep -q "No space left on device"' sh "$err2"
    done
    run tests/course/r7/vpout-01.scene --format csv --trace /dev/full
    check "lanes79-6.5 a small trace on one thread (csv) to /dev/full: exit 2, why said" \
        test "$rc" = 2 -a -n "$(echo "$err" | grep 'No space left on device')"
else
    echo "  skipped: no /dev/full to fail a write"
fi

report
