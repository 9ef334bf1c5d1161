#!/bin/sh
# tests/teach/teach79.sh -- step and why on scenes of the course's renderers 7 and 9
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/teach79.sh PIPETRACE.  Run from the repository root.
# Two kinds of checks: step's numbers are the trace's (--format jsonl, the
# same render's records), stage by stage; and every equation step prints is
# true arithmetic: with python3, each "... = EXPR = RESULT" whose EXPR is
# numbers only is evaluated again, in double (the stages' coordinates) or
# in float, every operation rounded to float (the clips' colour lines), and
# must give RESULT exactly.  The scenes are the course's cases in
# tests/course79/.
exe=$1
. tests/lib/testlib.sh
c=tests/course79

has() {     # has LINE: $tmp/out holds exactly this line
    grep -Fxq -- "$1" "$tmp/out"
}

# jv SCENE V STAGE KEY: the value KEY of vertex V's record at STAGE in the
# jsonl trace ("color": its three components, space-separated)
jv() {
    "$exe" "$1" --format jsonl | grep -F "\"v\":$2,\"stage\":\"$3\"" | head -1 |
        sed -n "s/.*\"$4\":\\[\\{0,1\\}\\([^]},]*\\(,[^]},\"]*\\)*\\).*/\\1/p" | tr ',' ' '
}

# sv NAME: the result (after the last " = ") of step's line "NAME = ..." in $tmp/out
sv() {
    sed -n "s/^ *\\(here \\)\\{0,1\\} *$1 = \\(.* = \\)\\{0,1\\}//p" "$tmp/out" | head -1
}

same() {    # same A B: A and B are the same double (or the same words)
    [ -n "$1" ] && awk -v a="$1" -v b="$2" 'BEGIN {
        na = split(a, x, " "); nb = split(b, y, " "); if (na != nb) exit 1
        for (i = 1; i <= na; i++) if (x[i] + 0 != y[i] + 0) exit 1 }'
}

# eqs: evaluate step's equations in $tmp/out; prints "N bad" (N evaluated)
eqs() {
    python3 - "$tmp/out" <<'EOF'
import ast, re, struct, sys
def f32(x): return struct.unpack('f', struct.pack('f', x))[0]
def ev(node, fl):
    r = lambda x: f32(x) if fl else x
    if isinstance(node, ast.Expression): return ev(node.body, fl)
    if isinstance(node, ast.Constant): return float(node.value)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub): return -ev(node.operand, fl)
    if isinstance(node, ast.BinOp):
        a, b = ev(node.left, fl), ev(node.right, fl)
        op = type(node.op)
        if op is ast.Add: return r(a + b)
        if op is ast.Sub: return r(a - b)
        if op is ast.Mult: return r(a * b)
        if op is ast.Div: return r(a / b)
    raise ValueError("unexpected")
n = bad = 0
for line in open(sys.argv[1]):
    line = line.strip()
    if line.startswith("here "): line = line[5:].strip()
    parts = line.split(" = ")
    if len(parts) < 3: continue
    expr, res = parts[-2], parts[-1]
    if not re.fullmatch(r"[-0-9.e+*/() ]+", expr) or not re.search(r"[0-9]", expr) or not re.fullmatch(r"-?[0-9.e+-]+", res):
        continue
    name = parts[0]
    fl = name in ("r", "g", "b")            # the clips' colours: float
    if name.startswith("t_"): continue
    n += 1
    try:
        if ev(ast.parse(expr, mode="eval"), fl) != float(res):
            bad += 1; print("not true: " + line, file=sys.stderr)
    except (ValueError, ZeroDivisionError, SyntaxError):
        bad += 1; print("cannot evaluate: " + line, file=sys.stderr)
print(n, bad)
EOF
}

# true_eqs DESC MIN: every equation of $tmp/out evaluated is true, and at least MIN were
true_eqs() {
    if ! command -v python3 >/dev/null 2>&1; then
        echo "  skipped: $1 (python3 not installed)"
        return
    fi
    set -- "$1" "$2" $(eqs)
    check "$1: $3 equations, all true" test "$3" -ge "$2" -a "$4" = 0
}

# ---- teach79-1: renderer 7, perspective, a scene vertex (the course's r7-asym-03)
s=$c/r7-asym-03.scene
run step $s --vertex 1
check "teach79-1.1 r7 step: exit 0" test "$rc" = 0
check "teach79-1.2 ... nine stages, model to raster" test "$(grep -c '^stage [1-9] of 9: ' "$tmp/out")" = 9
check "teach79-1.3 ... view is the translation" has "  here     x_v = x_t + x_m = 0.3259826012372261 + (-1) = -0.6740173987627739"
for k in x y z; do
    check "teach79-1.4 ... view ${k}_v is the trace's" same "$(sv ${k}_v)" "$(jv $s 1 view $k)"
    check "teach79-1.5 ... camera ${k}_c is the trace's" same "$(sv ${k}_c)" "$(jv $s 1 camera $k)"
done
for k in x y; do
    check "teach79-1.6 ... image ${k}_p is the trace's" same "$(sv ${k}_p)" "$(jv $s 1 image $k)"
done
check "teach79-1.7 ... the camera's skew, with l r b t n" grep -q "^  here     perspective, l = -2.6666666666666665, r = 2.6666666666666665, b = -2, t = 2, n = -0.1" "$tmp/out"
check "teach79-1.8 ... the skew's x, then the scaling" grep -q "^           x = x_v + (z_v\*(r+l))/2 = " "$tmp/out"
check "teach79-1.9 ... the near plane test" grep -q "^  here     z_c = -4 <= n = -0.1: on the visible side" "$tmp/out"
check "teach79-1.10 ... Math.round in the viewport stage" grep -q "^  here     x_vp = Math.round(x_pp) - 1 = Math.round(" "$tmp/out"
true_eqs "teach79-1.11 r7 perspective" 14
# the pixel: step's (x_fb, y_fb) and bytes are a pixel record of the trace
xy=$(sed -n 's/^ *(x_fb, y_fb) = .* = (\([0-9]*\), \([0-9]*\))$/\1,\2/p' "$tmp/out")
by=$(sed -n 's/^ *bytes = .* = (\([0-9]*\), \([0-9]*\), \([0-9]*\))$/\1,\2,\3/p' "$tmp/out" | head -1)
check "teach79-1.12 ... its pixel and bytes are a pixel record of the trace" \
    sh -c "'$exe' $s --format jsonl | grep -q '\"x\":${xy%,*},\"y\":${xy#*,},\"rgb\":\\[$by\\]'"

# ---- teach79-2: renderer 7, orthographic, a vertex the rectangle clip made
s=$c/r7-clip-08-corner-ur.scene
run step $s --vertex 3
check "teach79-2.1 clip-made vertex 3: exit 0, four stages from the clip" test "$rc" = 0 -a "$(grep -c '^stage [1-4] of 4: ' "$tmp/out")" = 4
check "teach79-2.2 ... says where it came from" grep -q "^vertex 3 is not the scene's: the model has 2, a clip stage made this one" "$tmp/out"
check "teach79-2.3 ... the edge and t" has "  here     made by the clip of segment 1 at the edge x = +1: the end o = (1.8, 1.4) lies beyond it, i = (0, 0) is the other end"
check "teach79-2.4 ... t is the trace's" same "$(sv t)" "$(jv $s 3 clip t)"
check "teach79-2.5 ... y is the trace's" same "$(sv y)" "$(jv $s 3 clip y)"
check "teach79-2.6 ... its colour is the trace's" same "$(sv r) $(sv g) $(sv b)" "$(jv $s 3 clip color)"
true_eqs "teach79-2.7 r7 rectangle clip (colours in float)" 8
run step $s --vertex 1
check "teach79-2.8 orthographic camera: the shift, not the skew" grep -q "^           x = x_v - ((r+l))/2 = \|^           x = x_v - (r+l)/2 = " "$tmp/out"
check "teach79-2.9 ... image: x_p = x_c" grep -q "^  here     x_p = x_c = " "$tmp/out"
run step $s --vertex 2
check "teach79-2.10 the end cut off: its segment, t, the new vertex" grep -q "^           segment 1 is cut at x = +1, t = 0.4444444444444445: its end here is replaced by vertex 3" "$tmp/out"
true_eqs "teach79-2.11 r7 orthographic" 8
check "teach79-2.12 ... outside the view rectangle: no pixel of its own" has "  here     none: the vertex lies outside the view rectangle, and the rasterizer maps only what the clip keeps (the clipped segments' ends)"

# ---- teach79-3: renderer 9, a vertex the near clip made
s=$c/r9-near-05.scene
run step $s --vertex 13
check "teach79-3.1 near-clipped vertex 13: six stages from the near clip" test "$rc" = 0 -a "$(grep -c '^stage [1-6] of 6: ' "$tmp/out")" = 6
check "teach79-3.2 ... segment and plane" grep -q "^  here     made by the near clip of segment 3: z0 = -2.2368061748657655, z1 = -1.9343190030141275, n = -2" "$tmp/out"
for k in t x y; do
    check "teach79-3.3 ... $k is the trace's" same "$(sv $k)" "$(jv $s 13 nearclip $k)"
done
check "teach79-3.4 ... z = n" has "           z = n = -2"
check "teach79-3.5 ... its colour is the trace's" same "$(sv r) $(sv g) $(sv b)" "$(jv $s 13 nearclip color)"
check "teach79-3.6 ... image x_p is the trace's" same "$(sv x_p)" "$(jv $s 13 image x)"
true_eqs "teach79-3.7 r9 near clip" 10
run step $s --vertex 6
check "teach79-3.8 the end beyond the near plane: cut off, replaced by 13" grep -q "segment 3 is cut at z = n, t = 0.2171364708916889: its end here is replaced by vertex 13" "$tmp/out"
check "teach79-3.9 ... beyond n" grep -q "^  here     z_c = -1.9343190030141275 > n = -2: beyond the near plane" "$tmp/out"

# ---- teach79-4: renderer 9, the position's matrix and the normalize matrix
s=$c/r9-mat-07-order-TRS.scene
run step $s --vertex 1
check "teach79-4.1 r9 step: ten stages, world included" test "$rc" = 0 -a "$(grep -c '^stage [0-9]* of 10: ' "$tmp/out")" = 10
check "teach79-4.2 ... the 4x4 matrix shown" grep -q "^  here     M = \[.*; .*; .*; .*\]$" "$tmp/out"
for k in x y z w; do
    check "teach79-4.3 ... world ${k}_w is the trace's" same "$(sv ${k}_w)" "$(jv $s 1 world $k)"
done
for k in x y z; do
    check "teach79-4.4 ... view ${k}_v is the trace's" same "$(sv ${k}_v)" "$(jv $s 1 view $k)"
    check "teach79-4.5 ... camera ${k}_c is the trace's" same "$(sv ${k}_c)" "$(jv $s 1 camera $k)"
done
check "teach79-4.6 ... the view stage comes from world" has "stage 3 of 10: view (world -> view)"
check "teach79-4.7 ... the normalize matrix" grep -q "^           N = \[" "$tmp/out"
true_eqs "teach79-4.8 r9 matrices" 14

# ---- teach79-5: renderer 9's Pipeline2: the same numbers
s=$c/r9-pipe2-two-models.scene
run step $s --vertex 2 --model b
check "teach79-5.1 pipeline2: exit 0, says so" grep -q "^pipetrace step: vertex 2 of model b (position b) in .*, renderer 9 (pipeline2)$" "$tmp/out"
for k in x y; do
    check "teach79-5.2 ... image ${k}_p is the trace's" same "$(sv ${k}_p)" "$("$exe" $s --format jsonl | grep -F '"model":"b"' | grep -F '"v":2,"stage":"image"' | sed -n "s/.*\"$k\":\([^,]*\).*/\1/p")"
done
true_eqs "teach79-5.3 pipeline2" 10

# ---- teach79-6: the pixel: anti-aliasing's weight, gamma on and off
s=$c/r9-aa-04.scene
run step $s --vertex 2
check "teach79-6.1 AA: the weight, f = (float)(y - floor(y))" grep -q "^           weight f = (float)([xy] - floor([xy])) = (float)(" "$tmp/out"
check "teach79-6.2 ... the blend with the background" grep -q "^           r = (1 - f)\*c + f\*bg = (1 - " "$tmp/out"
check "teach79-6.3 ... gamma" grep -q "^           gamma: r' = (float)Math.pow(r, 1/2.2) = (float)Math.pow(" "$tmp/out"
xy=$(sed -n 's/^ *(x_fb, y_fb) = .* = (\([0-9]*\), \([0-9]*\))$/\1,\2/p' "$tmp/out")
for by in $(sed -n 's/^ *bytes = .* = (\([0-9]*\), \([0-9]*\), \([0-9]*\))$/\1,\2,\3/p' "$tmp/out"); do
    check "teach79-6.4 ... bytes $by at ($xy) are a pixel record of the trace" \
        sh -c "'$exe' $s --format jsonl | grep -q '\"x\":${xy%,*},\"y\":${xy#*,},\"rgb\":\\[$by\\]'"
done
true_eqs "teach79-6.5 AA (blends in float)" 8
sed 's/^gamma on/gamma off/' $s > "$tmp/nogamma.scene"
grep -q '^gamma off' "$tmp/nogamma.scene" || echo "gamma off" >> "$tmp/nogamma.scene"
run step "$tmp/nogamma.scene" --vertex 2
check "teach79-6.6 gamma off: said, no Math.pow" test "$rc" = 0 -a "$(grep -c 'gamma off: the colour is written as it is' "$tmp/out")" -ge 1 -a "$(grep -c "gamma: r' = " "$tmp/out")" = 0
for by in $(sed -n 's/^ *bytes = .* = (\([0-9]*\), \([0-9]*\), \([0-9]*\))$/\1,\2,\3/p' "$tmp/out"); do
    check "teach79-6.7 ... bytes $by at ($xy) are a pixel record of that trace" \
        sh -c "'$exe' '$tmp/nogamma.scene' --format jsonl | grep -q '\"x\":${xy%,*},\"y\":${xy#*,},\"rgb\":\\[$by\\]'"
done

# ---- teach79-7: why on renderers 7 and 9
s=$c/r9-near-05.scene
run why $s 19 25
check "teach79-7.1 why r9: exit 0" test "$rc" = 0
check "teach79-7.2 ... the segment that lit it, its coverage and bytes (the trace's pixel record)" \
    grep -q "^  near segment 1 (v1 v2), drawn as primitive 1: an anti-aliased step, coverage 0.84375, bytes 214 71 127 (gamma-encoded)" "$tmp/out"
check "teach79-7.3 ... that record is in the trace" sh -c "'$exe' $s --format jsonl | grep -q '\"primitive\":1,\"x\":19,\"y\":25,\"rgb\":\\[214,71,127\\],\"coverage\":0.84375'"
check "teach79-7.4 ... the colour it keeps" grep -q "^color 214 71 127: the last write, by near segment 1 (v1 v2)" "$tmp/out"
t=$(jv $s 13 nearclip t)
check "teach79-7.5 ... a segment cut at the near plane, with the trace's t" grep -q "^  near segment 3 (v5 v6): drawn as primitive 2, 97 pixels elsewhere; cut at the near plane z = n, t = $t, new vertex 13" "$tmp/out"
check "teach79-7.6 ... a segment dropped by the near clip" grep -q "^  near segment 2 (v3 v4): not drawn; dropped by the near clip: both ends lie beyond the near plane z = n = -2" "$tmp/out"
s=$c/r7-clip-08-corner-ur.scene
run why $s 49 10
check "teach79-7.7 why r7: not lit, the background" grep -q "^not lit: no primitive writes it; it keeps the viewport's background 0 0 0" "$tmp/out"
check "teach79-7.8 ... the segment cut at the rectangle's edge, with t" grep -q "^  seg segment 1 (v1 v2): drawn as primitive 1, 26 pixels elsewhere; cut at the edge x = +1, t = 0.4444444444444445, new vertex 3" "$tmp/out"
# every pixel record of a primitive is what why says about that pixel
"$exe" $c/r7-aa-00.scene --format jsonl | grep '"type":"pixel"' | sed -n '5p;9p' > "$tmp/px"
while IFS= read -r rec; do
    x=$(printf '%s' "$rec" | sed 's/.*"x":\([0-9]*\),.*/\1/')
    y=$(printf '%s' "$rec" | sed 's/.*"y":\([0-9]*\),.*/\1/')
    rgb=$(printf '%s' "$rec" | sed 's/.*"rgb":\[\([0-9,]*\)\].*/\1/' | tr ',' ' ')
    cov=$(printf '%s' "$rec" | sed 's/.*"coverage":\([0-9.e-]*\).*/\1/')
    run why $c/r7-aa-00.scene "$x" "$y"
    check "teach79-7.9 why r7 AA ($x, $y): coverage $cov, bytes $rgb as the trace's record" \
        grep -q "coverage $cov, bytes $rgb" "$tmp/out"
    last=$("$exe" $c/r7-aa-00.scene --format jsonl | grep -F "\"x\":$x,\"y\":$y," | tail -1 |
           sed 's/.*"rgb":\[\([0-9,]*\)\].*/\1/' | tr ',' ' ')
    check "teach79-7.10 ... the colour kept is the trace's last record there, $last" \
        grep -q "^color $last: the last write" "$tmp/out"
done < "$tmp/px"

# ---- teach79-9: --explain on the trace: step's text, under each vertex record
# here STAGE: step's "here" block of STAGE in $tmp/out, its lines joined by "; "
here() {
    awk -v st="$1" '/^stage [0-9]+ of [0-9]+: / { on = ($5 == st) } on && /^  here / { p = 1 }
        on && p && /^ *$/ { exit } on && p { sub(/^  here +|^ +/, ""); s = s (n++ ? "; " : "") $0 }
        END { print s }' "$tmp/out"
}
for s in $c/r7-asym-03.scene $c/r9-mat-07-order-TRS.scene; do
    run $s --explain
    check "teach79-9.1 --explain $(basename $s): every vertex record has its line" \
        test "$(grep -c '^[^ ].* v[0-9]* *[a-z]* *x = ' "$tmp/out")" = "$(grep -c '^              [a-zA-Z]' "$tmp/out")" -a "$rc" = 0
    tr ';' '\n' < "$tmp/out" | sed 's/^ *//' > "$tmp/lines"
    cp "$tmp/lines" "$tmp/out"
    true_eqs "teach79-9.2 ... its equations" 40
    run step $s --vertex 1
    for st in model view camera image; do
        want=$(here $st)
        got=$("$exe" $s --explain --format jsonl | grep -F '"v":1,"stage":"'$st'"' | head -1 |
              sed 's/.*"explain":"\(.*\)"}$/\1/')
        check "teach79-9.3 ... jsonl $st of v1 explains as step does" test -n "$want" -a "$got" = "$want"
    done
done
run $c/r9-near-05.scene --explain --format jsonl
check "teach79-9.4 ... a near-clipped vertex: its cut" grep -q '"v":13,"stage":"nearclip".*"explain":"made by the near clip of segment 3: z0 = ' "$tmp/out"
run $c/r7-clip-08-corner-ur.scene --explain
check "teach79-9.5 ... a rectangle-clipped vertex: its cut" grep -q '^              made by the clip of segment 1 at the edge x = +1: ' "$tmp/out"
run $c/r7-clip-08-corner-ur.scene --explain --format csv
check "teach79-9.6 ... not with csv: a usage error" test "$rc" = 1

# ---- teach79-8: what step refuses, and one stage at a time
run step $c/r7-asym-03.scene --vertex 99
check "teach79-8.1 no vertex 99: exit 2, said" test "$rc" = 2 -a -n "$(grep 'no position of .* has a vertex 99, not even after the clips' "$tmp/err")"
run step $c/r7-asym-03.scene --compare-cameras
check "teach79-8.2 --compare-cameras on renderer 7: a usage error" test "$rc" = 1
feed '\n\nb\nq\n' step $c/r9-near-05.scene --vertex 13 --interactive
check "teach79-8.3 interactive: Enter, Enter, b, q shows stages 1 2 3 2" test "$(grep '^stage' "$tmp/out" | cut -c7 | tr -d '\n')" = 1232
run step $c/r9-near-05.scene --vertex 1 --model nosuch
check "teach79-8.4 --model unknown: exit 2" test "$rc" = 2
run step $c/r9-near-05.scene --vertex 16
check "teach79-8.5 without --model, a vertex only a clip made: its position is found" grep -q "^pipetrace step: vertex 16 of model near (position near) in " "$tmp/out"
run step $c/r9-pipe2-two-models.scene --vertex 2
check "teach79-8.6 without --model: the first position with that vertex" grep -q "^pipetrace step: vertex 2 of model a (position a) in " "$tmp/out"
run step $c/r9-hidden-warn-p2.scene --vertex 1 --model hp
check "teach79-8.7 a hidden position: exit 2, says it is hidden" test "$rc" = 2 -a -n "$(grep 'no vertex 1 (it has 0 after the clips; it is hidden)' "$tmp/err")"
run why $c/r9-hidden-warn-p2.scene 5 5
check "teach79-8.8 why: hidden models are named, nothing of them drawn" grep -q "^  model hm: hidden, nothing of it is drawn" "$tmp/out"
# A viewport that sticks out: the vertex's pixel goes where the course's index
# puts it.  vpout-01 v5 lands at (26, 12) of a 20-wide framebuffer: the array
# pixel named must show the last pixel record the trace writes at (26, 12);
# vpout-02 v1's write is dropped, as the course's log says.
run step tests/course/r7/vpout-01.scene --vertex 5 --all
at=$(sed -n 's/.* the pixel written is (\([0-9]*\), \([0-9]*\)) of the array.*/\1 \2/p' "$tmp/out" | head -n 1)
"$exe" tests/course/r7/vpout-01.scene --format jsonl --trace "$tmp/vp.jsonl" 2>/dev/null
check "teach79-8.9 step, viewport sticking out: the wrapped pixel shows the trace's last write at (x_fb, y_fb)" \
    python3 -c '
import gzip, json, re, sys
x, y = map(int, sys.argv[3].split())
last = [r["rgb"] for r in map(json.loads, open(sys.argv[2]))
        if r.get("type") == "pixel" and (r["x"], r["y"]) == (26, 12)][-1]
d = gzip.open(sys.argv[1]).read()
m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", d)
i = m.end() + 3 * (y * int(m.group(1)) + x)
sys.exit(0 if (x, y) != (26, 12) and list(d[i:i + 3]) == last else 1)' tests/course/r7/vpout-01.ppm.gz "$tmp/vp.jsonl" "${at:-none}"
run step tests/course/r7/vpout-02.scene --vertex 1 --all
check "teach79-8.10 step, viewport sticking out: a write past the array is dropped, as the course logs it" \
    sh -c 'grep -q "= -5\*20 + 11 = -89 lies outside the pixel array: the write is dropped" "$1" &&
           gzip -dc tests/course/r7/vpout-02.log.gz | grep -q "^FrameBuffer: Bad pixel coordinate (11, -5) "' _ "$tmp/out"

# ---- teach79-10: why on a viewport that sticks out of the framebuffer (the
# course's vpout-* scenes): the viewport pixels that land on a pixel, what
# each wrote, and the last write, against the trace's pixel records (their
# index) and the image (tests/teach/why_vpout.py says what it checks)
why_vpout() {   # why_vpout ID SCENE [every] [lit2]
    id=$1; s=$2; shift 2
    python3 tests/teach/why_vpout.py "$exe" "$s" "$id" "$@" > "$tmp/py" 2>&1
    check "$id why on $s (viewport sticking out): every viewport pixel, against the trace ($(tail -1 "$tmp/py"))" test $? = 0
    grep '^FAIL\|^  \|Error' "$tmp/py" | head -10
}
# renderer 9's corpus lights no pixel reached twice: vpout-14 moved right
sed 's/^viewport .*/viewport 2 0 20 20/' tests/course/r9/vpout-14.scene > "$tmp/r9-wide.scene"
if command -v python3 >/dev/null 2>&1; then
    why_vpout teach79-10.1 tests/course/r7/vpout-12.scene every lit2
    why_vpout teach79-10.2 tests/course/r7/vpout-13.scene
    why_vpout teach79-10.3 tests/course/r7/vpout-04.scene
    why_vpout teach79-10.4 tests/course/r9/vpout-12.scene every
    why_vpout teach79-10.5 "$tmp/r9-wide.scene" every lit2
    why_vpout teach79-10.6 tests/course/r9/vpout-13.scene
    why_vpout teach79-10.7 tests/course/r9/vpout-04.scene
fi
run why tests/course/r7/vpout-12.scene 0 3
check "teach79-10.8 two viewport pixels, wrapped by two rows and by one: said" \
    test "$rc" = 0 -a -n "$(grep -Fx "viewport pixel (x_vp, y_vp) = (38, 0) -> framebuffer (x_fb, y_fb) = (40, 1) -> index y_fb * W + x_fb = 1 * 20 + 40 = 60 -> shown at (x_fb, y_fb) = (0, 3): x_fb = 40 lies past its width, so the index falls 2 rows down" "$tmp/out")" \
    -a -n "$(grep -F "viewport pixel (x_vp, y_vp) = (18, 1) -> framebuffer (x_fb, y_fb) = (20, 2) -> index y_fb * W + x_fb = 2 * 20 + 20 = 60 -> shown at (x_fb, y_fb) = (0, 3): " "$tmp/out")"
printf 'renderer 9\nframebuffer 1 100\nviewport 0 0 100 100\ncamera orthographic\nmodel m\nv -1 0 0\nv 1 0 0\nsegment 1 2\n' > "$tmp/thin.scene"
run why "$tmp/thin.scene" 0 99
check "teach79-10.10 100 viewport pixels on one index: all listed, the first 64 explained, the last write" \
    test "$rc" = 0 -a "$(grep -c '^viewport pixel (x_vp, y_vp) = ' "$tmp/out")" = 100 -a "$(grep -c '^not lit from there\|^lit by' "$tmp/out")" = 64 \
    -a -n "$(grep -Fx '(the 36 viewport pixels after the first 64 are listed, not explained)' "$tmp/out")" \
    -a -n "$(grep '^color [0-9 ]*: the last write, by m segment 1 (v1 v2), drawn as primitive 1, from viewport pixel (x_vp, y_vp) = (49, 50)$' "$tmp/out")"
run why tests/course/r7/vpout-00.scene 6 0
check "teach79-10.9 reached by none: said, the background" \
    test "$rc" = 0 -a -n "$(grep '^no viewport pixel lands on index 6: nothing is ever drawn there$' "$tmp/out")" -a -n "$(grep '^not lit: no viewport pixel writes it; it keeps the background ' "$tmp/out")"

report
