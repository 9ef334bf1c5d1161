#!/bin/sh
# tests/journey/journey_browser.sh -- the journey page in headless Chromium
# See LICENSE for copyright and license.
#
# Usage: sh tests/journey/journey_browser.sh PIPETRACE [SHOTDIR].  Run from the
# repository root.  Loads pages written by `pipetrace journey --html` from
# disk in headless Chromium (no network, no driver: tests/journey/journey_clicks.html
# opens the page in a frame and clicks it, and --dump-dom shows the result):
#   - it clicks Prev and Next through every stage of every vertex of the
#     scene; each stage's #coords must equal the JSONL trace;
#   - #v=N&m=MODEL&stage=K opens a chosen vertex and stage;
#   - pages of the course's renderers 7 and 9: every stage of every vertex
#     clicked, each #coords equal to that panel's label in the vertex's SVG;
#     a vertex and stage by URL, #present;
#   - tests/journey/journey_layout.html checks the layout at 1024x768, 1280x900 and
#     1920x1080 and presenter mode, for both cameras and renderers 7 and 9;
#   - tests/journey/journey_labels.html checks that no label of a panel overlaps
#     another, lies under the zoom inset or is crossed by a line (web-7), the
#     course's renderers 7 and 9 too;
#   - screenshots of the SVG and of each stage of the page go to SHOTDIR
#     (default: journey-shots beside PIPETRACE); `make screenshots` copies two
#     of them into docs/.
# Without chromium (Debian package `chromium`) it skips: "0 passed, 0 failed".
exe=$1
shots=${2:-$(dirname "$exe")/journey-shots}
browser=
for b in chromium chromium-browser google-chrome; do
    if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
if [ -z "$browser" ] || ! command -v python3 >/dev/null 2>&1; then
    echo "  skipped: chromium (or python3) not installed"
    echo "0 passed, 0 failed"
    exit 0
fi
. tests/lib/testlib.sh
mkdir -p "$shots"

py() {      # py MODE ARGS...: tests/journey/journey_check.py, its counts added to ours
    pyrun tests/journey/journey_check.py "$@"
}

chrome() {  # chrome ARGS... URL: one headless run, its own profile, no network
    prof=$(mktemp -d "$tmp/profile.XXXXXX")
    timeout 60 "$browser" --headless --no-sandbox --disable-gpu --disable-quic \
        --no-first-run --disable-background-networking --disable-component-update \
        --disable-sync --disable-extensions --hide-scrollbars --user-data-dir="$prof" \
        --virtual-time-budget=3000 "$@" 2>>"$tmp/chrome.log"
}

url() { printf 'file://%s%s' "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" "$2"; }

clicks() {  # clicks PAGE.html: tests/journey/journey_clicks.html's DOM after clicking PAGE
    chrome --allow-file-access-from-files --dump-dom \
        "$(url tests/journey/journey_clicks.html "?page=$(url "$1")")"
}

# ---- every stage of every vertex, by clicking
for s in "" docs/examples/clip.scene docs/examples/behind.scene docs/examples/ortho.scene; do
    "$exe" journey $s --vertex 1 --html "$tmp/p.html"
    clicks "$tmp/p.html" > "$tmp/dom.html"
    check "web-1 ${s:-builtin}: the page loads" test -s "$tmp/dom.html"
    py clicks "$exe" "$tmp/dom.html" $s
done
# the matrix camera: vertices inside, behind the eye and off to the side
for s in docs/examples/lookat-near.scene docs/examples/lookat-cube.scene; do
    "$exe" journey $s --vertex 1 --html "$tmp/p.html"
    clicks "$tmp/p.html" > "$tmp/dom.html"
    check "web-4 $s (matrix camera): the page loads" test -s "$tmp/dom.html"
    py clicks "$exe" "$tmp/dom.html" $s
done
# a page of listed vertices (--vertex 3,1): the list holds just those two
"$exe" journey --vertex 3,1 --model pyramid --html "$tmp/l.html"
clicks "$tmp/l.html" > "$tmp/dom.html"
check "web-6 --vertex 3,1: the page lists 2 vertices and steps through them" \
    grep -q '<pre id="clicks">ok 2 vertices, ' "$tmp/dom.html"
check "web-6.2 ... pyramid v1 and v3" test "$(grep -c '^pyramid	[13]	' "$tmp/dom.html")" -gt 0
printf 'framebuffer 20 10\nmodel m\nv 1 0.5 0\nv 0 0 -2\nl 1 2\n' > "$tmp/z0.scene"
"$exe" journey "$tmp/z0.scene" --vertex 1 --html "$tmp/z.html"
clicks "$tmp/z.html" > "$tmp/dom.html"
py clicks "$exe" "$tmp/dom.html" "$tmp/z0.scene"

# ---- the course's renderers 7 and 9: every stage of every vertex listed,
# each #coords the panel's label of that vertex's SVG (journey_check.py
# clicks79): perspective with a near clip that cuts and makes vertices,
# orthographic with anti-aliasing, a clip that makes a vertex, renderer 9
c=tests/course79
for cs in "r7-near-01 9 14" "r7-clip-08-corner-ur 1 3" "r9-near-05 2 16" "r9-aa-04 1 14" \
          "r9-clip-12-through-x 3 4"; do
    set -- $cs
    "$exe" journey $c/$1.scene --vertex $2 --html "$tmp/p79.html"
    clicks "$tmp/p79.html" > "$tmp/dom.html"
    check "web-8 $1: the page loads" test -s "$tmp/dom.html"
    py clicks79 "$exe" "$tmp/dom.html" $c/$1.scene $3
done
"$exe" journey $c/r7-near-01.scene --vertex 9 --html "$tmp/r7.html"
chrome --dump-dom "$(url "$tmp/r7.html" '#v=11&stage=image')" > "$tmp/dom.html"
check "web-9 r7 page, #v=11&stage=image: that vertex and stage, the clip's point" \
    sh -c 'grep -q "<span id=\"stage\">image</span>" "$1" &&
           grep -q "id=\"coords\"[^>]*><span class=\"expr\">(x_p, y_p, z_p)</span> = <span class=\"expr\">(1, 0.7796206032502786, 0)" "$1"' \
    - "$tmp/dom.html"
quiet() {   # quiet PAGE FRAGMENT: the page loads, its module runs, the console stays empty
    prof=$(mktemp -d "$tmp/profile.XXXXXX")
    timeout 60 "$browser" --headless --no-sandbox --disable-gpu --disable-quic \
        --no-first-run --disable-background-networking --disable-component-update \
        --disable-sync --disable-extensions --user-data-dir="$prof" \
        --virtual-time-budget=3000 --enable-logging=stderr --v=0 \
        --dump-dom "$(url "$1" "$2")" > "$tmp/dom.html" 2> "$tmp/console.log"
    ! grep -q ':CONSOLE' "$tmp/console.log" &&
        { grep -q 'data-ready="1"' "$tmp/dom.html" || grep -q 'data-wasm="no"' "$tmp/dom.html"; }
}
"$exe" journey $c/r9-mat-07-order-TRS.scene --vertex 1 --html "$tmp/trs.html"
check "web-10 r7 page: loads, runs its module, nothing on the console" quiet "$tmp/r7.html" ''
check "web-10 r9 page: the same" quiet "$tmp/trs.html" '#stage=world'
check "web-10 r7 page in presenter mode: the same" quiet "$tmp/r7.html" '#present&stage=8'
grep ':CONSOLE' "$tmp/console.log" | head -3
chrome --dump-dom "$(url "$tmp/r7.html" '#stage=3&present')" > "$tmp/dom.html"
check "web-9.2 r7 page, #present: presenter mode" grep -q '<html lang="en" class="present">' \
    "$tmp/dom.html"

# ---- a vertex and stage chosen by the URL
"$exe" journey --vertex 1 --html "$tmp/b.html" --svg "$tmp/b.svg"
chrome --dump-dom "$(url "$tmp/b.html" '#v=5&m=pyramid&stage=4')" > "$tmp/dom.html"
py dom "$exe" "$tmp/dom.html" pyramid 5 pixel
chrome --dump-dom "$(url "$tmp/b.html" '#v=2&stage=index')" > "$tmp/dom.html"
py dom "$exe" "$tmp/dom.html" cube 2 index

# ---- the layout at three window sizes, presenter mode (tests/journey/journey_layout.html)
"$exe" journey docs/examples/lookat-near.scene --vertex 2 --html "$tmp/m.html"
"$exe" journey tests/course79/r9-near-05.scene --vertex 13 --html "$tmp/r9.html"
for pg in b m r7 r9; do
    for size in 1024x768 1280x900 1920x1080; do
        chrome --window-size=2000,1200 --allow-file-access-from-files --dump-dom \
            "$(url tests/journey/journey_layout.html "?page=$(url "$tmp/$pg.html")&w=${size%x*}&h=${size#*x}")" \
            > "$tmp/dom.html"
        check "web-5 $pg.html at $size: fills the window, no expression wraps, presenter mode" \
            grep -q '<pre id="layout">ok ' "$tmp/dom.html"
        grep -o '<pre id="layout">FAIL[^<]*' "$tmp/dom.html" | cut -c1-400
    done
done

# ---- every label clear of the others, of the zoom inset and of the lines
# (tests/journey/journey_labels.html), in the pictures of vertices 1-8 of every model
# of the example scenes (both cameras) and vertices 1-3 of the extreme scenes
labels() {  # labels NAME MAXV SCENE...: the check over those scenes' pictures
    name=$1; maxv=$2; shift 2
    q=; n=0
    for s in "$@"; do
        for m in $(awk '$1 == "model" { print $2 }' "$s"); do
            v=1
            while [ "$v" -le "$maxv" ]; do
                n=$((n + 1))
                if "$exe" journey "$s" --model "$m" --vertex "$v" --svg "$tmp/lab$n.svg" 2>/dev/null
                then q="$q&svg=$(url "$tmp/lab$n.svg")"; fi
                v=$((v + 1))
            done
        done
    done
    chrome --allow-file-access-from-files --dump-dom --virtual-time-budget=60000 \
        "$(url tests/journey/journey_labels.html "?$q")" > "$tmp/dom.html"
    check "web-7 $name: every label clear of the others, the inset and the lines" \
        grep -q '<pre id="labels">ok ' "$tmp/dom.html"
    grep -o '<pre id="labels">[^<]*' "$tmp/dom.html" | sed 's/^<pre id="labels">//' | cut -c1-600
    rm -f "$tmp"/lab*.svg
}
labels "the example scenes" 8 docs/examples/*.scene
labels "the extreme scenes" 3 tests/extreme/*.scene
labels "renderers 7 and 9" 3 tests/course79/*.scene

# ---- screenshots: the SVG, and the page at each stage of vertex 1
rm -f "$shots"/journey-*.png
chrome --window-size=1680,772 --screenshot="$shots/journey-builtin.png" "$(url "$tmp/b.svg")" >/dev/null
check "web-2 screenshot of the SVG" test -s "$shots/journey-builtin.png"
py color "$shots/journey-builtin.png" d62728
for k in 1 2 3 4 5 6 7; do
    chrome --window-size=1200,860 --screenshot="$shots/journey-page-stage$k.png" \
        "$(url "$tmp/b.html" "#v=1&stage=$k")" >/dev/null
    check "web-3 screenshot of the page at stage $k" test -s "$shots/journey-page-stage$k.png"
done
py color "$shots/journey-page-stage4.png" d62728
chrome --window-size=1280,720 --screenshot="$shots/journey-present.png" \
    "$(url "$tmp/b.html" "#v=1&stage=5&present")" >/dev/null
check "web-3 screenshot of presenter mode" test -s "$shots/journey-present.png"
chrome --window-size=1200,860 --screenshot="$shots/journey-matrix.png" \
    "$(url "$tmp/m.html" "#stage=clip")" >/dev/null
check "web-3 screenshot of the matrix camera's page" test -s "$shots/journey-matrix.png"
chrome --window-size=1280,720 --screenshot="$shots/journey-present-r7.png" \
    "$(url "$tmp/r7.html" "#stage=nearclip&present")" >/dev/null
check "web-3 screenshot of a renderer 7 page in presenter mode" \
    test -s "$shots/journey-present-r7.png"
py color "$shots/journey-present-r7.png" d62728
py color "$shots/journey-matrix.png" d62728
echo "screenshots in $shots" >&2
report
