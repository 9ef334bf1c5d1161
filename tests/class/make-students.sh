#!/bin/sh
# tests/class/make-students.sh -- make the class of student renderers in tests/data/students/
# See LICENSE for copyright and license.
#
# Usage: sh tests/class/make-students.sh [COURSE_DIR [MIRROR]]   (from the repository root,
#        after make)
# COURSE_DIR holds the course's renderer4/renderer4.jar and its harness
# renderer4/Kraft4.java (default /work/shared/reference/course); MIRROR is a
# git copy of the course's repository, whose hw2/renderer at d3ff288 is the
# jar's source (default /work/.mirror/peter-biz+cs45500/repo).  Needs Java 17.
# Not run by `make test`, which only reads what this script stored.
# ONLY="NAME ..." makes only those students again and keeps the others;
# SCENES="NAME ..." renders only those scenes, keeping the others.
#
# tests/data/students/students.txt lists the scenes and the students.  A Java
# student is the course's renderer 4 with the `edit` lines of its name applied
# to copies of the course's source files (each OLD must occur N times), those
# classes compiled against the jar and put before it on the class path; each
# scene, written as the harness's case (tests/course4/scene2case.py; a face
# `f` as its closed outline `l`), is rendered with every debug switch:
# SCENE/NAME.log.gz is the log, SCENE/NAME.ppm.gz the framebuffer.  A C
# student is pipetrace built with the stages of tests/teach/student.sh its
# `stage` lines name (make STAGE_x=FILE): SCENE/NAME.jsonl.gz is its trace
# with every stage and its pixels, SCENE/NAME.ppm.gz its image.
set -e
course=${1:-/work/shared/reference/course}
mirror=${2:-/work/.mirror/peter-biz+cs45500/repo}
rev=d3ff288
list=tests/data/students/students.txt
data=tests/data/students
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
jar=$course/renderer4/renderer4.jar
javac -cp "$jar" -d "$tmp/k4" "$course/renderer4/Kraft4.java"

field() {   # field KIND N: field N of every line of kind KIND (a scene: of $SCENES)
    awk -F '\t' -v k="$1" -v n="$2" -v only=" $SCENES " '$1 == k &&
        (k != "scene" || only == "  " || index(only, " " $2 " ")) { print $n }' "$list"
}

# ---- the scenes, as the harness's cases
for s in $(field scene 2); do
    file=$(awk -F '\t' -v n="$s" '$1 == "scene" && $2 == n { print $3 }' "$list")
    awk '/^f / { $1 = "l"; $0 = $0 " " $2 } { print }' "$file" > "$tmp/$s.scene"
    python3 tests/course4/scene2case.py "$tmp/$s.scene" > "$tmp/$s.case"
    [ -n "$ONLY" ] || [ -n "$SCENES" ] || rm -rf "${data:?}/$s"
    mkdir -p "$data/$s"
done

# ---- Java students
students() {    # students LANG: the names, or those of $ONLY
    awk -F '\t' -v l="$1" -v only=" $ONLY " '$1 == "student" && $3 == l &&
        (only == "  " || index(only, " " $2 " ")) { print $2 }' "$list"
}
for who in $(students java); do
    src=$tmp/src-$who
    mkdir -p "$src" "$tmp/cls-$who"
    for f in $(awk -F '\t' -v n="$who" '$1 == "edit" && $2 == n { print $3 }' "$list" | sort -u); do
        mkdir -p "$src/$(dirname "$f")"
        git -C "$mirror" show "$rev:hw2/renderer/$f" > "$src/$f"
    done
    # apply the edits in their order; each OLD must occur exactly N times
    python3 - "$list" "$who" "$src" <<'EOF'
import sys
path, who, src = sys.argv[1:]
for line in open(path, encoding="utf-8"):
    f = line.rstrip("\n").split("\t")
    if f[0] != "edit" or f[1] != who:
        continue
    name, n, old, new = f[2], int(f[3]), f[4], f[5]
    text = open(src + "/" + name, encoding="utf-8").read()
    if text.count(old) != n:
        sys.exit("%s: %s: %r occurs %d times, not %d" % (who, name, old, text.count(old), n))
    open(src + "/" + name, "w", encoding="utf-8").write(text.replace(old, new))
EOF
    cp=$jar:$tmp/k4
    if [ -n "$(ls -A "$src")" ]; then
        javac -nowarn -cp "$jar" -d "$tmp/cls-$who" $(cd "$src" && find . -name '*.java' | sed "s|^\.|$src|")
        cp=$tmp/cls-$who:$cp
    fi
    for s in $(field scene 2); do
        timeout 300 java -cp "$cp" Kraft4 "$tmp/$s.case" "$tmp/out.ppm" "$tmp/out.log" debug=all > "$tmp/out" ||
            { echo "$who on $s:"; cat "$tmp/out"; exit 1; }
        gzip -9n < "$tmp/out.log" > "$data/$s/$who.log.gz"
        gzip -9n < "$tmp/out.ppm" > "$data/$s/$who.ppm.gz"
    done
    echo "$who: java"
done

# ---- C students
for who in $(students c); do
    set --
    for m in $(awk -F '\t' -v n="$who" '$1 == "stage" && $2 == n { print $3 }' "$list"); do
        var=$(sh tests/teach/student.sh --list | awk -v n="$m" '$1 == n { print $3 }')
        sh tests/teach/student.sh "$m" "$tmp/$m.c"
        set -- "$@" "STAGE_$var=$tmp/$m.c"
    done
    exe=build/pipetrace
    if [ $# -gt 0 ]; then
        rm -rf "$tmp/cb"
        mkdir "$tmp/cb"
        cp -p build/*.o build/builtin.c "$tmp/cb/"      # the reference's objects, as tests/lib/studentlib.sh
        MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/cb" "$@" "$tmp/cb/pipetrace" > "$tmp/make.log" 2>&1 ||
            { cat "$tmp/make.log"; exit 1; }
        exe=$tmp/cb/pipetrace
    fi
    for s in $(field scene 2); do
        file=$(awk -F '\t' -v n="$s" '$1 == "scene" && $2 == n { print $3 }' "$list")
        "$exe" "$file" --all-stages --format jsonl --trace "$tmp/out.jsonl" --image "$tmp/out.ppm"
        # the trace names the scene's file: keep it as the list gives it
        gzip -9n < "$tmp/out.jsonl" > "$data/$s/$who.jsonl.gz"
        gzip -9n < "$tmp/out.ppm" > "$data/$s/$who.ppm.gz"
    done
    echo "$who: c $*" | sed "s|$tmp/||g"
done
du -sh "$data"
