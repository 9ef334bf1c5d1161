#!/bin/sh
# tests/data/shapes/make.sh -- remake the .expect files here with the course's jar
# See LICENSE for copyright and license.
#
# Usage: sh tests/data/shapes/make.sh RENDERER_4.JAR   (needs a JDK; run from the top)
# The jar is hw2/renderer_4.jar of github:peter-biz/cs45500.  Each case below
# becomes NAME_ARGS.expect (spaces as '_'): what `new Name(ARGS)` builds, in the
# format of ShapeDump.java, or "error MESSAGE" when the constructor refuses.
# index lists the files in order.  The six cases of the course's own samples
# (../shared/reference/shapes/) are among them, byte for byte the same.
# tests/unit/test_shapes.c compares `shape NAME ARGS` with every file here; the tests
# need neither Java nor the jar.
set -e
jar=${1:?usage: sh tests/data/shapes/make.sh RENDERER_4.JAR}
dir=tests/data/shapes
cls=$(mktemp -d)
trap 'rm -rf "$cls"' EXIT
javac -cp "$jar" -d "$cls" $dir/ShapeDump.java
rm -f $dir/*.expect $dir/index
while read -r args; do
    [ -n "$args" ] || continue
    # shellcheck disable=SC2086
    file=$(echo "$args" | tr ' ' _).expect
    java -cp "$jar:$cls" ShapeDump $args > "$dir/$file"
    echo "$file" >> $dir/index
done <<'CASES'
sphere
sphere 2
sphere 1 15 8
sphere 0.5 1 3
sphere 3 4 7
sphere 1.25 7 12
sphere 1 0 5
sphere 1 3 2
cylinder
cylinder 0.5 1.5
cylinder 2 1 2 4
cylinder 1 2 12 4
cylinder 1 0.25 3 9
cylinder 1 1 1 5
cylinder 1 1 3 3
cone
cone 1 2
cone 1 2 3 5
cone 0.75 1.5 2 4
cone 2 -1 4 6
cone 1 1 1 4
cone 1 1 2 3
torus
torus 1 0.3
torus 1.5 0.5 16 8
torus 1 0.25 3 3
torus 2 0.75 5 7
torus 1 1 2 3
torus 1 1 3 2
disk
disk 2
disk 1 1 3
disk 1.5 3 8
disk 1 0 3
disk 1 1 2
ring
ring 2 1
ring 1 0.5 1 3
ring 2 0.5 3 10
ring 1 1 0 3
ring 1 1 1 2
circle
circle 2
circle 1 3
circle 1 16
circle 0.3 7
circle 1 997
circle 1 2
square
square 2.5
square 0.125
square 0
square -1
squaregrid
squaregrid 2
squaregrid 1 3
squaregrid 1 2 5
squaregrid 0.5 0 3
squaregrid 1 -1 0
squaregrid 1 0 -1
squaregrid 0 1 1
cube
box
box 1 2 3
box -1 0.5 -0.0
tetrahedron
octahedron
dodecahedron
icosahedron
icosidodecahedron
pyramid
pyramid 2 1
pyramid 3 1.5
pyramid 2 1 1 1
pyramid 2 1 3 2
pyramid 1.5 2 4 5
pyramid 1 1 0 1
pyramid 1 1 1 0
axes3d
axes3d 1 1 1
axes3d 2 3 -1
CASES
echo "wrote $(ls $dir/*.expect | wc -l) files in $dir"
