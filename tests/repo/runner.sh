#!/bin/sh
# tests/repo/runner.sh -- tests/run.sh itself: sums, skips, and its last line
# See LICENSE for copyright and license.
#
# Usage: sh tests/repo/runner.sh BUILD_DIR (part of `make test`).  Runs tests/run.sh
# on small group lists (PT_RUN_GROUPS) and checks what it prints: the sum as
# the very last line, "N skipped (...)" just before it when a group skipped for
# want of a tool, and exit status 1 when a group failed or printed no count.
# valgrind.sh skips for a binary built with AddressSanitizer, which it tells by
# the bytes "__asan_init": a file holding them stands in for one.
B=${1:-build}
exe=$B/pipetrace
. tests/lib/testlib.sh
printf '__asan_init\n' > "$tmp/asan"

PT_RUN_GROUPS="layers 1 sh tests/repo/layers.sh
valgrind 2 sh tests/cli/valgrind.sh $tmp/asan" sh tests/run.sh "$B" > "$tmp/out" 2>&1
rc=$?
check "run-1.1 a group skipped for want of a tool: still exit 0 (exit $rc)" test "$rc" = 0
check "run-1.2 ... the last line is the sum" sh -c 'tail -1 "$1" | grep -Eqx "[1-9][0-9]* passed, 0 failed"' _ "$tmp/out"
check "run-1.3 ... and the line before it counts the skip and says why" \
    sh -c 'tail -2 "$1" | head -1 | grep -Fqx "1 skipped (valgrind: built with AddressSanitizer)"' _ "$tmp/out"

# a binary valgrind cannot run (an instruction it does not know, as in a
# -march=native build on a CPU with AVX-512): a script that dies of SIGILL
# as such a binary does under it stands in for one
if command -v valgrind > /dev/null 2>&1; then
    printf '#!/bin/sh\necho "vex amd64->IR: unhandled instruction bytes" >&2\nkill -ILL $$\n' > "$tmp/sigill"
    chmod +x "$tmp/sigill"
    sh tests/cli/valgrind.sh "$tmp/sigill" > "$tmp/out" 2>&1
    rc=$?
    check "run-1.4 valgrind's group skips a binary it cannot run, says why (exit $rc)" \
        sh -c 'test "$2" = 0 && grep -q "skipped: valgrind cannot run" "$1" && tail -1 "$1" | grep -qx "0 passed, 0 failed"' _ "$tmp/out" "$rc"
fi

PT_RUN_GROUPS="layers 1 sh tests/repo/layers.sh" sh tests/run.sh "$B" > "$tmp/out" 2>&1
check "run-2.1 nothing skipped: no skip line" sh -c '! grep -q skipped "$1" && tail -1 "$1" | grep -Eqx "[1-9][0-9]* passed, 0 failed"' _ "$tmp/out"

PT_RUN_GROUPS="layers 1 sh tests/repo/layers.sh
lost 2 sh tests/no-such-test.sh" sh tests/run.sh "$B" > "$tmp/out" 2>&1
rc=$?
check "run-3.1 a group with no count fails the run (exit $rc)" test "$rc" = 1
check "run-3.2 ... and counts as one failure on the last line" sh -c 'tail -1 "$1" | grep -Eqx "[1-9][0-9]* passed, 1 failed"' _ "$tmp/out"
report
