#!/bin/sh
# tests/run.sh -- run every test program and script; add up their counts.
# See LICENSE for copyright and license.
#
# Usage: sh tests/run.sh BUILD_DIR.  Each test prints "N passed, N failed" as its
# last line; this script prints the sum as its own last line and exits 1 when
# anything failed (or a test crashed without printing its count).  A group that
# cannot run for want of a tool prints "  skipped: WHY" (each such line is one
# skip); then the line before the sum says "N skipped (GROUP: WHY, ...)".  The
# groups run in two lanes at once (CI has two cores; PT_TEST_LANES=N for N):
# each lane takes the longest group not yet taken (by the seconds listed
# below), so the lanes end close together; the reports are printed afterwards
# in the order listed below.
# PT_RUN_GROUPS, when set, replaces the list (tests/repo/runner.sh tests this script).
# Names after BUILD_DIR keep only those groups: sh tests/run.sh build cli diff.
# PT_TEST_TIMES=1 adds each group's seconds to its line, then each lane's
# total (tests/README.md maps the groups to their files).
B=${1:-build}
[ $# -gt 0 ] && shift
ref=tests/reference
[ -d ../shared/reference ] && ref=../shared/reference
unset COLUMNS                   # step and why wrap to it (src/tools/cli.h)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0
failed=0
skipped=0
why=

# NAME SECONDS COMMAND...: the groups, in report order; SECONDS is about what
# the group takes on one idle core (PT_TEST_TIMES=1 shows it)
groups=${PT_RUN_GROUPS:-"stages           1 $B/test_stages
numfmt          10 $B/test_numfmt
numfmt-portable 10 $B/test_numfmt_portable
jnum             1 $B/test_jnum
jmath            1 $B/test_jmath
raster           1 $B/test_raster
rv-raster        1 $B/test_rv_raster
pipelines        1 $B/test_pipelines
journey-rows     1 $B/test_journey
matrix           1 $B/test_matrix
rv-stages        1 $B/test_rv_stages tests/data/course
scene            1 $B/test_scene
nameset          1 $B/test_nameset
numparse         1 $B/test_numparse
baseline         2 sh tests/bench/baseline.sh $B
stream           1 sh tests/cli/stream.sh $B/pipetrace
shapes           1 $B/test_shapes
reference        1 $B/test_reference $ref
catalogue        1 $B/test_catalogue $ref
fuzz             1 $B/test_fuzz
tread            1 $B/test_tread
trace            1 $B/test_trace
lanes           31 sh tests/formats/lanes.sh $B
lanes79         11 sh tests/formats/lanes79.sh $B
explain          1 $B/test_explain
png              1 $B/test_png
layers           1 sh tests/repo/layers.sh
paths            1 sh tests/repo/paths.sh
runner           1 sh tests/repo/runner.sh $B
golden           1 sh tests/formats/golden.sh $B/pipetrace
shapes-cli       1 sh tests/cli/shapes.sh $B/pipetrace
install          1 sh tests/cli/install.sh $B/pipetrace
export           4 sh tests/cli/export.sh $B/pipetrace
cli              1 sh tests/cli/cli.sh $B/pipetrace
hostile         35 sh tests/cli/hostile.sh $B/pipetrace
outputs          1 sh tests/cli/outputs.sh $B/pipetrace
diff            45 sh tests/teach/diff.sh $B/pipetrace
diff79          11 sh tests/teach/diff79.sh $B/pipetrace
kraft            3 sh tests/formats/kraft.sh $B/pipetrace $ref
course79         2 sh tests/course79/course79.sh $B/pipetrace
course4          2 sh tests/course4/course4.sh $B/pipetrace
course          20 python3 tests/course/check.py $B/pipetrace
selfcheck       31 sh tests/teach/selfcheck.sh $B/pipetrace
extreme          1 sh tests/cli/extreme.sh $B/pipetrace
teach            2 sh tests/teach/teach.sh $B/pipetrace
teach79          3 sh tests/teach/teach79.sh $B/pipetrace
classroom        6 sh tests/teach/classroom.sh $B/pipetrace
class           14 sh tests/teach/class.sh $B/pipetrace
students         8 sh tests/class/students.sh $B/pipetrace
quiz79           2 sh tests/teach/quiz79.sh $B/pipetrace
term             1 sh tests/cli/term.sh $B/pipetrace
accuracy         8 sh tests/cli/accuracy.sh $B/pipetrace
journey          6 sh tests/journey/journey.sh $B/pipetrace
journey79        4 sh tests/journey/journey79.sh $B/pipetrace
browser         42 sh tests/journey/journey_browser.sh $B/pipetrace
wasm            48 sh tests/journey/journey_wasm.sh $B/pipetrace
wasm-libm        1 $B/test_wasm_libm
docs             2 sh tests/repo/docs.sh $B/pipetrace
valgrind        16 sh tests/cli/valgrind.sh $B/pipetrace"}

if [ $# -gt 0 ]; then       # only the groups named
    groups=$(printf '%s\n' "$groups" | awk -v names=" $* " 'index(names, " " $1 " ")')
    [ -n "$groups" ] || { echo "tests/run.sh: no group named $*" >&2; exit 2; }
fi

stamp() {   # stamp FILE: the time (epoch seconds) and `times`: on its third
            # line the CPU time of this shell's children so far
    { date +%s.%N | cut -c1-13; times; } > "$1"
}

lanes=${PT_TEST_LANES:-2}
# the order the lanes take the groups in: the longest first
order=$(printf '%s\n' "$groups" | awk '{ print $2, NR, $1 }' | sort -k1,1nr -k2,2n | cut -d' ' -f3)

lane() {    # lane N: take the next group nobody has taken, run it into $out/NAME; again
    for name in $order; do
        mkdir "$out/$name.taken" 2>/dev/null || continue    # (atomic: one lane wins)
        echo "$1" > "$out/$name.lane"
        cmd=$(printf '%s\n' "$groups" | awk -v g="$name" '$1 == g { $1 = $2 = ""; print; exit }')
        stamp "$out/$name.t0"
        $cmd > "$out/$name" 2>&1 < /dev/null
        echo $? > "$out/$name.rc"
        stamp "$out/$name.t1"
        cat "$out/$name.t0" "$out/$name.t1" | awk '{ gsub(/[ms]/, " ") }
            NR % 3 == 1 { t[NR > 3] = $1 } NR % 3 == 0 { c[NR > 3] = $1 * 60 + $2 + $3 * 60 + $4 }
            END { printf "%.1f %.1f\n", t[1] - t[0], c[1] - c[0] }' > "$out/$name.s"
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
    if [ -n "${PT_TEST_TIMES:-}" ]; then
        printf '%-16s %-24s %s (lane %s)\n' "$name" "$last" \
            "$(awk '{ printf "%6.1fs wall %6.1fs CPU", $1, $2 }' "$out/$name.s")" "$(cat "$out/$name.lane")"
    else
        printf '%-16s %s\n' "$name" "$last"
    fi
    passed=$((passed + p)); failed=$((failed + f))
}

t0=$(date +%s)
l=1
while [ "$l" -lt "$lanes" ]; do lane "$l" & l=$((l + 1)); done
lane "$lanes" &   # (each in the background: `times` counts only its own)
wait
for name in $(printf '%s\n' "$groups" | cut -d' ' -f1); do report "$name"; done
if [ -n "${PT_TEST_TIMES:-}" ]; then
    l=1
    while [ "$l" -le "$lanes" ]; do
        for name in $order; do
            [ "$(cat "$out/$name.lane" 2>/dev/null)" = "$l" ] && cat "$out/$name.s"
        done | awk -v l="$l" '{ t += $1; c += $2 } END { printf "lane %s: %.1fs wall, %.1fs CPU\n", l, t, c }'
        l=$((l + 1))
    done
    echo "all lanes: $(($(date +%s) - t0))s wall"
fi
[ "$skipped" -gt 0 ] && echo "$skipped skipped ($why)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
