#!/bin/sh
# tests/teach/class.sh -- pipetrace class: a folder of students against one EXPECTED
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/class.sh PIPETRACE.  Run from the repository root.
# Builds student stages of tests/teach/student.sh, puts their traces and
# images in a folder with files a class folder really has (a .docx, a broken
# link, a link loop, a FIFO, a folder, names with quotes, formulas and
# terminal escapes), and checks: every row's verdict, first wrong stage and
# mistake are diff --verdict's own on that file; the counts; the histograms;
# CSV and HTML (escaping, a link per student to that student's diff, the page
# in headless Chromium when it is installed); that nothing in the folder is
# written or blocks; the same bytes on every run and with --jobs 1; the
# errors.  docs/examples/class/ is the worked example of docs/teaching.md.
exe=$1
. tests/lib/testlib.sh
. tests/lib/studentlib.sh
scene=docs/examples/selfcheck.scene
dir=$tmp/class
mkdir -p "$dir"

# ---- the students
for pair in ann:s4_trunc ben:s4_noflip cat:s3_two dan:u_s6_xle eve:s1_subtract; do
    who=${pair%%:*} name=${pair#*:}
    mistaken "$name"
    check "class-0.1 $name: the student build" test -x "$tmp/sb/pipetrace"
    "$tmp/sb/pipetrace" $scene --all-stages --format jsonl --trace "$dir/$who.jsonl" \
        --image "$dir/$who.ppm" 2>/dev/null
done
"$exe" $scene --all-stages --trace "$dir/ok.txt" --image "$dir/ok.png"
"$exe" $scene --trace "$dir/part.txt" --stage viewport
rm "$dir/eve.ppm"                       # a trace without its image
printf 'PK\003\004 answers\n' > "$dir/word.docx"
ln -s nowhere "$dir/gone.log"
ln -s loop2 "$dir/loop1"; ln -s loop1 "$dir/loop2"
mkfifo "$dir/pipe.log"
mkdir "$dir/sub"
printf 'x\n' > "$dir/.hidden"
cp "$dir/ann.jsonl" "$dir/=SUM(A1)\"q.jsonl"
cp "$dir/ok.txt" "$dir/$(printf 'esc\033]0;pwned\007')x.txt"
( cd "$dir" && ls -lA --time-style=+%s . && find . -type f -exec cksum {} + ) > "$tmp/before"

timeout 60 "$exe" class $scene "$dir" --csv "$tmp/c.csv" --html "$tmp/c.html" >"$tmp/out" 2>"$tmp/err"
rc=$?
check "class-1.1 exit 0" test "$rc" = 0
check "class-1.2 nothing on standard error" test ! -s "$tmp/err"
( cd "$dir" && ls -lA --time-style=+%s . && find . -type f -exec cksum {} + ) > "$tmp/after"
check "class-1.3 nothing in the folder written (a FIFO neither opened nor blocking)" \
    cmp "$tmp/before" "$tmp/after"

row() {     # row NAME: the table's line for NAME
    grep "^$1 " "$tmp/out"
}
# each student's row says what diff --verdict says of that file
for pair in ann:s4_trunc ben:s4_noflip cat:s3_two dan:u_s6_xle eve:s1_subtract; do
    who=${pair%%:*}
    "$exe" diff --verdict "$tmp/exp.jsonl" "$dir/$who.jsonl" >/dev/null 2>&1
    [ -f "$tmp/exp.jsonl" ] || "$exe" $scene --all-stages --format jsonl --trace "$tmp/exp.jsonl"
    "$exe" diff --verdict "$tmp/exp.jsonl" "$dir/$who.jsonl" > "$tmp/d" 2>&1
    v=$(awk 'BEGIN { RS = "" } { p = $0 } END { print p }' "$tmp/d" | tr '\n' ' ')
    stage=$(printf '%s\n' "$v" | sed -n 's/^Verdict: FAIL at the \([a-z]*\) stage.*/\1/p')
    mistake=$(printf '%s\n' "$v" | sed -n 's/.*Likely mistake: \([^:]*\):.*/\1/p')
    [ -n "$mistake" ] || mistake=unknown
    check "class-2.1 $who: FAIL at diff's stage ($stage)" \
        sh -c "grep '^$who ' '$tmp/out' | grep -qE '^$who +FAIL +$stage +'"
    printf '  %s  \n' "$mistake" > "$tmp/want"
    check "class-2.2 $who: diff's mistake ($mistake)" sh -c "grep '^$who ' '$tmp/out' | grep -qF -f '$tmp/want'"
done
check "class-2.3 ann: 5 of 16 vertices and 1 pixel differ, and 1 of its image" \
    sh -c "grep '^ann ' '$tmp/out' | grep -qE '  5/16 +1 +1$'"
check "class-2.4 eve: no image, '-' in its column" sh -c "grep '^eve ' '$tmp/out' | grep -qE ' -$'"
check "class-2.5 ok (text trace and PNG): PASS" sh -c "grep -qE '^ok +PASS ' '$tmp/out'"
check "class-2.6 part (the viewport stage only): NOT PROVEN" \
    sh -c "grep -qE '^part +NOT PROVEN ' '$tmp/out'"
check "class-2.7 the .docx: UNREADABLE, with diff's reason" \
    sh -c "grep -E '^word +UNREADABLE ' '$tmp/out' | grep -qF 'word.docx:1:1: error: not a pipetrace trace'"
check "class-2.8 a broken link said so" sh -c "grep -qE '^gone.log +UNREADABLE +a broken symbolic link' '$tmp/out'"
check "class-2.9 a link loop said so" sh -c "grep -qE '^loop1 +UNREADABLE +a symbolic link in a loop' '$tmp/out'"
check "class-2.10 a FIFO said so" sh -c "grep -qE '^pipe.log +UNREADABLE +not a regular file' '$tmp/out'"
check "class-2.11 a folder said so" sh -c "grep -qE '^sub +UNREADABLE +a folder' '$tmp/out'"
check "class-2.12 a dot file skipped" sh -c "! grep -q hidden '$tmp/out'"
check "class-2.13 no terminal escape reaches the terminal" sh -c "! grep -q \"\$(printf '\\033')\" '$tmp/out'"
check "class-2.14 ... the name shown escaped" grep -qF 'esc\x1b]0;pwned\x07x' "$tmp/out"
check "class-2.15 the totals" grep -qx '2 passed, 6 failed, 1 not proven, 6 unreadable' "$tmp/out"
check "class-2.16 histogram by stage: viewport 3" \
    sh -c "sed -n '/by first wrong stage/,/^\$/p' '$tmp/out' | grep -qE '^  viewport +3  #+\$'"
check "class-2.17 histogram by mistake: unknown 1" \
    sh -c "sed -n '/by mistake/,\$p' '$tmp/out' | grep -qE '^  unknown +1  #+\$'"
check "class-2.18 the copy named like a formula: FAIL as ann" \
    sh -c "grep -F '=SUM(A1)\"q' '$tmp/out' | grep -q 'truncation toward zero'"

# ---- CSV
python3 - "$tmp/c.csv" > "$tmp/csv" 2>&1 <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="", encoding="utf-8")))
head, body = rows[0], rows[1:]
assert head[:6] == ["student", "trace", "image", "verdict", "first_wrong_stage", "mistake"], head
assert len(body) == 15, len(body)
assert all(len(r) == len(head) for r in body)
by = {r[0]: r for r in body}
assert "'=SUM(A1)\"q" in by, sorted(by)           # a formula kept as text
assert by["ann"][3:6] == ["FAIL", "viewport", "truncation toward zero instead of Java's Math.round"]
assert by["ann"][6:9] == ["5/16", "1", "1"], by["ann"]
assert by["ok"][3:6] == ["PASS", "", ""], by["ok"]
assert by["gone.log"][9] == "a broken symbolic link"
for r in body:
    for cell in r:
        assert not cell[:1] in ("=", "+", "-", "@"), cell
print("ok")
EOF
check "class-3.1 CSV: RFC 4180, a row per student, formulas as text ($(tail -1 "$tmp/csv"))" \
    grep -qx ok "$tmp/csv"

# ---- HTML
python3 - "$tmp/c.html" > "$tmp/html" 2>&1 <<'EOF'
import html.parser, sys
text = open(sys.argv[1], encoding="utf-8").read()
class P(html.parser.HTMLParser):
    def __init__(s):
        super().__init__(); s.ids, s.links, s.rows, s.bars, s.scripts = set(), [], 0, 0, 0
    def handle_starttag(s, tag, attrs):
        a = dict(attrs)
        if "id" in a: s.ids.add(a["id"])
        if tag == "a" and a.get("href", "").startswith("#"): s.links.append(a["href"][1:])
        if tag == "tr" and a.get("class") == "student": s.rows += 1
        if tag == "g" and a.get("class") == "bar": s.bars += 1
        if tag in ("script", "link", "img", "iframe"): s.scripts += 1
p = P(); p.feed(text)
assert p.rows == 15, p.rows
assert len(p.links) == 15 and all(l in p.ids for l in p.links), p.links
assert "by-stage" in p.ids and "by-mistake" in p.ids
assert p.bars >= 5, p.bars
assert p.scripts == 0                       # self-contained, nothing fetched
assert "\x1b" not in text and "pipetrace-class-" not in text
assert "=SUM(A1)&quot;q" in text
print("ok")
EOF
check "class-4.1 HTML: a row and a link to its diff per student, two charts, self-contained ($(tail -1 "$tmp/html"))" \
    grep -qx ok "$tmp/html"
check "class-4.2 ... each student's diff in the page" \
    test "$(grep -c '^Verdict: FAIL' "$tmp/c.html")" = 6

browser=
for b in chromium chromium-browser google-chrome; do
    command -v "$b" >/dev/null 2>&1 && { browser=$b; break; }
done
if [ -n "$browser" ]; then
    cp "$tmp/c.html" "$tmp/page.html"
    timeout 60 "$browser" --headless --no-sandbox --disable-gpu --no-first-run \
        --disable-background-networking --user-data-dir="$tmp/prof" --dump-dom \
        "file://$tmp/page.html" > "$tmp/dom" 2>/dev/null
    check "class-4.3 headless Chromium: 15 student rows" \
        test "$(grep -o '<tr class="student">' "$tmp/dom" | wc -l)" = 15
    check "class-4.4 headless Chromium: the bars of both charts" \
        test "$(grep -o '<g class="bar"' "$tmp/dom" | wc -l)" -ge 5
else
    echo "  skipped class-4.3, class-4.4: chromium not installed"
fi

# ---- the same bytes every run, on one job or two; EXPECTED as a trace
"$exe" class $scene "$dir" --jobs 1 --csv "$tmp/c1.csv" --html "$tmp/c1.html" >"$tmp/out1" 2>&1
check "class-5.1 --jobs 1: the same table" cmp "$tmp/out" "$tmp/out1"
check "class-5.2 --jobs 1: the same CSV" cmp "$tmp/c.csv" "$tmp/c1.csv"
check "class-5.3 --jobs 1: the same page" cmp "$tmp/c.html" "$tmp/c1.html"
run class "$tmp/exp.jsonl" "$dir"
check "class-5.4 EXPECTED a trace: exit 0" test "$rc" = 0
check "class-5.5 ... the same verdicts, no image compared" \
    sh -c "grep -E '^ann ' '$tmp/out' | grep -qE 'truncation toward zero.*  5/16 +1 +-$'"

# ---- errors
run class $scene "$dir" --csv "$dir/grades.csv"
check "class-6.1 an output in the folder: exit 2" test "$rc" = 2
check "class-6.2 ... said, and not written" sh -c "grep -q 'in the class.s folder' '$tmp/err' && test ! -e '$dir/grades.csv'"
run class "$dir/ann.ppm" "$dir"
check "class-6.3 EXPECTED an image: exit 2, said" sh -c "test $rc = 2 && grep -q 'EXPECTED is an image' '$tmp/err'"
run class $scene "$tmp/none"
check "class-6.4 no such DIR: exit 2" sh -c "test $rc = 2 && grep -q 'none: error:' '$tmp/err'"
printf 'framebuffer 10 10\nv 1 2\n' > "$tmp/bad.scene"
run class "$tmp/bad.scene" "$dir"
check "class-6.5 a bad scene: exit 2 with its FILE:LINE:COL message" \
    sh -c "test $rc = 2 && grep -q 'bad.scene:2:' '$tmp/err'"
check "class-6.10 ... and the scene is still there, as it was" \
    sh -c "printf 'framebuffer 10 10\\nv 1 2\\n' | cmp - '$tmp/bad.scene'"
run class $scene
check "class-6.6 DIR missing: usage error, exit 1" test "$rc" = 1
run class $scene "$dir" --jobs 0
check "class-6.7 --jobs 0: usage error" test "$rc" = 1
run class $scene "$dir" --csv "$scene"
check "class-6.8 an output over EXPECTED: exit 2" test "$rc" = 2
run class --help
check "class-6.9 --help: exit 0, the usage" sh -c "test $rc = 0 && grep -q 'usage: pipetrace class EXPECTED DIR' '$tmp/out'"

# ---- the worked example of docs/teaching.md
run class $scene docs/examples/class
check "class-7.1 docs/examples/class: bob's truncation, dave unknown, erin unreadable" \
    sh -c "grep -qE '^bob +FAIL +viewport +truncation' '$tmp/out' && grep -qE '^dave +FAIL +index +unknown' '$tmp/out' && grep -qE '^erin +UNREADABLE' '$tmp/out'"
# ---- renderers 7 and 9: the course's logs of student copies (tests/data/diff79)
mkdir "$tmp/c79"
for f in tests/data/diff79/r7-near-amb.*.log.gz tests/data/diff79/r7-near.neart.log.gz; do
    b=$(basename "$f" .log.gz)
    gzip -dc "$f" > "$tmp/c79/${b#*.}.log"
done
run class tests/data/diff79/r7-near-amb.scene "$tmp/c79"
check "class-8.1 renderer 7: exit 0" test "$rc" = 0
check "class-8.2 the right log passes" sh -c "grep -qE '^right +PASS ' '$tmp/out'"
check "class-8.3 two mistakes that give the same log: ambiguous, both named" \
    sh -c "grep -E '^nearoff +FAIL +nearclip +ambiguous: ' '$tmp/out' | grep -q 'the near plane ignored' && grep -E '^nearoff ' '$tmp/out' | grep -q \"the near plane's sign wrong\""
check "class-8.4 histogram: the ambiguous pair one bar, 2 students" \
    sh -c "sed -n '/by mistake/,\$p' '$tmp/out' | grep -qE '^  ambiguous: .* +2  #+\$'"
check "class-8.5 a log of another scene: not a pass" sh -c "! grep -qE '^neart +PASS' '$tmp/out'"
# an ambiguous row carries the scene diff prints to tell its mistakes apart
run class tests/data/diff79/r7-near-amb.scene "$tmp/c79" --csv "$tmp/c79.csv" --html "$tmp/c79.html"
check "class-8.6 --csv: a separating_scene column, the scene in the ambiguous rows' cells" \
    sh -c "head -1 '$tmp/c79.csv' | grep -q ',note,separating_scene' && grep -qF 'nearoff,nearoff.log,,FAIL,nearclip,ambiguous' '$tmp/c79.csv' && grep -qF 'segment 1 2' '$tmp/c79.csv'"
check "class-8.7 ... and none in a row that is not ambiguous" \
    sh -c "grep -E '^right,' '$tmp/c79.csv' | tr -d '\\r' | grep -qE ',\$'"
check "class-8.8 --html: the ambiguous rows link to the scene, shown below their diff" \
    sh -c "test \$(grep -c 'href=\"#scene-[0-9]*\">a scene that tells them apart' '$tmp/c79.html') = 2 && test \$(grep -c 'id=\"scene-[0-9]*\">The separating scene' '$tmp/c79.html') = 2"

report
