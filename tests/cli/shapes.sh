#!/bin/sh
# tests/cli/shapes.sh -- pipetrace shapes, and `shape` lines from the command line
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/shapes.sh PIPETRACE.  (tests/unit/test_shapes.c checks the shapes'
# vertices and segments against the course's; this checks the command.)
exe=$1
. tests/lib/testlib.sh

run shapes
check "shapes-cli-1.1 pipetrace shapes exits 0" [ "$rc" -eq 0 ]
check "shapes-cli-1.2 it lists the 18 shapes of the course's list" \
    [ "$(grep -c '^shape ' "$tmp/out")" -eq 18 ]
for name in sphere cylinder cone torus disk ring circle square squaregrid cube box \
            tetrahedron octahedron dodecahedron icosahedron icosidodecahedron pyramid axes3d; do
    check "shapes-cli-1.3 $name is listed" grep -q "^shape $name\\b" "$tmp/out"
done
check "shapes-cli-1.4 sphere's parameters in the Java order" grep -qx 'shape sphere r n k' "$tmp/out"
check "shapes-cli-1.5 torus's defaults as in Torus()" \
    grep -q 'by default r1=0.75 r2=0.25 n=12 k=16$' "$tmp/out"
check "shapes-cli-1.6 squaregrid's k defaults to n" grep -q 'by default r=1 n=0 k=n$' "$tmp/out"
run shapes pyramid
n=$(grep -c '^shape ' "$tmp/out")
check "shapes-cli-1.7 one shape by name" [ "$rc.$n" = 0.1 ]
check "shapes-cli-1.8 ... with its overloads" grep -q '^  takes 0, 2 or 4 arguments' "$tmp/out"
run shapes blob
check "shapes-cli-1.9 an unknown name is a usage error" [ "$rc" -eq 1 ]
check "shapes-cli-1.10 ... that says so" grep -q "no shape called 'blob'" "$tmp/err"
run shapes --help
check "shapes-cli-1.11 --help" [ "$rc.$(head -c 23 "$tmp/out")" = "0.usage: pipetrace shapes" ]

printf 'model m\nshape sphere 1 0 8\n' > "$tmp/bad.scene"
run "$tmp/bad.scene"
check "shapes-cli-2.1 a refused shape is bad input (exit 2)" [ "$rc" -eq 2 ]
check "shapes-cli-2.2 ... with the Java condition at its argument" \
    [ "$err" = "$tmp/bad.scene:2:16: error: shape sphere: n must be greater than 0, found 0" ]
run "$tmp/bad.scene" --image "$tmp/bad.ppm"
check "shapes-cli-2.3 ... and no image written" [ ! -e "$tmp/bad.ppm" ]
printf 'model m\ntranslate 0 0 -3\nshape cube\n' > "$tmp/cube.scene"
printf 'model m\ntranslate 0 0 -3\nv -1 -1 -1\nv 1 -1 -1\nv 1 -1 1\nv -1 -1 1\nv -1 1 -1\nv 1 1 -1\nv 1 1 1\nv -1 1 1\nf 1 2 3 4\nf 5 6 7 8\nl 1 5\nl 2 6\nl 3 7\nl 4 8\n' > "$tmp/cube_v.scene"
"$exe" "$tmp/cube.scene" --image "$tmp/a.ppm" > /dev/null 2>&1
"$exe" "$tmp/cube_v.scene" --image "$tmp/b.ppm" > /dev/null 2>&1
check "shapes-cli-2.4 shape cube draws what the same 8 v lines and 12 edges draw" \
    cmp -s "$tmp/a.ppm" "$tmp/b.ppm"
report
