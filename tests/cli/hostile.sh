#!/bin/sh
# tests/cli/hostile.sh -- input that is out to hurt: endless, blocking, secret, dead pipes,
# names and paths that forge or break output, outputs over inputs, scenes too large to keep
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/hostile.sh PIPETRACE.  Run from the repository root.  Issue
# 31 (a class folder is hostile input): each check here failed before its fix.
# Nothing is timed: an endless input runs under a memory cap (ulimit -v) and
# `timeout` only stops a hang, which is then a failure.
exe=${1:-build/pipetrace}
. tests/lib/testlib.sh

# ---- obj PATH reads regular files only, at once
mkfifo "$tmp/fifo"
printf 'model m\nobj %s\n' "$tmp/fifo" > "$tmp/fifo.scene"
timeout 20 "$exe" "$tmp/fifo.scene" > "$tmp/out" 2> "$tmp/err" < /dev/null; rc=$?
check "hostile-1.1 obj of a FIFO with no writer is refused at once (exit $rc, not a hang)" test "$rc" = 2
check "hostile-1.2 ... with one message that says why" \
    test "$(cat "$tmp/err")" = "$tmp/fifo.scene:2:5: error: cannot read '$tmp/fifo': it is a FIFO, not a regular file"
printf 'model m\nobj /etc/passwd\n' > "$tmp/passwd.scene"
run "$tmp/passwd.scene"
check "hostile-1.3 obj /etc/passwd: exit 2 at its line 1" grep -q '^/etc/passwd:1:1: error: not an OBJ statement' "$tmp/err"
check "hostile-1.4 ... and none of its text in the message" sh -c "! grep -q root '$tmp/err'"

# ---- standard input is a stream, as a file is
# (each line of `yes` is valid until its end never comes, or the data fills memory)
lim() {     # lim KIB COMMAND: run COMMAND under a memory cap, at most 60 s
    ( ulimit -v "$1"; timeout 60 sh -c "$2" ) > "$tmp/out" 2> "$tmp/err"; rc=$?
}
# AddressSanitizer reserves terabytes of address space: under a cap it cannot
# start, so a sanitizer build runs only the checks that end without one
if grep -qa __asan_init "$exe"; then
    echo "  skipped: hostile-2.1 .. 2.4, 2.8, 2.9 (they need a memory cap, under which AddressSanitizer cannot run)"
    capped=
else
    capped=1
fi
if [ -n "$capped" ]; then
lim 400000 "tr '\\000' ' ' < /dev/zero | '$exe' -"
check "hostile-2.1 an endless line on standard input ends (exit $rc) under a 400 MB cap" test "$rc" = 2
check "hostile-2.2 ... with one message: out of memory" test "$(cat "$tmp/err")" = "<stdin>:1:1: error: out of memory"
lim 400000 "{ echo 'model m'; yes 'v 1 2 3'; } | '$exe' -"
check "hostile-2.3 endless valid vertices on standard input end (exit $rc) under a 400 MB cap" test "$rc" = 2
check "hostile-2.4 ... with one message: out of memory" grep -q '^<stdin>:[0-9]*:[0-9]*: error: out of memory$' "$tmp/err"
fi
cap=${capped:+400000}
lim "${cap:-unlimited}" "yes | '$exe' -"
check "hostile-2.5 yes | pipetrace - stops at its first line (exit $rc)" test "$rc" = 2
check "hostile-2.6 ... with its error" test "$(cat "$tmp/err")" = "<stdin>:1:1: error: unknown directive 'y'"
lim "${cap:-unlimited}" "'$exe' - < /dev/zero"
check "hostile-2.7 pipetrace - < /dev/zero: a NUL byte (exit $rc)" grep -q '^<stdin>:1:1: error: NUL byte$' "$tmp/err"
if [ -n "$capped" ]; then
printf 'model m\nv 0 0 -1\nv 1 1 -2\nl 1 2\n' > "$tmp/head.scene"
lim 400000 "{ cat '$tmp/head.scene'; yes '# a comment of sixty bytes, repeated to make a large scene.' | head -c 600000000; } | '$exe' - --trace '$tmp/t.trace'"
check "hostile-2.8 600 MB of scene on standard input is read under a 400 MB cap (exit $rc)" test "$rc" = 0
check "hostile-2.9 ... and its model is traced" grep -q "segments 1 " "$tmp/t.trace"
fi

# ---- a write error on standard output is said, with its reason
for c in stages shapes "stages --help" "shapes --help" --help "step --help" "why --help" \
         "quiz --help" "journey --help" "accuracy --help" "diff --help" "export --help"; do
    name=${c%--help}; name=${name% }; name=${name:+ $name}
    $exe $c > /dev/full 2> "$tmp/err"; rc=$?
    check "hostile-4.1 pipetrace $c > /dev/full: exit 2 (got $rc)" test "$rc" = 2
    check "hostile-4.2 pipetrace $c > /dev/full: one line says why" \
        test "$(cat "$tmp/err")" = "pipetrace$name: cannot write to standard output: No space left on device"
done
for f in kraft kraft-pixels; do
    $exe docs/examples/triangle.scene --format $f > /dev/full 2> "$tmp/err"; rc=$?
    check "hostile-4.5 the course's log ($f) to a full standard output: exit 2 (got $rc), with the reason" \
        sh -c 'test "$1" = 2 && grep -q "No space left on device" "$2"' _ "$rc" "$tmp/err"
done
$exe docs/examples/triangle.scene > /dev/full 2> "$tmp/err"; rc=$?
check "hostile-4.3 the render command's trace to a full standard output: exit 2 (got $rc)" test "$rc" = 2
check "hostile-4.4 ... with the reason" grep -q 'No space left on device' "$tmp/err"

# ---- --vertex N: a number past 2^32 - 1 is out of range, and says so
run --vertex 4294967296
check "hostile-5.1 --vertex 4294967296: a usage error" test "$rc" = 1
check "hostile-5.2 ... out of range, with the range" \
    grep -q "^pipetrace: --vertex 4294967296 is out of range: vertex numbers go from 1 to 4294967295" "$tmp/err"
run step --vertex 18446744073709551616
check "hostile-5.3 step --vertex 2^64: out of range too" \
    grep -q "^pipetrace step: --vertex 18446744073709551616 is out of range: vertex numbers go from 1 to 4294967295" "$tmp/err"
run step --vertex 0
check "hostile-5.4 step --vertex 0: out of range, numbered from 1" \
    grep -q "^pipetrace step: --vertex 0 is out of range: vertices are numbered from 1" "$tmp/err"
run --vertex x1
check "hostile-5.5 --vertex x1: not a number, with the range" \
    grep -q "^pipetrace: --vertex takes a vertex number from 1 to 4294967295, not 'x1'" "$tmp/err"

# ---- a closed pipe ends the run at its first write, even when SIGPIPE was ignored
# A scene whose jsonl trace is some 19 GB (2,000 diagonals of a 16384 x 16384
# framebuffer): formatting it all into a dead pipe takes minutes, so the run
# must end on its own long before `timeout` (which would make it 124) and by
# SIGPIPE (status 141), with nothing on standard error.
{ printf 'framebuffer 16384 16384\nmodel m\nv -0.99 -0.99 -1\nv 0.99 0.99 -1\n'
  yes 'l 1 2' | head -n 2000; } > "$tmp/huge.scene"
{ (trap '' PIPE; timeout 60 "$exe" "$tmp/huge.scene" --format jsonl --threads 1 2> "$tmp/err"
   echo $? > "$tmp/rc"); } | head -c 100 > "$tmp/head"
rc=$(cat "$tmp/rc")
check "hostile-6.1 a trace piped into head -c 100, SIGPIPE ignored: ends by SIGPIPE (status $rc)" test "$rc" = 141
check "hostile-6.2 ... quietly" test ! -s "$tmp/err"
check "hostile-6.3 ... after head had its 100 bytes" test "$(wc -c < "$tmp/head")" -eq 100
{ (trap '' PIPE; timeout 60 "$exe" "$tmp/huge.scene" --format jsonl 2> "$tmp/err"
   echo $? > "$tmp/rc"); } | head -c 100 > /dev/null
rc=$(cat "$tmp/rc")
check "hostile-6.4 ... and so with two threads (status $rc)" test "$rc" = 141
if command -v strace > /dev/null 2>&1; then
    { (trap '' PIPE; strace -f -qq -e trace=write -o "$tmp/strace" timeout 60 "$exe" \
        "$tmp/huge.scene" --format jsonl --threads 1 2> /dev/null); } | head -c 100 > /dev/null
    n=$(grep -c 'write(1,' "$tmp/strace")
    check "hostile-6.5 ... after at most two writes to the pipe (strace counts $n)" test "$n" -le 2
else
    echo "  skipped: strace is not installed (hostile-6.5)"
fi

run journey --vertex 4294967296 --svg "$tmp/j.svg"
check "hostile-5.6 journey --vertex 4294967296: a usage error that gives the range" \
    sh -c 'test "$1" = 1 && grep -q "is out of range: vertex numbers go from 1 to 4294967295" "$2"' _ "$rc" "$tmp/err"
check "hostile-5.7 ... and no picture" test ! -e "$tmp/j.svg"

# ---- a name read from an untrusted trace never reaches the terminal raw
# (an escape sequence, a bidirectional control): diff prints it written out
"$exe" docs/examples/two-models.scene --format jsonl --trace "$tmp/a.jsonl"
sed 's/"arrow"/"arr\\u001b]0;pwned\\u0007\\u202eow"/g' "$tmp/a.jsonl" > "$tmp/b.jsonl"
sed 's/"arrow"/"arr\\u001b]0;pwned\\u0007\\u202eow"/g; s/"x":1\.5/"x":1.75/' "$tmp/a.jsonl" > "$tmp/c.jsonl"
"$exe" diff "$tmp/b.jsonl" "$tmp/c.jsonl" > "$tmp/out" 2>&1; rc=$?
check "hostile-8.1 diff of traces whose model name holds ESC, BEL and U+202E: they differ (exit $rc)" test "$rc" = 1
check "hostile-8.2 ... no ESC, BEL or U+202E in what it prints" \
    sh -c "! grep -q \"\$(printf '\\033\\|\\007\\|\\342\\200\\256')\" '$tmp/out'"
check "hostile-8.3 ... the name written out: arr\\x1b]0;pwned\\x07\\u202eow" \
    grep -qF 'arr\x1b]0;pwned\x07\u202eow v4' "$tmp/out"

# ---- CSV cells: one quoting (pt_sbuf_add_csv) for the grade sheet and the trace
# (a sheet's name must not forge a row of grades, nor a name become a formula)
mkdir "$tmp/sheets"
nl='
'
forged="x\"$nl${nl}mallory,1,1,1,1,1,1,1,7,7${nl}y"
printf 'nothing\n' > "$tmp/sheets/$forged"
printf 'nothing\n' > "$tmp/sheets/=1+1"
printf 'nothing\n' > "$tmp/sheets/end\""
"$exe" quiz docs/examples/triangle.scene --vertex 1 --grade "$tmp/sheets" > "$tmp/grades.csv" 2> "$tmp/err"
if command -v python3 > /dev/null 2>&1; then
    rows=$(python3 -c 'import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
print(len(rows), sum(r[0] == "mallory" for r in rows), sum(r[0].startswith("x\"") for r in rows))' "$tmp/grades.csv")
    check "hostile-7.1 a sheet named x\" + newlines + a row of grades: read as CSV, a header and 3 rows, none for mallory ($rows)" \
        test "$rows" = "4 0 1"
else
    echo "  skipped: python3 is not installed (hostile-7.1)"
fi
check "hostile-7.2 ... its name one quoted cell on one line, the quote doubled, the newlines written out" \
    grep -qF '"x""\x0a\x0amallory,1,1,1,1,1,1,1,7,7\x0ay",' "$tmp/grades.csv"
check "hostile-7.3 a sheet named =1+1: a text cell, not a formula" grep -q "^\"'=1+1\"," "$tmp/grades.csv"
check "hostile-7.4 a name ending in a quote: doubled, and no NUL byte in the CSV" \
    sh -c "grep -q '^\"end\"\"\",' '$tmp/grades.csv' && test \$(tr -d '\\000' < '$tmp/grades.csv' | wc -c) = \$(wc -c < '$tmp/grades.csv')"
printf 'framebuffer 20 10\nmodel =1+1\ntranslate 0 0 -2\nv 0 0 0\nv 1 1 0\nl 1 2\nmodel @x\nv 0 0 -1\nv 1 0 -1\nl 1 2\n' > "$tmp/formula.scene"
"$exe" "$tmp/formula.scene" --format csv > "$tmp/f.csv" 2> "$tmp/err"
check "hostile-7.5 a model named =1+1 in a CSV trace: a text cell" \
    test "$(grep -c "^\"'=1+1\"," "$tmp/f.csv")" -gt 0 -a "$(grep -c '^=' "$tmp/f.csv")" = 0
check "hostile-7.6 ... and @x too" test "$(grep -c '^@' "$tmp/f.csv")" = 0 -a "$(grep -c "^\"'@x\"," "$tmp/f.csv")" -gt 0

# ---- SVG and HTML: one escaping (pt_sbuf_add_xml) for every untrusted text
# A model name with U+FFFE and U+FFFF (XML forbids both) in a folder whose
# name holds a control byte and a byte that is not UTF-8: every picture must
# still be well-formed XML, the characters written as U+FFFD (in the page's
# JSON as \ufffe, the same character in ASCII).
bad="$tmp/p$(printf '\001')q$(printf '\033')"
mkdir "$bad"
printf 'framebuffer 20 10\nmodel a\357\277\276b\357\277\277c\ntranslate 0 0 -2\nv 0 0 0\nv 1 1 0\nl 1 2\n' \
    > "$bad/x$(printf '\377').scene"
"$exe" journey "$bad/x$(printf '\377').scene" --vertex 1 --svg "$tmp/j9.svg" --html "$tmp/j9.html" 2> "$tmp/err"; rc=$?
check "hostile-9.1 journey of a model named with U+FFFE, U+FFFF from a path with \\x01, ESC, \\xff: exit 0 ($rc)" test "$rc" = 0
noraw() {   # noraw FILE: none of U+FFFE, U+FFFF, \x01, ESC, or a \xff byte in FILE
    ! grep -q "$(printf '\357\277\276\|\357\277\277\|\001\|\033\|\377')" "$1"
}
check "hostile-9.2 ... the SVG holds none of them raw" noraw "$tmp/j9.svg"
check "hostile-9.3 ... nor the HTML page" noraw "$tmp/j9.html"
check "hostile-9.4 ... the name in the SVG with U+FFFD for each" \
    grep -q "a$(printf '\357\277\275')b$(printf '\357\277\275')c" "$tmp/j9.svg"
check "hostile-9.5 ... and in the page's data as \\ufffe, \\uffff" grep -qF 'a\ufffeb\uffffc' "$tmp/j9.html"
"$exe" accuracy "$bad/x$(printf '\377').scene" --repeat 1 --svg "$tmp/a9.svg" > /dev/null 2> "$tmp/err"; rc=$?
check "hostile-9.6 accuracy --svg of that scene: exit 0 ($rc)" test "$rc" = 0
check "hostile-9.7 ... the SVG holds no control byte or bad UTF-8 from the path" noraw "$tmp/a9.svg"
if command -v python3 > /dev/null 2>&1; then
    for f in j9.svg a9.svg; do
        check "hostile-9.8 $f is well-formed XML" python3 -c 'import sys, xml.dom.minidom
xml.dom.minidom.parse(sys.argv[1])' "$tmp/$f"
    done
else
    echo "  skipped: python3 is not installed (hostile-9.8)"
fi

# ---- a model name holds no format character: one that turns or hides text
# (a name that shows as "cube" must be "cube"), each said at its column
for c in '342 200 256:202E' '342 200 216:200E' '342 200 217:200F' '342 201 246:2066' \
         '342 201 251:2069' '357 273 277:FEFF' '342 200 213:200B' '302 255:00AD' '363 240 200 201:E0001'; do
    bytes=$(printf '\%s' ${c%%:*})
    printf 'model ab%s\nv 0 0 -1\n' "$(printf "$bytes")" > "$tmp/cf.scene"
    run "$tmp/cf.scene"
    check "hostile-10.1 model name with U+${c#*:}: exit 2 (got $rc)" test "$rc" = 2
    check "hostile-10.2 ... one message at its column" \
        test "$err" = "$tmp/cf.scene:1:9: error: a model name may not contain U+${c#*:}, a format character (it turns or hides text)"
done
printf 'model caf\303\251_\316\273\nv 0 0 -1\n' > "$tmp/cf.scene"
run "$tmp/cf.scene"
check "hostile-10.3 other non-ASCII letters stay allowed (exit $rc)" test "$rc" = 0
cp docs/examples/tetra.obj "$tmp/a$(printf '\342\200\256')b.obj"
run "$tmp/a$(printf '\342\200\256')b.obj"
check "hostile-10.4 a plain OBJ file whose name holds U+202E: model 'obj', not its file name" \
    grep -q '^model        obj: ' "$tmp/out"
printf 'model m p\342\200\256q\nv 0 0 -1\n' > "$tmp/cf.scene"
run "$tmp/cf.scene"
check "hostile-10.5 a position name (model NAME POSITION) with U+202E: refused at its column" \
    test "$err" = "$tmp/cf.scene:1:10: error: a position name may not contain U+202E, a format character (it turns or hides text)"

# ---- no output over an input of the run: the OBJ files the scene reads
# (by device and inode, through a link too), for every command that writes one
mkdir "$tmp/inc"
cp docs/examples/obj-include.scene docs/examples/tetra.obj "$tmp/inc/"
cp "$tmp/inc/tetra.obj" "$tmp/tetra.orig"
ln -s tetra.obj "$tmp/inc/link.obj"
for c in "--image $tmp/inc/tetra.obj:--image" "--trace $tmp/inc/tetra.obj:--trace" \
         "--trace $tmp/inc/link.obj:--trace" "--image $tmp/inc/link.obj --trace $tmp/inc/t.txt:--image" \
         "journey --vertex 1 --svg $tmp/inc/tetra.obj:--svg" \
         "journey --vertex 1 --html $tmp/inc/link.obj:--html" \
         "journey --vertex 1 --image $tmp/inc/tetra.obj:--image" \
         "accuracy --repeat 1 --svg $tmp/inc/tetra.obj:--svg"; do
    args=${c%:*}; opt=${c##*:}
    case $args in journey*|accuracy*) set -- ${args%% *} "$tmp/inc/obj-include.scene" ${args#* } ;;
                  *) set -- "$tmp/inc/obj-include.scene" $args ;; esac
    "$exe" "$@" > "$tmp/out" 2> "$tmp/err"; rc=$?
    check "hostile-11.1 pipetrace $args: refused over the scene's OBJ file (exit $rc)" test "$rc" = 2
    check "hostile-11.2 ... one message naming $opt and the OBJ file" \
        grep -q "error: $opt names '.*tetra.obj', an OBJ file the scene reads; writing it would destroy it" "$tmp/err"
    check "hostile-11.3 ... the OBJ file kept" cmp -s "$tmp/tetra.orig" "$tmp/inc/tetra.obj"
done
check "hostile-11.4 ... and no other output written" test ! -e "$tmp/inc/t.txt"
run "$tmp/inc/obj-include.scene" --image "$tmp/inc/other.obj"
check "hostile-11.5 an output beside the OBJ file, not one of the scene's: written (exit $rc)" \
    sh -c 'test "$1" = 0 && test -s "$2"' _ "$rc" "$tmp/inc/other.obj"

# ---- the scene fuzz target reads no file of the host: an `obj PATH` line
# reads one of its own private folder (tests/fuzz/fuzz_scene.c); its corpus
# holds obj /etc/passwd, /dev/zero, paths out of the tree
fuzz=$(dirname "$exe")/test_fuzz
if [ -x "$fuzz" ] && command -v strace > /dev/null 2>&1; then
    # (LeakSanitizer cannot run under ptrace: without it in a sanitizer build)
    ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        strace -f -qq -e trace=open,openat -o "$tmp/fstrace" "$fuzz" > "$tmp/fout" 2>&1; rc=$?
    check "hostile-12.1 the scene fuzz target replays obj /etc/passwd and /dev/zero as correct refusals (exit $rc)" \
        test "$rc" = 0
    check "hostile-12.2 ... and opens neither" sh -c "! grep -q '\"/etc/passwd\"\\|\"/dev/zero\"\\|\\.\\./etc/passwd' '$tmp/fstrace'"
    check "hostile-12.3 ... its obj lines read its own folder" grep -q 'pt-fuzz-scene-.*/good.obj' "$tmp/fstrace"
else
    echo "  skipped: $fuzz is not built or strace is not installed (hostile-12.1 .. 12.3)"
fi

# ---- tests that see a change (make mutate, tests/mutate/): diff's edges
# A text trace prints 1e15 as 1.000000e+15 ("%.Ne" from 1e15 up): half a unit
# of its last digit is 5e8, so an exact 1000000100000000 agrees with it.
printf 'framebuffer 20 10\nmodel m\nv 1e15 0 -1\nv 0 0 -1\nl 1 2\n' > "$tmp/e15.scene"
"$exe" "$tmp/e15.scene" --all-stages --trace "$tmp/e15.trace"
"$exe" "$tmp/e15.scene" --all-stages --format jsonl --trace "$tmp/e15.jsonl"
for x in 1000000100000000:0 1000000600000000:1; do
    sed "s/\"v\":1,\"stage\":\"model\",\"x\":1e+15/\"v\":1,\"stage\":\"model\",\"x\":${x%:*}/" \
        "$tmp/e15.jsonl" > "$tmp/e15b.jsonl"
    "$exe" diff "$tmp/e15.trace" "$tmp/e15b.jsonl" > "$tmp/out" 2>&1; rc=$?
    check "hostile-13.1 diff: x_m = 1.000000e+15 printed against ${x%:*} exact: exit ${x#*:} (got $rc)" \
        test "$rc" = "${x#*:}"
done
# a trace's pixels moved by (1, 1): the last of its row leaves the
# framebuffer at x = W exactly, and the rest is still a shift
printf 'framebuffer 10 4\nmodel m\nv -0.999 0 -1\nv 0.999 0 -1\nl 1 2\n' > "$tmp/row.scene"
"$exe" "$tmp/row.scene" --format jsonl --image /dev/null --trace "$tmp/row.jsonl"
awk -F'"x":' '/"type":"pixel"/ { split($2, a, ","); x = a[1] + 1; if (x >= 10) next
    sub(/"x":[0-9]+,"y":2,"i":[0-9]+/, "\"x\":" x ",\"y\":3,\"i\":" (30 + x)) } { print }' \
    "$tmp/row.jsonl" > "$tmp/row2.jsonl"
"$exe" diff "$tmp/row.jsonl" "$tmp/row2.jsonl" > "$tmp/out" 2>&1; rc=$?
check "hostile-13.2 diff: a row of pixels x = 0 .. 9 moved by (1, 1) in a 10-wide framebuffer: a shift (exit $rc)" \
    sh -c 'test "$1" = 1 && grep -q "all of them moved by (1, 1)" "$2"' _ "$rc" "$tmp/out"
check "hostile-13.3 ... one of them out of the framebuffer" \
    sh -c 'tr "\n" " " < "$1" | grep -q "1 of them out of the *framebuffer"' _ "$tmp/out"

# ---- accuracy runs a block of vertices or segments at a time (PT_ACC_BLOCK):
# one `shape sphere 1 1400 1400` line took 3 GB when it kept every journey
# (then refused past 100,000 vertices); now its memory is the scene's and a
# byte a vertex.  It takes minutes under a sanitizer, so only a plain build
# runs it.  journey and why keep only what they show
printf 'model s\nshape sphere 1 1400 1400\ntranslate 0 0 -3\n' > "$tmp/sphere.scene"
if [ -n "$capped" ]; then
( ulimit -v 400000; timeout 600 "$exe" accuracy "$tmp/sphere.scene" --no-time ) > "$tmp/out" 2> "$tmp/err"; rc=$?
check "hostile-14.1 accuracy of a 1,960,002-vertex sphere: done (exit $rc) under a 400 MB cap" \
    test "$rc" = 0 -a ! -s "$tmp/err"
check "hostile-14.2 ... every used vertex and segment counted, every vertex compared (double's model stage exact on all)" \
    sh -c 'grep -q "^scene  *1 models, 1960002 vertices used, 3921400 segments, " "$1" &&
           grep -q "^model  *double  *0  *0  *0  *0/1960002 vertices$" "$1"' _ "$tmp/out"
fi
# journey on the course's renderers 7 and 9 keeps only what its panels draw
# (the first 5000 primitives, a bit a vertex): the 100,001-vertex scene once
# refused is drawn, and renderer 9's 1,960,002-vertex sphere runs under an
# 800 MB cap (the render command alone needs more than 600 MB; keeping every
# stage's model took more)
{ echo 'renderer 7'; echo 'model m'; yes 'v 0 0 -1' | head -n 100001; echo 'l 1 2'; } > "$tmp/r7cap.scene"
run journey "$tmp/r7cap.scene" --vertex 1 --image "$tmp/r7cap.ppm"
check "hostile-14.3 journey of 100,001 vertices on renderer 7 (once refused by a cap): done" \
    sh -c 'test "$1" = 0 -a -s "$2"' _ "$rc" "$tmp/r7cap.ppm"
if [ -n "$capped" ]; then
printf 'renderer 9\nmodel s\nshape sphere 1 1400 1400\ntranslate 0 0 -3\n' > "$tmp/r9sph.scene"
lim 800000 "'$exe' journey '$tmp/r9sph.scene' --vertex 1 --svg '$tmp/r9sph.svg'"
check "hostile-14.18 journey of renderer 9's 1,960,002-vertex sphere under an 800 MB cap: done, 8 panels (exit $rc)" \
    sh -c 'test "$1" = 0 && test "$(grep -c "<g class=\"panel\"" "$2")" = 8' _ "$rc" "$tmp/r9sph.svg"
check "hostile-14.19 ... its 7 wireframe panels say they draw the first 5000 of 3921400 primitives" \
    test "$(grep -c ">the first 5000 of 3921400 primitives drawn; " "$tmp/r9sph.svg")" = 7
fi
if [ -n "$capped" ]; then
lim 400000 "'$exe' journey '$tmp/sphere.scene' --vertex 1 --image '$tmp/sph.ppm'"
check "hostile-14.14 journey --image alone (one journey kept) of the same sphere: done under the 400 MB cap (exit $rc)" \
    test "$rc" = 0 -a -s "$tmp/sph.ppm"
fi
{ echo 'model m'; yes 'v 0 0 -1' | head -n 100000; echo 'l 1 2'; } > "$tmp/cap.scene"
run why "$tmp/cap.scene" 1 1
check "hostile-14.4 why of 100,000 vertices: done (exit $rc)" test "$rc" = 0
{ echo 'model m'; yes 'v 0 0 -1' | head -n 100000; echo 'model n'; echo 'v 0 0 -1'; echo 'l 1 1'; } > "$tmp/cap1.scene"
run accuracy "$tmp/cap1.scene" --no-time
check "hostile-14.5 accuracy of 100,001 vertices in two models, one used (once refused): done" \
    sh -c 'test "$1" = 0 && grep -q "^scene  *2 models, 1 vertices used, 1 segments" "$2"' _ "$rc" "$tmp/out"
{ echo 'model m'; echo 'v 0 0 -1'; yes 'l 1 1' | head -n 400001; } > "$tmp/cap2.scene"
run accuracy "$tmp/cap2.scene" --no-time
check "hostile-14.6 accuracy of 400,001 segments on one vertex, 98 blocks (once refused): done" \
    sh -c 'test "$1" = 0 && grep -q "^scene  *1 models, 1 vertices used, 400001 segments" "$2"' _ "$rc" "$tmp/out"
{ printf 'framebuffer 16384 16384\nmodel m\nv -0.99 -0.99 -1\nv 0.99 0.99 -1\n'
  yes 'l 1 2' | head -n 600; } > "$tmp/px.scene"
lim "${cap:-unlimited}" "'$exe' journey '$tmp/px.scene' --vertex 1 --svg '$tmp/px.svg'"
check "hostile-14.7 journey of 600 diagonals of a 16384 x 16384 framebuffer (9.8 M pixels): refused (exit $rc)" \
    test "$rc" = 2
check "hostile-14.8 ... saying the pixel cap" grep -q "^pipetrace journey: the segments of the vertices shown of .* draw more than 8000000 pixels; journey keeps them in memory and takes at most that many (docs/limits.md)$" "$tmp/err"
# the pixels kept are those of the segments of the vertex shown: the same
# 9.8 M pixels beside a short segment whose vertex is shown (refused before)
{ cat "$tmp/px.scene"; printf 'v 0 0 -1\nv 0.001 0 -1\nl 3 4\n'; } > "$tmp/px3.scene"
lim "${cap:-unlimited}" "'$exe' journey '$tmp/px3.scene' --vertex 3 --svg '$tmp/px3.svg'"
check "hostile-14.12 journey of a vertex beside 9.8 M pixels of other segments: done (exit $rc)" \
    test "$rc" = 0
{ head -n 4 "$tmp/px.scene"; printf 'v 0 0 -1\nv 0.001 0 -1\nl 3 4\n'; } > "$tmp/px3b.scene"
"$exe" journey "$tmp/px3b.scene" --vertex 3 --svg "$tmp/px3b.svg"
inset() { sed -n '/data-stage="viewport"/,/<\/g>/p' "$1" | sed -n '/<g class="inset">/,/<\/g>/p'; }
check "hostile-14.13 ... its segment's pixels in the viewport panel's zoom as without the others" \
    sh -c 'test -n "$1" -a "$1" = "$2" && echo "$1" | grep -q "fill=.#a8c7ee"' _ \
    "$(inset "$tmp/px3.svg")" "$(inset "$tmp/px3b.svg")"
# accuracy keeps its image's pixels once each: 2101 segments over one row,
# 8.4 M writes (past the old cap of 8,000,000 writes), 4000 pixels
awk 'BEGIN { print "framebuffer 4000 4"; print "model m"; print "v -2 0 -2"; print "v 2 0 -2";
             for (i = 0; i < 2101; i++) print "l 1 2" }' > "$tmp/over.scene"
run accuracy "$tmp/over.scene" --no-time
check "hostile-14.15 accuracy of 8.4 M pixel writes on 4000 pixels: done (exit $rc)" \
    test "$rc" = 0 -a -n "$(grep '3999 pixels in the reference image' "$tmp/out")"
# why keeps of every vertex only what measuring a segment needs (32 bytes)
# and the whole journeys of the vertices it shows: a sphere of 360,002
# vertices (616 MB of journeys, refused before) under a 300 MB cap, and a
# pixel of it the same as the image says
printf 'model s\nshape sphere 1 600 600\ntranslate 0 0 -3\n' > "$tmp/sph6.scene"
if [ -n "$capped" ]; then
lim 300000 "'$exe' why '$tmp/sph6.scene' 400 300"
check "hostile-14.9 why of a 360,002-vertex sphere under a 300 MB cap: done (exit $rc)" test "$rc" = 0
check "hostile-14.10 ... lit by segments, each with its two vertices' journeys" \
    sh -c 'grep -q "^lit by:$" "$1" && n=$(grep -c "^  s s[0-9]* (v" "$1") &&
           test "$n" -ge 1 -a "$(grep -c "^    v[0-9]*  model (" "$1")" = $((2 * n))' _ "$tmp/out"
fi
# journey keeps the whole journeys of the vertices it draws (the vertex, its
# neighbours, the wireframe's first 5000 segments) and the extent of the
# others: the same sphere under the same cap, its panels fitted as before
if [ -n "$capped" ]; then
lim 300000 "'$exe' journey '$tmp/sph6.scene' --vertex 180149 --svg '$tmp/sph6.svg'"
check "hostile-14.16 journey of a vertex of the 360,002-vertex sphere under a 300 MB cap: done (exit $rc)" \
    sh -c 'test "$1" = 0 && test "$(grep -c "<g class=\"panel\"" "$2")" = 7' _ "$rc" "$tmp/sph6.svg"
check "hostile-14.17 ... its viewport panel marks pixel (401, 300), as why says" \
    grep -q "(x_vp, y_vp) = (401, 300)" "$tmp/sph6.svg"
fi
"$exe" why "$tmp/sph6.scene" 400 300 > "$tmp/w6" 2>&1
"$exe" "$tmp/sph6.scene" --image "$tmp/sph6.ppm" > /dev/null 2>&1
px=$(tail -c $((3 * (800 * 600 - (300 * 800 + 400)))) "$tmp/sph6.ppm" | head -c 3 | od -An -tu1 | tr -s ' ' ' ')
check "hostile-14.11 ... its colour that of the image's pixel (400, 300) (${px# })" \
    grep -q "^color${px% } *: s s[0-9]* is the last segment drawn there$" "$tmp/w6"

# ---- a point's radius costs the viewport, not (2r + 1)^2: 200 points of
# radius 4096 in renderer 7 (about 25 s of CPU when every one of their 67
# million pixels was tested) end at once; the image is the same
{ printf 'renderer 7\nframebuffer 100 100\nmodel a\n'
  i=0; while [ $i -lt 200 ]; do echo 'v 0 0 -1'; i=$((i + 1)); done
  i=1; while [ $i -le 200 ]; do echo "point $i 1 4096"; i=$((i + 1)); done; } > "$tmp/points.scene"
( ulimit -t 10; "$exe" "$tmp/points.scene" --image "$tmp/points.ppm" ) > "$tmp/out" 2> "$tmp/err"; rc=$?
check "hostile-15.1 200 points of radius 4096: drawn within 10 s of CPU (exit $rc)" test "$rc" = 0
check "hostile-15.2 ... the viewport filled with the points' colour" \
    sh -c 'test "$(tail -c 30000 "$1" | od -An -tu1 -v | tr -s " \n" "\n" | grep -c "^255$")" = 30000' _ "$tmp/points.ppm"

# ---- the course's log of renderers 7 and 9 with the rasterizer's lines has
# renderer 4's rule (docs/limits.md): a point of more than 2^24 pixels is
# refused before anything is written (its log would be 4 GB here), one of
# 2^24 or fewer is logged; renderer 4 says it alike
for r in 7 9; do
    printf 'renderer %s\nframebuffer 20 20\nmodel a\nv 0 0 -1\npoint 1 1 2048\n' "$r" > "$tmp/bigpt.scene"
    ( ulimit -t 10; "$exe" "$tmp/bigpt.scene" --kraft-debug all ) > "$tmp/out" 2> "$tmp/err"; rc=$?
    check "hostile-16.1 renderer $r, a point of radius 2048 with Rasterize.debug: refused (exit $rc)" test "$rc" = 2
    check "hostile-16.2 ... saying the rule, nothing written" sh -c 'test ! -s "$1" && grep -q "^pipetrace: .*bigpt.scene: error: model .a.: a point of radius 2048 has 16785409 pixels, more than the 16777216 lines a point.s pixel log may have$" "$2"' _ "$tmp/out" "$tmp/err"
    ( ulimit -t 10; "$exe" "$tmp/bigpt.scene" --kraft-debug scene,position,clip ) > "$tmp/out" 2> "$tmp/err"; rc=$?
    check "hostile-16.3 ... without the rasterizer's lines: logged (exit $rc)" sh -c 'test "$1" = 0 && grep -q "Rasterize" "$2"' _ "$rc" "$tmp/out"
    printf 'renderer %s\nframebuffer 20 20\nmodel a\nv 0 0 -1\npoint 1 1 30\n' "$r" > "$tmp/pt.scene"
    run "$tmp/pt.scene" --kraft-debug all
    check "hostile-16.4 ... a point of radius 30: its 3721 pixel lines logged" test "$rc" = 0 -a "$(grep -c "^ *fb_\[" "$tmp/out")" -ge 3721
done
printf 'framebuffer 20 20\ncamera perspective\nmodel a\nv 0 0 -1\npoint 1 1 2048\n' > "$tmp/bigpt.scene"
run "$tmp/bigpt.scene" --kraft-debug all
check "hostile-16.5 renderer 4: the same rule, the same words" grep -q "error: model .a.: a point of radius 2048 has 16785409 pixels, more than the 16777216 lines" "$tmp/err"

# ---- 17: sheet and student names with terminal escapes in a CSV on standard output
mkdir -p "$tmp/esc17"
printf '%s\n' '-1 -1 0' > "$tmp/esc17/$(printf 'a\033[31mb')"
"$exe" quiz docs/examples/triangle.scene --vertex 1 --grade "$tmp/esc17" > "$tmp/q17" 2>&1
check "hostile-17.1 quiz --grade: no ESC byte from a sheet's name in its CSV" \
    sh -c "! grep -q \"\$(printf '\\033')\" '$tmp/q17'"
check "hostile-17.2 ... the name shown escaped" grep -qF 'a\x1b[31mb,' "$tmp/q17"
"$exe" docs/examples/triangle.scene --trace "$tmp/esc17/$(printf 'c\033]0;t\007')d.txt"
"$exe" class docs/examples/triangle.scene "$tmp/esc17" --csv - > "$tmp/c17" 2>&1
check "hostile-17.3 class --csv -: no ESC or BEL byte from a file's name" \
    sh -c "! grep -q \"\$(printf '\\033\\|\\007')\" '$tmp/c17'"
check "hostile-17.4 ... the name shown escaped" grep -qF 'c\x1b]0;t\x07d' "$tmp/c17"

report
