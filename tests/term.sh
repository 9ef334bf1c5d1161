#!/bin/sh
# tests/term.sh -- messages and the terminal: suggestions for a mistyped command
# or option, the stages listed, "no models", every --help's Docs line, the
# top-level usage listing every option; step, why and --compare-cameras
# wrapped to the terminal's width; step's keys
# See LICENSE for copyright and license.
#
# Usage: sh tests/term.sh PIPETRACE.  Run from the repository root.
exe=$1
. tests/testlib.sh
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
    check "term-1.8 pipetrace $1 $2: a suggestion from its own options" \
        test "$rc" = 1 -a -n "$(grep "^pipetrace $1: unknown option '$2' (did you mean '--[a-z-]*'?)$" "$tmp/err")"
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

# ---- --help: a Docs line at the end, naming files that exist; every option in the top-level usage
"$exe" --help > "$tmp/top"
cmds=$(sed -n 's/^ *\(usage: \)\{0,1\}pipetrace \([a-z][a-z-]*\) .*/\2/p; s/^ *pipetrace \([a-z][a-z-]*\)$/\1/p' "$tmp/top" | sort -u)
check "term-3.1 the top-level usage names the commands" test "$(echo $cmds)" = "accuracy diff journey quiz stages step why"
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
report
