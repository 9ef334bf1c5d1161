#!/bin/sh
# tests/formats/golden.sh -- the text trace of every example scene, against traces/
# See LICENSE for copyright and license.
#
# Usage: sh tests/formats/golden.sh PIPETRACE [--write]
# For each docs/examples/NAME.scene or NAME.obj, run PIPETRACE on it and compare
# the text trace with traces/NAME.trace (docs/examples/shapes/NAME.scene: with
# traces/shapes/NAME.trace).  --write rewrites traces/ instead
# (that is `make golden`: do it on purpose, and read the diff before committing).
exe=$1
write=${2:-}
passed=0
failed=0
for scene in docs/examples/*.scene docs/examples/*.obj docs/examples/shapes/*.scene; do
    name=${scene#docs/examples/}; name=${name%.*}
    want=traces/$name.trace
    got=$("$exe" "$scene" --trace - 2>&1); rc=$?
    if [ "$write" = "--write" ]; then
        mkdir -p "$(dirname "$want")"
        printf '%s\n' "$got" > "$want"
        echo "wrote $want"
        continue
    fi
    if [ "$rc" -eq 0 ] && [ -f "$want" ] && printf '%s\n' "$got" | cmp -s - "$want"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL golden $name: trace differs from $want (exit $rc)"
        printf '%s\n' "$got" | diff "$want" - | head -10 | sed 's/^/  /'
    fi
done
[ "$write" = "--write" ] && exit 0
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
