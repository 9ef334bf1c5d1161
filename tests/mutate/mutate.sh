#!/bin/sh
# tests/mutate/mutate.sh -- apply each listed mutation in a scratch copy; report survivors
# See LICENSE for copyright and license.
#
# Usage: sh tests/mutate/mutate.sh "PROGRAMS" [ID...]  (make mutate), from the
# repository root.  PROGRAMS are the build/ files the test groups run.  The
# tree (build/ too, so the builds are incremental) is copied to a scratch
# folder; the listed groups must pass there unmutated; then each mutation of
# tests/mutate/mutations (only the IDs named, if any) is applied alone, the
# programs rebuilt, its groups run, and the file put back.  A mutation is
# killed when its groups fail (or it does not build), survives when they
# pass.  Prints a line a mutation and "N killed, N survived" last; exits 1
# when one survived or did not apply.  Not part of `make test`: it takes
# minutes.
progs=$1; shift
list=tests/mutate/mutations
[ -f "$list" ] || { echo "mutate: run from the repository root" >&2; exit 2; }
scratch=$(mktemp -d "${TMPDIR:-/tmp}/pipetrace-mutate-XXXXXX") || exit 2
trap 'rm -rf "$scratch"' EXIT
trap 'exit 130' INT TERM HUP
tar -cf - --exclude=./.git --exclude='./build-*' . | tar -xf - -C "$scratch" || exit 2
rm -f "$scratch/build/pixelpath.c"      # it names the sources by absolute path

# the lines of the list: ID FILE EXPR GROUPS, one a line, tab-separated
sed -e '/^#/d' -e '/^[[:space:]]*$/d' \
    -e 's/[[:space:]]*::[[:space:]]*/	/g' "$list" > "$scratch/.mutations"
wanted() { w=$1; shift; [ $# -eq 0 ] && return 0; for i; do [ "$i" = "$w" ] && return 0; done; return 1; }
build() { make -C "$scratch" -j2 $progs > "$scratch/.build.log" 2>&1; }
groups=$(cut -f4 "$scratch/.mutations" | tr ' ' '\n' | sort -u | tr '\n' ' ')

echo "mutate: building in $scratch, then the unmutated groups: $groups"
build || { echo "mutate: the unmutated tree does not build:"; tail -20 "$scratch/.build.log"; exit 2; }
(cd "$scratch" && sh tests/run.sh build $groups > .base.log 2>&1) || {
    echo "mutate: the unmutated tree fails its groups:"; grep FAIL "$scratch/.base.log" | head; exit 2; }

killed=0; survived=0; bad=0; names=
tab=$(printf '\t')
while IFS="$tab" read -r id file expr grp; do
    wanted "$id" "$@" || continue
    f=$scratch/$file
    cp "$f" "$scratch/.orig"
    if ! sed -e "$expr" "$scratch/.orig" > "$f" || cmp -s "$f" "$scratch/.orig"; then
        echo "NOT APPLIED  $id: '$expr' changes nothing in $file"
        bad=$((bad + 1))
    elif ! build; then
        echo "killed       $id (does not build)"
        killed=$((killed + 1))
    elif (cd "$scratch" && sh tests/run.sh build $grp > .run.log 2>&1); then
        echo "SURVIVED     $id: $file, $expr; groups $grp all pass"
        survived=$((survived + 1)); names="$names $id"
    else
        echo "killed       $id by $(grep -c '^FAIL' "$scratch/.run.log") failed checks in $grp" \
             "($(grep '^FAIL' "$scratch/.run.log" | head -1 | cut -c1-60))"
        killed=$((killed + 1))
    fi
    cat "$scratch/.orig" > "$f"          # put back, newer than its objects
    touch "$f"
done < "$scratch/.mutations"
[ -n "$names" ] && echo "survivors:$names"
[ "$bad" -gt 0 ] && echo "$bad mutations did not apply: tests/mutate/mutations is out of date"
echo "$killed killed, $survived survived"
[ "$survived" -eq 0 ] && [ "$bad" -eq 0 ]
