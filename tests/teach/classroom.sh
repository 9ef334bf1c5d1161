#!/bin/sh
# tests/teach/classroom.sh -- the student workflow and grading: make STAGE_x=FILE,
# the student build marked in --version and every trace header, diff's
# warning, and quiz for class and grading
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/classroom.sh PIPETRACE.  Run from the repository root.
# Student builds go to $tmp/sb (make B=...); the first starts from PIPETRACE's
# own objects when they are plain (no sanitizers), as tests/teach/diff.sh does.
exe=$1
. tests/lib/testlib.sh
tri=docs/examples/triangle.scene

mk() {      # mk ARGS...: make in the repository, nothing passed down; output in $tmp/make.log
    MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/sb" "$@" >"$tmp/make.log" 2>&1
}
mkdir -p "$tmp/sb"
bdir=$(dirname "$exe")
if [ -f "$bdir/main.o" ] && [ -f "$bdir/builtin.c" ] && ! grep -q __asan_ "$bdir/main.o"; then
    cp -p "$bdir"/*.o "$bdir/builtin.c" "$tmp/sb/"
fi
sh tests/teach/student.sh s3_two "$tmp/s3_two.c"

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
sh tests/teach/student.sh s2_divz "$tmp/s2_divz.c"
mk STAGE_image="$tmp/s2_divz.c"; rc=$?
check "class-1.7 STAGE_image (the trace's name) is accepted" test "$rc" = 0 -a -x "$tmp/sb/pipetrace"
check "class-1.8 ... and builds the image stage from FILE" \
    sh -c "'$tmp/sb/pipetrace' --version | grep -qxF 'student build: the image stage is yours (make STAGE_image=...)'"
mk STAGE_image="$tmp/s2_divz.c" STAGE_projection="$tmp/s2_divz.c"; rc=$?
check "class-1.8a STAGE_image and its old name STAGE_projection together: make fails" \
    test "$rc" != 0 -a -n "$(grep 'STAGE_projection is STAGE_image: give one of them' "$tmp/make.log")"
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
    test "$(grep '^student ' "$tmp/out")" = "student      pixel=s3_two.c#$sum"
cp "$tmp/out" "$tmp/st.txt"
run_sb $tri --vertex 1 --format jsonl
check "class-2.3 JSON Lines: a student field in the header" \
    grep -qF "{\"type\":\"header\",\"version\":1,\"student\":\"pixel=s3_two.c#$sum\",\"scene\":" "$tmp/out"
cp "$tmp/out" "$tmp/st.jsonl"
run_sb $tri --vertex 1 --format csv
check "class-2.4 CSV: a first line before the column names" \
    test "$(head -2 "$tmp/out" | tr '\n' '|')" = "# student pixel=s3_two.c#$sum|model,v,stage,x,y,z,inside,behind,i,warning,digits_lost|"
cp "$tmp/out" "$tmp/st.csv"
"$exe" diff "$tmp/st.csv" "$tmp/st.csv" >/dev/null 2>"$tmp/err"
check "class-2.4a ... and it is still read as a CSV trace" grep -qF "$tmp/st.csv:1:1: error: a CSV trace has no header" "$tmp/err"
"$exe" $tri --vertex 1 --format jsonl --trace "$tmp/ref.jsonl"
"$exe" $tri --vertex 1 --format csv --trace "$tmp/ref.csv"
check "class-2.5 the reference build writes no student line" \
    test "$(cat "$tmp/ref.jsonl" "$tmp/ref.csv" | grep -c student)" = 0
sh tests/teach/student.sh s3_two "$tmp/s3_two.c" && echo '/* changed */' >> "$tmp/s3_two.c"
mk STAGE_pixel="$tmp/s3_two.c"
run_sb $tri --vertex 1
check "class-2.6 a changed file: a new cksum in the header" \
    test "$(grep '^student ' "$tmp/out")" = "student      pixel=s3_two.c#$(cksum < "$tmp/s3_two.c" | awk '{ printf "%08x", $1 }')"
for f in txt jsonl; do
    "$exe" diff "$tmp/st.$f" "$tmp/ref.jsonl" >"$tmp/out" 2>"$tmp/err"
    check "class-2.7.$f diff with a student's $f trace as EXPECTED warns (read back from the header)" \
        grep -qF "pipetrace diff: warning: EXPECTED $tmp/st.$f comes from a student build (student pixel=s3_two.c#$sum)" "$tmp/err"
done
"$exe" diff "$tmp/ref.jsonl" "$tmp/st.jsonl" >"$tmp/out" 2>"$tmp/err"
check "class-2.8 ... and not the right way round" test "$(grep -c warning "$tmp/err")" = 0

# ---- quiz for class and grading
right='-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.497501249375313 2.9987506246876565\n4 7\n4 7\n144\n'
feed "$right" quiz $tri --vertex 1
check "class-3.1 all right: exit 0" test "$rc" = 0 -a -n "$(grep -x 'score: 7/7' "$tmp/out")"
feed '-1 -1 0\nbanana\n\n-1 -1 -2\n5.5 3\n-0.5 -0.5 -1\n' quiz $tri --vertex 1 --interactive
check "class-3.2 at a terminal, 'banana' and an empty line are asked again" \
    test "$(grep -c '^camera: x_c y_c z_c = ? ' "$tmp/out")" = 3
check "class-3.3 ... saying what to write" grep -qxF "  (not read: write 3 numbers for x_c y_c z_c, separated by spaces or commas; try again)" "$tmp/out"
check "class-3.4 ... a miscounted line too, not counted and the answer not shown" \
    test "$(grep -c '^image: x_ip y_ip z_ip = ? ' "$tmp/out")" = 2 -a "$(grep -c 'go on with' "$tmp/out")" = 0
check "class-3.5 ... the score counts each stage once" grep -qx "score: 3/3 (input ended after 3 of 7 stages)" "$tmp/out"
check "class-3.6 ... end of input is said in words" grep -qx "(end of input)" "$tmp/out"
check "class-3.7 ... unanswered stages: exit 1" test "$rc" = 1
feed '-1 -1 0\nbanana\n-0.5 -0.5 -1\n' quiz $tri --vertex 1
check "class-3.8 from a file, 'banana' is wrong for its stage only" \
    test "$(grep -c '^  wrong' "$tmp/out")" = 1 -a "$(grep -c '^  correct' "$tmp/out")" = 2
check "class-3.9 ... exit 1" test "$rc" = 1
feed '-1 -1 0\nbanana\n-0.5 -0.5 -1\n' quiz $tri --vertex 1 --json
check "class-3.10 --json: one line, the score per stage" test "$(cat "$tmp/out")" = \
    '{"scene":"docs/examples/triangle.scene","model":"tri","vertex":1,"stages":[{"stage":"model","score":1},{"stage":"camera","score":0},{"stage":"image","score":1},{"stage":"pixel","score":null},{"stage":"viewport","score":null},{"stage":"framebuffer","score":null},{"stage":"index","score":null}],"right":2,"answered":3,"of":7}'
if command -v python3 >/dev/null 2>&1; then
    check "class-3.11 ... JSON" python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$tmp/out"
fi
feed '5.497501249375313 2.9987506246876565\n' quiz $tri --vertex 1 --stage pixel
check "class-3.12 --stage pixel asks that stage only" test "$rc" = 0 -a "$(grep -c ' = ? ' "$tmp/out")" = 1
check "class-3.13 ... given the stage before" grep -qxF "given: (x_ip, y_ip, z_ip) = (-0.5, -0.5, -1)" "$tmp/out"
run quiz $tri --vertex 1 --stage pixle
check "class-3.14 --stage with an unknown name: exit 1, listing the stages" \
    test "$rc" = 1 -a -n "$(grep -F "unknown stage 'pixle' (the stages: model, camera, image, pixel," "$tmp/err")"
run quiz $tri --vertex 1 --stage ndc
check "class-3.15 --stage of the other camera: exit 2, listing this journey's stages" \
    test "$rc" = 2 -a -n "$(grep -F "(its stages: model, camera, image, pixel, viewport, framebuffer, index)" "$tmp/err")"
printf '%b' "$right" | "$exe" quiz $tri --vertex 1 >/dev/full 2>"$tmp/err"; rc=$?
check "class-3.16 quiz >/dev/full: exit 2" test "$rc" = 2 -a -n "$(grep 'cannot write' "$tmp/err")"
printf '%b' "$right" | "$exe" quiz $tri --vertex 1 >&- 2>"$tmp/err"; rc=$?
check "class-3.17 quiz with standard output closed: exit 2" test "$rc" = 2
feed '' quiz $tri --vertex 1 --json
check "class-3.17a --json without answers: nothing answered, exit 1" \
    test "$rc" = 1 -a -n "$(grep -F '"right":0,"answered":0,"of":7}' "$tmp/out")"

# ---- a student build's teaching commands state the reference formula, with
# true arithmetic, and say apart what the student's stage gave; quiz grades
# against the reference.  Before the reference build (stages/pt_ref.h):
# --explain printed y_vp = ... = 7 under a record saying y_vp = 2, step ended
# the pixel equation with the student's 5.5 after the reference's operands,
# and quiz marked the right viewport wrong.
sh tests/teach/student.sh s3_two2 "$tmp/s3_two2.c"
mk STAGE_pixel="$tmp/s3_two2.c"
"$tmp/sb/pipetrace" step $tri --vertex 1 --all >"$tmp/out" 2>&1
check "class-5.1 step, student pixel stage: the formula's result ends the here line" \
    grep -qxF "  here     x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313" "$tmp/out"
check "class-5.2 ... then what the student's stage gave" \
    grep -qxF "           your stage gave x_pp = 5.5" "$tmp/out"
check "class-5.3 ... and the viewport computes from the student's x_pp, truly" \
    grep -qxF "  here     x_vp = round(x_pp) - 1 = round(5.5) - 1 = 6 - 1 = 5" "$tmp/out"
check "class-5.6 ... and no equation with the reference's operands and the student's result" \
    test "$(grep -c '20/2.001 \* (-0.5 + 1) = 5.5$' "$tmp/out")" = 0
sh tests/teach/student.sh s4_noflip "$tmp/s4_noflip.c"
mk STAGE_viewport="$tmp/s4_noflip.c"
"$tmp/sb/pipetrace" $tri --vertex 1 --explain >"$tmp/out" 2>&1
check "class-5.4 --explain, student viewport stage: the formula's 7, then the record's 2" \
    grep -qF "= 10 - 3 = 7; your stage gave y_vp = 2" "$tmp/out"
"$tmp/sb/pipetrace" step $tri --vertex 1 --all >"$tmp/out" 2>&1
check "class-5.5 step: the viewport's here line as the pixel's: the formula's, then yours" \
    test "$(grep -A1 'y_vp = h - round(y_pp) = ' "$tmp/out" | tr '\n' '|')" = \
    "           y_vp = h - round(y_pp) = 10 - round(2.9987506246876565) = 10 - 3 = 7|           your stage gave y_vp = 2|"
sh tests/teach/student.sh s5_nooffset "$tmp/s5_nooffset.c"
mk STAGE_framebuffer="$tmp/s5_nooffset.c"
"$tmp/sb/pipetrace" step --model cube --vertex 7 --all >"$tmp/out" 2>&1
check "class-5.7 step, student framebuffer stage: x_ul + x_vp added truly" \
    test "$(grep -A1 'x_fb = x_ul + x_vp = ' "$tmp/out" | tr '\n' '|')" = \
    "  here     x_fb = x_ul + x_vp = 40 + 139 = 179|           your stage gave x_fb = 139|"
mk STAGE_viewport="$tmp/s4_noflip.c"
feed "$right" quiz $tri --vertex 1
mv "$tmp/out" "$tmp/ref.out"
printf '%b' "$right" | "$tmp/sb/pipetrace" quiz $tri --vertex 1 >"$tmp/out" 2>&1; rc=$?
check "class-5.8 quiz in a student build: the right answers are right (exit 0, 7/7)" \
    test "$rc" = 0 -a -n "$(grep -x 'score: 7/7' "$tmp/out")"
check "class-5.9 ... one line says it is a student build, graded against the reference" \
    grep -qxF "student build: the viewport stage is yours (make STAGE_viewport=...); the answers are checked against the reference stages" "$tmp/out"
check "class-5.10 ... otherwise the reference build's quiz, byte for byte" \
    sh -c "grep -v '^student build: ' '$tmp/out' | cmp -s - '$tmp/ref.out'"
printf -- '-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.497501249375313 2.9987506246876565\n4 2\n' |
    "$tmp/sb/pipetrace" quiz $tri --vertex 1 >"$tmp/out" 2>&1
check "class-5.11 ... the student's own y_vp is wrong, with the true equation and the right value" \
    test "$(grep -A5 '^viewport: ' "$tmp/out" | tail -4 | tr '\n' '|')" = \
    "  x_vp = round(x_pp) - 1, y_vp = h - round(y_pp)|    x_vp = round(x_pp) - 1 = round(5.497501249375313) - 1 = 5 - 1 = 4|    y_vp = h - round(y_pp) = 10 - round(2.9987506246876565) = 10 - 3 = 7|  go on with (x_vp, y_vp) = (4, 7)|"

# ---- grading a folder of answer sheets
mkdir -p "$tmp/sheets/sub"
printf '%b' "$right" > "$tmp/sheets/alice.txt"
printf '# Bob\n-1 -1 0\nbanana\n-0.5 -0.5 -1\n5.5 3\n4 7\n4 7\n' > "$tmp/sheets/bob, b.txt"
printf 'x\n' > "$tmp/sheets/.hidden"
run quiz $tri --vertex 1 --grade "$tmp/sheets" --out "$tmp/scores.csv"
check "class-4.1 --grade: exit 1 (a sheet has a wrong answer)" test "$rc" = 1
check "class-4.2 ... a CSV, a row per sheet in name order, 1/0 per stage, empty unanswered" \
    test "$(tr '\n' '|' < "$tmp/scores.csv")" = 'sheet,model,camera,image,pixel,viewport,framebuffer,index,right,of,note|alice.txt,1,1,1,1,1,1,1,7,7,|"bob, b.txt",1,0,1,0,1,1,,4,7,|'
rm "$tmp/sheets/bob, b.txt"
run quiz $tri --vertex 1 --grade "$tmp/sheets"
check "class-4.3 all sheets right: exit 0, the CSV on standard output" \
    test "$rc" = 0 -a "$(sed -n 2p "$tmp/out")" = "alice.txt,1,1,1,1,1,1,1,7,7,"
run quiz $tri --grade "$tmp/sheets"
check "class-4.4 --grade without --vertex or --seed: exit 1" test "$rc" = 1
run quiz $tri --vertex 1 --grade "$tmp/nosuch"
check "class-4.5 --grade of a missing folder: exit 2" test "$rc" = 2
run quiz $tri --vertex 1 --stage index --grade "$tmp/sheets"
check "class-4.6 --grade with --stage: that stage's column only" test "$(sed -n 1p "$tmp/out")" = "sheet,index,right,of,note"

# ---- grading like a teacher: what a sheet holds besides answers, a slip
# carried forward, files that are no sheets
rm -rf "$tmp/sheets"; mkdir -p "$tmp/sheets/sub"
printf '\357\273\277-1 -1 0\r\n\r\n# camera next\r\n-1 -1 -2   # mine\r\n-0.5 -0.5 -1\r\n5.497501249375313 2.9987506246876565\r\n\n4 7\r\n4 7\r\n144\r\n' > "$tmp/sheets/a-bom.txt"
printf -- '-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.6 3.6\n5 6\n5 6\n125\n' > "$tmp/sheets/b-slip.txt"
printf -- '-1 -1 0\n-1 -1 -2\n-0.5 -0.5 -1\n5.6 3.6\n5 6\n6 6\n126\n' > "$tmp/sheets/c-two.txt"
printf 'PK\003\004\000\000junk' > "$tmp/sheets/d-essay.docx"
printf -- '-1 -1 0\n\377\376\n' > "$tmp/sheets/e-latin1.txt"
ln -s nowhere "$tmp/sheets/f-broken"
ln -s f-loop "$tmp/sheets/f-loop"
head -c 1048577 /dev/zero | tr '\000' '1' > "$tmp/sheets/g-big.txt"
run quiz $tri --vertex 1 --grade "$tmp/sheets" --out "$tmp/grades.csv"
row() { grep "^$1," "$tmp/grades.csv"; }
check "class-4.7 a sheet with a byte-order mark, CRLF, blank lines and comments: 7/7" \
    test "$(row a-bom.txt)" = "a-bom.txt,1,1,1,1,1,1,1,7,7,"
check "class-4.8 one slip carried forward: the stages after it follow, one stage lost" \
    test "$(row b-slip.txt)" = "b-slip.txt,1,1,1,0,follows,follows,follows,6,7,"
check "class-4.9 ... a second slip is wrong, and what follows from it follows" \
    test "$(row c-two.txt)" = "c-two.txt,1,1,1,0,follows,0,follows,5,7,"
check "class-4.10 a word processor's file: a row that says so" \
    sh -c 'grep -q "^d-essay.docx,,,,,,,,0,7,not a text file" "$1"' _ "$tmp/grades.csv"
check "class-4.11 ... text that is not UTF-8: a row that says so" \
    sh -c 'grep -q "^e-latin1.txt,,,,,,,,0,7,not UTF-8 text" "$1"' _ "$tmp/grades.csv"
check "class-4.12 a broken symbolic link and a loop: rows that say so" \
    sh -c 'grep -q "^f-broken,.*,a broken symbolic link" "$1" && grep -q "^f-loop,.*,a symbolic link that loops" "$1"' _ "$tmp/grades.csv"
check "class-4.13 a sheet over 1 MiB: not read, a row that says so" \
    sh -c 'grep -q "^g-big.txt,,,,,,,,0,7,larger than 1048576 bytes" "$1"' _ "$tmp/grades.csv"
check "class-4.14 ... exit 2, each named on standard error, the folder passed over" \
    sh -c 'test "$1" = 2 && test "$(grep -c "^pipetrace quiz: [d-g]-" "$2")" = 5 && ! grep -q "^sub," "$3"' _ "$rc" "$tmp/err" "$tmp/grades.csv"
esc=$(printf 'h-\033]0;owned\007')
printf 'PK\000' > "$tmp/sheets/$esc"
run quiz $tri --vertex 1 --grade "$tmp/sheets" --out "$tmp/grades.csv"
check "class-4.15 a sheet's name goes to the terminal with its escapes written out" \
    sh -c '! grep -q "$(printf "\\033")" "$1" && grep -Fq "h-\\x1b]0;owned\\x07: not a text file" "$1"' _ "$tmp/err"
cp "$tmp/sheets/a-bom.txt" "$tmp/keep"
run quiz $tri --vertex 1 --grade "$tmp/sheets" --out "$tmp/sheets/a-bom.txt"
check "class-4.16 --out over a sheet of the folder: refused, exit 2, the sheet kept" \
    sh -c 'test "$1" = 2 && cmp -s "$2" "$3" && grep -q "would overwrite an answer sheet" "$4"' _ "$rc" "$tmp/keep" "$tmp/sheets/a-bom.txt" "$tmp/err"
report
