#!/bin/sh
# tests/hostile.sh -- input that is out to hurt: endless, blocking, secret, dead pipes
# See LICENSE for copyright and license.
#
# Usage: sh tests/hostile.sh PIPETRACE.  Run from the repository root.  Issue
# 31 (a class folder is hostile input): each check here failed before its fix.
# Nothing is timed: an endless input runs under a memory cap (ulimit -v) and
# `timeout` only stops a hang, which is then a failure.
exe=${1:-build/pipetrace}
. tests/testlib.sh

# ---- obj PATH reads regular files only, at once
mkfifo "$tmp/fifo"
printf 'model m\nobj %s\n' "$tmp/fifo" > "$tmp/fifo.scene"
timeout 20 "$exe" "$tmp/fifo.scene" > "$tmp/out" 2> "$tmp/err" < /dev/null; rc=$?
check "hostile-1.1 obj of a FIFO with no writer is refused at once (exit $rc, not a hang)" test "$rc" = 2
check "hostile-1.2 ... with one message that says why" \
    test "$(cat "$tmp/err")" = "$tmp/fifo.scene:2:5: error: cannot read '$tmp/fifo': it is a FIFO, not a regular file"
printf 'model m\nobj /etc/passwd\n' > "$tmp/passwd.scene"
run "$tmp/passwd.scene"
check "hostile-1.3 obj /etc/passwd: exit 2 at its line 1" grep -q '^/etc/passwd:1:1: error: not an OBJ statement' "$tmp/err"
check "hostile-1.4 ... and none of its text in the message" sh -c "! grep -q root '$tmp/err'"

# ---- standard input is a stream, as a file is
# (each line of `yes` is valid until its end never comes, or the data fills memory)
lim() {     # lim KIB COMMAND: run COMMAND under a memory cap, at most 60 s
    ( ulimit -v "$1"; timeout 60 sh -c "$2" ) > "$tmp/out" 2> "$tmp/err"; rc=$?
}
lim 400000 "tr '\\000' ' ' < /dev/zero | '$exe' -"
check "hostile-2.1 an endless line on standard input ends (exit $rc) under a 400 MB cap" test "$rc" = 2
check "hostile-2.2 ... with one message: out of memory" test "$(cat "$tmp/err")" = "<stdin>:1:1: error: out of memory"
lim 400000 "{ echo 'model m'; yes 'v 1 2 3'; } | '$exe' -"
check "hostile-2.3 endless valid vertices on standard input end (exit $rc) under a 400 MB cap" test "$rc" = 2
check "hostile-2.4 ... with one message: out of memory" grep -q '^<stdin>:[0-9]*:[0-9]*: error: out of memory$' "$tmp/err"
lim 400000 "yes | '$exe' -"
check "hostile-2.5 yes | pipetrace - stops at its first line (exit $rc)" test "$rc" = 2
check "hostile-2.6 ... with its error" test "$(cat "$tmp/err")" = "<stdin>:1:1: error: unknown directive 'y'"
lim 400000 "'$exe' - < /dev/zero"
check "hostile-2.7 pipetrace - < /dev/zero: a NUL byte (exit $rc)" grep -q '^<stdin>:1:1: error: NUL byte$' "$tmp/err"
printf 'model m\nv 0 0 -1\nv 1 1 -2\nl 1 2\n' > "$tmp/head.scene"
lim 400000 "{ cat '$tmp/head.scene'; yes '# a comment of sixty bytes, repeated to make a large scene.' | head -c 600000000; } | '$exe' - --trace '$tmp/t.trace'"
check "hostile-2.8 600 MB of scene on standard input is read under a 400 MB cap (exit $rc)" test "$rc" = 0
check "hostile-2.9 ... and its model is traced" grep -q "segments 1 " "$tmp/t.trace"

report
