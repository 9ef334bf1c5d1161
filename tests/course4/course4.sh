#!/bin/sh
# tests/course4/course4.sh -- renderer 4 byte for byte: images and logs against the course's own
# See LICENSE for copyright and license.
#
# Usage: sh tests/course4/course4.sh PIPETRACE.  Run from the repository root.
# Each NAME.scene here has NAME.ppm.gz, the course's renderer 4's framebuffer,
# and NAME.DEBUG.log.gz, what it printed with the debug switches DEBUG
# (make_expected.sh made them with the course's jar).  The image of
# `pipetrace NAME.scene --image` and the log of `--kraft-debug DEBUG` must be
# those bytes.
exe=$1
dir=tests/course4
. tests/lib/testlib.sh

n=0
for scene in "$dir"/*.scene; do
    name=$(basename "$scene" .scene)
    run "$scene" --image "$tmp/$name.ppm"
    check "course4-1.1 $name: exit 0" test "$rc" = 0
    gzip -dc "$dir/$name.ppm.gz" > "$tmp/want.ppm"
    check "course4-1.2 $name: the image byte for byte" cmp -s "$tmp/want.ppm" "$tmp/$name.ppm"
    for log in "$dir/$name".*.log.gz; do
        d=${log#"$dir/$name."}
        d=${d%.log.gz}
        run "$scene" --kraft-debug "$d"
        gzip -dc "$log" > "$tmp/want.log"
        check "course4-2.1 $name --kraft-debug $d: the log byte for byte" cmp -s "$tmp/want.log" "$tmp/out"
        n=$((n + 1))
    done
done
check "course4-2.2 17 logs" test "$n" = 17

# ---- course4-3: the switches' spellings
run "$dir/switches.scene" --kraft-debug scene,bogus
check "course4-3.1 an unknown switch: usage error" test "$rc" = 1
check "course4-3.2 ... naming the list" grep -q "scene, position, rasterize" "$tmp/err"
run "$dir/switches.scene" --kraft-debug all --format csv
check "course4-3.3 --kraft-debug with --format csv: usage error" test "$rc" = 1
run "$dir/switches.scene" --format kraft-pixels
cp "$tmp/out" "$tmp/pixels.log"
run "$dir/switches.scene" --kraft-debug scene,rasterize
check "course4-3.4 kraft-pixels is scene,rasterize" cmp -s "$tmp/pixels.log" "$tmp/out"
run "$dir/switches.scene" --format kraft
gzip -dc "$dir/switches.scene.log.gz" > "$tmp/want.log"
check "course4-3.5 kraft is scene" cmp -s "$tmp/want.log" "$tmp/out"
run "$dir/switches.scene" --kraft-debug none
check "course4-3.6 none: the warnings alone" test "$(grep -cv '^\*\*\*WARNING\|^Model\|^[0-9]*: \|^This Model\|^$' "$tmp/out")" = 0
check "course4-3.7 ... and some" grep -q "WARNING: Added default color to model: plain." "$tmp/out"

# ---- course4-4: the fast path and the walked path draw the same image
run "$dir/aa-edges.scene" --image "$tmp/a.ppm" --format kraft-pixels --trace "$tmp/a.log"
check "course4-4.1 an image drawn beside the pixel log is the same" cmp -s "$tmp/a.ppm" "$tmp/aa-edges.ppm"
run "$dir/colors-int.scene" --image "$tmp/c.ppm" --format jsonl --trace "$tmp/c.jsonl"
check "course4-4.2 ... and beside a trace of every pixel" cmp -s "$tmp/c.ppm" "$tmp/colors-int.ppm"

# ---- course4-5: pipetrace diff reads the course's log: anti-aliased pairs as
# two pixels each, points' vertices as used, their pixels passed over
for name in aa-edges points; do
    run "$dir/$name.scene" --trace "$tmp/$name.txt"
    gzip -dc "$dir/$name.all.log.gz" > "$tmp/$name.log"
    run diff "$tmp/$name.txt" "$tmp/$name.log"
    check "course4-5.1 $name: the trace and the course's log agree" test "$rc" = 0
    check "course4-5.2 ... on every pixel" grep -q "The traces agree" "$tmp/out"
done
sed 's/{y_hi = *-*[0-9]*/{y_hi =  -7/' "$tmp/aa-edges.log" > "$tmp/moved.log"
run diff "$tmp/aa-edges.txt" "$tmp/moved.log"
check "course4-5.3 a pair's upper pixel moved: the pixels differ" test "$rc" = 1
report
