# tests/lib/testlib.sh -- what the shell tests share; sourced after setting $exe
# See LICENSE for copyright and license.
#
# check DESCRIPTION COMMAND...  counts one check: COMMAND must succeed
# run ARGS...                   runs $exe ARGS with no input; sets $out, $err, $rc
#                               (also in $tmp/out and $tmp/err)
# feed INPUT ARGS...            the same with INPUT (backslash escapes: printf %b)
#                               on standard input
# add_counts FILE PROGRAM        adds the counts of FILE, a test program's output,
#                               to this script's (its other lines printed, 20 at most)
# pyrun SCRIPT ARGS...          runs python3 SCRIPT ARGS (SCRIPT "-": the script on
#                               standard input) and adds the "N passed, N failed"
#                               it ends with to ours, its FAIL lines shown; no last
#                               line counts as a failure; without python3, nothing
# report                        prints "N passed, N failed"; fails if any failed
unset COLUMNS                   # step and why wrap to it: tests set it themselves
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

check() {
    d=$1; shift
    if "$@" >/dev/null 2>&1; then passed=$((passed + 1))
    else failed=$((failed + 1)); echo "FAIL $d"; fi
}

run() {
    "$exe" "$@" >"$tmp/out" 2>"$tmp/err" </dev/null; rc=$?
    out=$(cat "$tmp/out"); err=$(cat "$tmp/err")
}

feed() {
    input=$1; shift
    printf '%b' "$input" | "$exe" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?
    out=$(cat "$tmp/out"); err=$(cat "$tmp/err")
}

add_counts() {
    grep -v '^[0-9]* passed, [0-9]* failed$' "$1" | head -20
    counts=$(tail -1 "$1")
    case $counts in
        *" passed, "*" failed") passed=$((passed + ${counts%% passed*}))
                                f=${counts#*passed, }; failed=$((failed + ${f%% failed}));;
        *) failed=$((failed + 1)); echo "FAIL $2 printed no count";;
    esac
}

pyrun() {
    command -v python3 >/dev/null 2>&1 || return 0
    python3 "$@" > "$tmp/py" 2>&1
    grep -E '^(FAIL|  )' "$tmp/py" | head -20
    last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$tmp/py" | tail -1)
    if [ -z "$last" ]; then
        tail -5 "$tmp/py"; echo "FAIL python3 $* crashed"; failed=$((failed + 1)); return 0
    fi
    p=${last%% passed*}; f=${last#*, }; f=${f%% failed*}
    passed=$((passed + p)); failed=$((failed + f))
}

report() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
