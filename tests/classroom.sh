#!/bin/sh
# tests/classroom.sh -- the student workflow and grading: make STAGE_x=FILE,
# the student build marked in --version and every trace header, diff's
# warning, and quiz for class and grading
# See LICENSE for copyright and license.
#
# Usage: sh tests/classroom.sh PIPETRACE.  Run from the repository root.
# Student builds go to $tmp/sb (make B=...); the first starts from PIPETRACE's
# own objects when they are plain (no sanitizers), as tests/diff.sh does.
exe=$1
. tests/testlib.sh
tri=docs/examples/triangle.scene

mk() {      # mk ARGS...: make in the repository, nothing passed down; output in $tmp/make.log
    MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/sb" "$@" >"$tmp/make.log" 2>&1
}
mkdir -p "$tmp/sb"
bdir=$(dirname "$exe")
if [ -f "$bdir/main.o" ] && [ -f "$bdir/builtin.c" ] && ! grep -q __asan_ "$bdir/main.o"; then
    cp -p "$bdir"/*.o "$bdir/builtin.c" "$tmp/sb/"
fi
sh tests/student.sh s3_two "$tmp/s3_two.c"

# ---- make: the stage variables
mk STAGE_pixle="$tmp/s3_two.c"; rc=$?
check "class-1.1 make STAGE_pixle=FILE (a typo): make fails" test "$rc" != 0
check "class-1.2 ... naming the unknown variable" grep -q "unknown student stage STAGE_pixle" "$tmp/make.log"
check "class-1.3 ... and listing the stages, as the stage table names them" \
    grep -qF "the stages are STAGE_camera STAGE_image STAGE_pixel STAGE_viewport STAGE_framebuffer STAGE_index" "$tmp/make.log"
names=$("$exe" stages --camera classic | awk '/^[a-z]/ { print $1 }' | tail -n +2 | tr '\n' ' ')
check "class-1.4 ... the same names as 'pipetrace stages' lists" \
    grep -qF "the stages are $(printf '%s' "$names" | sed 's/\([a-z]*\) */STAGE_\1 /g; s/ $//')" "$tmp/make.log"
mk STAGE_pixel="$tmp/nosuch.c"; rc=$?
check "class-1.5 a file that does not exist: make fails, naming it" \
    test "$rc" != 0 -a -n "$(grep "STAGE_pixel=$tmp/nosuch.c: no such file" "$tmp/make.log")"
mk STAGE_pixel="$tmp/s3_two.c"; rc=$?
check "class-1.6 make STAGE_pixel=FILE builds the student binary" test "$rc" = 0 -a -x "$tmp/sb/pipetrace"
[ "$rc" = 0 ] || sed 's/^/  /' "$tmp/make.log" | head -20
cp "$tmp/s3_two.c" "$tmp/s2_same.c"
sh tests/student.sh s2_divz "$tmp/s2_divz.c"
mk STAGE_image="$tmp/s2_divz.c"; rc=$?
check "class-1.7 STAGE_image (the trace's name) is accepted" test "$rc" = 0 -a -x "$tmp/sb/pipetrace"
check "class-1.8 ... and builds the image stage from FILE" \
    sh -c "'$tmp/sb/pipetrace' --version | grep -qxF 'student build: the image stage is yours (make STAGE_image=...)'"
printf 'this is not C\n' > "$tmp/broken.c"
mk STAGE_image="$tmp/broken.c"; rc=$?
check "class-1.9 a stage file that does not compile: make fails" test "$rc" != 0
check "class-1.10 ... and leaves no old student binary behind" test ! -e "$tmp/sb/pipetrace"
mk STAGE_pixle="$tmp/s3_two.c"
check "class-1.11 (an unknown variable leaves none either)" test ! -e "$tmp/sb/pipetrace"

# ---- the student build says so: --version, every trace header, diff
mk STAGE_pixel="$tmp/s3_two.c"
sum=$(cksum < "$tmp/s3_two.c" | awk '{ printf "%08x", $1 }')
run_sb() { "$tmp/sb/pipetrace" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?; }
run_sb --version
check "class-2.1 --version names the stage" grep -qxF "student build: the pixel stage is yours (make STAGE_pixel=...)" "$tmp/out"
run_sb $tri --vertex 1
check "class-2.2 text trace: a student line, with the file and its cksum" \
    test "$(sed -n 2p "$tmp/out")" = "student      pixel=$tmp/s3_two.c#$sum"
cp "$tmp/out" "$tmp/st.txt"
run_sb $tri --vertex 1 --format jsonl
check "class-2.3 JSON Lines: a student field in the header" \
    grep -qF "{\"type\":\"header\",\"version\":1,\"student\":\"pixel=$tmp/s3_two.c#$sum\",\"scene\":" "$tmp/out"
cp "$tmp/out" "$tmp/st.jsonl"
run_sb $tri --vertex 1 --format csv
check "class-2.4 CSV: a first line before the column names" \
    test "$(head -2 "$tmp/out" | tr '\n' '|')" = "# student pixel=$tmp/s3_two.c#$sum|model,v,stage,x,y,z,inside,behind,i,warning,digits_lost|"
"$exe" $tri --vertex 1 --format jsonl --trace "$tmp/ref.jsonl"
"$exe" $tri --vertex 1 --format csv --trace "$tmp/ref.csv"
check "class-2.5 the reference build writes no student line" \
    test "$(cat "$tmp/ref.jsonl" "$tmp/ref.csv" | grep -c student)" = 0
sh tests/student.sh s3_two "$tmp/s3_two.c" && echo '/* changed */' >> "$tmp/s3_two.c"
mk STAGE_pixel="$tmp/s3_two.c"
run_sb $tri --vertex 1
check "class-2.6 a changed file: a new cksum in the header" \
    test "$(sed -n 2p "$tmp/out")" = "student      pixel=$tmp/s3_two.c#$(cksum < "$tmp/s3_two.c" | awk '{ printf "%08x", $1 }')"
for f in txt jsonl; do
    "$exe" diff "$tmp/st.$f" "$tmp/ref.jsonl" >"$tmp/out" 2>"$tmp/err"
    check "class-2.7.$f diff with a student's $f trace as EXPECTED warns (read back from the header)" \
        grep -qF "pipetrace diff: warning: EXPECTED $tmp/st.$f comes from a student build (student pixel=$tmp/s3_two.c#$sum)" "$tmp/err"
done
"$exe" diff "$tmp/ref.jsonl" "$tmp/st.jsonl" >"$tmp/out" 2>"$tmp/err"
check "class-2.8 ... and not the right way round" test "$(grep -c warning "$tmp/err")" = 0
report
