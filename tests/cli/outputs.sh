#!/bin/sh
# tests/cli/outputs.sh -- output files: signals, replacing a file, writing over an
# input, what the trace writes of paths and numbers
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/outputs.sh PIPETRACE.  Run from the repository root.
exe=$1
. tests/lib/testlib.sh
skipped=0
tri=docs/examples/triangle.scene

# ---- a signal while writing leaves no temporary file and the old file whole
# The trace is written to a temporary file first; the image goes to a FIFO
# afterwards, and that FIFO is opened for reading only here: once the open
# returns, pipetrace has the whole trace in its temporary file and blocks on
# the image (360 kB, more than a pipe holds).  Then the signal.  No sleep: the
# open is the synchronisation (timeout only guards against a run that fails).
signal_case() {     # signal_case ID SIGNAL
    dir="$tmp/sig-$2"
    mkdir "$dir"
    echo "old trace" > "$dir/out.trace"
    mkfifo "$dir/img.ppm"
    "$exe" --trace "$dir/out.trace" --image "$dir/img.ppm" 2>/dev/null &
    pid=$!
    timeout 60 sh -c 'exec 3<"$1"; kill -"$2" "$3"' sh "$dir/img.ppm" "$2" "$pid"
    opened=$?
    { wait "$pid"; } 2>/dev/null; prc=$?
    check "$1 SIG$2 while writing: the run was stopped by it" test "$opened" = 0 -a "$prc" -gt 128
    check "$1 ... leaves no temporary file" test "$(ls -A "$dir" | tr '\n' ' ')" = "img.ppm out.trace "
    check "$1 ... and the old file as it was" test "$(cat "$dir/out.trace")" = "old trace"
}
signal_case out-3.1 INT
signal_case out-3.2 TERM
# SIGKILL cannot be caught: only a temporary file without a name (O_TMPFILE,
# where the file system has it) leaves nothing then.
if python3 -c 'import os, sys; os.close(os.open(sys.argv[1], os.O_TMPFILE | os.O_WRONLY))' "$tmp" 2>/dev/null
then signal_case out-3.3 KILL
else skipped=$((skipped + 3))
fi

# ---- replacing a file keeps what it was
dir="$tmp/keep"
mkdir "$dir"
echo old > "$dir/private.trace"
chmod 600 "$dir/private.trace"
run "$tri" --trace "$dir/private.trace"
check "out-7.1 a 0600 trace is replaced" test "$rc" = 0 -a "$(head -c 9 "$dir/private.trace")" = "# pipetra"
check "out-7.2 ... and stays 0600" test "$(stat -c %a "$dir/private.trace")" = 600
echo old > "$dir/shared.trace"
chmod 640 "$dir/shared.trace"
run "$tri" --format jsonl --trace "$dir/shared.trace"
check "out-7.3 a 0640 trace stays 0640" test "$(stat -c %a "$dir/shared.trace")" = 640
( umask 022 && "$exe" "$tri" --trace "$dir/new.trace" )
check "out-7.4 a new file is 0666 less the umask" test "$(stat -c %a "$dir/new.trace")" = 644

echo "read only" > "$dir/ro.trace"
chmod 444 "$dir/ro.trace"
run "$tri" --trace "$dir/ro.trace"
check "out-7.5 a read-only file is refused: exit 2" test "$rc" = 2
check "out-7.6 ... with the reason" grep -q "^pipetrace: cannot write '$dir/ro.trace': " "$tmp/err"
check "out-7.7 ... and kept" test "$(cat "$dir/ro.trace")" = "read only"

echo "linked" > "$dir/a.trace"
ln "$dir/a.trace" "$dir/b.trace"
run "$tri" --trace "$dir/a.trace"
check "out-7.8 a file with two links is written" test "$rc" = 0 -a "$(head -c 9 "$dir/a.trace")" = "# pipetra"
check "out-7.9 ... and keeps its links" test "$(stat -c %h "$dir/a.trace")" = 2 -a \
    "$(stat -c %i "$dir/a.trace")" = "$(stat -c %i "$dir/b.trace")"
check "out-7.10 ... so the other name sees the new trace" cmp -s "$dir/a.trace" "$dir/b.trace"
echo "linked" > "$dir/a.trace"
run "$tri" --trace "$dir/a.trace" --image /dev/full
check "out-7.11 a failed run leaves a linked file as it was" test "$rc" = 2 -a "$(cat "$dir/b.trace")" = linked

long=$(printf 'n%.0s' $(seq 249))
for n in 249 255; do
    name=$(printf '%s' "$long$long" | cut -c1-$((n - 6))).trace
    run "$tri" --trace "$dir/$name"
    check "out-7.12 a name of $n bytes is written" test "$rc" = 0 -a -s "$dir/$name"
done
ls -A "$dir" > "$tmp/listing"
check "out-7.13 no temporary file left" test "$(grep -c pipetrace "$tmp/listing")" = 0

# A directory where no file can be made (immutable with chattr, else
# read-only when not root): a writable file in it is written in place.
dir="$tmp/rodir"
mkdir "$dir"
echo old > "$dir/t.trace"
locked=
if chattr +i "$dir" 2>/dev/null; then locked=chattr
elif [ "$(id -u)" != 0 ]; then chmod 555 "$dir"; locked=chmod
fi
if [ -n "$locked" ]; then
    run "$tri" --trace "$dir/t.trace" --image /dev/full
    check "out-7.14 no temporary file can be made: a failed run keeps the old file" \
        test "$rc" = 2 -a "$(cat "$dir/t.trace")" = old
    run "$tri" --trace "$dir/t.trace"
    check "out-7.15 ... and a good run writes it in place" test "$rc" = 0 -a \
        "$(head -c 9 "$dir/t.trace")" = "# pipetra"
    run "$tri" --trace "$dir/new.trace"
    check "out-7.16 ... a new file there cannot be made: exit 2" test "$rc" = 2 -a ! -e "$dir/new.trace"
    if [ "$locked" = chattr ]; then chattr -i "$dir"; else chmod 755 "$dir"; fi
else
    skipped=$((skipped + 3))
fi

# ---- an output over an input, or over the other output
dir="$tmp/same"
mkdir "$dir"
cp "$tri" "$dir/x.scene"
run "$dir/x.scene" --trace "$dir/x.scene"
check "out-4.1 --trace SCENE is refused: exit 2" test "$rc" = 2
check "out-4.2 ... with OUT: error: ..." grep -q "^$dir/x.scene: error: --trace names the scene file" "$tmp/err"
check "out-4.3 ... and the scene kept" cmp -s "$tri" "$dir/x.scene"
ln -s x.scene "$dir/sym.scene"
ln "$dir/x.scene" "$dir/hard.scene"
run "$dir/x.scene" --image "$dir/sym.scene"
check "out-4.4 --image through a symbolic link to the scene: exit 2" test "$rc" = 2
run "$dir/sym.scene" --trace "$dir/hard.scene"
check "out-4.5 --trace a hard link of the scene: exit 2" test "$rc" = 2
check "out-4.6 ... and the scene kept" cmp -s "$tri" "$dir/x.scene"
"$exe" - --trace "$dir/x.scene" < "$dir/x.scene" 2>"$tmp/err"
check "out-4.7 --trace the file standard input reads the scene from: exit 2" test "$?" = 2
check "out-4.8 ... and the scene kept" cmp -s "$tri" "$dir/x.scene"
echo "old" > "$dir/out"
run "$tri" --trace "$dir/out" --image "$dir/./out"
check "out-4.9 --image F --trace F: exit 2" test "$rc" = 2 -a "$(cat "$dir/out")" = old
check "out-4.10 ... with OUT: error: ..." grep -q "^$dir/./out: error: --trace and --image name the same file" "$tmp/err"
run "$tri" --trace "$dir/new" --image "$dir/../same/new"
check "out-4.11 ... also when F does not exist yet" test "$rc" = 2 -a ! -e "$dir/new"
run "$tri" --trace /dev/null --image /dev/null
check "out-4.12 a device twice is fine" test "$rc" = 0
run journey "$dir/x.scene" --vertex 1 --svg "$dir/hard.scene"
check "out-4.13 journey --svg over the scene: exit 2, scene kept" test "$rc" = 2 -a \
    -n "$(grep "^$dir/hard.scene: error: --svg names the scene file" "$tmp/err")" -a "$(cmp "$tri" "$dir/x.scene" && echo same)" = same
run journey "$dir/x.scene" --vertex 1 --svg "$dir/j.svg" --html "$dir/./j.svg"
check "out-4.14 journey --svg F --html F: exit 2" test "$rc" = 2
run accuracy "$dir/x.scene" --repeat 1 --svg "$dir/sym.scene"
check "out-4.15 accuracy --svg over the scene: exit 2, scene kept" test "$rc" = 2 -a \
    "$(cmp "$tri" "$dir/x.scene" && echo same)" = same
"$exe" "$tri" --image "$dir/a.ppm" && cp "$dir/a.ppm" "$dir/a0.ppm" && "$exe" "$tri" --image "$dir/b.ppm"
run diff "$dir/a.ppm" "$dir/b.ppm" --image-out "$dir/./a.ppm"
check "out-4.16 diff --image-out over EXPECTED: exit 2, the image kept" test "$rc" = 2 -a \
    -n "$(grep "^$dir/./a.ppm: error: --image-out names EXPECTED, $dir/a.ppm; writing it would destroy it" "$tmp/err")" -a "$(cmp "$dir/a.ppm" "$dir/a0.ppm" && echo same)" = same
ln -f "$dir/b.ppm" "$dir/b-link.ppm"
run diff "$dir/a.ppm" "$dir/b.ppm" --image-out "$dir/b-link.ppm"
check "out-4.17 ... over ACTUAL through a hard link: exit 2" test "$rc" = 2

# ---- the text trace escapes the scene path as JSONL does
dir="$tmp/path"
mkdir "$dir"
odd="$dir/$(printf 'a\nb\033[31mc\\d"')e.scene"
cp "$tri" "$odd"
run "$odd" --trace "$dir/odd.trace"
check "out-8.1 a path with a newline, ESC, \\ and \": one scene line" \
    test "$rc" = 0 -a "$(sed -n 2p "$dir/odd.trace")" = "scene        $dir/a\\u000ab\\u001b[31mc\\\\d\\\"e.scene"
check "out-8.2 ... no ESC byte for the terminal" test "$(tr -dc '\033' < "$dir/odd.trace" | wc -c)" = 0
run "$odd" --format jsonl --trace "$dir/odd.jsonl"
check "out-8.3 ... escaped as the JSONL header's \"scene\"" grep -qF \
    "\"scene\":\"$(sed -n 's/^scene        //p' "$dir/odd.trace")\"," "$dir/odd.jsonl"
run diff "$dir/odd.trace" "$dir/odd.trace"
check "out-8.4 ... and the text reader reads it back (diff)" test "$rc" = 0
run diff "$dir/odd.jsonl" "$dir/odd.trace"
check "out-8.5 ... against the JSONL trace too" test "$rc" = 0
sed '2s/$/\\q/' "$dir/odd.trace" > "$dir/bad.trace"
run diff "$dir/bad.trace" "$dir/odd.trace"
check "out-8.6 a bad escape in the scene path: FILE:LINE:COL: error" test "$rc" = 2 -a \
    -n "$(grep "^$dir/bad.trace:2:[0-9]*: error: bad escape in the scene path" "$tmp/err")"

# ---- negative zero in JSON keeps its sign
run tests/extreme/negative-zero.scene --format jsonl
check "out-9.1 JSON writes negative zero as -0.0" grep -q '"v":1,"stage":"model","x":-0.0,"y":-0.0,"z":-2}' "$tmp/out"
check "out-9.2 ... and no -0 that reads back as the integer 0" test -z "$(grep -E '[:,[]-0[],}]' "$tmp/out")"
cp "$tmp/out" "$tmp/nz.jsonl"
run diff "$tmp/nz.jsonl" "$tmp/nz.jsonl"
check "out-9.3 ... and diff reads it back" test "$rc" = 0

# ---- null per value: x_pp infinite, y_pp = 22.9895 keeps y_vp = 7, y_fb = 10
half=tests/data/null-per-value.scene
run "$half" --vertex 1 --format jsonl --trace "$tmp/half.jsonl"
check "out-10.1 JSONL viewport: x null, y kept" grep -q '"stage":"viewport","x":null,"y":7,"inside":false,"warning":\["out_of_range"\]}' "$tmp/half.jsonl"
check "out-10.2 JSONL framebuffer: x null, y kept" grep -q '"stage":"framebuffer","x":null,"y":10}' "$tmp/half.jsonl"
check "out-10.3 ... and no index" grep -q '"stage":"index","i":null}' "$tmp/half.jsonl"
run "$half" --vertex 1 --all-stages --trace "$tmp/half.trace"
check "out-10.4 text: none and 7" grep -qE '^m v1 +viewport +x_vp = +none +y_vp = +7 +outside' "$tmp/half.trace"
check "out-10.5 text: none and 10" grep -qE '^m v1 +framebuffer +x_fb = +none +y_fb = +10$' "$tmp/half.trace"
run "$half" --vertex 1 --format csv
check "out-10.6 CSV: x empty, y kept" test -n "$(echo "$out" | grep -x 'm,1,viewport,,7,,0,,,out_of_range,')" \
    -a -n "$(echo "$out" | grep -x 'm,1,framebuffer,,10,,,,,,')"
run diff "$tmp/half.trace" "$tmp/half.jsonl"
check "out-10.7 both readers read a half-null pixel back" test "$rc" = 0
sed 's/"y":7,/"y":8,/' "$tmp/half.jsonl" > "$tmp/half8.jsonl"
run diff "$tmp/half.trace" "$tmp/half8.jsonl"
check "out-10.8 ... and its value counts (y_vp 7 against 8 differs)" test "$rc" = 1
# a student's missing y flip on that vertex: y_vp = round(y_pp) - 1 = 22, y_fb = 25;
# diff recomputes null per value too (x_vp stays none, y_vp has its value)
sed 's/"x":null,"y":7,"inside"/"x":null,"y":22,"inside"/; s/"x":null,"y":10}/"x":null,"y":25}/' \
    "$tmp/half.jsonl" > "$tmp/flip.jsonl"
run diff "$tmp/half.jsonl" "$tmp/flip.jsonl"
check "out-10.9 diff names the missing y flip on a half-null pixel: x_vp = none, y_vp = 22" \
    test "$rc" = 1 -a -n "$(echo "$out" | grep -x '  explains all: missing y flip (viewport stage), which reproduces the 1')" \
    -a -n "$(echo "$out" | tr '\n' ' ' | grep 'gives x_vp = none, y_vp = *22, as ACTUAL has')"

# ---- smaller: the reason a trace cannot be written; '-' as the scene
run "$tri" --trace /dev/full
check "out-14.1 --trace /dev/full: exit 2 with the reason" test "$rc" = 2 -a \
    "$err" = "pipetrace: cannot write the trace to '/dev/full': No space left on device"
"$exe" - < "$tri" > "$tmp/stdin.trace" 2>"$tmp/err"
check "out-14.2 '-' reads the scene from standard input" test "$?" = 0
"$exe" "$tri" | sed "s|^scene        $tri\$|scene        <stdin>|" > "$tmp/file.trace"
check "out-14.3 ... the trace of the file, named <stdin>" cmp -s "$tmp/stdin.trace" "$tmp/file.trace"
printf 'framebuffer 10 10\nmodel m\nv 1 2\n' | "$exe" - > /dev/null 2>"$tmp/err"
check "out-14.4 ... its errors say <stdin>:LINE:COL" test "$?" = 2 -a \
    "$(cat "$tmp/err")" = "<stdin>:3:1: error: expected 3 numbers after 'v', found 2"
"$exe" step - --vertex 1 --all < "$tri" > "$tmp/out" 2>&1
check "out-14.5 ... in the other commands too" grep -q "of model tri in <stdin>" "$tmp/out"

# A CSV trace has no raster rows: drawing the image too (each model right
# after its vertices, src/core/pipeline.c) must not change a byte of it.
{ sed -n '/^framebuffer/,$p' docs/examples/lookat-near.scene; printf 'model two\nv 0.5 0.25 4\nv 0.5 0.25 -4\nl 1 2\n'; } \
    > "$tmp/two-clipped.scene"      # the matrix camera clips while it draws
for sc in docs/examples/two-models.scene docs/examples/builtin.scene docs/examples/clip.scene \
          docs/examples/lookat-world.scene "$tmp/two-clipped.scene"; do
    "$exe" "$sc" --format csv --trace "$tmp/a.csv" 2>/dev/null
    "$exe" "$sc" --format csv --trace "$tmp/b.csv" --image "$tmp/b.ppm" 2>/dev/null
    check "out-15 $(basename "$sc"): the CSV trace is the same with --image" cmp -s "$tmp/a.csv" "$tmp/b.csv"
done
# ... and the points clipping makes (no v) come after every model's vertices
check "out-15.1 two clipped models: their clipping points after all vertices" \
    awk -F, 'NR > 1 && $2 == "" { cut = 1 } NR > 1 && $2 != "" && cut { bad = 1 }
             END { exit !(cut && !bad) }' "$tmp/b.csv"

[ "$skipped" -gt 0 ] && echo "$skipped skipped (no O_TMPFILE, or no way to lock a directory here)"
report
