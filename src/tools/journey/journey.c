/*
** src/tools/journey/journey.c -- one vertex's journey drawn: the panels laid out, the SVG document
** See LICENSE for copyright and license.
**
** Layout of a panel (PT_JOURNEY_PW x PT_JOURNEY_PH units): a title and the
** stage's formula on top, the plot box (PT_JBOX_*) in the middle, the
** vertex's coordinates and a note below.  The driver draws the frame, the
** title, the formula, the coordinates; what is in the box, and the note, are
** drawn by the rows of the scene's pipeline (jrows.c), so that this file
** never asks which pipeline it draws.  Each plot is a pt_jview: a window of
** the stage's own coordinates fitted into the box at one scale for x and y.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey.h"
#include "tools/journey/jdraw.h"
#include "tools/journey/jrows.h"
#include "tools/journey/jpanel.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define CAPTION_Y 308.0          /* the coordinates */
#define NOTE_Y    327.0          /* the note */

/* ===== layout ===== */

/* What run_model() keeps of the records of one pt_run(). */
typedef struct keeper {
    pt_jmodel *jm;
    const unsigned char *show;   /* show[k]: vertex k + 1's foreground is drawn */
    size_t npix, cap;            /* pixels in jm->pix, room for */
    size_t nstart;               /* segments whose jm->pixat is set */
    size_t nkept;                /* journeys in jm->kept so far */
    int oom;                     /* 1: out of memory; 2: past PT_JOURNEY_MAXPIX */
} keeper;

/* A vertex's journey: its part in the layout when a segment uses it, the
** whole journey when it is one jm->keep lists (they come in vertex order). */
static void keep_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    keeper *kp = ud;
    pt_jmodel *jm = kp->jm;

    if (m != jm->m || v < 1 || v > m->nv) return;
    if (jm->used[v - 1]) jm->rows->absorb(jm, j, (size_t)(v - 1));
    if (kp->nkept < jm->nkeep && jm->keep[kp->nkept] == v - 1) jm->kept[kp->nkept++] = *j;
}

/* The vertices whose journeys the panels draw into jm->keep, ascending; the
** used ones into jm->used; the shown ones into jm->show.  Returns 0, or -1
** when out of memory. */
static int choose_kept(pt_jmodel *jm, const unsigned char *show)
{
    const pt_model *m = jm->m;
    size_t nv = m->nv ? m->nv : 1, s, k;
    unsigned char *want = calloc(nv, 1);

    jm->used = calloc(nv, 1);
    jm->show = malloc(nv);
    if (!want || !jm->used || !jm->show) { free(want); return -1; }
    memcpy(jm->show, show, m->nv);
    if (m->nv) want[0] = 1;                  /* the matrices every journey carries */
    for (k = 0; k < m->nv; k++) want[k] |= show[k];
    for (s = 0; s < m->nseg; s++) {
        size_t a = m->seg[s].a, b = m->seg[s].b;
        jm->used[a] = jm->used[b] = 1;
        if (pt_jseg_drawn(jm, s)) want[a] = want[b] = 1;
    }
    for (k = 0; k < m->nv; k++) jm->nkeep += want[k];
    jm->keep = malloc((jm->nkeep ? jm->nkeep : 1) * sizeof *jm->keep);
    jm->kept = calloc(jm->nkeep ? jm->nkeep : 1, sizeof *jm->kept);
    if (!jm->keep || !jm->kept) { free(want); return -1; }
    for (k = 0, s = 0; k < m->nv; k++)
        if (want[k]) jm->keep[s++] = k;
    free(want);
    return 0;
}

/* Segments before seg (1-based) have all their pixels: mark where seg's
** start. */
static void seg_reach(keeper *kp, uint64_t seg)
{
    while (kp->nstart < seg) kp->jm->pixat[kp->nstart++] = kp->npix;
}

static void keep_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                        size_t n)
{
    keeper *kp = ud;
    pt_jmodel *jm = kp->jm;
    pt_pix ul = {0, 0, 1};
    size_t k;

    if (m != jm->m || kp->oom) return;
    seg_reach(kp, seg);
    if (!kp->show[m->seg[seg - 1].a] && !kp->show[m->seg[seg - 1].b]) return;  /* not drawn */
    if (n > PT_JOURNEY_MAXPIX - kp->npix) { kp->oom = 2; return; }
    if (kp->npix + n > kp->cap) {
        size_t cap = kp->cap ? 2 * kp->cap : 1024;
        pt_jpix *p;
        while (cap < kp->npix + n) cap *= 2;
        if (!(p = realloc(jm->pix, cap * sizeof *p))) { kp->oom = 1; return; }
        jm->pix = p;
        kp->cap = cap;
    }
    ul = pt_viewport2fb(ul, jm->s->vp_x, jm->s->vp_y, NULL);   /* viewport pixel (0, 0) */
    for (k = 0; k < n; k++) {                                  /* back through the
                                                               ** framebuffer stage */
        jm->pix[kp->npix].x_vp = px[k].x_fb - ul.x;
        jm->pix[kp->npix].y_vp = px[k].y_fb - ul.y;
        kp->npix++;
    }
}

/* One pt_run() of model jm->m (every vertex traced, used or not): each used
** vertex's part in the layout into jm->span (its pipeline's absorb), the
** whole journeys of the vertices drawn into jm->kept (choose_kept()), the
** pixels drawn of each segment of a vertex shown (the only ones a panel
** draws) into jm->pix and jm->pixat (the others get none).  Nothing else of
** the run is kept.  Returns 0, or -1 when out of memory, -2 past
** PT_JOURNEY_MAXPIX pixels. */
static int run_model(pt_jmodel *jm, const unsigned char *show)
{
    const pt_model *m = jm->m;
    pt_options o;
    pt_listener l;
    keeper kp;

    pt_jspan_start(&jm->span);
    if (choose_kept(jm, show) != 0) return -1;
    jm->code = calloc(m->nv ? m->nv : 1, 1);      /* the matrix camera's absorb fills it */
    jm->pixat = calloc(m->nseg + 1, sizeof *jm->pixat);
    if (!jm->code || !jm->pixat) return -1;
    memset(&kp, 0, sizeof kp);
    kp.jm = jm;
    kp.show = show;
    pt_options_default(&o);
    o.model = m->name;           /* models of the same name: the callbacks pick m */
    o.every_vertex = 1;
    memset(&l, 0, sizeof l);
    l.journey = keep_journey;
    l.pixels = keep_pixels;
    l.ud = &kp;
    if (pt_run_plain(jm->s, &o, &l) != 0) return -1;
    if (kp.oom) return -kp.oom;
    seg_reach(&kp, m->nseg + 1);
    return 0;
}

int pt_jmodel_init(pt_jmodel *jm, const pt_scene *s, const pt_model *m, const pt_fb *frame,
                   const unsigned char *show)
{
    double area[4] = { PT_JBOX_X, PT_JBOX_Y, PT_JBOX_X + PT_JBOX_W, PT_JBOX_Y + PT_JBOX_H };
    int st, rc;

    memset(jm, 0, sizeof *jm);
    jm->s = s;
    jm->m = m;
    jm->rows = &pt_jpipes[pt_scene_pipeline(s)->id];
    pt_stage_params_of(&jm->par, s, m);
    if ((rc = run_model(jm, show)) != 0) { pt_jmodel_free(jm); return rc; }
    if (!(jm->place = calloc(PT_NSTAGES_ALL, sizeof *jm->place))) { pt_jmodel_free(jm); return -1; }
    for (st = 0; st < PT_NSTAGES_ALL; st++) pt_jplace_init(&jm->place[st], area);
    if (jm->rows->layout(jm) != 0) { pt_jmodel_free(jm); return -1; }
    if ((int64_t)s->fb_w * s->fb_h <= PT_JOURNEY_FRAMEMAX) {
        if (frame) jm->frame = frame;       /* rendered once for every model */
        else {
            if (pt_journey_render(&jm->own_frame, s) != 0) { pt_jmodel_free(jm); return -1; }
            jm->owns_frame = 1;
            jm->frame = &jm->own_frame;
        }
    }
    return 0;
}

int pt_journey_render(pt_fb *fb, const pt_scene *s)
{
    pt_options o;
    pt_plan p;
    pt_summary sum;
    pt_listener quiet;                      /* no trace: every hook NULL */

    memset(&quiet, 0, sizeof quiet);
    pt_options_default(&o);
    if (pt_plan_make(&p, s, &o) != 0) return -1;
    if (pt_fb_init(fb, s->fb_w, s->fb_h, s->background) != 0) { pt_plan_free(&p); return -1; }
    if (pt_run(s, &p, &o, &quiet, fb, &sum) != 0) {
        pt_plan_free(&p);
        pt_fb_free(fb);
        return -1;
    }
    pt_plan_free(&p);
    return 0;
}

void pt_jmodel_free(pt_jmodel *jm)
{
    int st;

    if (jm->owns_frame) pt_fb_free(&jm->own_frame);
    jm->owns_frame = 0;
    jm->frame = NULL;
    if (jm->place)
        for (st = 0; st < PT_NSTAGES_ALL; st++) pt_jplace_free(&jm->place[st]);
    free(jm->place);
    jm->place = NULL;
    free(jm->used);
    free(jm->show);
    free(jm->keep);
    free(jm->kept);
    free(jm->code);
    jm->used = jm->show = jm->code = NULL;
    jm->keep = NULL;
    jm->kept = NULL;
    jm->nkeep = 0;
    free(jm->pix);
    free(jm->pixat);
    jm->pix = NULL;
    jm->pixat = NULL;
    free(jm->cut);
    free(jm->cutix);
    jm->cut = NULL;
    jm->cutix = NULL;
}

/* ===== titles ===== */

static const char *const titles[PT_NSTAGES_ALL][2] = {
    {"model space", "(x_m, y_m, z_m)"},
    {"camera space", "(x_c, y_c, z_c)"},
    {"image plane", "(x_ip, y_ip)"},
    {"logical pixel plane", "(x_pp, y_pp)"},
    {"viewport pixels", "(x_vp, y_vp)"},
    {"framebuffer", "(x_fb, y_fb)"},
    {"pixel array", "idx"},
    {"world space", "(x_w, y_w, z_w)"},      /* the matrix camera's (journey_matrix.c) */
    {"view space", "(x_v, y_v, z_v)"},
    {"clip space", "(x_k, y_k, z_k, w_k)"},
    {"the six planes", "outcode"},
    {"NDC cube", "(x_n, y_n, z_n)"},
    {"screen", "(x_s, y_s)"},
};

const char *pt_journey_title(pt_stage st)
{
    return (int)st < PT_NSTAGES_ALL ? titles[st][0] : "";
}

/* The formula line under the title. */
static const char *formula_of(const pt_jmodel *jm, pt_stage st)
{
    if (st == PT_STAGE_MODEL) return "(x_m, y_m, z_m): the vertex as the scene gives it";
    if (st == PT_STAGE_IMAGE)
        return jm->par.perspective ? "x_ip = x_c / -z_c, y_ip = y_c / -z_c, z_ip = -1"
                                   : "orthographic: x_ip = x_c, y_ip = y_c, z_ip = 0";
    if (st == PT_STAGE_VIEWPORT) return pt_scene_pipeline(jm->s)->viewport_info->formula;
    return pt_stage_infos[st].formula;
}

/* The 1-based place of stage st in jm's pipeline's order. */
static int number_of(const pt_jmodel *jm, pt_stage st)
{
    const pt_pipeline *pl = pt_scene_pipeline(jm->s);
    int k;

    for (k = 0; k < pl->norder; k++)
        if (pl->order[k] == st) return k + 1;
    return (int)st + 1;
}

/* ===== a panel ===== */

void pt_journey_panel_bg(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_jstage_row *row;
    pt_jplace *p;
    char t[160];

    if ((int)st >= PT_NSTAGES_ALL) return;
    row = jm->rows->stage[st];
    p = &jm->place[st];
    pt_jplace_clear(p);
    pt_jdraw_to(p);
    pt_jrect(sb, 0.5, 0.5, PT_JOURNEY_PW - 1, PT_JOURNEY_PH - 1, "#fff", PT_JC_FRAME, "rx=\"6\"");
    snprintf(t, sizeof t, "%d  %s  %s", number_of(jm, st), titles[st][0], titles[st][1]);
    pt_jtext(sb, 12, 21, 15, "start", "font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"", t, 376);
    pt_jtext(sb, 12, 36, 10.5, "start", "font-family=\"" PT_JMONO "\" fill=\"" PT_JC_NOTE "\"",
             formula_of(jm, st), 376);
    pt_jrect(sb, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H, "#fbfcfe", "#e3e6eb", "");
    if (row) row->bg(sb, jm, st);           /* what the box shows: the pipeline's row */
    pt_jdraw_to(NULL);
    p->ready = 1;
    if (p->failed) sb->failed = 1;
}

void pt_journey_panel_fg(pt_sbuf *sb, const pt_jmodel *jm, uint64_t vn, pt_stage st)
{
    const pt_jrows *rows = jm->rows;
    size_t k = (size_t)(vn - 1), s;
    int used = 0, stopped;
    const pt_journey *j;
    char t[PT_EXPLAINLEN];
    pt_jplace_mark mark;

    if ((int)st >= PT_NSTAGES_ALL || vn < 1 || vn > jm->m->nv) return;
    if (!jm->place[st].ready) {              /* the background's lines and labels */
        pt_sbuf bg;
        pt_sbuf_init(&bg);
        pt_journey_panel_bg(&bg, jm, st);
        if (bg.failed) sb->failed = 1;
        pt_sbuf_free(&bg);
    }
    mark = pt_jplace_save(&jm->place[st]);
    pt_jdraw_to(&jm->place[st]);
    for (s = 0; s < jm->m->nseg && !used; s++)
        used = jm->m->seg[s].a == k || jm->m->seg[s].b == k;
    j = pt_jmodel_journey(jm, k);
    stopped = pt_journey_stopped(j, st) && rows->stopped_fg;
    if (stopped) rows->stopped_fg(sb, jm, j, k, st);   /* a stage it did not reach */
    else if (rows->stage[st]) rows->stage[st]->fg(sb, jm, j, k, st);
    pt_jdraw_to(NULL);
    pt_jdraw_labels(sb, &jm->place[st]);    /* the background's labels and ours */
    if (jm->place[st].failed) sb->failed = 1;
    pt_jplace_back(&jm->place[st], mark);
    if (stopped) rows->stopped_coords(t, sizeof t, st);
    else pt_explain_values(t, sizeof t, j, st);
    pt_sbuf_addf(sb, "<g data-stage=\"%s\">\n", pt_stage_infos[st].name);
    pt_jtext(sb, 12, CAPTION_Y, 12, "start", "class=\"coords\" font-family=\"" PT_JMONO
             "\" font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"", t, 376);
    t[0] = '\0';
    if (stopped) rows->stopped_note(t, sizeof t, j, st);
    else if (rows->stage[st]) rows->stage[st]->note(t, sizeof t, jm, j, st, used);
    pt_jtext(sb, 12, NOTE_Y, 11, "start", "class=\"note\" fill=\"" PT_JC_NOTE "\"", t, 376);
    pt_sbuf_add(sb, "</g>\n");
}

/* ===== the SVG document ===== */

#define GAP      16              /* between panels */
#define HEAD     62              /* the header band */
#define DOC_W    (GAP + 4 * (PT_JOURNEY_PW + GAP))
#define DOC_H(n) (HEAD + ((n) + 4) / 4 * (PT_JOURNEY_PH + GAP))  /* n panels, legend */

/* The eighth cell: what the scene is and what the colors mean. */
static void legend(pt_sbuf *sb, const pt_jmodel *jm)
{
    const pt_stage_params *p = &jm->par;
    double y = 28;
    char t[200], a[PT_NUMLEN], b[PT_NUMLEN], c[PT_NUMLEN];
    pt_sbuf u;

    pt_jrect(sb, 0.5, 0.5, PT_JOURNEY_PW - 1, PT_JOURNEY_PH - 1, "#fff", PT_JC_FRAME, "rx=\"6\"");
    pt_jtext(sb, 12, 21, 15, "start", "font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"", "how to read it", 0);
    pt_jcircle(sb, 22, y + 14, 5, PT_JC_VTX, "stroke=\"#fff\" stroke-width=\"1.5\"");
    pt_jtext(sb, 36, y + 18, 12, "start", "fill=\"" PT_JC_TEXT "\"", "the vertex, labelled with its number", 0);
    pt_jline(sb, 14, y + 36, 30, y + 36, PT_JC_SEG, 2.5, "");
    pt_jtext(sb, 36, y + 40, 12, "start", "fill=\"" PT_JC_TEXT "\"", "the segments that use it", 0);
    pt_jline(sb, 14, y + 58, 30, y + 58, PT_JC_FAINT, 1.5, "");
    pt_jtext(sb, 36, y + 62, 12, "start", "fill=\"" PT_JC_TEXT "\"", "the rest of its model", 0);
    pt_jrect(sb, 15, y + 73, 14, 10, PT_JC_CELL, "", "");
    pt_jtext(sb, 36, y + 83, 12, "start", "fill=\"" PT_JC_TEXT "\"", "pixels its segments light", 0);
    pt_jrect(sb, 15, y + 95, 14, 10, PT_JC_FRAMEPX, "", "");
    pt_jtext(sb, 36, y + 105, 12, "start", "fill=\"" PT_JC_TEXT "\"",
            "the whole frame: every model's pixels", 0);
    pt_jrect(sb, 15, y + 117, 14, 10, PT_JC_AREA, PT_JC_EDGE, "");
    pt_jtext(sb, 36, y + 127, 12, "start", "fill=\"" PT_JC_TEXT "\"",
            "what reaches the viewport", 0);
    pt_jline(sb, 13, y + 146, 22, y + 146, PT_JC_VTX, 2.5, "");
    pt_jarrow(sb, 13, y + 146, 31, y + 146, 10, PT_JC_VTX);
    pt_jtext(sb, 36, y + 150, 12, "start", "fill=\"" PT_JC_TEXT "\"",
            "the vertex lies off the panel that way", 0);
    y += 176;
    pt_fmt_shortest(a, p->translate.x); pt_fmt_shortest(b, p->translate.y);
    pt_fmt_shortest(c, p->translate.z);
    pt_sbuf_init(&u);
    pt_sbuf_add(&u, "model ");
    pt_sbuf_add(&u, jm->m->name);
    pt_sbuf_addf(&u, ": translate (x_t, y_t, z_t) = (%s, %s, %s)", a, b, c);
    pt_jtext(sb, 12, y, 11, "start", "fill=\"" PT_JC_NOTE "\"", u.s ? u.s : "", 376);
    pt_sbuf_free(&u);
    snprintf(t, sizeof t, "camera %s; viewport w x h = %d x %d at (x_ul, y_ul) = (%d, %d)",
             pt_scene_camera_word(jm->s),
             p->w, p->h, p->x_ul, p->y_ul);
    pt_jtext(sb, 12, y + 17, 11, "start", "fill=\"" PT_JC_NOTE "\"", t, 376);
    snprintf(t, sizeof t, "framebuffer W x H = %d x %d; round() is Java's Math.round", p->W, p->H);
    pt_jtext(sb, 12, y + 34, 11, "start", "fill=\"" PT_JC_NOTE "\"", t, 376);
    pt_jtext(sb, 12, y + 51, 11, "start", "fill=\"" PT_JC_NOTE "\"",
            "numbers: shortest decimals that read back exactly, as in the trace", 376);
    pt_jtext(sb, 12, y + 68, 11, "start", "fill=\"" PT_JC_NOTE "\"",
            "pipetrace step shows each formula with its numbers put in", 376);
}

int pt_journey_svg(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t vn)
{
    pt_jmodel jm;
    pt_sbuf t;
    int i, rc, n = pt_scene_pipeline(s)->norder;
    const pt_stage *ord = pt_scene_pipeline(s)->order;
    unsigned char *show = calloc(m->nv ? m->nv : 1, 1);

    if (!show) return -1;
    show[vn - 1] = 1;
    rc = pt_jmodel_init(&jm, s, m, NULL, show);
    free(show);
    if (rc != 0) return rc;
    pt_sbuf_add(sb, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    pt_sbuf_addf(sb, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %d %d\" "
                 "width=\"100%%\" font-family=\"%s\">\n", DOC_W, DOC_H(n), PT_JFONT);
    pt_sbuf_add(sb, "<title>pipetrace journey: vertex ");
    pt_sbuf_addf(sb, "%llu of model ", (unsigned long long)vn);
    pt_sbuf_add_xml(sb, m->name);
    pt_sbuf_add(sb, " in ");
    pt_sbuf_add_xml(sb, s->path);
    pt_sbuf_add(sb, "</title>\n");
    pt_sbuf_addf(sb, "<rect width=\"%d\" height=\"%d\" fill=\"#f3f4f6\"/>\n", DOC_W, DOC_H(n));
    pt_sbuf_init(&t);
    pt_sbuf_addf(&t, "pipetrace journey: vertex %llu of model ", (unsigned long long)vn);
    pt_sbuf_add(&t, m->name);
    pt_jtext(sb, GAP, 30, 22, "start", "font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"",
            t.s ? t.s : "", DOC_W - 2 * GAP);
    pt_sbuf_free(&t);
    pt_sbuf_add(&t, "scene ");
    pt_sbuf_add(&t, s->path);
    pt_sbuf_add(&t, ": from model coordinates to its element of the pixel array, "
                "one panel per coordinate system");
    pt_jtext(sb, GAP, 50, 13, "start", "fill=\"" PT_JC_NOTE "\"", t.s ? t.s : "", DOC_W - 2 * GAP);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
    for (i = 0; i <= n; i++) {
        int col = i % 4, row = i / 4, st = i < n ? (int)ord[i] : -1;
        int px = GAP + col * (PT_JOURNEY_PW + GAP), py = HEAD + row * (PT_JOURNEY_PH + GAP);
        if (i == n) {
            pt_sbuf_addf(sb, "<g class=\"legend\" transform=\"translate(%d %d)\">\n", px, py);
            legend(sb, &jm);
        } else {
            pt_sbuf_addf(sb, "<g class=\"panel\" data-stage=\"%s\" transform=\"translate(%d %d)\">\n",
                         pt_stage_infos[st].name, px, py);
            pt_journey_panel_bg(sb, &jm, (pt_stage)st);
            pt_journey_panel_fg(sb, &jm, vn, (pt_stage)st);
        }
        pt_sbuf_add(sb, "</g>\n");
        if (col < 3 && i < n - 1)            /* an arrow to the next panel */
            pt_jarrow(sb, px + PT_JOURNEY_PW + 1, py + PT_JOURNEY_PH / 2.0,
                      px + PT_JOURNEY_PW + GAP - 2, py + PT_JOURNEY_PH / 2.0, 12, "#8a919b");
    }
    pt_sbuf_add(sb, "</svg>\n");
    pt_jmodel_free(&jm);
    return sb->failed ? -1 : 0;
}
