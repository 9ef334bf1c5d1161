/*
** src/tools/journey/journey_html.c -- the journey as one self-contained HTML page
** See LICENSE for copyright and license.
**
** The page holds everything it shows: the panels as SVG fragments (one
** background per model and stage, one foreground per vertex and stage, see
** journey.h), the numbers and formulas of every listed vertex as a JSON blob
** in a <script type="application/json">, and a small script that puts one
** stage on screen at a time.  No network, no other file: it works opened
** from disk.
**
** What the page offers (ids for the tests and for people who script it):
**   #prev, #next      buttons: the stage before and after
**   #vertex           <select>: every used vertex of the scene (at most
**                     PT_JOURNEY_MAXV), "MODEL vN"
**   #stage            the current stage's trace name ("camera")
**   #coords           its values as pt_explain_values() writes them, numbers
**                     as the JSONL trace writes them (shortest round trip)
**   #formula          the formula with the numbers put in (pt_explain_stage)
**   #after            what the next stage will do with the result
** The URL fragment chooses what is shown first: #v=N&m=MODEL&stage=K (K is
** 1..7 or a stage name; m defaults to the model first shown).
** tests/journey/journey_clicks.html drives the page through these ids from outside.
*/
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey.h"
#include "tools/journey/jpanel.h"
#include "tools/journey/journey_wasm.h"

/* The page scales with the window: type in rem, the root's size following the
** window's width; the panel takes three fifths of the width (all of it below
** 800 pixels) and at most the window's height.  Presenter mode (html.present)
** hides the controls and sets the type larger. */
static const char style[] =
"html{font-size:clamp(14px,1.15vw,24px)}\n"
"html.present{font-size:clamp(18px,2vw,44px)}\n"
"body{font-family:'DejaVu Sans',Helvetica,Arial,sans-serif;margin:0;background:#f3f4f6;"
"color:#222}\n"
"header{padding:.9rem 1.3rem .25rem}\n"
"h1{font-size:1.4rem;margin:0 0 .25rem}\n"
"#where{color:#5f6670;margin:0;font-size:.95rem}\n"
"nav{display:flex;flex-wrap:wrap;gap:.6rem;align-items:center;padding:.5rem 1.3rem}\n"
"nav button{font-size:1rem;padding:.3rem .9rem;cursor:pointer}\n"
"#stagenum{min-width:7em;text-align:center}\n"
"#stages{display:flex;flex-wrap:wrap;gap:.3rem;list-style:none;padding:0 1.3rem;margin:.25rem 0}\n"
"#stages button{border:1px solid #c9ced6;background:#fff;border-radius:4px;"
"padding:.2rem .6rem;cursor:pointer;font-size:.85rem}\n"
"#stages button.on{background:#d62728;color:#fff;border-color:#d62728}\n"
"main{display:grid;grid-template-columns:minmax(0,3fr) minmax(0,2fr);gap:1.2rem;"
"padding:.5rem 1.3rem 1.5rem;align-items:start}\n"
"@media (max-width:800px){main{grid-template-columns:minmax(0,1fr)}}\n"
"#panel svg{width:100%;height:auto;max-height:calc(100vh - 1rem);display:block}\n"
"aside{min-width:0}\n"
"aside h2{font-size:.8rem;text-transform:uppercase;letter-spacing:.06em;color:#5f6670;"
"margin:1rem 0 .25rem}\n"
".mono{font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;white-space:pre-wrap;margin:0}\n"
".expr{white-space:nowrap}\n"
"#coords{font-size:1.1rem;font-weight:bold;overflow-x:auto}\n"
"#general,#formula{overflow-x:auto}\n"
"#formula{font-size:.95rem;background:#fff;border:1px solid #e3e6eb;padding:.5rem;"
"border-radius:4px}\n"
"#stage{font-weight:bold}\n"
"footer{color:#5f6670;font-size:.8rem;padding:0 1.3rem 1.3rem}\n"
"html.present header,html.present nav,html.present #stages,html.present footer,"
"html.present #live{display:none}\n"
"html.present main{grid-template-columns:minmax(0,1fr);justify-items:center;gap:.4rem;"
"padding:.5rem 1rem}\n"
"html.present #panel svg{height:66vh;width:auto;max-width:100%}\n"
"html.present aside{max-width:100%}\n"
"html.present aside>:not(#coords):not(#formula){display:none}\n"
"html.present #formula{font-size:1rem}\n";

static const char body[] =
"<header>\n"
"<h1 id=\"title\">pipetrace journey</h1>\n"
"<p id=\"where\"></p>\n"
"</header>\n"
"<nav>\n"
"<button type=\"button\" id=\"prev\">&#9664; Prev</button>\n"
"<span id=\"stagenum\"></span>\n"
"<button type=\"button\" id=\"next\">Next &#9654;</button>\n"
"<label>vertex <select id=\"vertex\"></select></label>\n"
"<button type=\"button\" id=\"present\" title=\"P; Escape leaves\">Present</button>\n"
"</nav>\n"
"<ol id=\"stages\"></ol>\n"
"<noscript><p>This page needs JavaScript to show the stages.</p></noscript>\n"
"<main>\n"
"<div id=\"panel\"></div>\n"
"<aside>\n"
"<h2>stage</h2><p><span id=\"stage\"></span>: <span id=\"spaces\"></span></p>\n"
"<p id=\"what\"></p>\n"
"<h2>coordinates</h2><p id=\"coords\" class=\"mono\"></p>\n"
"<h2>formula</h2><p id=\"general\" class=\"mono\"></p>\n"
"<h2>with the numbers</h2><p id=\"formula\" class=\"mono\"></p>\n"
"<h2>next</h2><p id=\"after\"></p>\n"
"</aside>\n"
"</main>\n"
"<footer id=\"foot\">In the panels: red, the vertex (an arrow at the edge when it lies off "
"the panel); blue, the segments that use it and the pixels they light; grey, the rest of "
"its model, and in the framebuffer the whole frame, every model's pixels.  Keys: left and right arrows (or Page Up and Page Down, Space) move between "
"stages, Home and End go to the first and the last, P shows one panel large for a projector "
"(presenter mode), Escape leaves it.  Numbers are the shortest "
"decimals that read back to the same double, as in the trace (pipetrace --format jsonl)."
"</footer>\n";

/* The page's script, in pieces (C11 promises string literals of 4095 bytes). */
static const char *const script[] = {
"(function () {\n"
"  'use strict';\n"
"  var D = JSON.parse(document.getElementById('data').textContent);\n"
"  function $(id) { return document.getElementById(id); }\n"
"  var sel = $('vertex'), cur = D.start, st = 0, n = D.stages.length;\n"
"  function vname(x) { return D.models[x.m].name + ' v' + x.v; }\n"
"  D.vertices.forEach(function (x, k) {\n"
"    var o = document.createElement('option');\n"
"    o.value = String(k);\n"
"    o.textContent = vname(x) + (x.used ? '' : ' (used by no segment)');\n"
"    sel.appendChild(o);\n"
"  });\n"
"  D.stages.forEach(function (s, k) {\n"
"    var li = document.createElement('li'), b = document.createElement('button');\n"
"    b.type = 'button';\n"
"    b.id = 'go' + (k + 1);\n"
"    b.textContent = (k + 1) + ' ' + s.title;\n"
"    b.addEventListener('click', function () { st = k; show(); });\n"
"    li.appendChild(b);\n"
"    $('stages').appendChild(li);\n"
"  });\n"
"  $('where').textContent = D.where + (D.capped ? ' (the first ' + D.vertices.length +\n"
"    ' of ' + D.total + ' used vertices are listed)' : '');\n"
"  /* Text as spans of class expr that never wrap: lines break only between\n"
"  ** the expressions of a chain (' = ') or a list (', '), outside parentheses;\n"
"  ** the text itself stays as it was. */\n"
"  function exprs(el, text) {\n"
"    var depth = 0, from = 0, k, cut = [], sep;\n"
"    el.textContent = '';\n"
"    for (k = 0; k < text.length; k++) {\n"
"      var c = text.charAt(k);\n"
"      if (c === '(') depth++;\n"
"      else if (c === ')') depth--;\n"
"      sep = c === '\\n' ? 1 : depth === 0 && text.substr(k, 3) === ' = ' ? 3 :\n"
"            depth === 0 && text.substr(k, 2) === ', ' ? 2 : 0;\n"
"      if (sep) { cut.push([from, k, text.substr(k, sep)]); from = k + sep; k += sep - 1; }\n"
"    }\n"
"    cut.push([from, text.length, '']);\n"
"    cut.forEach(function (c) {\n"
"      var sp = document.createElement('span');\n"
"      sp.className = 'expr';\n"
"      sp.textContent = text.slice(c[0], c[1]);\n"
"      el.appendChild(sp);\n"
"      if (c[2]) el.appendChild(document.createTextNode(c[2]));\n"
"    });\n"
"  }\n"
"  function show() {\n"
"    var x = D.vertices[cur], s = D.stages[st];\n"
"    $('panel').innerHTML = '<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ' +\n"
"      D.panel[0] + ' ' + D.panel[1] + '\" font-family=\"' + D.font + '\">' +\n"
"      D.models[x.m].bg[st] + x.fg[st] + '</svg>';\n"
"    $('title').textContent = 'pipetrace journey: ' + vname(x);\n"
"    document.title = 'pipetrace journey: ' + vname(x) + ', ' + s.name;\n"
"    $('stage').textContent = s.name;\n"
"    $('stagenum').textContent = 'stage ' + (st + 1) + ' of ' + n;\n"
"    $('spaces').textContent = s.title + ', from ' + s.from + ' to ' + s.to;\n"
"    $('what').textContent = s.what;\n"
"    exprs($('coords'), x.coords[st]);\n"
"    exprs($('general'), s.formula);\n"
"    exprs($('formula'), x.here[st]);\n"
"    $('after').textContent = x.next[st];\n"
"    $('prev').disabled = st === 0;\n"
"    $('next').disabled = st === n - 1;\n"
"    sel.value = String(cur);\n"
"    for (var k = 0; k < n; k++) $('go' + (k + 1)).className = k === st ? 'on' : '';\n"
"  }\n"
"  $('prev').addEventListener('click', function () { if (st > 0) { st--; show(); } });\n"
"  $('next').addEventListener('click', function () { if (st < n - 1) { st++; show(); } });\n"
"  sel.addEventListener('change', function () { cur = Number(sel.value); show(); });\n"
"  function present(on) {\n"
"    document.documentElement.classList.toggle('present', on);\n"
"  }\n"
"  $('present').addEventListener('click', function () { present(true); });\n"
"  document.addEventListener('keydown', function (e) {\n"
"    var t = e.target, k = e.key;\n"
"    if (t === sel || (t && t.tagName === 'INPUT') || e.ctrlKey || e.altKey || e.metaKey) return;\n"
"    if (k === 'ArrowLeft' || k === 'PageUp') { if (st > 0) { st--; show(); } }\n"
"    else if (k === 'ArrowRight' || k === 'PageDown' || k === ' ') {\n"
"      if (st < n - 1) { st++; show(); }\n"
"    } else if (k === 'Home') { st = 0; show(); }\n"
"    else if (k === 'End') { st = n - 1; show(); }\n"
"    else if (k === 'p' || k === 'P') present(!document.documentElement.classList.contains('present'));\n"
"    else if (k === 'Escape') present(false);\n"
"    else return;\n"
"    e.preventDefault();\n"
"  });\n",
"  function fromHash() {\n"
"    var q = {};\n"
"    location.hash.replace(/^#/, '').split('&').forEach(function (p) {\n"
"      var e = p.indexOf('=');\n"
"      if (p) q[e < 0 ? p : p.slice(0, e)] = e < 0 ? '' : decodeURIComponent(p.slice(e + 1));\n"
"    });\n"
"    if (q.v !== undefined) {\n"
"      var want = Number(q.v), m = q.m, home = D.vertices[cur].m, other = -1, k;\n"
"      for (k = 0; k < D.vertices.length; k++) {\n"
"        var x = D.vertices[k];\n"
"        if (x.v !== want) continue;\n"
"        if (m !== undefined ? D.models[x.m].name === m : x.m === home) break;\n"
"        if (other < 0 && m === undefined) other = k;\n"
"      }\n"
"      if (k < D.vertices.length) cur = k; else if (other >= 0) cur = other;\n"
"    }\n"
"    if (q.present !== undefined) present(true);\n"
"    if (q.stage !== undefined) {\n"
"      var t = Number(q.stage);\n"
"      if (!(t >= 1 && t <= n)) t = D.stages.map(function (s) { return s.name; })\n"
"                                   .indexOf(q.stage) + 1;\n"
"      if (t >= 1) st = t - 1;\n"
"    }\n"
"  }\n",
"  fromHash();\n"
"  show();\n"
"  window.addEventListener('hashchange', function () { fromHash(); show(); });\n"
"})();\n",
    NULL
};

void pt_journey_page_head(pt_sbuf *sb, const char *model, uint64_t v)
{
    pt_sbuf_add(sb, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                "<title>pipetrace journey: ");
    pt_sbuf_add_xml(sb, model);
    pt_sbuf_addf(sb, " v%llu</title>\n<style>\n", (unsigned long long)v);
    pt_sbuf_add(sb, style);
    pt_sbuf_add(sb, "</style>\n</head>\n<body>\n");
    pt_sbuf_add(sb, body);
}

void pt_journey_page_stage(pt_sbuf *sb, int k, const char *name, const char *title,
                           const char *from, const char *to, const char *formula,
                           const char *what)
{
    pt_sbuf_add(sb, k ? ",\n{\"name\":" : "{\"name\":");
    pt_sbuf_add_json(sb, name);
    pt_sbuf_add(sb, ",\"title\":");
    pt_sbuf_add_json(sb, title);
    pt_sbuf_add(sb, ",\"from\":");
    pt_sbuf_add_json(sb, from);
    pt_sbuf_add(sb, ",\"to\":");
    pt_sbuf_add_json(sb, to);
    pt_sbuf_add(sb, ",\"formula\":");
    pt_sbuf_add_json(sb, formula ? formula : "");
    pt_sbuf_add(sb, ",\"what\":");
    pt_sbuf_add_json(sb, what);
    pt_sbuf_add(sb, "}");
}

void pt_journey_page_script(pt_sbuf *sb)
{
    int k;

    pt_sbuf_add(sb, "<script>\n");
    for (k = 0; script[k]; k++) pt_sbuf_add(sb, script[k]);
    pt_sbuf_add(sb, "</script>\n");
}

/* One vertex listed on the page. */
typedef struct item {
    size_t m;                    /* model index */
    uint64_t v;                  /* 1-based vertex */
    int used;                    /* some segment uses it */
} item;

/* Append ["a","b",...] of the camera's stages' texts of one kind for vertex
** it (the matrix camera's stages past the cvv of a vertex outside: a note). */
static void texts(pt_sbuf *sb, const pt_jmodel *jm, const item *it, int kind)
{
    char b[PT_EXPLAINLEN];
    pt_journey j;
    int i, st;

    j = *pt_jmodel_journey(jm, (size_t)(it->v - 1));
    pt_sbuf_add(sb, "[");
    for (i = 0; i < j.pipe->norder; i++) {
        st = j.pipe->order[i];
        if (i) pt_sbuf_add(sb, ",");
        if (pt_journey_stopped(&j, st) && jm->rows->stopped_coords) {
            if (kind == 0) jm->rows->stopped_coords(b, sizeof b, (pt_stage)st);
            else if (kind == 1) jm->rows->stopped_note(b, sizeof b, &j, (pt_stage)st);
            else b[0] = '\0';
        } else if (kind == 0) pt_explain_values(b, sizeof b, &j, (pt_stage)st);
        else if (kind == 1) pt_explain_stage(b, sizeof b, &j, (pt_stage)st, "\n");
        else pt_explain_next(b, sizeof b, &j, (pt_stage)st);
        pt_sbuf_add_json(sb, b);
    }
    pt_sbuf_add(sb, "]");
}

int pt_journey_html(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t v,
                    const unsigned char *pick)
{
    size_t mi, k, n = 0, total = 0, start = 0, first;
    item *items = malloc((PT_JOURNEY_MAXV + 1) * sizeof *items);
    pt_jmodel *jms = calloc(s->nmodels ? s->nmodels : 1, sizeof *jms);
    unsigned char *has = calloc(s->nmodels ? s->nmodels : 1, 1), *used = NULL;
    pt_sbuf t;
    const pt_fb *frame = NULL;
    int i, rc = -1, found = 0;
    int n_st = pt_scene_pipeline(s)->norder;
    const pt_stage *ord = pt_scene_pipeline(s)->order;

    pt_sbuf_init(&t);
    if (!items || !jms || !has) goto done;
    /* the vertices listed: every used vertex in scene order, up to the cap */
    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *mm = &s->models[mi];
        if (pick && mm != m) continue;      /* a list: m's vertices only */
        free(used);
        used = calloc(mm->nv ? mm->nv : 1, 1);
        if (!used) goto done;
        for (k = 0; k < mm->nseg; k++) used[mm->seg[k].a] = used[mm->seg[k].b] = 1;
        for (k = 0; k < mm->nv; k++) {
            int here = mm == m && k + 1 == v, want = pick ? pick[k] : used[k];
            if (!want && !here) continue;
            if (want) total++;
            if (n >= PT_JOURNEY_MAXV && !(here && !found)) continue;
            if (here) { found = 1; start = n; }
            items[n].m = mi; items[n].v = k + 1; items[n].used = used[k];
            n++;
            has[mi] = 1;
        }
    }
    for (mi = 0; mi < s->nmodels; mi++) {
        if (!has[mi]) continue;
        free(used);                         /* now: the model's vertices listed */
        if (!(used = calloc(s->models[mi].nv ? s->models[mi].nv : 1, 1))) goto done;
        for (k = 0; k < n; k++)
            if (items[k].m == mi) used[items[k].v - 1] = 1;
        if ((i = pt_jmodel_init(&jms[mi], s, &s->models[mi], frame, used)) != 0) {
            rc = i;
            goto done;
        }
        if (!frame) frame = jms[mi].frame;  /* the scene rendered once for every model */
    }

    pt_journey_page_head(sb, m->name, v);

    /* the data */
    pt_sbuf_add(sb, "<script type=\"application/json\" id=\"data\">\n{\"where\":");
    pt_sbuf_add(&t, "scene ");
    pt_sbuf_add(&t, s->path);
    pt_sbuf_addf(&t, "; camera %s%s%s%s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); "
                 "framebuffer %d x %d", pt_scene_camera_word(s),
                 pt_scene_pipeline(s)->camera ? " (the " : "",
                 pt_scene_pipeline(s)->camera ? pt_scene_pipeline(s)->title : "",
                 pt_scene_pipeline(s)->camera ? ")" : "",
                 s->vp_w, s->vp_h, s->vp_x, s->vp_y, s->fb_w, s->fb_h);
    pt_sbuf_add_json(sb, t.s ? t.s : "");
    pt_sbuf_addf(sb, ",\n\"panel\":[%d,%d],\"font\":", PT_JOURNEY_PW, PT_JOURNEY_PH);
    pt_sbuf_add_json(sb, "DejaVu Sans, Helvetica, Arial, sans-serif");
    pt_sbuf_addf(sb, ",\"capped\":%s,\"total\":%llu,\"start\":%llu,\n\"stages\":[\n",
                 total > PT_JOURNEY_MAXV ? "true" : "false", (unsigned long long)total,
                 (unsigned long long)start);
    for (i = 0; i < n_st; i++) {
        const pt_stage_info *in = pt_pipeline_info(pt_scene_pipeline(s), ord[i]);
        pt_journey_page_stage(sb, i, in->name, pt_journey_title(ord[i]), in->from, in->to,
                              in->formula, in->what);
    }
    pt_sbuf_add(sb, "],\n\"models\":[\n");
    for (mi = 0; mi < s->nmodels; mi++) {
        pt_sbuf_add(sb, mi ? ",\n{\"name\":" : "{\"name\":");
        pt_sbuf_add_json(sb, s->models[mi].name);
        pt_sbuf_add(sb, ",\"bg\":[");
        for (i = 0; i < n_st && has[mi]; i++) {
            pt_sbuf_free(&t);
            pt_journey_panel_bg(&t, &jms[mi], ord[i]);
            if (t.failed) goto done;
            pt_sbuf_add(sb, i ? ",\n" : "\n");
            pt_sbuf_add_json(sb, t.s ? t.s : "");
        }
        pt_sbuf_add(sb, "]}");
    }
    pt_sbuf_add(sb, "],\n\"vertices\":[\n");
    first = 1;
    for (k = 0; k < n; k++) {
        const pt_jmodel *jm = &jms[items[k].m];
        pt_sbuf_addf(sb, "%s{\"m\":%llu,\"v\":%llu,\"used\":%s,\"coords\":", first ? "" : ",\n",
                     (unsigned long long)items[k].m, (unsigned long long)items[k].v,
                     items[k].used ? "true" : "false");
        first = 0;
        texts(sb, jm, &items[k], 0);
        pt_sbuf_add(sb, ",\n\"here\":");
        texts(sb, jm, &items[k], 1);
        pt_sbuf_add(sb, ",\n\"next\":");
        texts(sb, jm, &items[k], 2);
        pt_sbuf_add(sb, ",\n\"fg\":[");
        for (i = 0; i < n_st; i++) {
            pt_sbuf_free(&t);
            pt_journey_panel_fg(&t, jm, items[k].v, ord[i]);
            if (t.failed) goto done;
            pt_sbuf_add(sb, i ? ",\n" : "\n");
            pt_sbuf_add_json(sb, t.s ? t.s : "");
        }
        pt_sbuf_add(sb, "]}");
    }
    pt_sbuf_add(sb, "]}\n</script>\n");
    pt_journey_page_script(sb);
    pt_journey_wasm(sb, s);                 /* the sliders (journey_wasm.c) */
    pt_sbuf_add(sb, "</body>\n</html>\n");
    rc = sb->failed ? -1 : 0;
done:
    pt_sbuf_free(&t);
    free(items);
    for (mi = 0; jms && mi < s->nmodels; mi++) pt_jmodel_free(&jms[mi]);
    free(jms);
    free(has);
    free(used);
    return rc;
}
