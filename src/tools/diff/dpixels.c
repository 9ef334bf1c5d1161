/*
** src/tools/diff/dpixels.c -- pipetrace diff: the lit pixels, and the rasterizer replayed
** See LICENSE for copyright and license.
**
** The sets of lit pixels are compared position by position.  When every
** vertex agrees and the pixels differ, the rasterizer (pt_raster_segment) is
** run again on each differing segment from its rounded endpoints (its first
** and last steps in EXPECTED), first with the right viewport stage, which
** must give EXPECTED's pixels, then with each of the catalogue's mistakes of
** the rasterizer (a viewport stage that rounds or maps wrongly, the loop
** bound off by one, setPixelVP without the offset), which must give ACTUAL's:
** its pixels, and its clip records too where the reference replay gives
** EXPECTED's own (only they tell truncation from floor(x + 0.5)).
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/diff/diff.h"

/* A pixel record's place, for sorting by position. */
typedef struct pkey {
    int64_t y, x, i;             /* sort keys */
    size_t k;                    /* index into px[] */
} pkey;

static int pkey_cmp(const void *pa, const void *pb)
{
    const pkey *a = pa, *b = pb;

    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->i != b->i) return a->i < b->i ? -1 : 1;
    return a->k < b->k ? -1 : a->k > b->k;
}

/* A raster record (pixel or clip) in its segment, for sorting by segment. */
typedef struct skey {
    uint64_t seg;                /* 1-based segment */
    uint32_t model;              /* name id */
    int clip;                    /* 1: cl[k], 0: px[k] */
    size_t order;                /* place in the file: 2 npix (clip), 2 k + 1 (pixel) */
    size_t k;                    /* index */
} skey;

/* Order of the segments of a and b: model id, then segment number. */
static int seg_cmp(const skey *a, const skey *b)
{
    if (a->model != b->model) return a->model < b->model ? -1 : 1;
    if (a->seg != b->seg) return a->seg < b->seg ? -1 : 1;
    return 0;
}

static int skey_cmp(const void *pa, const void *pb)
{
    const skey *a = pa, *b = pb;
    int c = seg_cmp(a, b);

    if (c) return c;
    return a->order < b->order ? -1 : a->order > b->order;
}

static size_t pix_hash(int64_t x, int64_t y, int64_t i)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15u ^ (uint64_t)y * 0xC2B2AE3D27D4EB4Fu ^
                 (uint64_t)i * 0x165667B19E3779F9u;
    h ^= h >> 31;
    return (size_t)h;
}

/* The distinct pixels (x, y, i) of t sorted by position, each with its first
** record's index.  A hash set drops the repeats first (a pixel lit by many
** segments), so only distinct pixels are sorted: at most the framebuffer's
** worth however long the trace. */
static pkey *sorted_pixels(const pt_tread *t, size_t *n)
{
    size_t nslot = 1024, m = 0, cap = 256, k, j;
    uint32_t *slot = calloc(nslot, sizeof *slot);
    pkey *p = malloc(cap * sizeof *p);

    if (!slot || !p || t->npx >= UINT32_MAX) goto fail;
    for (k = 0; k < t->npx; k++) {
        const pt_tpix *x = &t->px[k];
        size_t h = pix_hash(x->x, x->y, x->i) & (nslot - 1);
        for (; slot[h]; h = (h + 1) & (nslot - 1)) {
            const pkey *q = &p[slot[h] - 1];
            if (q->x == x->x && q->y == x->y && q->i == x->i) break;
        }
        if (slot[h]) continue;              /* seen */
        if (m == cap) {
            pkey *np = realloc(p, 2 * cap * sizeof *np);
            if (!np) goto fail;
            p = np;
            cap *= 2;
        }
        p[m].x = x->x; p[m].y = x->y; p[m].i = x->i; p[m].k = k;
        slot[h] = (uint32_t)++m;
        if (2 * m >= nslot) {               /* grow and rehash */
            uint32_t *ns = calloc(2 * nslot, sizeof *ns);
            if (!ns) goto fail;
            nslot *= 2;
            for (j = 0; j < m; j++) {
                h = pix_hash(p[j].x, p[j].y, p[j].i) & (nslot - 1);
                while (ns[h]) h = (h + 1) & (nslot - 1);
                ns[h] = (uint32_t)j + 1;
            }
            free(slot);
            slot = ns;
        }
    }
    free(slot);
    qsort(p, m, sizeof *p, pkey_cmp);
    *n = m;
    return p;
fail:
    free(slot);
    free(p);
    return NULL;
}

/* The raster records of t sorted by segment, in step order within each. */
static skey *sorted_steps(const pt_tread *t, size_t *n)
{
    size_t k, m = 0;
    skey *s = malloc((t->npx + t->ncl ? t->npx + t->ncl : 1) * sizeof *s);

    if (!s) return NULL;
    for (k = 0; k < t->npx; k++, m++) {
        s[m].seg = t->px[k].seg; s[m].model = t->px[k].model;
        s[m].clip = 0; s[m].order = 2 * k + 1; s[m].k = k;
    }
    for (k = 0; k < t->ncl; k++, m++) {
        s[m].seg = t->cl[k].seg; s[m].model = t->cl[k].model;
        s[m].clip = 1; s[m].order = 2 * t->cl[k].npix; s[m].k = k;
    }
    qsort(s, m, sizeof *s, skey_cmp);
    *n = m;
    return s;
}

/* The pixels of one segment in viewport coordinates, step order. */
typedef struct plist {
    int64_t (*p)[2];             /* owned */
    size_t n, cap;
    int oom;                     /* 1: plist_add failed while replaying */
} plist;

static int plist_add(plist *l, int64_t x, int64_t y)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        int64_t (*np)[2] = realloc(l->p, cap * sizeof *np);
        if (!np) return -1;
        l->p = np;
        l->cap = cap;
    }
    l->p[l->n][0] = x;
    l->p[l->n][1] = y;
    l->n++;
    return 0;
}

/* A replayed segment: its pixels, and its clip records as three pairs each,
** (count, 0) (x_vp, y_vp of the first step) (... of the last). */
typedef struct replayed {
    plist px, cl;                /* owned */
} replayed;

/* The clip record of a trace as replay_clip() keeps it. */
static int clip_add(plist *l, const pt_tclip *q)
{
    return plist_add(l, (int64_t)q->count, 0) || plist_add(l, q->first[0], q->first[1]) ||
           plist_add(l, q->last[0], q->last[1]) ? -1 : 0;
}

static void replay_pixel(void *ud, int64_t x, int64_t y)
{
    replayed *r = ud;
    if (plist_add(&r->px, x, y) != 0) r->px.oom = 1;
}

static void replay_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    replayed *r = ud;
    if (plist_add(&r->cl, (int64_t)count, 0) || plist_add(&r->cl, first.x, first.y) ||
        plist_add(&r->cl, last.x, last.y))
        r->px.oom = 1;
}

/* The DDA's setup and last step, heard by a replay of the loop bound. */
typedef struct lasting {
    int kind;                    /* PT_RASTER_DRAWN, ... */
    int ymajor;                  /* the setup's */
    double m;                    /* the setup's slope */
    int have;                    /* 1: last is set */
    pt_raster_step last;         /* the last step heard */
} lasting;

static void last_setup(void *ud, const pt_raster_setup *su)
{
    lasting *l = ud;
    l->kind = su->kind;
    l->ymajor = su->ymajor;
    l->m = su->m;
}

static void last_step(void *ud, const pt_raster_step *st)
{
    lasting *l = ud;
    l->last = *st;
    l->have = 1;
}

/* The longest segment whose loop bound is replayed: its steps are heard one
** by one (pt_raster_walk), not fast-forwarded. */
#define LOOP_MOST 65536

/* Run the rasterizer again, each step's pixel found by to_vp (NULL: the
** viewport stage), for the segment whose rounded endpoints are ends[] = X0 Y0
** X1 Y1 (logical pixels), in a w x h viewport, with the loop's last step
** moved by steps (-1: not taken, +1: one more, y += m once more: the DDA's
** own step, its pixel from the viewport stage); what it writes goes to *out
** in step order (with steps, the pixels only).  Returns 0, 1 when steps is
** not replayed (a segment longer than LOOP_MOST steps), or -1 when out of
** memory. */
static int replay(const int64_t ends[4], int w, int h, pt_raster_vp to_vp, int steps,
                  replayed *out)
{
    pt_vec2 p0, p1;
    pt_raster_out ro;
    pt_raster_steps ls;
    lasting l;

    p0.x = (double)ends[0]; p0.y = (double)ends[1];
    p1.x = (double)ends[2]; p1.y = (double)ends[3];
    ro.pixel = replay_pixel;
    ro.clip = replay_clip;
    ro.ud = out;
    out->px.n = out->cl.n = 0;
    out->px.oom = 0;
    if (!to_vp) to_vp = pt_pixel2viewport;
    if (!steps) {
        pt_raster_segment(p0, p1, w, h, to_vp, &ro);
        return out->px.oom ? -1 : 0;
    }
    if (llabs(ends[2] - ends[0]) > LOOP_MOST || llabs(ends[3] - ends[1]) > LOOP_MOST) return 1;
    memset(&ls, 0, sizeof ls);
    memset(&l, 0, sizeof l);
    ls.setup = last_setup;
    ls.step = last_step;
    ls.ud = &l;
    pt_raster_walk(p0, p1, w, h, to_vp, &ro, &ls);
    if (l.kind == PT_RASTER_DRAWN && l.have && steps < 0 && l.last.inside)
        out->px.n--;                        /* its pixel is the last one */
    if (l.kind == PT_RASTER_DRAWN && l.have && steps > 0) {
        double a = l.last.a + l.m;          /* y += m */
        double s1 = (double)(l.last.s + 1);
        pt_vec2 pp;
        pt_pix vp;
        pp.x = l.ymajor ? a : s1;
        pp.y = l.ymajor ? s1 : a;
        vp = to_vp(pp, w, h, NULL);
        if (vp.ok && pt_inside(vp.x, vp.y, w, h)) replay_pixel(out, vp.x, vp.y);
    }
    return out->px.oom ? -1 : 0;
}

/* FNV-1a over the n pairs of l, from h. */
static uint64_t plist_hash(const plist *l, uint64_t h)
{
    size_t q;
    int k, b;

    for (q = 0; q < l->n; q++)
        for (k = 0; k < 2; k++)
            for (b = 0; b < 64; b += 8) {
                h ^= (uint64_t)l->p[q][k] >> b & 0xff;
                h *= UINT64_C(0x100000001b3);
            }
    return h;
}

int pt_diff_replay_sig(const int64_t ends[4], int w, int h, pt_raster_vp to_vp, int steps,
                       uint64_t sig[2])
{
    replayed r;
    int rc;

    memset(&r, 0, sizeof r);
    rc = replay(ends, w, h, to_vp, steps, &r);
    sig[0] = plist_hash(&r.px, UINT64_C(0xcbf29ce484222325));
    sig[1] = plist_hash(&r.cl, UINT64_C(0xcbf29ce484222325));
    free(r.px.p);
    free(r.cl.p);
    return rc;
}

/* 1 when the pixels b are the pixels a less the offset ul: setPixelVP
** without the offset, where the way back (fb_to_vp) takes ul off again. */
static int eq_less(const plist *a, const plist *b, pt_pix ul)
{
    size_t q;

    if (a->n != b->n) return 0;
    for (q = 0; q < a->n; q++)
        if (b->p[q][0] != a->p[q][0] - ul.x || b->p[q][1] != a->p[q][1] - ul.y) return 0;
    return 1;
}

static int plist_eq(const plist *a, const plist *b)
{
    return a->n == b->n && (a->n == 0 || memcmp(a->p, b->p, a->n * sizeof *a->p) == 0);
}

/* Mistake j replayed from ends into *out: 1 when it gives ACTUAL's pixels px
** (and with clips its clip records cl), 0 when not or not replayed; -1 when
** out of memory.  ref: the reference's replay; ul: the framebuffer pixel of
** viewport pixel (0, 0); log: 1 when ACTUAL is a course log, which the
** course's Java rasterizer may have written. */
static int mistake_fits(size_t j, const int64_t ends[4], const pt_thdr *hd, const replayed *ref,
                        pt_pix ul, const plist *px, const plist *cl, int clips, int log,
                        replayed *out)
{
    const pt_raster_mistake *mk = &pt_raster_mistakes[j];
    int r, ymajor;

    if (mk->no_offset)
        return eq_less(&ref->px, px, ul) && (!clips || plist_eq(&ref->cl, cl));
    r = replay(ends, hd->vp_w, hd->vp_h, mk->to_vp, mk->steps, out);
    if (r) return r < 0 ? -1 : 0;
    if (plist_eq(&out->px, px) && (mk->steps || !clips || plist_eq(&out->cl, cl))) return 1;
    /* the course's Java rasterizer makes it in the running coordinate only */
    ymajor = llabs(ends[3] - ends[1]) > llabs(ends[2] - ends[0]);
    if (!log || !mk->running[ymajor]) return 0;
    r = replay(ends, hd->vp_w, hd->vp_h, mk->running[ymajor], mk->steps, out);
    if (r) return r < 0 ? -1 : 0;
    return plist_eq(&out->px, px) && (mk->steps || !clips || plist_eq(&out->cl, cl));
}

/* 1 when the replayed viewport pixels re are ACTUAL's pixels act (taken to
** viewport pixels with the reference's offset, fb_to_vp) once its own offset
** d is taken off instead. */
static int own_eq(const plist *re, const plist *act, const pt_thdr *hd, const int64_t d[2])
{
    pt_pix o = {0, 0, 1}, ul = pt_viewport2fb(o, hd->vp_x, hd->vp_y, NULL);
    size_t q;

    if (re->n != act->n) return 0;
    for (q = 0; q < re->n; q++)
        if (re->p[q][0] != act->p[q][0] + ul.x - d[0] || re->p[q][1] != act->p[q][1] + ul.y - d[1])
            return 0;
    return 1;
}

/* Framebuffer pixel (x_fb, y_fb) of the header hd in viewport coordinates:
** the way back through the framebuffer stage, which offsets every pixel by
** the framebuffer pixel of viewport pixel (0, 0) (pt_viewport2fb). */
static pt_pix fb_to_vp(const pt_thdr *hd, int64_t x_fb, int64_t y_fb)
{
    pt_pix o = {0, 0, 1}, ul = pt_viewport2fb(o, hd->vp_x, hd->vp_y, NULL);
    pt_pix vp = {x_fb - ul.x, y_fb - ul.y, 1};

    return vp;
}

/* The logical pixel (x_pp, y_pp), ends[0] and ends[1], whose viewport pixel is
** (x_vp, y_vp) in a viewport h high: the viewport stage backwards for whole
** pixels, stated again on purpose (the stage has no way back):
**   x_pp = x_vp + 1            (x_vp = round(x_pp) - 1)
**   y_pp = h - y_vp            (y_vp = h - round(y_pp))
** Tied to the stage twice: a rasterizer mistake is named only when the replay
** from these endpoints gives EXPECTED's own pixels, and tests/teach/diff.sh names
** one on a viewport off the framebuffer's corner, h != H (diff-1.7a). */
static void vp_to_pp(int64_t x_vp, int64_t y_vp, int h, int64_t ends[2])
{
    ends[0] = x_vp + 1;                     /* x_pp = x_vp + 1 */
    ends[1] = h - y_vp;                     /* y_pp = h - y_vp */
}

/* The logical pixel (x_pp, y_pp), ends[0] and ends[1], that viewport stage
** to_vp takes to (x_vp, y_vp) in a w x h viewport, read off the stage itself:
** on whole numbers, which no rounding changes, each viewport stage of the
** catalogue is x_vp = a_x + s_x x_pp, y_vp = a_y + s_y y_pp with s = +-1, a
** and a + s its pixels of (0, 0) and (1, 1).  Returns 1, or 0 when to_vp is
** no such map. */
static int vp_back(pt_raster_vp to_vp, int w, int h, int64_t x_vp, int64_t y_vp, int64_t ends[2])
{
    pt_vec2 p0 = {0.0, 0.0}, p1 = {1.0, 1.0};
    pt_pix a = to_vp(p0, w, h, NULL), b = to_vp(p1, w, h, NULL);
    int64_t sx = b.x - a.x, sy = b.y - a.y;

    if (!a.ok || !b.ok || (sx != 1 && sx != -1) || (sy != 1 && sy != -1)) return 0;
    ends[0] = (x_vp - a.x) * sx;            /* x_pp = (x_vp - a_x) / s_x */
    ends[1] = (y_vp - a.y) * sy;            /* y_pp = (y_vp - a_y) / s_y */
    return 1;
}

/* ACTUAL's first and last step f, l of a segment as viewport pixels *fv,
** *lv: its clip records are, its pixel records less its own offset d. */
static void own_steps(const dctx *c, const skey *f, const skey *l, const int64_t d[2],
                      pt_pix *fv, pt_pix *lv)
{
    fv->ok = lv->ok = 1;
    if (f->clip) { fv->x = c->t[1].cl[f->k].first[0]; fv->y = c->t[1].cl[f->k].first[1]; }
    else { fv->x = c->t[1].px[f->k].x - d[0]; fv->y = c->t[1].px[f->k].y - d[1]; }
    if (l->clip) { lv->x = c->t[1].cl[l->k].last[0]; lv->y = c->t[1].cl[l->k].last[1]; }
    else { lv->x = c->t[1].px[l->k].x - d[0]; lv->y = c->t[1].px[l->k].y - d[1]; }
}

/* Each mistake of the viewport stage the DDA asks, replayed from ACTUAL's own
** first and last steps fv, lv taken back its own way (vp_back): counted in
** rs->own_misfit unless it draws ACTUAL's pixels act (with its offset d).
** The loop bound's mistakes and setPixelVP's are not replayed so: counted.
** Returns 0, or -1 when out of memory. */
static int own_mistakes(rstat *rs, const pt_thdr *hd, pt_pix fv, pt_pix lv, const plist *act,
                        const int64_t d[2], replayed *out)
{
    size_t j;

    for (j = 0; j < PT_NRASTER_MISTAKES; j++) {
        const pt_raster_mistake *mk = &pt_raster_mistakes[j];
        int64_t own[4];
        int r;

        if (mk->steps || mk->no_offset || !mk->to_vp ||
            !vp_back(mk->to_vp, hd->vp_w, hd->vp_h, fv.x, fv.y, &own[0]) ||
            !vp_back(mk->to_vp, hd->vp_w, hd->vp_h, lv.x, lv.y, &own[2])) {
            rs->own_misfit[j]++;
            continue;
        }
        if ((r = replay(own, hd->vp_w, hd->vp_h, mk->to_vp, 0, out)) < 0) return -1;
        if (r || !own_eq(&out->px, act, hd, d)) rs->own_misfit[j]++;
    }
    return 0;
}

/* The offset ACTUAL's framebuffer stage gives its viewport pixels, read off
** its vertices: 1 and *d when every vertex with both records has
** (x_fb, y_fb) = (x_vp, y_vp) + d (without such a vertex, the reference's
** offset for hd's corner), else 0.  Its pixel records less d are then
** viewport pixels, as its clip records are. */
static int actual_offset(const dctx *c, const pt_thdr *hd, int64_t d[2])
{
    pt_pix o = {0, 0, 1}, ul = pt_viewport2fb(o, hd->vp_x, hd->vp_y, NULL);
    int seen = 0;
    size_t k;

    d[0] = ul.x;
    d[1] = ul.y;
    for (k = 0; k < c->vt.n; k++) {
        uint32_t iv = c->vt.e[k].rec[1][PT_STAGE_VIEWPORT];
        uint32_t ifb = c->vt.e[k].rec[1][PT_STAGE_FRAMEBUFFER];
        const pt_tvrec *v, *f;

        if (iv == PT_DIFF_NONE || ifb == PT_DIFF_NONE) continue;
        v = &c->t[1].vx[iv];
        f = &c->t[1].vx[ifb];
        if ((v->flags | f->flags) & PT_REC_NULL) continue;
        if (!pt_diff_small(v->u.n[0]) || !pt_diff_small(v->u.n[1]) ||
            !pt_diff_small(f->u.n[0]) || !pt_diff_small(f->u.n[1])) continue;
        if (!seen) {
            d[0] = f->u.n[0] - v->u.n[0];
            d[1] = f->u.n[1] - v->u.n[1];
            seen = 1;
        } else if (f->u.n[0] - v->u.n[0] != d[0] || f->u.n[1] - v->u.n[1] != d[1]) {
            return 0;
        }
    }
    return 1;
}

/* Segment by segment: which differ, and which rounding mistake of the
** rasterizer reproduces ACTUAL's pixels from EXPECTED's endpoints. */
int pt_diff_check_raster(dctx *c, rstat *rs)
{
    const pt_thdr *hd = &c->t[0].hdr;
    size_t n[2], k[2] = {0, 0}, j;
    skey *s[2];
    plist pl[2] = {{NULL, 0, 0, 0}, {NULL, 0, 0, 0}}, cl[2] = {{NULL, 0, 0, 0}, {NULL, 0, 0, 0}};
    replayed re, mk, tw;
    pt_pix o = {0, 0, 1}, ul = pt_viewport2fb(o, hd->vp_x, hd->vp_y, NULL);
    int64_t d[2];
    int side, rc = 0, one_space = actual_offset(c, hd, d), same, own_ok;
    pt_pix af = {0, 0, 0}, al = {0, 0, 0};    /* ACTUAL's first and last step */
    int clips_both = c->t[0].ncl && c->t[1].ncl;
    int vertices_agree = !c->differ && !c->only[0] && !c->only[1];

    memset(rs, 0, sizeof *rs);
    memset(&re, 0, sizeof re);
    memset(&mk, 0, sizeof mk);
    memset(&tw, 0, sizeof tw);
    s[0] = sorted_steps(&c->t[0], &n[0]);
    s[1] = sorted_steps(&c->t[1], &n[1]);
    if (!s[0] || !s[1]) rc = -1;
    while (rc == 0 && (k[0] < n[0] || k[1] < n[1])) {
        uint32_t model;
        uint64_t seg;
        size_t beg[2], end[2];
        int64_t ends[4];
        int have_ends = 0, ok = 0, clips = 0, sane = 1; /* sane: every coordinate pt_diff_small() */

        /* the next segment of either list: the smaller (model, seg) */
        side = k[1] >= n[1] ? 0 : k[0] >= n[0] ? 1 : seg_cmp(&s[0][k[0]], &s[1][k[1]]) <= 0 ? 0 : 1;
        model = s[side][k[side]].model;
        seg = s[side][k[side]].seg;
        for (side = 0; side < 2; side++) {
            beg[side] = k[side];
            pl[side].n = cl[side].n = 0;
            while (k[side] < n[side] && s[side][k[side]].model == model &&
                   s[side][k[side]].seg == seg) {
                const skey *q = &s[side][k[side]++];
                if (!q->clip) {
                    const pt_tpix *p = &c->t[side].px[q->k];
                    if (!pt_diff_small(p->x) || !pt_diff_small(p->y)) sane = 0;
                    else {
                        pt_pix vp = fb_to_vp(hd, p->x, p->y);
                        if (plist_add(&pl[side], vp.x, vp.y) != 0) rc = -1;
                    }
                } else if (!pt_diff_small(c->t[side].cl[q->k].first[0]) ||
                           !pt_diff_small(c->t[side].cl[q->k].first[1]) ||
                           !pt_diff_small(c->t[side].cl[q->k].last[0]) ||
                           !pt_diff_small(c->t[side].cl[q->k].last[1])) {
                    sane = 0;
                } else if (clip_add(&cl[side], &c->t[side].cl[q->k]) != 0) {
                    rc = -1;
                }
            }
            end[side] = k[side];
        }
        if (rc != 0) continue;
        same = plist_eq(&pl[0], &pl[1]) && (!clips_both || plist_eq(&cl[0], &cl[1]));
        own_ok = end[1] > beg[1] && sane && one_space && hd->vp_w >= 1 && hd->vp_h >= 1 &&
                 hd->vp_w <= PT_MAX_SIZE && hd->vp_h <= PT_MAX_SIZE;
        if (own_ok) own_steps(c, &s[1][beg[1]], &s[1][end[1] - 1], d, &af, &al);
        if (same && !vertices_agree) {
            /* a mistake behind a vertex stage's leaves these as they are too */
            if (own_ok && own_mistakes(rs, hd, af, al, &pl[1], d, &mk) != 0) rc = -1;
            continue;
        }
        /* rounded endpoints: EXPECTED's first and last steps, as logical pixels;
        ** a viewport beyond PT_MAX_SIZE is no trace of pipetrace's: not replayed */
        if (end[0] > beg[0] && sane && hd->vp_w >= 1 && hd->vp_h >= 1 &&
            hd->vp_w <= PT_MAX_SIZE && hd->vp_h <= PT_MAX_SIZE) {
            const skey *f = &s[0][beg[0]], *l = &s[0][end[0] - 1];
            pt_pix fv, lv;
            if (f->clip) { fv.x = c->t[0].cl[f->k].first[0]; fv.y = c->t[0].cl[f->k].first[1]; }
            else fv = fb_to_vp(hd, c->t[0].px[f->k].x, c->t[0].px[f->k].y);
            if (l->clip) { lv.x = c->t[0].cl[l->k].last[0]; lv.y = c->t[0].cl[l->k].last[1]; }
            else lv = fb_to_vp(hd, c->t[0].px[l->k].x, c->t[0].px[l->k].y);
            vp_to_pp(fv.x, fv.y, hd->vp_h, &ends[0]);
            vp_to_pp(lv.x, lv.y, hd->vp_h, &ends[2]);
            have_ends = 1;
            if (replay(ends, hd->vp_w, hd->vp_h, NULL, 0, &re))
                rc = -1;
            ok = rc == 0 && plist_eq(&re.px, &pl[0]);
            /* clip records compared where the traces have them and the
            ** reference replay gives EXPECTED's own */
            clips = ok && (c->t[0].ncl || c->t[1].ncl) && plist_eq(&re.cl, &cl[0]);
        }
        if (same) {
            /* a segment both traces light alike: a mistake that would light
            ** it otherwise does not explain ACTUAL (as a vertex mistake must
            ** leave the agreeing vertices as they are) */
            for (j = 0; ok && rc == 0 && j < PT_NRASTER_MISTAKES; j++) {
                int fit = mistake_fits(j, ends, hd, &re, ul, &pl[1], &cl[1], clips,
                                       c->t[1].kind == PT_TK_KRAFT, &mk);
                if (fit < 0) rc = -1;
                else if (!fit) rs->breaks[j]++;
            }
            continue;
        }
        if (!rs->first_set) {
            rs->first_set = 1;
            rs->first_model = model;
            rs->first_seg = seg;
            if (have_ends) memcpy(rs->ends, ends, sizeof ends);
            rs->ends_ok = ok;
        }
        rs->segs_differ++;
        if (own_ok && rc == 0) {
            /* ACTUAL's pixels a consequence of its vertices?  The reference
            ** rasterizer from ACTUAL's own first and last step must give
            ** them; else, behind it, a mistake of the stage the DDA asks may */
            int64_t own[4];
            if (own_mistakes(rs, hd, af, al, &pl[1], d, &mk) != 0) rc = -1;
            vp_to_pp(af.x, af.y, hd->vp_h, &own[0]);
            vp_to_pp(al.x, al.y, hd->vp_h, &own[2]);
            rs->own_tried++;
            if (rc || replay(own, hd->vp_w, hd->vp_h, NULL, 0, &mk)) rc = -1;
            else if (!own_eq(&mk.px, &pl[1], hd, d) && rs->own_bad++ == 0) {
                rs->own_model = model;
                rs->own_seg = seg;
            }
        }
        for (j = 0; ok && rc == 0 && j < PT_NRASTER_MISTAKES; j++) {
            int tj = pt_raster_mistakes[j].twin - 1, fit;
            fit = mistake_fits(j, ends, hd, &re, ul, &pl[1], &cl[1], clips,
                               c->t[1].kind == PT_TK_KRAFT, &mk);
            if (fit < 0) { rc = -1; break; }
            rs->hits[j] += (size_t)fit;
            if (tj < 0) continue;
            /* a twin: apart where the two replays differ */
            if (replay(ends, hd->vp_w, hd->vp_h, pt_raster_mistakes[tj].to_vp, 0, &tw)) rc = -1;
            else if (!plist_eq(&mk.px, &tw.px) || (clips && !plist_eq(&mk.cl, &tw.cl)))
                rs->apart[j]++;
        }
    }
    free(s[0]);
    free(s[1]);
    free(pl[0].p);
    free(pl[1].p);
    free(cl[0].p);
    free(cl[1].p);
    free(re.px.p); free(re.cl.p);
    free(mk.px.p); free(mk.cl.p);
    free(tw.px.p); free(tw.cl.p);
    return rc;
}

/* 1 when the sorted pixels p[0..n) hold one at (x, y), whatever its index. */
static int has_pixel(const pkey *p, size_t n, int64_t x, int64_t y)
{
    size_t lo = 0, hi = n;

    while (lo < hi) {                       /* the first one at or past (y, x) */
        size_t mid = lo + (hi - lo) / 2;
        if (p[mid].y < y || (p[mid].y == y && p[mid].x < x)) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && p[lo].y == y && p[lo].x == x;
}

/* 1 when the pixels b are the pixels a moved by (dx, dy), (dx, dy) != (0, 0):
** each of a moved lands on one of b unless it leaves the W x H framebuffer
** (counted in *out), and each of b comes from one of a. */
static int is_shift(const pkey *a, size_t na, const pkey *b, size_t nb, int64_t dx, int64_t dy,
                    int64_t W, int64_t H, size_t *out)
{
    size_t k;

    *out = 0;
    if ((dx == 0 && dy == 0) || !na || !nb) return 0;
    for (k = 0; k < na; k++) {
        int64_t x = a[k].x + dx, y = a[k].y + dy;
        if (!pt_diff_small(a[k].x) || !pt_diff_small(a[k].y)) return 0;
        if (x < 0 || y < 0 || x >= W || y >= H) { ++*out; continue; }
        if (!has_pixel(b, nb, x, y)) return 0;
    }
    for (k = 0; k < nb; k++) {
        if (!pt_diff_small(b[k].x) || !pt_diff_small(b[k].y)) return 0;
        if (!has_pixel(a, na, b[k].x - dx, b[k].y - dy)) return 0;
    }
    return 1;
}

/* Whether ACTUAL's lit pixels are EXPECTED's moved: tried with the shift of
** the first pixels (top row first) and of the last ones; into c->px_shift. */
static void find_shift(dctx *c, const pkey *a, size_t na, const pkey *b, size_t nb)
{
    const pt_thdr *hd = &c->t[0].hdr;
    int64_t W = hd->have ? hd->fb_w : INT64_MAX, H = hd->have ? hd->fb_h : INT64_MAX;
    int64_t d[2][2];
    size_t out;
    int k;

    c->px_shift = 0;
    if (!na || !nb) return;
    d[0][0] = b[0].x - a[0].x; d[0][1] = b[0].y - a[0].y;
    d[1][0] = b[nb - 1].x - a[na - 1].x; d[1][1] = b[nb - 1].y - a[na - 1].y;
    for (k = 0; k < 2; k++)
        if (is_shift(a, na, b, nb, d[k][0], d[k][1], W, H, &out)) {
            c->px_shift = 1;
            c->px_d[0] = d[k][0];
            c->px_d[1] = d[k][1];
            c->px_out = out;
            return;
        }
}

/* Compare the sets of lit pixels: count the missing and extra ones into
** *nmiss and *nextra, and list a few of each.  nlit[s]: distinct pixels of
** side s. */
int pt_diff_compare_pixels(dctx *c, size_t *nmiss, size_t *nextra, size_t nlit[2])
{
    pkey *p[2];
    size_t n[2], count[2] = {0, 0};
    int pass;

    p[0] = sorted_pixels(&c->t[0], &n[0]);
    p[1] = sorted_pixels(&c->t[1], &n[1]);
    if (!p[0] || !p[1]) { free(p[0]); free(p[1]); return -1; }
    nlit[0] = n[0];
    nlit[1] = n[1];
    /* pass 0 counts; pass 1 lists the missing, pass 2 the extra ones */
    for (pass = 0; pass < 3; pass++) {
        size_t a = 0, b = 0, shown = 0;
        int want = pass - 1;                /* the side listed: 0 missing, 1 extra */
        if (pass == 1 && count[0] && count[1]) find_shift(c, p[0], n[0], p[1], n[1]);
        if (pass == 1 && c->px_shift) {
            pbuf sb;
            memset(&sb, 0, sizeof sb);
            pt_diff_add(&sb, "Lit pixels: %zu in EXPECTED, %zu in ACTUAL: ACTUAL's are EXPECTED's "
                        "moved by (%" PRId64 ", %" PRId64 ")", n[0], n[1], c->px_d[0], c->px_d[1]);
            if (c->px_out) pt_diff_add(&sb, ", %zu of them out of the framebuffer", c->px_out);
            pt_diff_add(&sb, ".");
            pt_diff_para("", sb.b);
            break;
        }
        if (pass == 1 && (count[0] || count[1]))
            printf("Lit pixels: %zu in EXPECTED, %zu in ACTUAL.\n", n[0], n[1]);
        if (pass && !count[want]) continue;
        if (pass) printf("  %s in ACTUAL: %zu\n", want ? "extra" : "missing", count[want]);
        while ((a < n[0] || b < n[1]) && (pass == 0 || shown < c->o->show)) {
            int side, cmp = a >= n[0] ? 1 : b >= n[1] ? -1 : 0;
            const pkey *q;
            if (!cmp) {
                pkey x = p[0][a], y = p[1][b];
                x.k = y.k = 0;
                cmp = pkey_cmp(&x, &y);
            }
            if (!cmp) { a++; b++; continue; }
            side = cmp < 0 ? 0 : 1;
            q = side ? &p[1][b++] : &p[0][a++];
            if (pass == 0) { count[side]++; continue; }
            if (side == want) {
                const pt_tpix *x = &c->t[side].px[q->k];
                printf("    (x_fb, y_fb) = (%" PRId64 ", %" PRId64 "), idx %" PRId64
                       ", from %s s%" PRIu64 "\n", x->x, x->y, x->i,
                       pt_names_get(&c->nm, x->model), x->seg);
                shown++;
            }
        }
        if (pass && count[want] > shown) printf("    ... and %zu more\n", count[want] - shown);
    }
    *nmiss = count[0];
    *nextra = count[1];
    free(p[0]);
    free(p[1]);
    return 0;
}

size_t pt_diff_raster_named(const rstat *rs, size_t named[PT_NRASTER_MISTAKES])
{
    size_t k, n = 0;

    for (k = 0; k < PT_NRASTER_MISTAKES; k++)
        if (rs->segs_differ && rs->hits[k] == rs->segs_differ && !rs->breaks[k]) named[n++] = k;
    return n;
}

void pt_diff_raster_second(const rstat *rs, pbuf *s)
{
    size_t j, one = 0, n = 0;

    if (!rs->own_bad || rs->own_tried != rs->segs_differ) return;
    for (j = 0; j < PT_NRASTER_MISTAKES; j++)
        if (!rs->own_misfit[j]) { one = j; n++; }
    if (n == 1)
        pt_diff_add(s, " Likely second mistake: %s %s, which from ACTUAL's own end pixels draws "
                    "ACTUAL's pixels in every segment.", pt_raster_mistakes[one].name,
                    pt_raster_mistakes[one].where);
}

/* Print the raster check's details for the first differing segment. */
void pt_diff_report_raster(const dctx *c, const rstat *rs)
{
    pbuf sb;
    size_t k, j, named[PT_NRASTER_MISTAKES], n = pt_diff_raster_named(rs, named);

    if (!rs->first_set) return;
    memset(&sb, 0, sizeof sb);
    if (rs->segs_differ == 1)
        pt_diff_add(&sb, "Every vertex agrees, so the rasterizer differs: segment %s s%" PRIu64
                    " lights other pixels.", pt_names_get(&c->nm, rs->first_model), rs->first_seg);
    else
        pt_diff_add(&sb, "Every vertex agrees, so the rasterizer differs: %zu segments light other "
                    "pixels, the first %s s%" PRIu64 ".", rs->segs_differ,
                    pt_names_get(&c->nm, rs->first_model), rs->first_seg);
    if (!rs->ends_ok)
        pt_diff_add(&sb, " Its endpoints cannot be read off EXPECTED's steps, so no mistake was "
                    "checked.");
    pt_diff_para("  ", sb.b);
    for (k = 0; rs->ends_ok && k < PT_NRASTER_MISTAKES; k++) {
        if (!rs->hits[k] || (rs->hits[k] == rs->segs_differ && !rs->breaks[k])) continue;
        memset(&sb, 0, sizeof sb);             /* never a confident name for part of it */
        if (rs->hits[k] < rs->segs_differ)
            pt_diff_add(&sb, "partial: %s reproduces %zu of the %zu segments that differ: it "
                        "does NOT explain them.", pt_raster_mistakes[k].name, rs->hits[k],
                        rs->segs_differ);
        else
            pt_diff_add(&sb, "partial: %s reproduces every segment that differs, but would "
                        "light %zu of those that agree otherwise: it does NOT explain them.",
                        pt_raster_mistakes[k].name, rs->breaks[k]);
        pt_diff_para("  ", sb.b);
    }
    if (!rs->ends_ok || !n) return;
    if (n > 1) {
        memset(&sb, 0, sizeof sb);
        pt_diff_add(&sb, "ambiguous: ");
        for (k = 0; k < n; k++)
            pt_diff_add(&sb, "%s%s", k ? " or " : "", pt_raster_mistakes[named[k]].name);
        pt_diff_add(&sb, ": each reproduces ACTUAL's pixels in every segment that differs.");
        for (k = 0; k < n; k++)
            for (j = 0; j < n; j++)
                if (pt_raster_mistakes[named[k]].twin - 1 == (int)named[j] && !rs->apart[named[k]])
                    pt_diff_add(&sb, " %s and %s light other pixels only at steps left of or "
                                "below the viewport, which this trace does not tell apart.",
                                pt_raster_mistakes[named[j]].name, pt_raster_mistakes[named[k]].name);
        pt_diff_para("  ", sb.b);
        {
            const char *names[PT_NRASTER_MISTAKES];
            for (k = 0; k < n; k++) names[k] = pt_raster_mistakes[named[k]].name;
            pt_diff_separate(c, names, n, 1);
        }
        return;
    }
    k = named[0];
    printf("  likely mistake: %s\n", pt_raster_mistakes[k].name);
    pt_diff_para("    ", pt_raster_mistakes[k].how);
    memset(&sb, 0, sizeof sb);
    pt_diff_add(&sb, "check: the DDA run again from the rounded endpoints (%" PRId64 ", %" PRId64
                ") and (%" PRId64 ", %" PRId64 ") lights EXPECTED's pixels without it and "
                "ACTUAL's with it", rs->ends[0], rs->ends[1], rs->ends[2], rs->ends[3]);
    if (rs->segs_differ > 1)
        pt_diff_add(&sb, "; so it does for all %zu segments that differ", rs->segs_differ);
    pt_diff_add(&sb, ".");
    pt_diff_para("    ", sb.b);
}
