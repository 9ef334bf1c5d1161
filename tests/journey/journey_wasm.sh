#!/bin/sh
# tests/journey/journey_wasm.sh -- the journey page's sliders: the stages in WebAssembly against the CLI
# See LICENSE for copyright and license.
#
# Usage: sh tests/journey/journey_wasm.sh PIPETRACE.  Run from the repository root.
#   - a page by PIPETRACE is loaded in headless Chromium through
#     tests/journey/journey_sliders.html, which moves its sliders (translation,
#     viewport, framebuffer; the matrix camera's fov, eye, near and far
#     too; renderers 7 and 9's camera, view, matrix operations (angle,
#     translation, scale, rows), viewport and framebuffer, the viewport
#     sticking out); tests/journey/journey_wasm.py writes the scene again
#     with the values the page shows, runs PIPETRACE on it and compares every
#     stage's values bit for bit, and #coords with the command line's page;
#   - a pipetrace built where clang is not found, or with `make WASM=no`,
#     writes a page that says it has no sliders, and no module; WASM=yes
#     in the same build directory brings them back.
# Without chromium the browser part is skipped (the builds without are not).
exe=$1
. tests/lib/testlib.sh
browser=
for b in chromium chromium-browser google-chrome; do
    if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
command -v python3 >/dev/null 2>&1 || browser=

url() { printf 'file://%s%s' "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" "$2"; }

sliders() { # sliders PAGE QUERY: tests/journey/journey_sliders.html's DOM after moving PAGE's sliders
    prof=$(mktemp -d "$tmp/profile.XXXXXX")
    timeout 60 "$browser" --headless --no-sandbox --disable-gpu --disable-quic \
        --no-first-run --disable-background-networking --disable-component-update \
        --disable-sync --disable-extensions --user-data-dir="$prof" \
        --virtual-time-budget=5000 --allow-file-access-from-files --dump-dom \
        "$(url tests/journey/journey_sliders.html "?page=$(url "$1")$2")" 2>>"$tmp/chrome.log"
}

compare() { # compare SCENE|- DOM: tests/journey/journey_wasm.py, its counts added to ours
    pyrun tests/journey/journey_wasm.py "$exe" "$2" "$1" "$tmp"
}

move() {    # move SCENE|- VERTEX QUERY: make the page, move its sliders, compare
    if [ "$1" = - ]; then "$exe" journey --vertex 1 --html "$tmp/p.html"
    else "$exe" journey "$1" --vertex 1 --html "$tmp/p.html"; fi
    sliders "$tmp/p.html" "&vertex=$2$3" > "$tmp/dom.html"
    compare "$1" "$tmp/dom.html"
}

"$exe" journey --vertex 1 --html "$tmp/b.html"
if ! grep -q 'id="wasmdata"' "$tmp/b.html"; then
    echo "  skipped: $exe was built without WebAssembly (no clang or wasm-ld)"
elif [ -z "$browser" ]; then
    echo "  skipped: chromium (or python3) not installed"
else
    # each slider, stages 1..7 shown, the clamps (H below the viewport's h),
    # a second model, orthographic, behind the camera, outside the framebuffer
    move - 'cube%20v1' '&set=W:500,H:350,w:300,h:200,x_ul:17,y_ul:40,x_t:-1.2,y_t:0.35,z_t:-6.5'
    move - 'pyramid%20v5' '&set=y_t:1.15,H:120&stage=6'
    move - 'cube%20v7' '&set=x_t:-4.95,w:1,h:1&stage=5'
    move docs/examples/ortho.scene 'far%20v1' '&set=x_t:0.4,w:7&stage=3'
    move docs/examples/behind.scene 'stick%20v2' '&set=z_t:-0.45&stage=2'
    move docs/examples/triangle.scene 'tri%20v2' '&set=x_t:4.5&stage=7'
    move docs/examples/clip.scene 'm%20v1' '&set=W:1,H:1,w:1,h:1&stage=1'
    # the numbers with no slider moved are the scene's, and so is #coords
    sliders "$tmp/b.html" '&stage=4' > "$tmp/dom.html"
    compare - "$tmp/dom.html"
    # a viewport that sticks out of the framebuffer stays where the scene puts
    # it, and its corner's sliders reach as far out
    move tests/data/vpout/r4-bad.scene 'plain%20v3' '&stage=7'
    move tests/data/vpout/r4-bad.scene 'plain%20v2' '&set=x_ul:-8,y_ul:7,x_t:0.1&stage=6'
    # the matrix camera: every slider (aspect auto follows w and h), a
    # lookat-target camera, a vertex behind the eye (stages past the cvv not
    # reached), world lines with rotations, an aspect given, the scene's own
    # fov between the slider's steps, and a camera pipetrace refuses
    move docs/examples/lookat-cube.scene 'cube%20v1' '&set=fov:45.5,eye_x:2.5,eye_y:1.35,eye_z:-5.4,near:0.35,far:20.5,W:70,w:40,h:30,x_ul:9,x_t:0.3&stage=5'
    move docs/examples/lookat-near.scene 'stick%20v2' '&set=fov:120,eye_z:-0.5&stage=8'
    move docs/examples/lookat-near.scene 'stick%20v3' '&set=fov:31&stage=4'
    move docs/examples/lookat-world.scene 'square%20v3' '&set=eye_y:1.65,y_t:-0.25,far:9.5&stage=3'
    move docs/examples/lookat-world.scene 'post%20v2' '&set=fov:179.5,near:4.95&stage=7'
    move docs/examples/compare-matrix.scene 'tri%20v1' '&set=fov:0.5,h:10&stage=10'
    sed 's/perspective 60 /perspective 47.3 /' docs/examples/lookat-cube.scene > "$tmp/fov.scene"
    move "$tmp/fov.scene" 'cube%20v8' '&set=x_t:-0.5&stage=2'
    move "$tmp/fov.scene" 'cube%20v8' ''
    move docs/examples/lookat-cube.scene 'cube%20v2' '&set=near:4.5,far:3'
    # the course's renderers 7 and 9: the view volume (l, r, b, t), the near
    # plane n, the translation (7) or the view vector (9), the viewport; a
    # vertex the near clip makes, one it cuts off, one the clip makes, an
    # orthographic camera, anti-aliasing, a viewport off the corner
    c=tests/course79
    move79() {  # move79 SCENE VERTEX QUERY: the page of that vertex, its sliders moved
        "$exe" journey "$1" --vertex "$2" --html "$tmp/p.html"
        sliders "$tmp/p.html" "&vertex=$(grep '^model' "$1" | head -1 | cut -d' ' -f2)%20v$2$3" \
            > "$tmp/dom.html"
        compare "$1" "$tmp/dom.html"
    }
    move79 $c/r7-near-01.scene 9 '&set=l:-1.5,t:1.2,n:-0.35,x_t:0.3,w:40,x_ul:5&stage=6'
    move79 $c/r7-near-01.scene 6 '&set=r:2.5,b:-0.5,z_t:-0.5&stage=5'
    move79 $c/r7-near-01.scene 11 '&set=n:-0.2,y_t:0.15&stage=6'
    move79 $c/r7-near-01.scene 1 ''
    move79 $c/r7-clip-08-corner-ur.scene 3 '&set=l:-2,r:1.5,y_t:0.4,h:20,y_ul:7&stage=6'
    move79 $c/r7-aa-00.scene 1 '&set=t:0.75,w:17&stage=7'
    move79 $c/r9-near-05.scene 13 '&set=view_x:0.5,view_z:-1.5,t:2,n:-1&stage=6'
    move79 $c/r9-near-05.scene 2 '&set=n:-3.5,l:-0.4&stage=8'
    move79 $c/r9-mat-14-camera-translate.scene 1 '&set=view_y:0.35,l:-0.8&stage=3'
    # renderer 9's matrix: a translate's x, y, z and a rotate's angle (sin and
    # cos from the page's table), the scene's own angle between the steps
    move79 $c/r9-mat-07-order-TRS.scene 1 '&set=angle_2:-45,tx_1:0.35,ty_1:-0.2&stage=2'
    move79 $c/r9-mat-14-camera-translate.scene 2 '&set=angle_2:359,view_y:0.35&stage=2'
    sed 's/^matrix rotate y 30.0/matrix-pre rotate 37.5 1 1 0/' \
        $c/r9-mat-07-order-TRS.scene > "$tmp/rot.scene"
    move79 "$tmp/rot.scene" 3 '&set=view_z:0.5,tz_1:-5.5&stage=2'
    move79 "$tmp/rot.scene" 3 '&set=angle_2:-360&stage=3'
    # renderer 9's matrix: a scale's factors (one slider for `scale S`, one a
    # factor for `scale X Y Z`), the 16 entries of `rows`, the last row too
    # (it moves only w_w), of `matrix` and of `matrix-pre`
    move79 $c/r9-mat-07-order-TRS.scene 1 '&set=sx_3:1.35,sy_3:-0.4,sz_3:2.05&stage=2'
    sed 's/^matrix scale 1.0 2.0 0.5/matrix scale 0.75/' $c/r9-mat-07-order-TRS.scene \
        > "$tmp/scale.scene"
    move79 "$tmp/scale.scene" 2 '&set=scale_3:1.25,angle_2:15&stage=3'
    move79 "$tmp/scale.scene" 5 '&set=scale_3:-0.5&stage=8'
    sed 's/^matrix translate 0.0 0.5 -6.0/matrix rows 1 0 0 0 0 1 0 0.5 0 0 1 -6 0 0 0 1/' \
        $c/r9-mat-07-order-TRS.scene > "$tmp/rows.scene"
    move79 "$tmp/rows.scene" 3 '&set=a00_1:0.5,a03_1:0.35,a12_1:-0.25,a23_1:-5.5,a30_1:0.1,a31_1:-0.15,a32_1:0.05,a33_1:1.2&stage=2'
    move79 "$tmp/rows.scene" 7 '&set=a01_1:0.3,a02_1:-0.2,a10_1:0.15,a11_1:1.5,a13_1:0.4,a20_1:-0.1,a21_1:0.25,a22_1:0.8&stage=6'
    move79 tests/course/r9/mat-29.scene 4 '&set=a11_3:0.9,a20_3:0.35,angle_2:40&stage=8'
    move79 tests/course/r9/mat-16.scene 2 '&set=sy_2:0.6,a03_3:0.2,angle_4:85&stage=2'
    # the framebuffer's size W, H, the viewport sticking out of it: an x_fb
    # past W lands in the next row and one left of 0 in the row above (the
    # course's y_fb*W + x_fb), an index past the array is none
    move79 $c/r9-vp-02.scene 3 '&set=W:50&stage=8'
    move79 $c/r9-vp-02.scene 3 '&set=x_ul:-70&stage=8'
    move79 $c/r9-vp-02.scene 3 '&set=H:60,x_ul:-70&stage=8'
    move79 $c/r7-near-01.scene 1 '&set=W:30,H:25,w:40,x_ul:-3,y_ul:4&stage=7'
    move79 $c/r9-aa-04.scene 1 '&set=W:250,H:7,y_ul:-2&stage=8'
    move79 $c/r9-aa-04.scene 1 '&set=b:-2.5,n:0.5,w:30,x_ul:20&stage=8'
    move79 $c/r9-clip-12-through-x.scene 3 '&set=r:0.6,w:33&stage=7'
    move79 $c/r9-vp-02.scene 3 '&set=y_ul:10,h:60,view_z:0.5&stage=5'
    # a page without sliders moved: the scene's numbers
    "$exe" journey $c/r9-near-05.scene --vertex 2 --html "$tmp/p.html"
    sliders "$tmp/p.html" '&stage=2' > "$tmp/dom.html"
    compare $c/r9-near-05.scene "$tmp/dom.html"
fi

# ---- built without WebAssembly: no clang found (WASM_CC names none), then
# make WASM=no, then WASM=yes in the same build directory (the choice is
# remembered in $B/wasm-choice, so the page follows it)
mk() {      # mk ARGS...: make pipetrace in $tmp/nowasm, nothing passed down
    MAKEFLAGS= MFLAGS= MAKELEVEL= make -s -j2 B="$tmp/nowasm" CFLAGS=-O0 "$@" \
        "$tmp/nowasm/pipetrace" > "$tmp/make.log" 2>&1
}
nowasm() {  # nowasm HOW: the page of $tmp/nowasm/pipetrace has no sliders
    "$tmp/nowasm/pipetrace" journey --vertex 1 --html "$tmp/n.html"
    check "wasm-2 $1: the page says it has no sliders" \
        sh -c "grep -q 'id=\"live\" data-wasm=\"no\"' '$tmp/n.html' &&
               grep -q 'No sliders on this page: pipetrace was built without' '$tmp/n.html'"
    check "wasm-3 $1: no module, no slider script" \
        sh -c "! grep -q 'wasmdata\|s_x_t' '$tmp/n.html'"
    "$tmp/nowasm/pipetrace" journey docs/examples/lookat-cube.scene --vertex 1 --html "$tmp/nm.html"
    check "wasm-2m $1: the matrix camera's page says it has no sliders, and why" \
        sh -c "grep -q 'No sliders on this page: pipetrace was built without' '$tmp/nm.html' &&
               ! grep -q 'wasmdata\|s_fov' '$tmp/nm.html'"
    "$tmp/nowasm/pipetrace" journey tests/course79/r7-near-01.scene --vertex 1 \
        --html "$tmp/n79.html"
    "$exe" journey tests/course79/r7-near-01.scene --vertex 1 --html "$tmp/b79.html"
    check "wasm-2c $1: a renderer 7 page says it has no sliders, and why" \
        sh -c "grep -q 'No sliders on this page: pipetrace was built without' '$tmp/n79.html' &&
               ! grep -q 'wasmdata\|s_x_t' '$tmp/n79.html'"
    check "wasm-4c $1: ... and is otherwise the same" \
        sh -c "sed '/<section id=\"live\"/,\$d' '$tmp/n79.html' > '$tmp/n79.top' &&
               sed '/<section id=\"live\"/,\$d' '$tmp/b79.html' > '$tmp/b79.top' &&
               cmp '$tmp/n79.top' '$tmp/b79.top'"
    check "wasm-4 $1: the page is otherwise the same" \
        sh -c "sed '/<section id=\"live\"/,\$d' '$tmp/n.html' > '$tmp/n.top' &&
               sed '/<section id=\"live\"/,\$d' '$tmp/b.html' > '$tmp/b.top' &&
               cmp '$tmp/n.top' '$tmp/b.top'"
}
mkdir -p "$tmp/nowasm"
if mk WASM_CC=pt-no-such-clang; then
    passed=$((passed + 1))
    nowasm "no clang"
    if [ -n "$browser" ]; then
        sliders "$tmp/n.html" '' > "$tmp/dom.html"
        check "wasm-5 no clang: the browser shows the note" \
            grep -q 'nowasm.*No sliders on this page' "$tmp/dom.html"
    fi
    check "wasm-6 make WASM=no" mk WASM=no
    nowasm "WASM=no"
    if command -v clang >/dev/null 2>&1 && command -v wasm-ld >/dev/null 2>&1; then
        check "wasm-7 make WASM=yes after WASM=no" mk WASM=yes
        "$tmp/nowasm/pipetrace" journey --vertex 1 --html "$tmp/y.html"
        check "wasm-8 WASM=yes: the page has the module again" cmp "$tmp/y.html" "$tmp/b.html"
        # the page runs the build's own stage files: a student's pixel stage
        # that divides by 2 (not 2.001), built with WASM=yes, moves the page's
        # numbers as it moves its pipetrace's, and away from the reference's
        sed 's|w / 2.001|w / 2.0|' stages/s3_image2pixel.c > "$tmp/s3_two.c"
        check "wasm-9 the student's stage differs from stages/s3_image2pixel.c" \
            sh -c "! cmp -s stages/s3_image2pixel.c '$tmp/s3_two.c'"
        if [ -n "$browser" ] && mk WASM=yes STAGE_pixel="$tmp/s3_two.c"; then
            "$tmp/nowasm/pipetrace" journey --vertex 1 --html "$tmp/s.html"
            sliders "$tmp/s.html" '&set=x_t:-1.2' > "$tmp/dom.html"
            exe0=$exe; exe=$tmp/nowasm/pipetrace
            compare - "$tmp/dom.html"
            exe=$exe0
            check "wasm-10 the student's page differs from the reference's" \
                sh -c "! python3 tests/journey/journey_wasm.py '$exe' '$tmp/dom.html' - '$tmp'"
        elif [ -n "$browser" ]; then
            failed=$((failed + 1)); echo "FAIL wasm-9 make WASM=yes STAGE_pixel=FILE"
        fi
    fi
else
    failed=$((failed + 1)); echo "FAIL wasm-1 make WASM_CC=pt-no-such-clang"; tail -5 "$tmp/make.log"
fi
report
