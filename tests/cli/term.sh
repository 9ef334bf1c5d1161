#!/bin/sh
# tests/cli/term.sh -- messages and the terminal: suggestions for a mistyped command
# or option, the stages listed, "no models", every --help's Docs line, the
# top-level usage listing every option; step, why and --compare-cameras
# wrapped to the terminal's width; step's keys
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/term.sh PIPETRACE.  Run from the repository root.
exe=$1
. tests/lib/testlib.sh
tri=docs/examples/triangle.scene


# ---- a mistyped command or option: the nearest is suggested
run stpe
check "term-1.1 'pipetrace stpe': a usage error (exit 1)" test "$rc" = 1
check "term-1.2 ... suggesting step" grep -qxF "pipetrace: no command or scene file 'stpe' (did you mean 'step'?)" "$tmp/err"
run qiuz --vertex 1
check "term-1.3 'qiuz': did you mean 'quiz'?" grep -qF "(did you mean 'quiz'?)" "$tmp/err"
run nosuch.scene
check "term-1.4 a scene that is no command's near miss: the file error, exit 2" \
    test "$rc" = 2 -a -n "$(grep '^nosuch.scene:1:1: error: cannot read file' "$tmp/err")"
run --vertx 1
check "term-1.5 unknown option of the render command: the nearest" grep -qxF "pipetrace: unknown option '--vertx' (did you mean '--vertex'?)" "$tmp/err"
check "term-1.6 ... exit 1" test "$rc" = 1
run --al
check "term-1.7 ... only among the render command's own options" grep -qxF "pipetrace: unknown option '--al'" "$tmp/err"
for c in "step --interactiv" "quiz --grde" "why --mdl" "journey --htm" "accuracy --no-tme" "diff --tl" "stages --cmra"; do
    set -- $c
    run $1 $2
    want=1; [ "$1" = diff ] && want=2      # diff's usage errors: 2, as diff(1)
    check "term-1.8 pipetrace $1 $2: a suggestion from its own options" \
        test "$rc" = "$want" -a -n "$(grep "^pipetrace $1: unknown option '$2' (did you mean '--[a-z-]*'?)$" "$tmp/err")"
done
run --qqqqqq
check "term-1.9 nothing near: no suggestion" grep -qxF "pipetrace: unknown option '--qqqqqq'" "$tmp/err"

# ---- --stage lists the stages; an empty scene warns
run $tri --stage pixle
check "term-2.1 --stage with an unknown name lists every stage (from the stage table)" \
    grep -qxF "pipetrace: unknown stage 'pixle' (the stages: $("$exe" stages | awk '/^[a-z]/ && !seen[$1]++ { printf "%s, ", $1 }')raster)" "$tmp/err"
check "term-2.2 ... exit 1" test "$rc" = 1
: > "$tmp/empty.scene"
run "$tmp/empty.scene"
check "term-2.3 an empty scene warns: no models" grep -qxF "pipetrace: warning: $tmp/empty.scene has no models: nothing to trace or draw" "$tmp/err"
check "term-2.4 ... and still writes its (empty) trace" test "$rc" = 0 -a -n "$(grep '^# pipetrace trace' "$tmp/out")"
run $tri
check "term-2.5 a scene with models: no warning" test -z "$err"
run step "$tmp/empty.scene"
check "term-2.6 step on an empty scene: 'has no models', exit 2" \
    test "$rc" = 2 -a "$err" = "pipetrace step: --vertex 1: $tmp/empty.scene has no models"

# ---- --help: a Docs line at the end, naming files that exist; every option in the top-level usage
"$exe" --help > "$tmp/top"
cmds=$(sed -n 's/^ *\(usage: \)\{0,1\}pipetrace \([a-z][a-z-]*\) .*/\2/p; s/^ *pipetrace \([a-z][a-z-]*\)$/\1/p' "$tmp/top" | sort -u)
for c in diff quiz step why; do
    check "term-3.1 the top-level usage names the command $c" sh -c "echo '$(echo $cmds)' | grep -qw $c"
done
for c in "" $cmds; do
    "$exe" $c --help > "$tmp/help"
    docs=$(tail -1 "$tmp/help")
    check "term-3.2 pipetrace $c --help ends with a Docs line" test "${docs#Docs: }" != "$docs"
    missing=
    for f in $(echo "${docs#Docs: }" | tr ',' ' '); do [ -f "$f" ] || missing="$missing $f"; done
    check "term-3.3 pipetrace $c --help: its Docs files exist ($missing)" test -z "$missing"
    [ -z "$c" ] && continue
    # the lines of the top-level usage that show this command
    awk -v c="$c" '/^ *(usage: )?pipetrace / { on = ($0 ~ "pipetrace " c "( |$)") } /^[A-Z]/ { on = 0 } on' "$tmp/top" > "$tmp/syn"
    missing=
    for o in $(grep -o -- '--[a-z][a-z-]*' "$tmp/help" | sort -u); do
        [ "$o" = --help ] && continue
        grep -q -- "$o\b" "$tmp/syn" || missing="$missing $o"
    done
    check "term-3.4 the top-level usage lists every option of $c ($missing)" test -z "$missing"
done

# ---- wrapped to the terminal's width, no number split
# words WIDTH ARGS...: every line of "COLUMNS=WIDTH pipetrace ARGS" fits (but
# for a word longer than the line), and the words are the unwrapped output's.
words() {
    w=$1; shift
    "$exe" "$@" > "$tmp/wide"
    COLUMNS=$w "$exe" "$@" > "$tmp/narrow"
    tr -s ' \n' '\n\n' < "$tmp/wide" > "$tmp/w1"
    tr -s ' \n' '\n\n' < "$tmp/narrow" > "$tmp/w2"
}
fits() {    # fits WIDTH FILE: no line longer than WIDTH unless it is one word after its indentation
    awk -v w="$1" 'length($0) > w && NF > 1 { bad = 1 } END { exit bad }' "$2"
}
words 40 step --vertex 1 --all
check "term-4.1 COLUMNS=40 step: lines fit in 40 columns" fits 40 "$tmp/narrow"
check "term-4.2 ... the same words, so no number split" cmp -s "$tmp/w1" "$tmp/w2"
check "term-4.3 ... and it was wrapped (wider than 40 without COLUMNS)" test "$(awk 'length($0) > 40' "$tmp/wide" | wc -l)" -gt 10
check "term-4.4 ... a continued 'here' line starts under the text" \
    grep -q '^           y_c = y_m + y_t = -1 + 0.25$' "$tmp/narrow"
words 50 why 200 150
check "term-4.5 COLUMNS=50 why: lines fit" fits 50 "$tmp/narrow"
check "term-4.6 ... the same words" cmp -s "$tmp/w1" "$tmp/w2"
words 60 step docs/examples/compare-classic.scene --vertex 1 --compare-cameras
check "term-4.7 COLUMNS=60 --compare-cameras: lines fit" fits 60 "$tmp/narrow"
check "term-4.8 ... one camera under the other" grep -qxF "  matrix   ndc       (x_n, y_n, z_n) = (0.5, -0.5," "$tmp/narrow"
tr -s ' \n' '\n\n' < "$tmp/narrow" | grep -E '^-?[0-9.]+[,)]*$' | tr -d ',)' | sort -u > "$tmp/n2"
tr -s ' \n' '\n\n' < "$tmp/wide" | grep -E '^-?[0-9.]+[,)]*$' | tr -d ',)' | sort -u > "$tmp/n1"
check "term-4.9 ... every number of the side-by-side table, whole" cmp -s "$tmp/n1" "$tmp/n2"
COLUMNS=60 "$exe" step $tri --vertex 1 --all > "$tmp/c60"
COLUMNS=abc "$exe" step $tri --vertex 1 --all > "$tmp/cabc"
"$exe" step $tri --vertex 1 --all > "$tmp/c0"
check "term-4.10 COLUMNS not a number: not wrapped" cmp -s "$tmp/cabc" "$tmp/c0"
check "term-4.11 (and COLUMNS=60 does wrap it)" test "$(cmp -s "$tmp/c60" "$tmp/c0"; echo $?)" = 1
# the terminal's own width, through a pseudo-terminal of 45 columns
if command -v python3 >/dev/null 2>&1; then
    python3 - "$exe" > "$tmp/pty" 2>&1 <<'PY'
import fcntl, os, pty, select, struct, subprocess, sys, termios, time
m, s = pty.openpty()
fcntl.ioctl(s, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 45, 0, 0))
env = dict(os.environ); env.pop("COLUMNS", None)
p = subprocess.Popen([sys.argv[1], "step", "--vertex", "1", "--all"], stdout=s, stderr=s,
                     stdin=subprocess.DEVNULL, env=env)
# The slave stays open here: Linux may flush a pty whose last slave closed
# before the master has read it all. Read until the child has ended and the
# master has been quiet for a while (60 s at most in all).
out, end = b"", time.monotonic() + 60
while time.monotonic() < end:
    if select.select([m], [], [], 0.3)[0]:
        out += os.read(m, 65536)
    elif p.poll() is not None:
        break
p.wait()
sys.stdout.write(out.decode().replace("\r\n", "\n"))
PY
    check "term-4.12 on a terminal of 45 columns, without COLUMNS: wrapped to 45" fits 45 "$tmp/pty"
    check "term-4.13 ... (the whole journey is there)" grep -q "^stage 7 of 7" "$tmp/pty"
fi

# ---- step's keys: a stage number, Q, back at the first stage, end of input
feed '5\nb\nQ\n' step $tri --vertex 1 --interactive
check "term-5.1 a stage number jumps there: stages 1 5 4, then Q quits" \
    test "$rc" = 0 -a "$(grep '^stage' "$tmp/out" | cut -c7 | tr -d '\n')" = 154
check "term-5.2 the prompt offers the numbers" grep -qF "[Enter] next stage, 1-7 go to a stage, b back, q quit: " "$tmp/out"
feed 'b\n\n' step $tri --vertex 1 --interactive
check "term-5.3 back at the first stage: said so" grep -qxF "(this is the first stage: there is none before it)" "$tmp/out"
check "term-5.4 ... and it stays there: stages 1 2" test "$(grep '^stage' "$tmp/out" | cut -c7 | tr -d '\n')" = 12
check "term-5.5 end of input ends with a word" grep -qxF "(end of input: step ends)" "$tmp/out"
feed '8\n0\n' step $tri --vertex 1 --interactive
check "term-5.6 a number past the last stage: the help, not a jump" \
    test "$(grep -c '^(Enter: next stage, 1-7: that stage, b: back, q: quit)$' "$tmp/out")" = 2
"$exe" step $tri --vertex 1 --all > /dev/full 2>"$tmp/err"; rc=$?
check "term-5.7 step >/dev/full: exit 2" test "$rc" = 2 -a -n "$(grep 'cannot write' "$tmp/err")"
COLUMNS=40 "$exe" why $tri 4 7 > /dev/full 2>"$tmp/err"; rc=$?
check "term-5.8 why, wrapped, >/dev/full: exit 2" test "$rc" = 2
report
