#!/bin/sh
# tests/cli/install.sh -- make install and make uninstall; the man page
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/install.sh PIPETRACE (in BUILD_DIR/, the one installed).
# Installs under a temporary PREFIX, checks what is there, that the man page
# names every command and every option their --help texts name, and that it
# renders without a warning (with groff and man, where they are installed),
# then uninstalls and checks that no file is left.  make gets -o PIPETRACE so
# that it never rebuilds the program another test may be running.
exe=$1
. tests/lib/testlib.sh
B=$(dirname "$exe")
man1=docs/pipetrace.1
p=$tmp/prefix

make -s --no-print-directory -o "$B/pipetrace" B="$B" PREFIX="$p" install > "$tmp/make" 2>&1
check "install-1.1 make install PREFIX=... succeeds" [ $? -eq 0 ]
check "install-1.2 the program in PREFIX/bin" [ -x "$p/bin/pipetrace" ]
check "install-1.3 ... that runs" "$p/bin/pipetrace" --version
check "install-1.4 the man page in PREFIX/share/man/man1" cmp -s "$man1" "$p/share/man/man1/pipetrace.1"
check "install-1.5 README.md in PREFIX/share/doc/pipetrace" [ -f "$p/share/doc/pipetrace/README.md" ]
check "install-1.5 ... and LICENSE" [ -f "$p/share/doc/pipetrace/LICENSE" ]
check "install-1.6 ... docs/ beside them, example scenes too" \
    [ -f "$p/share/doc/pipetrace/docs/scene-format.md" ]
check "install-1.7 ... and the shapes' examples" \
    [ -f "$p/share/doc/pipetrace/docs/examples/shapes/sphere.scene" ]
make -s --no-print-directory -o "$B/pipetrace" B="$B" PREFIX="$p" install > "$tmp/make" 2>&1
check "install-1.8 installing twice works" [ $? -eq 0 ]

make -s --no-print-directory -o "$B/pipetrace" B="$B" PREFIX="$p" uninstall > "$tmp/make" 2>&1
check "install-2.1 make uninstall succeeds" [ $? -eq 0 ]
check "install-2.2 ... and leaves no file behind" [ -z "$(find "$p" ! -type d)" ]
make -s --no-print-directory -o "$B/pipetrace" B="$B" DESTDIR="$tmp/stage" PREFIX=/opt/pt install > "$tmp/make" 2>&1
check "install-2.3 DESTDIR is put in front of PREFIX" [ -x "$tmp/stage/opt/pt/bin/pipetrace" ]

# Every command of the usage has a section, every option of every --help is
# in the page (roff writes '-' as '\-').
in_page() { grep -qF -- "$(printf '%s' "$1" | sed 's/-/\\-/g')" "$man1"; }
"$exe" --help > "$tmp/help"
for cmd in $(sed -n 's/^ *pipetrace \([a-z][a-z]*\) .*/\1/p; s/^ *pipetrace \([a-z][a-z]*\)$/\1/p' "$tmp/help"); do
    check "install-3.1 the man page has a section for pipetrace $cmd" \
        grep -q "^\\.SS \"pipetrace $cmd" "$man1"
    "$exe" "$cmd" --help >> "$tmp/help"
done
for opt in $(grep -o -- '--[a-z][a-z-]*' "$tmp/help" | sort -u); do
    check "install-3.2 the man page names $opt" in_page "$opt"
done

if command -v groff > /dev/null 2>&1; then
    groff -ww -man -Tutf8 -z "$man1" > "$tmp/groff" 2>&1
    check "install-4.1 groff -ww finds nothing to warn about" [ ! -s "$tmp/groff" ]
else
    echo "skipped: groff is not installed (install-4.1)"
fi
if command -v man > /dev/null 2>&1; then
    MANWIDTH=80 LC_ALL=C man -l "$man1" > "$tmp/man" 2> "$tmp/manerr"
    check "install-4.2 man -l renders the page without a message" [ ! -s "$tmp/manerr" ]
    check "install-4.3 ... with its sections" grep -q '^EXIT STATUS' "$tmp/man"
    check "install-4.4 ... no line wider than MANWIDTH" \
        [ "$(awk '{ if (length($0) > m) m = length($0) } END { print m + 0 }' "$tmp/man")" -le 80 ]
else
    echo "skipped: man is not installed (install-4.2 to 4.4)"
fi
report
