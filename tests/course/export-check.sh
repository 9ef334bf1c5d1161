#!/bin/sh
# tests/course/export-check.sh -- export java against the course's jars, on the corpus
# See LICENSE for copyright and license.
#
# Usage: sh tests/course/export-check.sh [PIPETRACE] [COURSE_DIR] [r4 r7 r9]
#   PIPETRACE: default build/pipetrace; COURSE_DIR: default
#   ../shared/reference/course (rendererN/*.jar).  Needs javac and java; not
#   part of make test.  Run from the repository root.
#
# For every case of tests/course/rN/ that the course renders (no NAME.error):
# `pipetrace export java NAME.scene --debug all`, compiled against renderer
# N's jar and run; its standard error must be NAME.log.gz (the harness's log
# with every debug switch) and its image NAME.ppm.gz, byte for byte.  Prints
# a line a difference and "N passed, N failed".  PT_CORPUS_CASES='GLOB ...'
# checks only the cases whose names match.
set -u
exe=${1:-build/pipetrace}
course=${2:-../shared/reference/course}
[ $# -gt 2 ] && shift 2 || set --
which=${*:-r4 r7 r9}
here=tests/course
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

for r in $which; do
    n=${r#r}
    jar=$(ls "$course/renderer$n"/*.jar | head -1)
    d=$tmp/$r
    mkdir -p "$d"
    for scene in "$here/$r"/*.scene; do
        name=$(basename "$scene" .scene)
        [ -e "$here/$r/$name.error" ] && continue
        if [ -n "${PT_CORPUS_CASES:-}" ]; then
            m=0
            for g in $PT_CORPUS_CASES; do
                case $name in $g) m=1 ;; esac
            done
            [ "$m" = 1 ] || continue
        fi
        cls=C_$(echo "$name" | tr -c 'A-Za-z0-9\n' _)
        "$exe" export java "$scene" --debug all -o "$d/$cls.java" 2> "$tmp/err" ||
            fail "$r/$name: export: $(head -1 "$tmp/err")"
    done
    javac -nowarn -encoding UTF-8 -cp "$jar" -d "$d" "$d"/*.java > "$tmp/javac" 2>&1 ||
        { fail "$r: javac: $(grep -m3 error "$tmp/javac")"; continue; }
    for j in "$d"/*.java; do
        cls=$(basename "$j" .java)
        name=$(grep -m1 '^// .* written by pipetrace export java from ' "$j" | sed 's,.*/,,; s,\.scene$,,')
        (cd "$d" && java -XX:+UseSerialGC -XX:TieredStopAtLevel=1 -cp "$jar:." "$cls" "$cls.ppm" \
            > /dev/null 2> "$cls.log")
        if ! gzip -dc "$here/$r/$name.log.gz" | cmp -s - "$d/$cls.log"; then
            fail "$r/$name: log: $(gzip -dc "$here/$r/$name.log.gz" | diff - "$d/$cls.log" | sed -n 2p | cut -c1-120)"
        elif ! gzip -dc "$here/$r/$name.ppm.gz" | cmp -s - "$d/$cls.ppm"; then
            fail "$r/$name: image differs"
        else
            passed=$((passed + 1))
        fi
    done
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
