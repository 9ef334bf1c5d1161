/*
** src/tools/journey/journey_wasm.c -- the journey page's sliders, recomputed by the stages in WebAssembly
** See LICENSE for copyright and license.
**
** The numbers go to the page exact: every double as the 16 hex digits of its
** IEEE bits, so that the module gets the very doubles pipetrace read from
** the scene; a slider's value is the decimal text the browser gives it,
** read by JavaScript's Number(), correctly rounded like pipetrace's reader.
*/
#include <math.h>
#include <string.h>
#include "tools/journey/journey.h"
#include "tools/journey/journey_wasm.h"
#include "tools/journey/jrows.h"

#define PT_JOURNEY_WASM_MAXV 100000  /* a model's first this many vertices get sliders */

/* The fov slider moves in steps of PT_JOURNEY_FOV_STEP degrees from one step
** to PT_JOURNEY_FOV_STEPS steps: the page holds the host's sin and cos for
** each (and for the scene's own fov), as the module has no sin of its own. */
#define PT_JOURNEY_FOV_STEP  0.5
#define PT_JOURNEY_FOV_STEPS 359
_Static_assert(PT_JOURNEY_FOV_STEPS + 1 <= PT_WASM_NSINCOS, "the module's table holds them");

static const char style[] =
"<style>\n"
"#live{margin:0 20px 18px;padding:8px 14px;background:#fff;border:1px solid #e3e6eb;"
"border-radius:4px}\n"
"#live h2{font-size:12px;text-transform:uppercase;letter-spacing:.06em;color:#5f6670;"
"margin:6px 0}\n"
"#sliders{display:grid;grid-template-columns:repeat(auto-fill,minmax(230px,1fr));gap:4px 16px}\n"
"#sliders label{display:flex;align-items:center;gap:6px;font-size:14px;min-width:0}\n"
"#sliders input{flex:1;min-width:60px}\n"
"#sliders output{font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;min-width:4.5em;"
"max-width:9em;overflow:hidden;text-overflow:ellipsis;white-space:nowrap}\n"
"#livetable{border-collapse:collapse;margin-top:8px;font-size:14px}\n"
"#livetable th{text-align:left;padding:2px 12px 2px 0;font-weight:normal;color:#5f6670}\n"
"#livetable td{font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;padding:2px 0}\n"
"body.live #panel,body.live #formula,body.live #after{opacity:.4}\n"
"</style>\n";

static const char without[] =
"<section id=\"live\" data-wasm=\"no\"><h2>recompute</h2>\n"
"<p id=\"livenote\">No sliders on this page: pipetrace was built without WebAssembly "
"(clang and wasm-ld, Debian's packages clang and lld, were not found, or make WASM=no), "
"so the page cannot run the stages itself.</p>\n</section>\n";

static const char section[] =
"<section id=\"live\" data-wasm=\"yes\"><h2>recompute</h2>\n"
"<div id=\"sliders\"></div>\n"
"<p><button type=\"button\" id=\"reset\">Reset to the scene</button></p>\n"
"<p id=\"livenote\">Loading the stages (WebAssembly) ...</p>\n"
"<table id=\"livetable\"></table>\n"
"</section>\n";

/* The start of both scripts: the data, and the numbers' forms. */
static const char prelude[] =
"<script>\n"
"(function () {\n"
"  'use strict';\n"
"  function $(id) { return document.getElementById(id); }\n"
"  var D = JSON.parse($('data').textContent), W = JSON.parse($('wasmdata').textContent);\n"
"  var sec = $('live'), note = $('livenote'), sel = $('vertex'), E = null, moved = false;\n"
"  if ($('foot')) document.body.insertBefore(sec, $('foot'));\n"
"  function dbl(h) {                       /* 16 hex digits -> the double */\n"
"    var v = new DataView(new ArrayBuffer(8));\n"
"    v.setUint32(0, parseInt(h.slice(0, 8), 16)); v.setUint32(4, parseInt(h.slice(8), 16));\n"
"    return v.getFloat64(0);\n"
"  }\n"
"  function hex(x) {\n"
"    var v = new DataView(new ArrayBuffer(8)), s = '', k;\n"
"    v.setFloat64(0, x);\n"
"    for (k = 0; k < 8; k++) s += (v.getUint8(k) + 256).toString(16).slice(1);\n"
"    return s;\n"
"  }\n"
"  function num(x) {                       /* as the trace: shortest round trip */\n"
"    return x !== x ? 'nan' : x === Infinity ? 'inf' : x === -Infinity ? '-inf' :\n"
"      Object.is(x, -0) ? '-0' : String(x);\n"
"  }\n"
"  function vertex() { return D.vertices[Number(sel.value)] || D.vertices[D.start]; }\n"
"  function slider(n) { return $('s_' + n); }\n"
"  function sliders(names, moved) {        /* a range input and its output per name */\n"
"    names.forEach(function (n, k) {\n"
"      var l = document.createElement('label'), i = document.createElement('input'),\n"
"          o = document.createElement('output');\n"
"      i.type = 'range'; i.id = 's_' + n; i.disabled = true;\n"
"      o.id = 'o_' + n;\n"
"      l.appendChild(document.createTextNode(n)); l.appendChild(i); l.appendChild(o);\n"
"      $('sliders').appendChild(l);\n"
"      i.addEventListener('keydown', function (e) { e.stopPropagation(); });  /* arrows: its own */\n"
"      i.addEventListener('input', function () { moved(n, k, Number(i.value)); });\n"
"    });\n"
"  }\n"
"  function around(c) {                    /* a real's slider: +-5 in steps of 0.05 */\n"
"    c = Math.abs(c) < 1e6 ? Math.floor(c) : 0;\n"
"    return [c - 5, c + 5, 0.05];\n"
"  }\n"
"  function put(want, st) {                /* #coords: want, or (null) the scene's */\n"
"    var c = $('coords');\n"
"    if (want === null && st >= 0) want = vertex().coords[st];\n"
"    if (want !== null && want !== undefined && c.textContent !== want) c.textContent = want;\n"
"  }\n"
"  function follow(coords) {               /* coords() on each change of #coords */\n"
"    new MutationObserver(coords).observe($('coords'), {childList: true, characterData: true,\n"
"                                                       subtree: true});\n"
"    sel.addEventListener('change', run);\n"
"  }\n"
"  function load(names, setup) {           /* the module; then setup(), the sliders, run() */\n"
"    var b = atob(W.wasm), bytes = new Uint8Array(b.length), k;\n"
"    for (k = 0; k < b.length; k++) bytes[k] = b.charCodeAt(k);\n"
"    WebAssembly.instantiate(bytes).then(function (r) {\n"
"      E = r.instance.exports;\n"
"      if (!setup()) return;\n"
"      names.forEach(function (n) { slider(n).disabled = false; });\n"
"      run();\n"
"      sec.dataset.ready = '1';\n"
"    }, function (e) { note.textContent = 'The stages (WebAssembly) did not load: ' + e; });\n"
"  }\n";

/* The script, in pieces (C11 promises string literals of 4095 bytes). */
static const char *const script[] = {
"  var M = W.matrix, C = W.cam;\n"
"  var T = W.models.map(function (m) { return m.t.map(dbl); });   /* live translations */\n"
"  var P = {}, names = ['x_t', 'y_t', 'z_t'].concat(M ? ['fov', 'eye_x', 'eye_y', 'eye_z',\n"
"      'near', 'far'] : [], ['w', 'h', 'x_ul', 'y_ul', 'W', 'H']);\n"
"  function scene() {\n"
"    P = {w: W.vp[0], h: W.vp[1], x_ul: W.vp[2], y_ul: W.vp[3], W: W.fb[0], H: W.fb[1]};\n"
"    if (M) { P.fov = dbl(C.fov); P.near = dbl(C.near); P.far = dbl(C.far);\n"
"             P.eye_x = dbl(C.eye[0]); P.eye_y = dbl(C.eye[1]); P.eye_z = dbl(C.eye[2]); }\n"
"  }\n"
"  scene();\n"
"  sliders(names, function (n, k, x) {\n"
"    if (k < 3) T[vertex().m][k] = x; else P[n] = x;\n"
"    moved = true;\n"
"    run();\n"
"  });\n",
"  function ranges() {                     /* the scene's limits: viewport inside, */\n"
"    var t = T[vertex().m];                /* or as far out as the scene's sticks out */\n"
"    var out = !M && (W.vp[2] < 0 || W.vp[3] < 0 || W.vp[2] + W.vp[0] > W.fb[0] ||\n"
"                     W.vp[3] + W.vp[1] > W.fb[1]);\n"
"    P.W = Math.min(Math.max(P.W, 1), W.max); P.H = Math.min(Math.max(P.H, 1), W.max);\n"
"    P.w = Math.min(Math.max(P.w, 1), out ? W.max : P.W);\n"
"    P.h = Math.min(Math.max(P.h, 1), out ? W.max : P.H);\n"
"    var xr = out ? [Math.min(W.vp[2], -P.w), Math.max(W.vp[2], P.W)] : [0, P.W - P.w];\n"
"    var yr = out ? [Math.min(W.vp[3], -P.h), Math.max(W.vp[3], P.H)] : [0, P.H - P.h];\n"
"    P.x_ul = Math.min(Math.max(P.x_ul, xr[0]), xr[1]);\n"
"    P.y_ul = Math.min(Math.max(P.y_ul, yr[0]), yr[1]);\n"
"    var lim = {w: [1, out ? Math.max(W.vp[0], P.W) : P.W, 1],\n"
"               h: [1, out ? Math.max(W.vp[1], P.H) : P.H, 1], x_ul: [xr[0], xr[1], 1],\n"
"               y_ul: [yr[0], yr[1], 1],\n"
"               W: [1, Math.min(W.max, Math.max(4 * W.fb[0], 256)), 1],\n"
"               H: [1, Math.min(W.max, Math.max(4 * W.fb[1], 256)), 1]};\n"
"    if (M) {                              /* fov: the steps the page has sin, cos for */\n"
"      lim.fov = [W.fov[0], W.fov[1], W.fov[2]];\n"
"      lim.near = [0.05, Math.max(5, 4 * dbl(C.near)), 0.05];\n"
"      lim.far = [0.5, Math.max(100, 4 * dbl(C.far)), 0.5];\n"
"    }\n"
"    names.forEach(function (n, k) {\n"
"      var v = k < 3 ? t[k] : P[n], r = lim[n] || around(v), i = slider(n);\n"
"      i.min = String(r[0]); i.max = String(r[1]); i.step = String(r[2]);\n"
"      if (Number(i.value) !== v) i.value = String(v);\n"
"      $('o_' + n).textContent = $('o_' + n).title = num(v);   /* title: all of it */\n"
"    });\n"
"  }\n"
"  function text(s, vals) {                /* as pipetrace explain writes #coords */\n"
"    var shown = vals.map(function (x) { return x === null ? 'none' : x; });\n"
"    var any = vals.some(function (x) { return x !== null; });\n"
"    if (s.coord.length === 1) return s.coord[0] + ' = ' + shown[0];\n"
"    return '(' + s.coord.join(', ') + ') = ' + (any ? '(' + shown.join(', ') + ')' : 'none');\n"
"  }\n"
"  function cstr(a) {                      /* a C string in the module's memory */\n"
"    var b = new Uint8Array(E.memory.buffer), s = '';\n"
"    while (b[a]) s += String.fromCharCode(b[a++]);\n"
"    return s;\n"
"  }\n"
"  function matrix(x, vm, t) {             /* the inputs in place (pt_wasm_in.h), run */\n"
"    var F = new Float64Array(E.memory.buffer, E.pt_wasm_in(), W.nin), I = W.in;\n"
"    F.set(W.models[x.m].w.map(dbl), I.world); F.set(t, I.t);\n"
"    F.set([P.eye_x, P.eye_y, P.eye_z], I.eye); F.set(C.dir.map(dbl), I.dir);\n"
"    F.set(C.up.map(dbl), I.up); F.set(vm, I.v);\n"
"    F[I.fov] = P.fov; F[I.aspect] = dbl(C.aspect); F[I.near] = P.near; F[I.far] = P.far;\n"
"    return E.pt_wasm_matrix_run(C.target ? 1 : 0, C.auto ? 1 : 0, P.w, P.h, P.x_ul, P.y_ul,\n"
"                                P.W, P.H);\n"
"  }\n"
"  var live = [], liveFor = null;         /* the values of vertex liveFor */\n",
"  function run() {\n"
"    var x = vertex(), vm = W.models[x.m].v[x.v - 1], t = T[x.m], st, k, rc;\n"
"    ranges();\n"
"    if (!E) return;\n"
"    $('livetable').textContent = '';\n"
"    live = []; liveFor = sel.value;\n"
"    if (!vm) { note.textContent = 'No sliders for this vertex (beyond the first ' +\n"
"               W.maxv + ' of its model).'; return; }\n"
"    vm = vm.map(dbl);\n"
"    rc = M ? matrix(x, vm, t) : E.pt_wasm_run(vm[0], vm[1], vm[2], t[0], t[1], t[2],\n"
"               W.perspective ? 1 : 0, P.w, P.h, P.x_ul, P.y_ul, P.W, P.H);\n"
"    if (rc >= 100) note.textContent = 'No camera: ' + cstr(E.pt_wasm_cam_error(rc - 100)) +\n"
"      ' (pipetrace would say so for this scene).';\n"
"    if (rc === -2) note.textContent = 'No sin and cos for fov = ' + num(P.fov) +\n"
"      ' in this page (it has them for the slider\\'s steps).';\n"
"    if (rc !== 0) { document.body.classList.toggle('live', moved); return; }\n"
"    for (st = 0; st < W.stages.length; st++) {\n"
"      var s = W.stages[st], vals = [], bits = [];\n"
"      if (M && !E.pt_wasm_reported(s.id)) {\n"
"        live.push(s.unreached); bits.push('unreached');\n"
"      } else {\n"
"        for (k = 0; k < s.nreal; k++) {\n"
"          var r = E.pt_wasm_real(s.id, k);\n"
"          vals.push(num(r)); bits.push(hex(r));\n"
"        }\n"
"        for (k = 0; k < s.nint; k++) {\n"
"          var i = E.pt_wasm_has(s.id, k) ? String(E.pt_wasm_int(s.id, k)) : null;\n"
"          vals.push(i); bits.push(i === null ? 'none' : i);\n"
"        }\n"
"        live.push(text(s, vals));\n"
"      }\n"
"      var tr = document.createElement('tr'), th = document.createElement('th'),\n"
"          td = document.createElement('td');\n"
"      tr.dataset.stage = s.name; th.textContent = s.name; td.textContent = live[st];\n"
"      td.dataset.values = bits.join(',');\n"
"      tr.appendChild(th); tr.appendChild(td); $('livetable').appendChild(tr);\n"
"    }\n"
"    note.textContent = (moved ? 'Recomputed' : 'Computed') + ' in this page by ' +\n"
"      'pipetrace\\'s own stage files compiled to WebAssembly, for ' + D.models[x.m].name +\n"
"      ' v' + x.v + ' with (x_t, y_t, z_t) = (' + t.map(num).join(', ') + ')' +\n"
"      (M ? ', fov ' + num(P.fov) + ', eye (' + [P.eye_x, P.eye_y, P.eye_z].map(num)\n"
"           .join(', ') + '), near ' + num(P.near) + ', far ' + num(P.far) : '') +\n"
"      ', viewport ' + P.w + ' x ' + P.h + ' at (x_ul, y_ul) = (' + P.x_ul + ', ' + P.y_ul +\n"
"      '), framebuffer ' + P.W + ' x ' + P.H + (moved ? '.  The panel, \"with the numbers\" ' +\n"
"      'and \"next\" (dimmed) still show the scene\\'s own numbers.' : '.');\n"
"    document.body.classList.toggle('live', moved);\n"
"    coords();\n"
"  }\n",
"  function coords() {                     /* the shown stage's #coords */\n"
"    if (moved && liveFor !== sel.value) return run();   /* chosen by the URL */\n"
"    var st = W.stages.map(function (s) { return s.name; }).indexOf($('stage').textContent);\n"
"    put(moved && live[st] !== undefined ? live[st] : null, st);\n"
"  }\n"
"  follow(coords);\n"
"  $('reset').addEventListener('click', function () {\n"
"    T = W.models.map(function (m) { return m.t.map(dbl); });\n"
"    scene(); moved = false; run();\n"
"  });\n"
"  ranges();\n"
"  load(names, function () {\n"
"    if (M) {                              /* the host's sin and cos, exact (journey_wasm.c) */\n"
"      var S = W.sincos, F = new Float64Array(E.memory.buffer, E.pt_wasm_table(S.length),\n"
"                                             3 * S.length);\n"
"      S.forEach(function (row, j) { F.set(row.map(dbl), 3 * j); });\n"
"    }\n"
"    return true;\n"
"  });\n"
"})();\n"
"</script>\n",
    NULL
};

/* The course page's script (renderers 7 and 9), after the prelude: sliders
** for the camera's l, r, b, t and n, the translation (renderer 7) or the
** view vector (renderer 9), the viewport's size and corner; each move runs
** the position's model through the module's course stages. */
static const char *const course_script[] = {
"  var R = W.renderer, C = W.cam.map(dbl), MV = W.move.map(dbl), P = {};\n"
"  var mv = R === 9 ? ['view_x', 'view_y', 'view_z'] : ['x_t', 'y_t', 'z_t'];\n"
"  var O = W.ops || [], os = [];            /* r9: the matrix's operations and their sliders */\n"
"  O.forEach(function (o, k) {             /* [name, operation, the arguments it gives] */\n"
"    o.sliders.forEach(function (n) { os.push([n[0], k, n[1]]); });\n"
"  });\n"
"  var names = ['l', 'r', 'b', 't', 'n'].concat(mv, os.map(function (o) { return o[0]; }),\n"
"                                               ['w', 'h', 'x_ul', 'y_ul', 'W', 'H']);\n"
"  function scene() {\n"
"    P = {l: C[0], r: C[1], b: C[2], t: C[3], n: C[4], w: W.vp[0], h: W.vp[1],\n"
"         x_ul: W.vp[2], y_ul: W.vp[3], W: W.fb[0], H: W.fb[1]};\n"
"    mv.forEach(function (n, k) { P[n] = MV[k]; });\n"
"    os.forEach(function (o) { P[o[0]] = dbl(O[o[1]].a[o[2][0]]); });\n"
"  }\n"
"  scene();\n"
"  sliders(names, function (n, k, x) { P[n] = x; moved = true; run(); });\n"
"  function ranges() {                     /* the course lets the viewport stick out: */\n"
"    var fw = Math.min(W.max, Math.max(4 * W.fb[0], 256)),   /* a viewport's size past */\n"
"        fh = Math.min(W.max, Math.max(4 * W.fb[1], 256));   /* each edge, or the scene's */\n"
"    P.W = Math.min(Math.max(P.W, 1), fw); P.H = Math.min(Math.max(P.H, 1), fh);\n"
"    var lim = {w: [1, Math.max(W.vp[0], P.W), 1], h: [1, Math.max(W.vp[1], P.H), 1],\n"
"               W: [1, fw, 1], H: [1, fh, 1]};\n"
"    P.w = Math.min(Math.max(P.w, 1), lim.w[1]); P.h = Math.min(Math.max(P.h, 1), lim.h[1]);\n"
"    lim.x_ul = [Math.min(W.vp[2], -P.w), Math.max(W.vp[2], P.W), 1];\n"
"    lim.y_ul = [Math.min(W.vp[3], -P.h), Math.max(W.vp[3], P.H), 1];\n"
"    P.x_ul = Math.min(Math.max(P.x_ul, lim.x_ul[0]), lim.x_ul[1]);\n"
"    P.y_ul = Math.min(Math.max(P.y_ul, lim.y_ul[0]), lim.y_ul[1]);\n"
"    os.forEach(function (o) { if (O[o[1]].angle) lim[o[0]] = W.angles; });\n"
"    names.forEach(function (n) {\n"
"      var v = P[n], r = lim[n] || around(v), i = slider(n);\n"
"      i.min = String(r[0]); i.max = String(r[1]); i.step = String(r[2]);\n"
"      if (Number(i.value) !== v) i.value = String(v);\n"
"      $('o_' + n).textContent = $('o_' + n).title = num(v);   /* title: all of it */\n"
"    });\n"
"  }\n"
"  var live = {}, liveFor = null;          /* the rows' texts for vertex liveFor */\n"
"  function row(name, text, bits, more) {  /* more: shown in the table, not in #coords */\n"
"    var tr = document.createElement('tr'), th = document.createElement('th'),\n"
"        td = document.createElement('td');\n"
"    tr.dataset.stage = name; th.textContent = name; td.textContent = text + (more || '');\n"
"    td.dataset.values = bits.join(',');\n"
"    tr.appendChild(th); tr.appendChild(td); $('livetable').appendChild(tr);\n"
"    live[name] = text;\n"
"  }\n",
"  function run() {\n"
"    var x = vertex(), rc, born = null, F, k;\n"
"    ranges();\n"
"    if (!E) return;\n"
"    $('livetable').textContent = '';\n"
"    live = {}; liveFor = sel.value;\n"
"    F = new Float64Array(E.memory.buffer, E.pt_wasm_course_in_at(), W.nin);\n"
"    F.set([P.l, P.r, P.b, P.t, P.n], W.in.cam);\n"
"    F.set(mv.map(function (n) { return P[n]; }), W.in.move);\n"
"    if (O.length) {                       /* the operations, the sliders' arguments in */\n"
"      F = new Float64Array(E.memory.buffer, E.pt_wasm_course_ops(O.length), W.cop * O.length);\n"
"      O.forEach(function (o, k) { F.set([o.mul, o.kind].concat(o.a.map(dbl)), W.cop * k); });\n"
"      os.forEach(function (o) {           /* scale S: one slider gives all three */\n"
"        o[2].forEach(function (a) { F[W.cop * o[1] + 2 + a] = P[o[0]]; });\n"
"      });\n"
"    }\n"
"    rc = E.pt_wasm_course_run(R, W.perspective ? 1 : 0, W.nearclip ? 1 : 0, x.v, P.w, P.h,\n"
"                              P.x_ul, P.y_ul, P.W, P.H, O.length ? O.length : -1);\n"
"    if (rc !== 0) {\n"
"      note.textContent = rc === -2 ? 'A clip stage made a colour java.awt.Color refuses ' +\n"
"        '(pipetrace would say so for this scene).' : rc === -3 ? 'No sin and cos for these ' +\n"
"        'angles in this page (it has them for the sliders\\' steps).' :\n"
"        'The stages ran out of memory.';\n"
"      document.body.classList.toggle('live', moved);\n"
"      return;\n"
"    }\n"
"    W.stages.forEach(function (s) {\n"
"      if (!E.pt_wasm_course_have(s.id)) {\n"
"        row(s.name, null, ['none', 'none', 'none', 'none']);\n"
"        return;\n"
"      }\n"
"      if (born === null) born = s.name;\n"
"      var v = [0, 1, 2, 3].map(function (k) { return E.pt_wasm_course_at(s.id, k); });\n"
"      row(s.name, s.coord + ' = (' + v.slice(0, 3).map(num).join(', ') + ')', v.map(hex),\n"
"          s.name === 'world' ? ', w_w = ' + num(v[3]) : '');   /* rows' last row */\n"
"    });\n"
"    W.stages.forEach(function (s) {       /* before the vertex is made: why not */\n"
"      if (live[s.name] === null) {\n"
"        live[s.name] = s.coord + (born === 'nearclip' ? W.notyet[0] : W.notyet[1]);\n"
"        $('livetable').querySelector('[data-stage=\"' + s.name + '\"] td').textContent =\n"
"          live[s.name];\n"
"      }\n"
"    });\n"
"    var px = [0, 1, 2, 3].map(function (k) { return String(E.pt_wasm_course_px(k)); });\n"
"    if (E.pt_wasm_course_px(4)) {\n"
"      row('viewport', '(x_vp, y_vp) = (' + px[0] + ', ' + px[1] + ')', px.slice(0, 2));\n"
"      row('framebuffer', '(x_fb, y_fb) = (' + px[2] + ', ' + px[3] + ')', px.slice(2));\n"
"      var i = E.pt_wasm_course_px(5), x_fb = Number(px[2]), y_fb = Number(px[3]);\n"
"      var out = x_fb < 0 || x_fb >= P.W || y_fb < 0 || y_fb >= P.H;\n"
"      row('index', i < 0 ? 'idx: none, y_fb*W + x_fb lies outside the pixel array (the ' +\n"
"          'course drops the pixel: Bad pixel coordinate)' : 'idx = ' + i + (out ? ' (' +\n"
"          '(x_fb, y_fb) lies outside the framebuffer: y_fb*W + x_fb wraps)' : ''),\n"
"          [i < 0 ? 'none' : String(i)]);\n"
"    } else {\n"
"      row('viewport', W.notyet[2], ['none', 'none']);\n"
"      row('framebuffer', '(x_fb, y_fb): none', ['none', 'none']);\n"
"      row('index', 'idx: none', ['none']);\n"
"    }\n"
"    note.textContent = (moved ? 'Recomputed' : 'Computed') + ' in this page by ' +\n"
"      'pipetrace\\'s own stage files compiled to WebAssembly, for ' + D.models[x.m].name +\n"
"      ' v' + x.v + ' with (l, r, b, t) = (' + [P.l, P.r, P.b, P.t].map(num).join(', ') +\n"
"      '), n = ' + num(P.n) + ', (' + mv.join(', ') + ') = (' +\n"
"      mv.map(function (n) { return num(P[n]); }).join(', ') + ')' +\n"
"      os.map(function (o) { return ', ' + o[0] + ' ' + num(P[o[0]]); }).join('') +\n"
"      ', viewport ' + P.w + ' x ' + P.h + ' at (x_ul, y_ul) = (' + P.x_ul + ', ' + P.y_ul +\n"
"      '), framebuffer ' + P.W + ' x ' + P.H + (moved ?\n"
"      '.  The panel, \"with the numbers\" and \"next\" (dimmed) still show the scene\\'s ' +\n"
"      'own numbers.' : '.');\n"
"    document.body.classList.toggle('live', moved);\n"
"    coords();\n"
"  }\n",
"  function coords() {                     /* the shown panel's #coords */\n"
"    if (moved && liveFor !== sel.value) return run();   /* chosen by the URL */\n"
"    var name = $('stage').textContent, k, want = null;\n"
"    var st = D.stages.map(function (s) { return s.name; }).indexOf(name);\n"
"    var rows = W.show[name] || [];\n"
"    for (k = 0; moved && k < rows.length && want === null; k++)\n"
"      if (live[rows[k]] !== undefined && (k === rows.length - 1 ||\n"
"          E.pt_wasm_course_have(W.ids[rows[k]]))) want = live[rows[k]];\n"
"    put(want, st);\n"
"  }\n"
"  follow(coords);\n"
"  $('reset').addEventListener('click', function () { scene(); moved = false; run(); });\n"
"  ranges();\n"
"  load(names, function () {               /* the model, once: each run copies it */\n"
"    var at = E.pt_wasm_course_in(W.v.length, W.c.length, W.p.length), F, k;\n"
"    if (!at) { note.textContent = 'The model is too large for the sliders.'; return false; }\n"
"    if (W.sincos) {                       /* the host's sin and cos, exact (journey_wasm.c) */\n"
"      F = new Float64Array(E.memory.buffer, E.pt_wasm_table(W.sincos.length),\n"
"                           3 * W.sincos.length);\n"
"      W.sincos.forEach(function (row, j) { F.set(row.map(dbl), 3 * j); });\n"
"    }\n"
"    F = new Float64Array(E.memory.buffer, at, W.nin);\n"
"    F.set(W.m.map(dbl), W.in.matrix);\n"
"    k = W.in.model;\n"
"    W.v.forEach(function (v) { F.set(v.map(dbl), k); k += 4; });\n"
"    W.c.forEach(function (c) { F.set(c.map(dbl), k); k += 3; });\n"
"    W.p.forEach(function (p) { F.set(p, k); k += 6; });\n"
"    return true;\n"
"  });\n"
"})();\n"
"</script>\n",
    NULL
};

/* Append "XXXXXXXXXXXXXXXX", the IEEE bits of x in hex, quoted. */
static void add_bits(pt_sbuf *sb, double x)
{
    uint64_t u;

    memcpy(&u, &x, sizeof u);               /* the same 8 bytes */
    pt_sbuf_addf(sb, "\"%08lx%08lx\"", (unsigned long)(u >> 32), (unsigned long)(u & 0xffffffffu));
}

/* Append [bits of x, of y, of z]. */
static void add_vec(pt_sbuf *sb, pt_vec3 v)
{
    pt_sbuf_add(sb, "[");
    add_bits(sb, v.x);
    pt_sbuf_add(sb, ",");
    add_bits(sb, v.y);
    pt_sbuf_add(sb, ",");
    add_bits(sb, v.z);
    pt_sbuf_add(sb, "]");
}

/* Append ,"NAME":bits of x. */
static void add_named(pt_sbuf *sb, const char *name, double x)
{
    pt_sbuf_addf(sb, ",\"%s\":", name);
    add_bits(sb, x);
}

/* Append the row [argument, sin, cos] for fov, when pt_perspective() calls
** sin and cos for it: the host's libm, the very values pipetrace gets. */
static int add_sincos(pt_sbuf *sb, double fov, int n)
{
    double rad, sn, cs;

    if (!pt_perspective_sincos_arg(fov, &rad, &sn, &cs)) return n;
    pt_sbuf_add(sb, n ? ",[" : "[");
    add_bits(sb, rad);
    pt_sbuf_add(sb, ",");
    add_bits(sb, sin(rad));
    pt_sbuf_add(sb, ",");
    add_bits(sb, cos(rad));
    pt_sbuf_add(sb, n % 4 == 3 ? "]\n" : "]");
    return n + 1;
}

/* The matrix camera's part of the data: its numbers, where the module wants
** them (pt_wasm_in.h), the fov slider's steps and their sin and cos. */
static void add_camera(pt_sbuf *sb, const pt_scene *s)
{
    int k, n = 0;

    pt_sbuf_add(sb, ",\n\"cam\":{\"eye\":");
    add_vec(sb, s->eye);
    pt_sbuf_add(sb, ",\"dir\":");
    add_vec(sb, s->target ? s->at : s->dir);
    pt_sbuf_add(sb, ",\"up\":");
    add_vec(sb, s->up);
    add_named(sb, "fov", s->fov);
    add_named(sb, "aspect", s->aspect);
    add_named(sb, "near", s->znear);
    add_named(sb, "far", s->zfar);
    pt_sbuf_addf(sb, ",\"target\":%s,\"auto\":%s},\n\"in\":{\"world\":%d,\"t\":%d,\"eye\":%d,"
                 "\"dir\":%d,\"up\":%d,\"fov\":%d,\"aspect\":%d,\"near\":%d,\"far\":%d,\"v\":%d},"
                 "\"nin\":%d,\n\"fov\":[%g,%g,%g],\"sincos\":[\n", s->target ? "true" : "false",
                 s->aspect_auto ? "true" : "false", PT_WASM_IN_WORLD, PT_WASM_IN_T,
                 PT_WASM_IN_EYE, PT_WASM_IN_DIR, PT_WASM_IN_UP, PT_WASM_IN_FOV,
                 PT_WASM_IN_ASPECT, PT_WASM_IN_NEAR, PT_WASM_IN_FAR, PT_WASM_IN_V, PT_WASM_NIN,
                 PT_JOURNEY_FOV_STEP, PT_JOURNEY_FOV_STEPS * PT_JOURNEY_FOV_STEP,
                 PT_JOURNEY_FOV_STEP);
    for (k = 1; k <= PT_JOURNEY_FOV_STEPS; k++) n = add_sincos(sb, k * PT_JOURNEY_FOV_STEP, n);
    add_sincos(sb, s->fov, n);              /* the scene's own, perhaps between steps */
    pt_sbuf_add(sb, "]");
}

void pt_journey_wasm(pt_sbuf *sb, const pt_scene *s)
{
    size_t mi, k;
    int i, st, c;
    const pt_stage *ord = pt_scene_pipeline(s)->order;
    int n_st = pt_scene_pipeline(s)->norder;

    pt_sbuf_add(sb, style);
    if (!pt_journey_wasm_b64[0]) { pt_sbuf_add(sb, without); return; }
    pt_sbuf_add(sb, section);
    pt_sbuf_add(sb, "<script type=\"application/json\" id=\"wasmdata\">\n{\"wasm\":\"");
    for (k = 0; pt_journey_wasm_b64[k]; k++) pt_sbuf_add(sb, pt_journey_wasm_b64[k]);
    pt_sbuf_addf(sb, "\",\n\"perspective\":%s,\"matrix\":%s,\"vp\":[%d,%d,%d,%d],\"fb\":[%d,%d],"
                 "\"max\":%d,\"maxv\":%d", s->perspective ? "true" : "false",
                 pt_scene_pipeline(s)->matrices ? "true" : "false", s->vp_w, s->vp_h, s->vp_x, s->vp_y,
                 s->fb_w, s->fb_h, PT_MAX_SIZE, PT_JOURNEY_WASM_MAXV);
    if (pt_scene_pipeline(s)->matrices) add_camera(sb, s);
    pt_sbuf_add(sb, ",\n\"stages\":[");
    for (i = 0; i < n_st; i++) {            /* names and value names: the table's */
        char b[PT_EXPLAINLEN];
        const pt_stage_info *in;

        st = ord[i];
        in = pt_pipeline_info(pt_scene_pipeline(s), st);
        pt_sbuf_add(sb, i ? ",\n{\"name\":" : "{\"name\":");
        pt_sbuf_add_json(sb, in->name);
        pt_sbuf_addf(sb, ",\"id\":%d,\"nreal\":%d,\"nint\":%d,\"coord\":[", st, in->nreal,
                     in->nint);
        for (c = 0; c < 4 && in->coord[c]; c++) {
            if (c) pt_sbuf_add(sb, ",");
            pt_sbuf_add_json(sb, in->coord[c]);
        }
        pt_sbuf_add(sb, "]");
        if (pt_jpipes[pt_scene_pipeline(s)->id].stopped_coords) {   /* past where a point stops */
            pt_jpipes[pt_scene_pipeline(s)->id].stopped_coords(b, sizeof b, (pt_stage)st);
            pt_sbuf_add(sb, ",\"unreached\":");
            pt_sbuf_add_json(sb, b);
        }
        pt_sbuf_add(sb, "}");
    }
    pt_sbuf_add(sb, "],\n\"models\":[");
    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *m = &s->models[mi];
        pt_sbuf_add(sb, mi ? ",\n{\"t\":" : "\n{\"t\":");
        add_vec(sb, m->translate);
        if (pt_scene_pipeline(s)->matrices) {                    /* its `world` lines, as the CLI computed them */
            pt_sbuf_add(sb, ",\"w\":[");
            for (c = 0; c < 16; c++) {
                if (c) pt_sbuf_add(sb, ",");
                add_bits(sb, m->world.m[c / 4][c % 4]);
            }
            pt_sbuf_add(sb, "]");
        }
        pt_sbuf_add(sb, ",\"v\":[");
        for (k = 0; k < m->nv && k < PT_JOURNEY_WASM_MAXV; k++) {
            if (k) pt_sbuf_add(sb, k % 8 ? "," : ",\n");
            add_vec(sb, m->v[k]);
        }
        pt_sbuf_add(sb, "]}");
    }
    pt_sbuf_add(sb, "]}\n</script>\n");
    pt_sbuf_add(sb, prelude);
    for (k = 0; script[k]; k++) pt_sbuf_add(sb, script[k]);
}

/* Renderer 9's rotate sliders: whole degrees from -PT_JOURNEY_ANGLE to
** PT_JOURNEY_ANGLE; the page holds sin and cos for each (and for the
** scene's own angles). */
#define PT_JOURNEY_ANGLE 360
_Static_assert(2 * PT_JOURNEY_ANGLE + 1 + PT_WASM_NCOPS <= PT_WASM_NSINCOS,
               "the module's table holds them");

/* Append the row [argument, sin, cos] for a rotate of theta degrees: the
** argument as stages/r9_matrix.c's rotate computes it, (PI/180.0)*theta
** (a copy: journey_wasm.sh's angle sliders miss the table if it differs),
** sin and cos the host's libm's, the very values pipetrace gets. */
static void add_angle(pt_sbuf *sb, double theta, int first)
{
    double a = (3.141592653589793 / 180.0) * theta;      /* Math.PI/180.0 * theta */

    pt_sbuf_add(sb, first ? "[" : ",[");
    add_bits(sb, a);
    pt_sbuf_add(sb, ",");
    add_bits(sb, sin(a));
    pt_sbuf_add(sb, ",");
    add_bits(sb, cos(a));
    pt_sbuf_add(sb, "]");
}

/* Append ["NAME",[I,...]] per slider of the K-th operation o, each with the
** arguments o->a[I] it gives: a rotate's angle (angle_K), a translate's x,
** y, z (tx_K, ty_K, tz_K), a scale's factor: one (scale_K, all three) when
** the three are equal, as `scale S` gives them, else one each (sx_K, sy_K,
** sz_K), and the 16 entries of rows (a00_K ... a33_K, row by row). */
static void add_op_sliders(pt_sbuf *sb, const pt_matop *o, size_t k)
{
    static const char *const xyz[2][3] = {{"tx", "ty", "tz"}, {"sx", "sy", "sz"}};
    unsigned long K = (unsigned long)k;
    int i;

    switch (o->kind) {
    case PT_MATOP_IDENTITY:
        break;
    case PT_MATOP_ROTATE:
        pt_sbuf_addf(sb, "[\"angle_%lu\",[0]]", K);
        break;
    case PT_MATOP_SCALE:
    case PT_MATOP_TRANSLATE:
        if (o->kind == PT_MATOP_SCALE && o->a[0] == o->a[1] && o->a[1] == o->a[2]) {
            pt_sbuf_addf(sb, "[\"scale_%lu\",[0,1,2]]", K);
            break;
        }
        for (i = 0; i < 3; i++)
            pt_sbuf_addf(sb, "%s[\"%s_%lu\",[%d]]", i ? "," : "",
                         xyz[o->kind == PT_MATOP_SCALE][i], K, i);
        break;
    case PT_MATOP_ROWS:
        for (i = 0; i < 16; i++)
            pt_sbuf_addf(sb, "%s[\"a%d%d_%lu\",[%d]]", i ? "," : "", i / 4, i % 4, K, i);
        break;
    }
}

/* Renderer 9's matrix operations, their sliders (add_op_sliders) and the
** sin and cos table for the angles. */
static void add_ops(pt_sbuf *sb, const pt_jwasm_course *cw)
{
    size_t k;
    int i, n = 0;

    pt_sbuf_addf(sb, ",\n\"cop\":%d,\"angles\":[%d,%d,1],\"ops\":[", PT_WASM_COP,
                 -PT_JOURNEY_ANGLE, PT_JOURNEY_ANGLE);
    for (k = 0; k < cw->nops; k++) {
        const pt_matop *o = &cw->ops[k];
        pt_sbuf_addf(sb, "%s{\"mul\":%d,\"kind\":%d,\"a\":[", k ? ",\n" : "", (int)o->mul,
                     (int)o->kind);
        for (i = 0; i < 16; i++) {
            if (i) pt_sbuf_add(sb, ",");
            add_bits(sb, o->a[i]);
        }
        pt_sbuf_add(sb, "],\"sliders\":[");
        add_op_sliders(sb, o, k + 1);
        pt_sbuf_add(sb, o->kind == PT_MATOP_ROTATE ? "],\"angle\":true}" : "]}");
    }
    pt_sbuf_add(sb, "],\n\"sincos\":[");
    for (i = -PT_JOURNEY_ANGLE; i <= PT_JOURNEY_ANGLE; i++) {
        add_angle(sb, i, n == 0);
        if (++n % 4 == 0) pt_sbuf_add(sb, "\n");
    }
    for (k = 0; k < cw->nops; k++)          /* the scene's own, perhaps between the steps */
        if (cw->ops[k].kind == PT_MATOP_ROTATE) add_angle(sb, cw->ops[k].a[0], 0);
    pt_sbuf_add(sb, "]");
}

/* The course's stages the page's table shows, in order, and which of them
** each panel's #coords shows (the first that has the vertex). */
static const struct { const char *name; int id; } course_rows[] = {
    {"model", PT_CST_MODEL}, {"world", PT_CST_WORLD}, {"view", PT_CST_VIEW},
    {"camera", PT_CST_CAMERA}, {"nearclip", PT_CST_NEARCLIP}, {"image", PT_CST_IMAGE},
    {"clip", PT_CST_CLIP}
};
_Static_assert((int)PT_WASM_CST_MODEL == (int)PT_CST_MODEL &&
               (int)PT_WASM_CST_WORLD == (int)PT_CST_WORLD &&
               (int)PT_WASM_CST_VIEW == (int)PT_CST_VIEW &&
               (int)PT_WASM_CST_CAMERA == (int)PT_CST_CAMERA &&
               (int)PT_WASM_CST_NEARCLIP == (int)PT_CST_NEARCLIP &&
               (int)PT_WASM_CST_IMAGE == (int)PT_CST_IMAGE &&
               (int)PT_WASM_CST_CLIP == (int)PT_CST_CLIP && (int)PT_NCOURSE == PT_NCST,
               "the module numbers the course's stages as core/course.h");

static const char course_show[] =
"\"show\":{\"model\":[\"model\"],\"world\":[\"world\"],\"view\":[\"view\"],"
"\"volume\":[\"view\"],\"camera\":[\"camera\"],\"nearclip\":[\"nearclip\"],"
"\"image\":[\"image\",\"clip\"],\"viewport\":[\"viewport\"]}";

void pt_journey_wasm_course(pt_sbuf *sb, const pt_scene *s, const pt_jwasm_course *cw)
{
    const pt_cx_journey *j = cw->j;
    const pt_rv_model *m = cw->m;
    size_t k, i;
    int c;

    pt_sbuf_add(sb, style);
    if (!pt_journey_wasm_b64[0]) { pt_sbuf_add(sb, without); return; }
    if (!m || m->nv > PT_JOURNEY_WASM_MAXV || m->np > PT_JOURNEY_WASM_MAXV ||
        m->nc > PT_JOURNEY_WASM_MAXV) {
        pt_sbuf_add(sb, "<section id=\"live\" data-wasm=\"yes\"><h2>recompute</h2>\n"
                    "<p id=\"livenote\">No sliders for this position: its model is hidden or "
                    "larger than the page runs.</p>\n</section>\n");
        return;
    }
    pt_sbuf_add(sb, section);
    pt_sbuf_add(sb, "<script type=\"application/json\" id=\"wasmdata\">\n{\"wasm\":\"");
    for (k = 0; pt_journey_wasm_b64[k]; k++) pt_sbuf_add(sb, pt_journey_wasm_b64[k]);
    pt_sbuf_addf(sb, "\",\n\"renderer\":%d,\"perspective\":%s,\"nearclip\":%s,"
                 "\"vp\":[%d,%d,%d,%d],\"fb\":[%d,%d],\"max\":%d,\"cam\":[", s->renderer,
                 j->cam.cam.perspective ? "true" : "false", s->nearclip ? "true" : "false",
                 s->vp_w, s->vp_h, s->vp_x, s->vp_y, s->fb_w, s->fb_h, PT_MAX_SIZE);
    add_bits(sb, j->cam.cam.l); pt_sbuf_add(sb, ",");
    add_bits(sb, j->cam.cam.r); pt_sbuf_add(sb, ",");
    add_bits(sb, j->cam.cam.b); pt_sbuf_add(sb, ",");
    add_bits(sb, j->cam.cam.t); pt_sbuf_add(sb, ",");
    add_bits(sb, j->cam.cam.n);
    pt_sbuf_add(sb, "],\"move\":");
    add_vec(sb, s->renderer == 9 ? j->cam.cam.view : j->translate);
    pt_sbuf_add(sb, ",\"m\":[");
    for (c = 0; c < 16; c++) {              /* r9: the position's matrix, column by column */
        pt_vec4 col = j->matrix.col[c / 4];
        double x = c % 4 == 0 ? col.x : c % 4 == 1 ? col.y : c % 4 == 2 ? col.z : col.w;
        if (c) pt_sbuf_add(sb, ",");
        add_bits(sb, x);
    }
    pt_sbuf_add(sb, "]");
    if (s->renderer == 9 && cw->nops <= PT_WASM_NCOPS) add_ops(sb, cw);
    pt_sbuf_addf(sb, ",\n\"in\":{\"cam\":%d,\"move\":%d,\"matrix\":%d,\"model\":%d},"
                 "\"nin\":%llu,\n\"notyet\":[", PT_WASM_CIN_L, PT_WASM_CIN_MOVE,
                 PT_WASM_CIN_MATRIX, PT_WASM_CIN_MODEL,
                 (unsigned long long)(PT_WASM_CIN_MODEL + 4 * m->nv + 3 * m->nc + 6 * m->np));
    for (c = 0; c < 3; c++) {
        if (c) pt_sbuf_add(sb, ",");
        pt_sbuf_add_json(sb, cw->text[c]);
    }
    pt_sbuf_add(sb, "],\n");
    pt_sbuf_add(sb, course_show);
    pt_sbuf_add(sb, ",\n\"stages\":[");
    for (i = c = 0; i < sizeof course_rows / sizeof course_rows[0]; i++) {
        if (course_rows[i].id == PT_CST_WORLD && s->renderer != 9) continue;
        pt_sbuf_addf(sb, "%s{\"name\":\"%s\",\"id\":%d,\"coord\":", c++ ? "," : "",
                     course_rows[i].name, course_rows[i].id);
        pt_sbuf_add_json(sb, cw->label[course_rows[i].id]);
        pt_sbuf_add(sb, "}");
    }
    pt_sbuf_add(sb, "],\"ids\":{");
    for (i = 0; i < sizeof course_rows / sizeof course_rows[0]; i++)
        pt_sbuf_addf(sb, "%s\"%s\":%d", i ? "," : "", course_rows[i].name, course_rows[i].id);
    pt_sbuf_add(sb, "},\n\"v\":[");
    for (k = 0; k < m->nv; k++) {
        pt_sbuf_add(sb, k ? (k % 4 ? ",[" : ",\n[") : "[");
        add_bits(sb, m->v[k].x); pt_sbuf_add(sb, ",");
        add_bits(sb, m->v[k].y); pt_sbuf_add(sb, ",");
        add_bits(sb, m->v[k].z); pt_sbuf_add(sb, ",");
        add_bits(sb, m->v[k].w); pt_sbuf_add(sb, "]");
    }
    pt_sbuf_add(sb, "],\n\"c\":[");
    for (k = 0; k < m->nc; k++) {           /* each float, exact as a double */
        pt_sbuf_add(sb, k ? (k % 4 ? ",[" : ",\n[") : "[");
        add_bits(sb, (double)m->c[k].r); pt_sbuf_add(sb, ",");
        add_bits(sb, (double)m->c[k].g); pt_sbuf_add(sb, ",");
        add_bits(sb, (double)m->c[k].b); pt_sbuf_add(sb, "]");
    }
    pt_sbuf_add(sb, "],\n\"p\":[");
    for (k = 0; k < m->np; k++) {
        const pt_rv_prim *p = &m->p[k];
        pt_sbuf_addf(sb, "%s[%d,%lu,%lu,%lu,%lu,%d]", k ? (k % 8 ? "," : ",\n") : "",
                     p->kind == PT_RV_POINT, (unsigned long)p->v[0], (unsigned long)p->v[1],
                     (unsigned long)p->c[0], (unsigned long)p->c[1], p->radius);
    }
    pt_sbuf_add(sb, "]}\n</script>\n");
    pt_sbuf_add(sb, prelude);
    for (k = 0; course_script[k]; k++) pt_sbuf_add(sb, course_script[k]);
}
