#!/bin/sh
# tests/repo/docs.sh -- every command shown in the docs runs and prints what is shown
# See LICENSE for copyright and license.
#
# Usage: sh tests/repo/docs.sh PIPETRACE.  In README.md and docs/**/*.md, a fenced
# block marked `console` holds commands ("$ " lines) each followed by the exact
# output (stdout and stderr) it must print.  "build/pipetrace" in a command is
# replaced by PIPETRACE.  Commands run with sh from the repository root.
exe=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

for md in README.md $(find docs -name '*.md' | sort); do
    # Split the file's console blocks into tmp/cN.cmd and tmp/cN.want.
    rm -f "$tmp"/c*
    awk -v dir="$tmp" '
        /^```console[ \t]*$/ { inblock = 1; next }
        /^```/ && inblock   { inblock = 0; next }
        inblock && /^\$ /   { n++; f = dir "/c" n; print substr($0, 3) > (f ".cmd");
                              printf "" > (f ".want"); next }
        inblock && n        { print > (f ".want") }
    ' "$md"
    for cmd in "$tmp"/c*.cmd; do
        [ -f "$cmd" ] || continue
        want=${cmd%.cmd}.want
        line=$(sed "s#build/pipetrace#$exe#g" "$cmd")
        sh -c "$line" > "$tmp/got" 2>&1
        if cmp -s "$tmp/got" "$want"; then
            passed=$((passed + 1))
        else
            failed=$((failed + 1))
            printf "FAIL docs %s: %s\n" "$md" "$(cat "$cmd")"
            diff "$want" "$tmp/got" | head -8 | sed 's/^/  /'
        fi
    done
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
