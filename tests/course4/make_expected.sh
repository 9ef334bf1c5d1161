#!/bin/sh
# tests/course4/make_expected.sh -- make the expected images and logs with the course's renderer 4
# See LICENSE for copyright and license.
#
# Usage: sh tests/course4/make_expected.sh COURSE_DIR   (run from the repository root)
# COURSE_DIR holds the course's renderer4.jar and its harness Kraft4.java (Java 17).
# Each NAME.scene here is written as a case of the harness (scene2case.py) and
# rendered by the course's jar: NAME.ppm.gz is its framebuffer, NAME.DEBUG.log.gz
# everything it printed with the debug switches DEBUG (all; switches.scene at
# every switch).  `make test` only compares (course4.sh); it needs neither Java
# nor the jar.
set -e
dir=${1:?usage: make_expected.sh COURSE_DIR}
here=tests/course4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
javac -cp "$dir/renderer4.jar" -d "$tmp" "$dir/Kraft4.java"
for scene in "$here"/*.scene; do
    name=$(basename "$scene" .scene)
    python3 "$here/scene2case.py" "$scene" > "$tmp/$name.case"
    debugs=all
    [ "$name" = switches ] && debugs="all none scene position rasterize scene,rasterize position,rasterize clip,nearclip"
    [ "$name" = inf-segment ] && debugs=none     # 2^31 steps: a log pipetrace refuses
    for d in $debugs; do
        java -cp "$dir/renderer4.jar:$tmp" Kraft4 "$tmp/$name.case" "$tmp/$name.ppm" \
            "$tmp/$name.$d.log" debug="$d" > "$tmp/out" || { cat "$tmp/out"; exit 1; }
        gzip -9n < "$tmp/$name.$d.log" > "$here/$name.$d.log.gz"
    done
    gzip -9n < "$tmp/$name.ppm" > "$here/$name.ppm.gz"
done
