/*
** src/tools/journey/journey_wasm.c -- the journey page's sliders, recomputed by the stages in WebAssembly
** See LICENSE for copyright and license.
**
** The numbers go to the page exact: every double as the 16 hex digits of its
** IEEE bits, so that the module gets the very doubles pipetrace read from
** the scene; a slider's value is the decimal text the browser gives it,
** read by JavaScript's Number(), correctly rounded like pipetrace's reader.
*/
#include <string.h>
#include "tools/journey/journey.h"
#include "tools/journey/journey_wasm.h"

#define PT_JOURNEY_WASM_MAXV 100000  /* a model's first this many vertices get sliders */

static const char style[] =
"<style>\n"
"#live{margin:0 20px 18px;padding:8px 14px;background:#fff;border:1px solid #e3e6eb;"
"border-radius:4px}\n"
"#live h2{font-size:12px;text-transform:uppercase;letter-spacing:.06em;color:#5f6670;"
"margin:6px 0}\n"
"#sliders{display:grid;grid-template-columns:repeat(auto-fill,minmax(230px,1fr));gap:4px 16px}\n"
"#sliders label{display:flex;align-items:center;gap:6px;font-size:14px}\n"
"#sliders input{flex:1}\n"
"#sliders output{font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;min-width:4.5em}\n"
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

static const char matrix_camera[] =
"<section id=\"live\" data-wasm=\"no\"><h2>recompute</h2>\n"
"<p id=\"livenote\">No sliders on this page: they rerun the classic camera's stages, "
"and this scene has the matrix camera (camera lookat).</p>\n</section>\n";

static const char section[] =
"<section id=\"live\" data-wasm=\"yes\"><h2>recompute</h2>\n"
"<div id=\"sliders\"></div>\n"
"<p><button type=\"button\" id=\"reset\">Reset to the scene</button></p>\n"
"<p id=\"livenote\">Loading the stages (WebAssembly) ...</p>\n"
"<table id=\"livetable\"></table>\n"
"</section>\n";

/* The script, in pieces (C11 promises string literals of 4095 bytes). */
static const char *const script[] = {
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
"  var T = W.models.map(function (m) { return m.t.map(dbl); });   /* live translations */\n"
"  var P = {}, names = ['x_t', 'y_t', 'z_t', 'w', 'h', 'x_ul', 'y_ul', 'W', 'H'];\n"
"  function scene() { P = {w: W.vp[0], h: W.vp[1], x_ul: W.vp[2], y_ul: W.vp[3],\n"
"                          W: W.fb[0], H: W.fb[1]}; }\n"
"  scene();\n"
"  function vertex() { return D.vertices[Number(sel.value)] || D.vertices[D.start]; }\n"
"  function slider(n) { return $('s_' + n); }\n"
"  names.forEach(function (n, k) {\n"
"    var l = document.createElement('label'), i = document.createElement('input'),\n"
"        o = document.createElement('output');\n"
"    i.type = 'range'; i.id = 's_' + n; i.disabled = true;\n"
"    o.id = 'o_' + n;\n"
"    l.appendChild(document.createTextNode(n)); l.appendChild(i); l.appendChild(o);\n"
"    $('sliders').appendChild(l);\n"
"    i.addEventListener('keydown', function (e) { e.stopPropagation(); });  /* arrows: its own */\n"
"    i.addEventListener('input', function () {\n"
"      if (k < 3) T[vertex().m][k] = Number(i.value); else P[n] = Number(i.value);\n"
"      moved = true;\n"
"      run();\n"
"    });\n"
"  });\n",
"  function ranges() {                     /* the scene's limits: viewport inside */\n"
"    var t = T[vertex().m], k, i;\n"
"    P.W = Math.min(Math.max(P.W, 1), W.max); P.H = Math.min(Math.max(P.H, 1), W.max);\n"
"    P.w = Math.min(Math.max(P.w, 1), P.W); P.h = Math.min(Math.max(P.h, 1), P.H);\n"
"    P.x_ul = Math.min(Math.max(P.x_ul, 0), P.W - P.w);\n"
"    P.y_ul = Math.min(Math.max(P.y_ul, 0), P.H - P.h);\n"
"    var lim = {w: [1, P.W], h: [1, P.H], x_ul: [0, P.W - P.w], y_ul: [0, P.H - P.h],\n"
"               W: [1, Math.min(W.max, Math.max(4 * W.fb[0], 256))],\n"
"               H: [1, Math.min(W.max, Math.max(4 * W.fb[1], 256))]};\n"
"    for (k = 0; k < 3; k++) {\n"
"      var c = Math.abs(t[k]) < 1e6 ? Math.floor(t[k]) : 0;\n"
"      i = slider(names[k]);\n"
"      i.min = String(c - 5); i.max = String(c + 5); i.step = '0.05';\n"
"      if (Number(i.value) !== t[k]) i.value = String(t[k]);\n"
"      $('o_' + names[k]).textContent = num(t[k]);\n"
"    }\n"
"    for (k = 3; k < names.length; k++) {\n"
"      var n = names[k];\n"
"      i = slider(n);\n"
"      i.min = String(lim[n][0]); i.max = String(lim[n][1]); i.step = '1';\n"
"      i.value = String(P[n]);\n"
"      $('o_' + n).textContent = String(P[n]);\n"
"    }\n"
"  }\n"
"  function text(st, vals) {               /* as pipetrace explain writes #coords */\n"
"    var s = W.stages[st], shown = vals.map(function (x) { return x === null ? 'none' : x; });\n"
"    var any = vals.some(function (x) { return x !== null; });\n"
"    if (s.coord.length === 1) return s.coord[0] + ' = ' + shown[0];\n"
"    return '(' + s.coord.join(', ') + ') = ' + (any ? '(' + shown.join(', ') + ')' : 'none');\n"
"  }\n"
"  var live = [], liveFor = null;         /* the values of vertex liveFor */\n",
"  function run() {\n"
"    var x = vertex(), vm = W.models[x.m].v[x.v - 1], t = T[x.m], st, k;\n"
"    ranges();\n"
"    if (!E) return;\n"
"    $('livetable').textContent = '';\n"
"    live = []; liveFor = sel.value;\n"
"    if (!vm) { note.textContent = 'No sliders for this vertex (beyond the first ' +\n"
"               W.maxv + ' of its model).'; return; }\n"
"    vm = vm.map(dbl);\n"
"    if (E.pt_wasm_run(vm[0], vm[1], vm[2], t[0], t[1], t[2], W.perspective ? 1 : 0,\n"
"                      P.w, P.h, P.x_ul, P.y_ul, P.W, P.H) !== 0) return;\n"
"    for (st = 0; st < W.stages.length; st++) {\n"
"      var s = W.stages[st], vals = [], bits = [];\n"
"      for (k = 0; k < s.nreal; k++) {\n"
"        var r = E.pt_wasm_real(st, k);\n"
"        vals.push(num(r)); bits.push(hex(r));\n"
"      }\n"
"      for (k = 0; k < s.nint; k++) {\n"
"        var i = E.pt_wasm_has(st, k) ? String(E.pt_wasm_int(st, k)) : null;\n"
"        vals.push(i); bits.push(i === null ? 'none' : i);\n"
"      }\n"
"      live.push(text(st, vals));\n"
"      var tr = document.createElement('tr'), th = document.createElement('th'),\n"
"          td = document.createElement('td');\n"
"      tr.dataset.stage = s.name; th.textContent = s.name; td.textContent = live[st];\n"
"      td.dataset.values = bits.join(',');\n"
"      tr.appendChild(th); tr.appendChild(td); $('livetable').appendChild(tr);\n"
"    }\n"
"    note.textContent = (moved ? 'Recomputed' : 'Computed') + ' in this page by ' +\n"
"      'pipetrace\\'s own stage files compiled to WebAssembly, for ' + D.models[x.m].name +\n"
"      ' v' + x.v + ' with (x_t, y_t, z_t) = (' + t.map(num).join(', ') + '), viewport ' +\n"
"      P.w + ' x ' + P.h + ' at (x_ul, y_ul) = (' + P.x_ul + ', ' + P.y_ul + '), framebuffer ' +\n"
"      P.W + ' x ' + P.H + (moved ? '.  The panel, \"with the numbers\" and \"next\" (dimmed) ' +\n"
"      'still show the scene\\'s own numbers.' : '.');\n"
"    document.body.classList.toggle('live', moved);\n"
"    coords();\n"
"  }\n",
"  function coords() {                     /* the shown stage's #coords */\n"
"    if (moved && liveFor !== sel.value) return run();   /* chosen by the URL */\n"
"    var c = $('coords'), st = W.stages.map(function (s) { return s.name; })\n"
"                                 .indexOf($('stage').textContent);\n"
"    var want = moved && live[st] !== undefined ? live[st] : null;\n"
"    if (want === null && st >= 0) want = vertex().coords[st];\n"
"    if (want !== null && want !== undefined && c.textContent !== want) c.textContent = want;\n"
"  }\n"
"  new MutationObserver(coords).observe($('coords'), {childList: true, characterData: true,\n"
"                                                     subtree: true});\n"
"  sel.addEventListener('change', run);\n"
"  $('reset').addEventListener('click', function () {\n"
"    T = W.models.map(function (m) { return m.t.map(dbl); });\n"
"    scene(); moved = false; run();\n"
"  });\n"
"  ranges();\n"
"  var b = atob(W.wasm), bytes = new Uint8Array(b.length), k;\n"
"  for (k = 0; k < b.length; k++) bytes[k] = b.charCodeAt(k);\n"
"  WebAssembly.instantiate(bytes).then(function (r) {\n"
"    E = r.instance.exports;\n"
"    names.forEach(function (n) { slider(n).disabled = false; });\n"
"    run();\n"
"    sec.dataset.ready = '1';\n"
"  }, function (e) { note.textContent = 'The stages (WebAssembly) did not load: ' + e; });\n"
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

void pt_journey_wasm(pt_sbuf *sb, const pt_scene *s)
{
    size_t mi, k;
    int st, c;

    pt_sbuf_add(sb, style);
    if (s->matrix) { pt_sbuf_add(sb, matrix_camera); return; }
    if (!pt_journey_wasm_b64[0]) { pt_sbuf_add(sb, without); return; }
    pt_sbuf_add(sb, section);
    pt_sbuf_add(sb, "<script type=\"application/json\" id=\"wasmdata\">\n{\"wasm\":\"");
    for (k = 0; pt_journey_wasm_b64[k]; k++) pt_sbuf_add(sb, pt_journey_wasm_b64[k]);
    pt_sbuf_addf(sb, "\",\n\"perspective\":%s,\"vp\":[%d,%d,%d,%d],\"fb\":[%d,%d],\"max\":%d,"
                 "\"maxv\":%d,\n\"stages\":[", s->perspective ? "true" : "false",
                 s->vp_w, s->vp_h, s->vp_x, s->vp_y, s->fb_w, s->fb_h, PT_MAX_SIZE,
                 PT_JOURNEY_WASM_MAXV);
    for (st = 0; st < PT_NSTAGES; st++) {          /* names and value names: the table's */
        const pt_stage_info *in = &pt_stage_infos[st];
        pt_sbuf_add(sb, st ? ",{\"name\":" : "{\"name\":");
        pt_sbuf_add_json(sb, in->name);
        pt_sbuf_addf(sb, ",\"nreal\":%d,\"nint\":%d,\"coord\":[", in->nreal, in->nint);
        for (c = 0; c < 4 && in->coord[c]; c++) {
            if (c) pt_sbuf_add(sb, ",");
            pt_sbuf_add_json(sb, in->coord[c]);
        }
        pt_sbuf_add(sb, "]}");
    }
    pt_sbuf_add(sb, "],\n\"models\":[");
    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *m = &s->models[mi];
        pt_sbuf_add(sb, mi ? ",\n{\"t\":" : "\n{\"t\":");
        add_vec(sb, m->translate);
        pt_sbuf_add(sb, ",\"v\":[");
        for (k = 0; k < m->nv && k < PT_JOURNEY_WASM_MAXV; k++) {
            if (k) pt_sbuf_add(sb, k % 8 ? "," : ",\n");
            add_vec(sb, m->v[k]);
        }
        pt_sbuf_add(sb, "]}");
    }
    pt_sbuf_add(sb, "]}\n</script>\n");
    for (k = 0; script[k]; k++) pt_sbuf_add(sb, script[k]);
}
