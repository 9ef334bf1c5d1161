#!/bin/sh
# tests/cli/extreme.sh -- the catalogue of extreme scenes in tests/extreme/
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/extreme.sh PIPETRACE.  Each tests/extreme/NAME.scene says in
# "# expect: FRAGMENT" lines what its JSONL trace (every stage traced) must
# contain, each fragment verbatim on some line; one of them must be the
# summary's whole "warnings":{...} object, so an extra warning fails too.
# Every scene must finish with exit 0 well within 10 seconds (a guard against
# hangs; speed itself is measured by `make bench`).  docs/stability.md explains each case.
exe=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
for scene in tests/extreme/*.scene; do
    name=$(basename "$scene" .scene)
    timeout 10 "$exe" "$scene" --format jsonl --all-stages > "$tmp/out" 2> "$tmp/err"
    rc=$?
    if [ "$rc" -ne 0 ]; then
        failed=$((failed + 1))
        echo "FAIL extreme $name: exit $rc $(head -c 200 "$tmp/err")"
        continue
    fi
    grep '^# expect: ' "$scene" | sed 's/^# expect: //' > "$tmp/want"
    ok=1
    while IFS= read -r frag; do
        if ! grep -qF -- "$frag" "$tmp/out"; then
            ok=0
            echo "FAIL extreme $name: no line contains $frag"
        fi
    done < "$tmp/want"
    [ -s "$tmp/want" ] || { ok=0; echo "FAIL extreme $name: no expect lines"; }
    grep -q '^"warnings":{' "$tmp/want" ||    # so that no warning comes or goes unseen
        { ok=0; echo "FAIL extreme $name: no expect line with the summary's \"warnings\""; }
    if [ "$ok" = 1 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
