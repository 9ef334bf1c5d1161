#!/bin/sh
# tests/course/make-corpus.sh -- run the corpus's scenes through the course's jars
# See LICENSE for copyright and license.
#
# Usage: sh tests/course/make-corpus.sh [COURSE_DIR] [r4 r7 r9]
#   COURSE_DIR: the course's reference folder (default ../shared/reference/course:
#   rendererN/ with the jar and the harness KraftN.java).  Needs java and javac;
#   not part of make test.  Run from the repository root.
#
# Writes the scenes (gen.py), then for each tests/course/rN/NAME.scene: the case
# (scene2case.py), run by the harness twice, with every debug switch and with
# the default one (debug scene), and stores, gzip-compressed:
#   NAME.ppm.gz     the image          NAME.log.gz      the log, `debug all`
#   NAME.stages.gz  every stage        NAME.deflog.gz   the log, `debug scene`
# A scene's OBJ file (`obj NAME.obj`, gen.py's obj-* family) is stored beside
# it; scene2case.py reads it into the case.  A scene's `shape NAME ARGS`
# (gen.py's shape-* family) is the model in tests/data/shapes/NAME_ARGS.expect
# (renderer 4's jar made it), which scene2case.py writes into the case; each
# is made again here with renderer N's jar (ShapeDump.java there) and must be
# the same, else the scene is dropped.
# A case on which the renderer throws (harness exit 3) is an expected error:
#   NAME.error      the exception's first line (pipetrace must refuse the scene)
# A case the harness refuses (exit 2), or that does not end within the time
# limit (renderer 4 loops on an infinite pixel), is a generator's mistake: its
# scene is removed and named on standard output.
# PT_CORPUS_CASES='GLOB ...' (e.g. 'face-* near-edge-*') runs only the cases
# whose names match, and keeps the others as they are.
set -u
course=${1:-../shared/reference/course}
[ $# -gt 0 ] && shift
which=${*:-r4 r7 r9}
here=tests/course
limit=${PT_CORPUS_TIMEOUT:-30}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
jopts="-XX:+UseSerialGC -XX:TieredStopAtLevel=1 -Xss16m"

python3 "$here/gen.py" "$tmp/gen" || exit 1
for r in $which; do
    n=${r#r}
    mkdir -p "$here/$r"
    if [ -z "${PT_CORPUS_CASES:-}" ]; then
        rm -f "$here/$r"/*.scene "$here/$r"/*.gz "$here/$r"/*.error "$here/$r"/*.obj
        cp "$tmp/gen/$r"/*.scene "$here/$r/"
        for o in "$tmp/gen/$r"/*.obj; do [ -e "$o" ] && cp "$o" "$here/$r/"; done
    else
        for g in $PT_CORPUS_CASES; do
            for f in "$tmp/gen/$r"/$g.scene; do
                [ -e "$f" ] || continue
                b=$(basename "$f" .scene)
                rm -f "$here/$r/$b".*
                cp "$f" "$here/$r/"
                [ -e "${f%.scene}.obj" ] && cp "${f%.scene}.obj" "$here/$r/"
            done
        done
    fi
    jar=$(ls "$course/renderer$n"/*.jar | head -1)
    mkdir -p "$tmp/k$n"
    javac -nowarn -cp "$jar" -d "$tmp/k$n" "$course/renderer$n/Kraft$n.java" \
        tests/data/shapes/ShapeDump.java || exit 1
    ok=0 err=0 drop=0
    for scene in "$here/$r"/*.scene; do
        name=${scene%.scene}
        if [ -n "${PT_CORPUS_CASES:-}" ]; then
            m=0
            for g in $PT_CORPUS_CASES; do
                case ${name##*/} in $g) m=1 ;; esac
            done
            [ "$m" = 1 ] || continue
        fi
        python3 "$here/scene2case.py" "$scene" all > "$tmp/c.case" || { rm -f "$scene" "$name.obj"; drop=$((drop + 1)); continue; }
        other=
        for args in $(sed -n 's/^shape  *//p' "$scene" | tr ' ' _); do
            # shellcheck disable=SC2046
            java $jopts -cp "$jar:$tmp/k$n" ShapeDump $(echo "$args" | tr _ ' ') > "$tmp/shape"
            cmp -s "$tmp/shape" "tests/data/shapes/$args.expect" || other=$args
        done
        if [ -n "$other" ]; then
            echo "dropped $scene: renderer $n's jar builds shape $other otherwise than tests/data/shapes"
            rm -f "$scene"
            drop=$((drop + 1))
            continue
        fi
        timeout "$limit" java $jopts -cp "$jar:$tmp/k$n" "Kraft$n" "$tmp/c.case" \
            "$tmp/o.ppm" "$tmp/o.log" "$tmp/o.stages" > "$tmp/out" 2>&1
        rc=$?
        if [ "$rc" -eq 3 ]; then
            grep -m1 -E '^[a-zA-Z.]+(Exception|Error)' "$tmp/out" > "$name.error" ||
                head -1 "$tmp/out" > "$name.error"
            err=$((err + 1))
            continue
        fi
        if [ "$rc" -ne 0 ]; then
            echo "dropped $scene: harness exit $rc: $(head -1 "$tmp/out")"
            rm -f "$scene"
            drop=$((drop + 1))
            continue
        fi
        timeout "$limit" java $jopts -cp "$jar:$tmp/k$n" "Kraft$n" "$tmp/c.case" \
            "$tmp/d.ppm" "$tmp/d.log" debug=scene > "$tmp/out" 2>&1 ||
            { echo "dropped $scene: debug scene run failed"; rm -f "$scene"; drop=$((drop + 1)); continue; }
        gzip -9n < "$tmp/o.ppm" > "$name.ppm.gz"
        gzip -9n < "$tmp/o.log" > "$name.log.gz"
        gzip -9n < "$tmp/o.stages" > "$name.stages.gz"
        gzip -9n < "$tmp/d.log" > "$name.deflog.gz"
        ok=$((ok + 1))
    done
    echo "$r: $ok cases, $err expected errors, $drop dropped"
done
du -sh "$here"
