#!/bin/sh
# tests/bench/class_bench.sh -- make bench: pipetrace class on a folder of 300 traces of 1 MB
# See LICENSE for copyright and license.
#
# Usage: sh tests/bench/class_bench.sh BUILD.  The scene: build/benchgen's 90
# octagons (720 vertices) with a viewport off the framebuffer's corner; its
# JSON Lines trace with every stage is 1 MB.  The folder: 300 copies, every
# other one with its first viewport x one more (a student whose viewport
# stage is off by one there).  Prints the wall seconds of `pipetrace class
# SCENE DIR` with both CPUs allowed, the least of 3 runs, and checks its
# counts.
b=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$b/benchgen" 90 | sed 's/^framebuffer 1920 1080$/&\nviewport 8 6 1900 1060/' > "$tmp/class.scene"
"$b/pipetrace" "$tmp/class.scene" --all-stages --format jsonl --trace "$tmp/expected.jsonl" || exit 1
mkdir "$tmp/dir"
i=1
while [ $i -le 300 ]; do
    n=$(printf 's%03d' $i)
    if [ $((i % 2)) = 0 ]; then
        cp "$tmp/expected.jsonl" "$tmp/dir/$n.jsonl"
    else
        awk '!done && /"stage":"viewport"/ { sub(/"x":[0-9]+/, "\"x\":" ($0 ~ /"x":0,/ ? 1 : 0)); done = 1 } 1' \
            "$tmp/expected.jsonl" > "$tmp/dir/$n.jsonl"
    fi
    i=$((i + 1))
done
size=$(wc -c < "$tmp/expected.jsonl")
best=
for run in 1 2 3; do
    t0=$(date +%s.%N)
    "$b/pipetrace" class "$tmp/class.scene" "$tmp/dir" > "$tmp/out" || exit 1
    t1=$(date +%s.%N)
    t=$(echo "$t1 $t0" | awk '{ printf "%.3f", $1 - $2 }')
    best=$(echo "$t ${best:-$t}" | awk '{ print ($1 < $2 ? $1 : $2) }')
done
counts=$(grep -E '^[0-9]+ passed,' "$tmp/out")
printf 'pipetrace class, 300 traces of %.2f MB each against their scene, both CPUs:\n' \
    "$(echo "$size" | awk '{ print $1 / 1e6 }')"
printf '  %.3f s wall, the least of 3   (%s; target: a few seconds)\n' "$best" "$counts"
[ "$counts" = "150 passed, 150 failed, 0 not proven, 0 unreadable" ]
