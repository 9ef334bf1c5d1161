# tests/lib/studentlib.sh -- build a student build in a test; sourced after tests/lib/testlib.sh
# See LICENSE for copyright and license.
#
# student VAR FILE   build $tmp/sb/pipetrace with FILE as stage VAR (make
#                    STAGE_VAR=FILE, the Makefile's student block)
# mistaken NAME      make $tmp/NAME.c with tests/teach/student.sh and build it so
#
# MAKEFLAGS is cleared so that a `make test` around the test passes nothing
# down.  The first build starts from PIPETRACE's own objects (cp -p keeps them
# up to date) unless they are built with sanitizers, which the default flags
# lack: then it compiles everything.  $reuse is 1 when the objects were
# reused, $bdir is PIPETRACE's directory.
mkdir -p "$tmp/sb"
bdir=$(dirname "$exe")
reuse=
if [ -f "$bdir/main.o" ] && [ -f "$bdir/builtin.c" ] && ! grep -q __asan_ "$bdir/main.o"; then
    reuse=1
    cp -p "$bdir"/*.o "$bdir/builtin.c" "$tmp/sb/"
fi
student() {
    rm -f "$tmp/sb/pipetrace"
    MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/sb" "STAGE_$1=$2" \
        "$tmp/sb/pipetrace" >"$tmp/make.log" 2>&1
}
mistaken() {
    sh tests/teach/student.sh "$1" "$tmp/$1.c" >"$tmp/make.log" 2>&1 &&
        student "$(sh tests/teach/student.sh --list | awk -v n="$1" '$1 == n { print $3 }')" "$tmp/$1.c"
}
