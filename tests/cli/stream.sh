#!/bin/sh
# tests/cli/stream.sh -- the scene is read as a stream: memory holds its data, not its text
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/stream.sh PIPETRACE.  100 MB of scene text, nearly all of
# it comments, arrives through a pipe; the process's peak resident memory
# must stay far below the text's size (a reader that holds the whole text
# needs more than 100 MB).  The trace streams too: a scene of two vertices
# whose trace is 120 MB of pixel records.  Memory is measured, not time:
# python3 asks the kernel for the child's peak (ru_maxrss; at least the
# forked python's own, some 14 MB).
exe=${1:-build/pipetrace}
. tests/lib/testlib.sh

peak_kib() {    # peak_kib COMMAND: run it, print its peak resident memory in KiB
    python3 -c 'import resource, subprocess, sys
r = subprocess.run(sys.argv[1], shell=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss if r.returncode == 0 else -1)' "$1"
}

comments="yes '# a comment of sixty bytes, repeated to make a large scene.' | head -c 100000000"
printf 'model m\nv 0 0 -1\nv 1 1 -2\nl 1 2\n' > "$tmp/head.scene"
kib=$(peak_kib "{ cat '$tmp/head.scene'; $comments; } | '$exe' /dev/stdin --trace '$tmp/t.trace'")
check "stream-1.1 100 MB of scene through a pipe is read (peak $kib KiB)" test "$kib" -gt 0
check "stream-1.2 ... in less than 60 MiB" test "$kib" -lt 61440
check "stream-1.3 ... and its model is traced" grep -q "segments 1 " "$tmp/t.trace"
printf 'model m\nv 0 0 -1\n' > "$tmp/a.scene"
awk 'BEGIN { printf "v 1 1 -2\nl 1 2 # "; for (i = 0; i < 200000; i++) printf "x"; print "" }' \
    >> "$tmp/a.scene"
run "$tmp/a.scene"
check "stream-1.4 a line longer than the read window (200 kB) is read whole" \
    grep -q "segments 1 " "$tmp/out"
# a hundred diagonals of a 16384 x 16384 framebuffer: 1.6 million pixel records
{ printf 'framebuffer 16384 16384\nmodel m\nv -0.99 -0.99 -1\nv 0.99 0.99 -1\n'
  i=0; while [ $i -lt 100 ]; do echo "l 1 2"; i=$((i + 1)); done; } > "$tmp/long.scene"
kib=$(peak_kib "'$exe' '$tmp/long.scene' --format jsonl --trace - | wc -c > '$tmp/bytes'")
bytes=$(tr -d ' ' < "$tmp/bytes")
check "stream-2.1 a trace of $bytes bytes from a scene of two vertices is written" \
    test "$bytes" -gt 100000000
check "stream-2.2 ... in blocks: the peak memory ($kib KiB) stays below 60 MiB, half the trace" \
    test "$kib" -gt 0 -a "$kib" -lt 61440
report
