#!/bin/sh
# tests/class/students.sh -- pipetrace diff and class on a class of student renderers
# See LICENSE for copyright and license.
#
# Usage: sh tests/class/students.sh PIPETRACE.  Run from the repository root.
# tests/data/students/ holds, per scene, what each student of students.txt
# handed in: the course's Java renderer 4 with a mistake or two (its debug
# log and image), or pipetrace built with mistaken stages (its JSON Lines
# trace and image); tests/class/make-students.sh made them.  For every
# student and scene, pipetrace diff --verdict against the scene's trace must
#   - never name a mistake the student did not make (a student of unknown
#     mistakes only: never any name),
#   - never say FAIL for a student without a mistake, nor PASS for one with
#     a mistake, unless the student's trace is the reference's record for
#     record (a rounding mistake on a scene without ties and negatives: no
#     trace can show it, which diff cannot know),
#   - when it says "ambiguous", list one of the student's mistakes among
#     the others;
#   - its image against the scene's, pipetrace diff --scene SCENE (the
#     viewport's corner: a picture moved by (-x_ul, -y_ul) is the corner
#     forgotten in setPixelVP, which the course's log cannot show), never
#     name a mistake the student did not make, nor the second mistake named
#     behind a vertex stage's (the rasterizer replayed from ACTUAL's own end
#     pixels);
#   - its image against its own log or trace, pipetrace diff --scene SCENE
#     LOG IMAGE (the logged pixels lit at their viewport coordinates: the
#     corner forgotten behind another mistake), never name a mistake the
#     student did not make;
# every mistake of the catalogue a student made must be named alone, by the
# diff of its trace or of its image, on at least one scene (known.txt: those no scene of the corpus can name, with the
# reason); and pipetrace class on each scene's folder must give every student
# the verdict and the mistake its diff gives (the CSV).
exe=$1
. tests/lib/testlib.sh
list=tests/data/students/students.txt
data=tests/data/students
known=$data/known.txt

# ---- every diff, its verdict and names as one line per student and scene:
# SCENE<TAB>STUDENT<TAB>VERDICT<TAB>NAME; NAME; ...<TAB>THE IMAGE'S NAME; ...<TAB>SECOND
# <TAB>THE NAME OF THE IMAGE AGAINST ITS OWN LOG
mkdir "$tmp/diff" "$tmp/img" "$tmp/own"
for s in $(awk -F '\t' '$1 == "scene" { print $2 }' "$list"); do
    scene=$(awk -F '\t' -v n="$s" '$1 == "scene" && $2 == n { print $3 }' "$list")
    mkdir -p "$tmp/$s" "$tmp/diff/$s" "$tmp/img/$s" "$tmp/own/$s"
    "$exe" "$scene" --all-stages --format jsonl --trace "$tmp/$s.jsonl" --image "$tmp/$s.ppm"
    for f in "$data/$s"/*.gz; do
        b=$(basename "$f" .gz)
        gzip -dc "$f" > "$tmp/$s/$b"
    done
    for f in "$tmp/$s"/*; do
        who=$(basename "$f"); who=${who%.*}
        case $f in *.ppm)
            "$exe" diff --scene "$scene" "$tmp/$s.ppm" "$f" > "$tmp/img/$s/$who" 2>&1
            for log in "$tmp/$s/$who.log" "$tmp/$s/$who.jsonl"; do
                [ -f "$log" ] && "$exe" diff --scene "$scene" "$log" "$f" > "$tmp/own/$s/$who" 2>&1
            done
            continue ;;
        esac
        "$exe" diff --verdict "$tmp/$s.jsonl" "$f" > "$tmp/diff/$s/$who" 2>&1
    done
done
python3 - "$tmp/diff" "$tmp/img" "$tmp/own" > "$tmp/diffs" <<'EOF'
import os, re, sys
top, img, own = sys.argv[1:]
for s in sorted(os.listdir(top)):
    for who in sorted(os.listdir(os.path.join(top, s))):
        flat = " ".join(open(os.path.join(top, s, who), encoding="utf-8").read().split())
        m = re.search(r"Verdict: (PASS|FAIL|NOT PROVEN)", flat)
        verdict = m.group(1) if m else "NONE"
        last = flat[m.start():] if m else ""
        names = []
        if verdict == "FAIL":
            one = re.search(r"Likely mistake: (.+?): ", last)
            many = re.search(r"reproduces every segment that differs: (.+?)\.$", last)
            if one:
                names = [one.group(1)]
            elif many:
                names = many.group(1).split(" or ")
            elif "More than one known mistake explains it" in last:
                names = re.findall(r"explains all: (.+?) \(\w+ stage\), which", flat)
        second = re.findall(r"Likely second mistake: (.+?) in the ", flat[:m.start()] if m else flat)
        path = os.path.join(img, s, who)
        image = " ".join(open(path, encoding="utf-8").read().split()) if os.path.exists(path) else ""
        shown = re.findall(r"Likely mistake: (.+?): ", image)
        path = os.path.join(own, s, who)
        mine = " ".join(open(path, encoding="utf-8").read().split()) if os.path.exists(path) else ""
        drew = re.findall(r"Likely mistake: (.+?): ", mine)
        print("\t".join([s, who, verdict, "; ".join(names), "; ".join(shown), "; ".join(second),
                         "; ".join(drew)]))
EOF

# ---- against the students' mistakes
python3 - "$list" "$tmp/diffs" "$known" "$tmp" > "$tmp/checks" 2>&1 <<'EOF'
import os, re, sys
lst, diffs, known, tmp = sys.argv[1:]
def same_as_reference(s, who):
    """1 when the student's trace of scene s is the reference's, record for
    record: the scene cannot show the student's mistake"""
    path = os.path.join(tmp, s, who + ".jsonl")
    if not os.path.exists(path):
        return False
    mine = open(path, encoding="utf-8").read()
    mine = re.sub(r'^(\{"type":"header","version":1,)"student":"[^"]*",', r"\1", mine)
    return mine == open(os.path.join(tmp, s + ".jsonl"), encoding="utf-8").read()
truth = {}
for line in open(lst, encoding="utf-8"):
    f = line.rstrip("\n").split("\t")
    if f[0] == "student":
        truth[f[1]] = [] if f[3] == "-" else f[3].split("; ")
# a mistake may be written A|B: B is its name where the scene cannot show more
# than B (w/2 in integers is 2 for 2.001 when w and h are even)
def aliases(m):
    return m.split("|")
expected_fail = {}
for line in open(known, encoding="utf-8"):
    if line.strip() and not line.startswith("#"):
        f = line.rstrip("\n").split("\t")
        expected_fail[(f[0], f[1])] = f[2]
named_alone = set()
for line in open(diffs, encoding="utf-8"):
    s, who, verdict, names, shown, second, drew = line.rstrip("\n").split("\t")
    names = names.split("; ") if names else []
    mine = truth[who]
    right = {a for m in mine for a in aliases(m) if m != "unknown"}
    tag = "%s %s" % (s, who)
    print("check\tstudents-1 %s: a verdict (%s)\t%d" % (tag, verdict, verdict != "NONE"))
    if mine and verdict == "PASS":
        print("check\tstudents-2 %s: PASS only where its trace is the reference's, record for "
              "record (the scene cannot show its mistake)\t%d" % (tag, same_as_reference(s, who)))
    elif mine:
        print("check\tstudents-2 %s: not PASS\t%d" % (tag, verdict != "PASS"))
    else:
        print("check\tstudents-2 %s: no mistake, not FAIL\t%d" % (tag, verdict != "FAIL"))
    if len(names) == 1:
        print("check\tstudents-3 %s: names one of its mistakes (%s)\t%d"
              % (tag, names[0], names[0] in right))
        for m in mine:
            if names[0] in aliases(m):
                named_alone.add((who, m))
    elif names:
        print("check\tstudents-4 %s: ambiguous, and one of its mistakes among them (%s)\t%d"
              % (tag, " or ".join(names), any(n in right for n in names)))
    # the image's diff (--scene), and the second mistake behind a vertex stage's
    for sid, what, got in (("students-8", "its image names", shown),
                           ("students-9", "the second mistake named is", second),
                           ("students-10", "its image against its own log names", drew)):
        for n in got.split("; ") if got else []:
            print("check\t%s %s: %s one of its mistakes (%s)\t%d" % (sid, tag, what, n, n in right))
            for m in mine:
                if n in aliases(m):
                    named_alone.add((who, m))
for who, mine in sorted(truth.items()):
    for m in mine:
        if m == "unknown":
            continue
        key = (who, aliases(m)[0])
        if key in expected_fail:
            print("check\tstudents-5 %s: %s never named, as known.txt says (%s)\t%d"
                  % (who, key[1], expected_fail[key], (who, m) not in named_alone))
        else:
            print("check\tstudents-5 %s: %s named alone on a scene\t%d"
                  % (who, key[1], (who, m) in named_alone))
EOF
while IFS='	' read -r kind descr ok; do
    [ "$kind" = check ] || { echo "  $kind $descr $ok"; failed=$((failed + 1)); continue; }
    check "$descr" test "$ok" = 1
done < "$tmp/checks"

# ---- pipetrace class on each scene's folder: the same verdicts and mistakes
for s in $(awk -F '\t' '$1 == "scene" { print $2 }' "$list"); do
    scene=$(awk -F '\t' -v n="$s" '$1 == "scene" && $2 == n { print $3 }' "$list")
    "$exe" class "$scene" "$tmp/$s" --csv "$tmp/$s.csv" > "$tmp/$s.out" 2>&1
    check "students-6 $s: class exit 0" test $? = 0
    python3 - "$tmp/$s.csv" "$tmp/diffs" "$s" "$list" "$scene" > "$tmp/cmp" 2>&1 <<'EOF'
import csv, sys
path, diffs, scene, lst, scenefile = sys.argv[1:]
rows = {r["student"]: r for r in csv.DictReader(open(path, newline="", encoding="utf-8"))}
bad = []
n = 0
# a forgotten viewport corner moves the image when the corner is not (0, 0)
corner = any(l.split()[:1] == ["viewport"] and l.split()[1:3] != ["0", "0"]
             for l in open(scenefile, encoding="utf-8"))
for line in open(lst, encoding="utf-8"):
    f = line.rstrip("\n").split("\t")
    if f[0] == "student" and corner and "viewport offset (x_ul, y_ul) forgotten" in f[3]:
        r = rows.get(f[1])
        if r is None or not r["image_pixels_differing"] or r["image_pixels_differing"] == "0":
            bad.append(f[1] + ": the corner forgotten, but its image agrees")
for line in open(diffs, encoding="utf-8"):
    s, who, verdict, names, shown, second, drew = line.rstrip("\n").split("\t")
    if s != scene:
        continue
    n += 1
    r = rows.get(who)
    if r is None:
        bad.append(who + ": no row")
        continue
    names = names.split("; ") if names else []
    want = ("" if verdict != "FAIL" else "unknown" if not names else names[0]
            if len(names) == 1 else "ambiguous: " + " or ".join(names))
    # a differing image proves a FAIL the trace alone could not (NOT PROVEN, or a
    # log that agrees): class names what the image's diff names, given the scene
    if verdict != "FAIL" and r["image_pixels_differing"] not in ("", "-", "0"):
        verdict = "FAIL"
        shown = shown.split("; ") if shown else []
        want = ("-" if not shown else shown[0] if len(shown) == 1
                else "ambiguous: " + " or ".join(shown))
    # the image against the student's own log: its name added, "; " before it
    if drew and drew not in want:
        want = drew if want == "-" else want + "; " + drew
    if r["verdict"] != verdict or r["mistake"] != want:
        bad.append("%s: class %s / %s, diff %s / %s" % (who, r["verdict"], r["mistake"], verdict, want))
print("%d students, %d rows; %s" % (n, len(rows), "; ".join(bad) if bad else "ok"))
EOF
    check "students-7 $s: class's CSV gives each student diff's verdict and mistake, and a forgotten viewport corner a differing image ($(cat "$tmp/cmp"))" \
        grep -q 'ok$' "$tmp/cmp"
done
report
