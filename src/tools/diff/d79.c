/*
** src/tools/diff/d79.c -- pipetrace diff for the course's renderers 7 and 9
** See LICENSE for copyright and license.
**
** Two traces or logs of one renderer 7 or 9 scene (io/tread79.h), compared
** stage by stage for each (position, vertex), the clip stages' new vertices
** included, then pixel by pixel; the first stage that differs tested against
** the catalogue of the two renderers' mistakes (tools/catalogue79.h); the
** verdict by renderer 4's rules: PASS only when every stage either side has
** and the pixels were compared and agree.
**
** Two numbers agree when |a - b| <= max(--tol, --rel * max(|a|, |b|)) plus
** half a unit in the last digit each side printed (a log: 5 decimals).
** Colours: bytes agree when equal; a byte and a float when the float's byte
** (java.awt.Color's rounding) is that byte; two floats as numbers.
*/
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread79.h"
#include "tools/catalogue79.h"
#include "tools/diff/diff.h"
#include "tools/diff/dseparate.h"

/* The two sides and the command line. */
typedef struct d79 {
    const dopts *o;
    pt_t79 t[2];
    pt_names nm;
    size_t *ix[2];               /* vertex records sorted by (pos, stage, v) */
    size_t *px[2];               /* pixels sorted by (x, y, file order) */
} d79;

static const d79 *sort_ctx;
static int sort_side;

static int cmp_vx(const void *a, const void *b)
{
    const pt_t79v *p = &sort_ctx->t[sort_side].vx[*(const size_t *)a];
    const pt_t79v *q = &sort_ctx->t[sort_side].vx[*(const size_t *)b];
    if (p->pos != q->pos) return p->pos < q->pos ? -1 : 1;
    if (p->st != q->st) return p->st < q->st ? -1 : 1;
    if (p->v != q->v) return p->v < q->v ? -1 : 1;
    return *(const size_t *)a < *(const size_t *)b ? -1 : 1;
}

/* Primitives by (position, stage), in file order within. */
static int cmp_pr(const void *a, const void *b)
{
    const pt_t79prim *p = a, *q = b;
    if (p->pos != q->pos) return p->pos < q->pos ? -1 : 1;
    if (p->st != q->st) return p->st < q->st ? -1 : 1;
    return p->seq < q->seq ? -1 : p->seq > q->seq;
}

static int cmp_px(const void *a, const void *b)
{
    const pt_t79px *p = &sort_ctx->t[sort_side].px[*(const size_t *)a];
    const pt_t79px *q = &sort_ctx->t[sort_side].px[*(const size_t *)b];
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    if (p->y != q->y) return p->y < q->y ? -1 : 1;
    return *(const size_t *)a < *(const size_t *)b ? -1 : 1;
}

/* -1, 0, 1 as vertex record a of side 0 sorts before, with, after b of side 1. */
static int key_cmp(const pt_t79v *a, const pt_t79v *b)
{
    if (a->pos != b->pos) return a->pos < b->pos ? -1 : 1;
    if (a->st != b->st) return a->st < b->st ? -1 : 1;
    if (a->v != b->v) return a->v < b->v ? -1 : 1;
    return 0;
}

static int pkey_cmp(const pt_t79px *a, const pt_t79px *b)
{
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    return 0;
}

/* 1 when a (exact to half a unit ta) and b (tb) agree. */
static int num_agree(const d79 *c, double a, double b, double ta, double tb)
{
    double m = fmax(fabs(a), fabs(b));
    if (isnan(a) || isnan(b)) return isnan(a) && isnan(b);
    if (a == b) return 1;
    return fabs(a - b) <= fmax(c->o->tol, c->o->rel * m) + ta + tb;
}

/* x * 255 rounded, within -1 .. 256 (NaN: -1): a byte read back, or out of range. */
static long byte_of(double x)
{
    double b = x * 255;
    if (!(b > -1)) return -1;
    return b > 256 ? 256 : lround(b);
}

/* The bytes java.awt.Color may make of side s's colour component x: [*lo, *hi]
** (a byte itself; a float printed to fewer digits may stand for either of two). */
static void byte_range(const d79 *c, int s, double x, unsigned *lo, unsigned *hi)
{
    if (c->t[s].cbytes) {
        *lo = *hi = (unsigned)(byte_of(x) + 1);     /* shifted by 1, as below */
    } else {
        *lo = pt_color_byte((float)(x - c->t[s].ctol)) + 1u;
        *hi = pt_color_byte((float)(x + c->t[s].ctol)) + 1u;
    }
}

/* 1 when the vertex colours a (of side 0) and b (side 1) agree. */
static int color_agree(const d79 *c, const double *a, const double *b)
{
    int k, bytes = c->t[0].cbytes || c->t[1].cbytes;
    for (k = 0; k < 3; k++) {
        if (bytes) {
            unsigned alo, ahi, blo, bhi;
            byte_range(c, 0, a[k], &alo, &ahi);
            byte_range(c, 1, b[k], &blo, &bhi);
            if (ahi < blo || bhi < alo) return 0;
        } else if (!num_agree(c, a[k], b[k], c->t[0].ctol, c->t[1].ctol)) {
            return 0;
        }
    }
    return 1;
}

/* Which of x, y, z, w (bits 0..3) and the colour (bit 4) differ. */
static unsigned vx_differ(const d79 *c, const pt_t79v *a, const pt_t79v *b)
{
    unsigned m = 0;
    int k;
    for (k = 0; k < 4; k++) {
        if (k == 3 && !(a->has_w && b->has_w)) continue;
        if (!num_agree(c, a->x[k], b->x[k], c->t[0].vtol, c->t[1].vtol)) m |= 1u << k;
    }
    if (a->has_rgb && b->has_rgb && !color_agree(c, a->rgb, b->rgb)) m |= 16;
    return m;
}

/* Side s's record of (pos, st, v), or NULL. */
static const pt_t79v *find(const d79 *c, int s, uint32_t pos, int st, uint32_t v)
{
    size_t lo = 0, hi = c->t[s].nvx;
    pt_t79v key;
    key.pos = pos; key.st = (unsigned char)st; key.v = v;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int r = key_cmp(&c->t[s].vx[c->ix[s][mid]], &key);
        if (r == 0) return &c->t[s].vx[c->ix[s][mid]];
        if (r < 0) lo = mid + 1; else hi = mid;
    }
    return NULL;
}

/* ===== the stages ===== */

typedef struct stagecount {
    size_t both, differ, only[2];
    size_t first;                /* index in ix[0] of the first that differs */
} stagecount;

static void print_vertex(const d79 *c, const pt_t79v *a, const pt_t79v *b, unsigned m)
{
    static const char *const nm[5] = {"x", "y", "z", "w", "rgb"};
    int k;
    printf("  %s v%lu %s:", pt_names_get(&c->nm, a->pos), (unsigned long)a->v,
           pt_t79_stage_name(a->st));
    for (k = 0; k < 5; k++) {
        if (!(m & (1u << k))) continue;
        if (k < 4) {
            char ea[PT_NUMLEN], eb[PT_NUMLEN];
            printf("  %s %s | %s", nm[k], pt_diff_num(a->x[k], ea), pt_diff_num(b->x[k], eb));
        }
        else printf("  rgb %.6g %.6g %.6g | %.6g %.6g %.6g", a->rgb[0], a->rgb[1], a->rgb[2],
                    b->rgb[0], b->rgb[1], b->rgb[2]);
    }
    printf("   (lines %lu, %lu)\n", (unsigned long)a->line, (unsigned long)b->line);
}

/* Compare every vertex; fill sc[st]; print the differences, at most show. */
static void compare_vertices(const d79 *c, stagecount sc[PT_T79_NSTAGES])
{
    size_t i = 0, j = 0, shown = 0;
    const pt_t79 *e = &c->t[0], *a = &c->t[1];

    memset(sc, 0, PT_T79_NSTAGES * sizeof sc[0]);
    while (i < e->nvx || j < a->nvx) {
        const pt_t79v *p = i < e->nvx ? &e->vx[c->ix[0][i]] : NULL;
        const pt_t79v *q = j < a->nvx ? &a->vx[c->ix[1][j]] : NULL;
        int r = !p ? 1 : !q ? -1 : key_cmp(p, q);
        if (r < 0) { sc[p->st].only[0]++; i++; continue; }
        if (r > 0) { sc[q->st].only[1]++; j++; continue; }
        sc[p->st].both++;
        {
            unsigned m = vx_differ(c, p, q);
            if (m) {
                if (!sc[p->st].differ++) sc[p->st].first = i;
                if (shown++ < c->o->show) {
                    if (shown == 1) printf("Vertices that differ (position vN stage: EXPECTED | ACTUAL):\n");
                    print_vertex(c, p, q, m);
                }
            }
        }
        i++; j++;
    }
    if (shown > c->o->show) printf("  ... and %zu more\n", shown - c->o->show);
    if (shown) printf("\n");
}

/* ===== the pixels ===== */

typedef struct pixcount {
    size_t both, missing, extra, color;
} pixcount;

/* 1 when pixel colours a (side 0) and b (side 1) agree. */
static int pcolor_agree(const d79 *c, const double *a, const double *b)
{
    int k;
    for (k = 0; k < 3; k++) {
        if (c->t[0].kind != PT_T79_LOG && c->t[1].kind != PT_T79_LOG) {
            if (byte_of(a[k]) != byte_of(b[k])) return 0;
        } else if (fabs(a[k] - b[k]) > c->t[0].ptol + c->t[1].ptol + 1e-9) {
            return 0;
        }
    }
    return 1;
}

/* Walk the matched pixels; f (may be NULL) is told each pair.  Counts into *pc. */
static void walk_pixels(const d79 *c, pixcount *pc, int (*f)(const d79 *, size_t, size_t, void *),
                        void *ud, int print)
{
    size_t i = 0, j = 0, shown = 0;
    memset(pc, 0, sizeof *pc);
    while (i < c->t[0].npx || j < c->t[1].npx) {
        const pt_t79px *p = i < c->t[0].npx ? &c->t[0].px[c->px[0][i]] : NULL;
        const pt_t79px *q = j < c->t[1].npx ? &c->t[1].px[c->px[1][j]] : NULL;
        int r = !p ? 1 : !q ? -1 : pkey_cmp(p, q);
        if (r != 0) {
            if (r < 0) { pc->missing++; i++; } else { pc->extra++; j++; }
            if (print && shown++ < c->o->show)
                printf("  pixel (%lld, %lld) only in %s (line %lu)\n",
                       (long long)(r < 0 ? p->x : q->x), (long long)(r < 0 ? p->y : q->y),
                       r < 0 ? "EXPECTED" : "ACTUAL", (unsigned long)(r < 0 ? p->line : q->line));
            continue;
        }
        pc->both++;
        if (f) f(c, c->px[0][i], c->px[1][j], ud);
        else if (!pcolor_agree(c, p->rgb, q->rgb)) {
            pc->color++;
            if (print && shown++ < c->o->show)
                printf("  pixel (%lld, %lld) rgb %.4f %.4f %.4f | %.4f %.4f %.4f (lines %lu, %lu)\n",
                       (long long)p->x, (long long)p->y, p->rgb[0], p->rgb[1], p->rgb[2],
                       q->rgb[0], q->rgb[1], q->rgb[2], (unsigned long)p->line,
                       (unsigned long)q->line);
        }
        i++; j++;
    }
    if (print && shown > c->o->show) printf("  ... and %zu more pixels differ\n", shown - c->o->show);
}

/* ===== the catalogue ===== */

/* The stage a vertex mistake of st computes from. */
static int prev_stage(const d79 *c, int st)
{
    if (st == PT_T79_WORLD) return PT_T79_MODEL;
    if (st == PT_T79_CAMERA) return PT_T79_VIEW;
    if (st == PT_T79_VIEW) return c->t[0].renderer == 9 ? PT_T79_WORLD : PT_T79_MODEL;
    return -1;
}

/* How much a stage of cam may grow an error of EXPECTED's numbers (its
** rounding to the digits it printed): the camera stage's skew and scale, at
** least 3 (the view mistake's 2 world - view). */
static double gain(const pt_c79cam *cam)
{
    double s = fmax(2 / fabs(cam->r - cam->l), 2 / fabs(cam->t - cam->b));
    double g = 4 * (1 + fabs(cam->r + cam->l) + fabs(cam->t + cam->b)) * fmax(1, s);
    return isfinite(g) && g > 3 ? g : 3;
}

/* 1 when ACTUAL has every vertex EXPECTED has at stage st. */
static int all_in_actual(const d79 *c, int st)
{
    size_t k;
    for (k = 0; k < c->t[0].nvx; k++)
        if (c->t[0].vx[k].st == st && !find(c, 1, c->t[0].vx[k].pos, st, c->t[0].vx[k].v))
            return 0;
    return 1;
}

/* 1 when vertex mistake m gives ACTUAL's values at its stage for every vertex. */
static int explains_vertices(const d79 *c, const pt_mistake79 *m, const pt_c79cam *cam)
{
    size_t k;
    int ps = prev_stage(c, m->stage), any = 0;

    if (ps < 0) return 0;
    for (k = 0; k < c->t[1].nvx; k++) {
        const pt_t79v *a = &c->t[1].vx[c->ix[1][k]], *e, *p;
        double out[4];
        int i;
        if (a->st != m->stage) continue;
        e = find(c, 0, a->pos, a->st, a->v);
        p = find(c, 0, a->pos, ps, a->v);
        if (!e || !p) return 0;
        m->vertex(cam, p->x, e->x, out);
        for (i = 0; i < 3; i++) {
            double tol = c->t[1].vtol + gain(cam) * c->t[0].vtol +
                         4 * DBL_EPSILON * fmax(fabs(out[i]), fabs(a->x[i]));
            if (!(fabs(out[i] - a->x[i]) <= fmax(tol, c->o->tol)) && !(out[i] == a->x[i]))
                return 0;
        }
        any = 1;
    }
    return any && all_in_actual(c, m->stage);
}

/* Record r's values as (x, y, z, w), w 1 when it has none. */
static void xyzw(const pt_t79v *r, double o[4])
{
    o[0] = r->x[0]; o[1] = r->x[1]; o[2] = r->x[2]; o[3] = r->has_w ? r->x[3] : 1.0;
}

/* 1 when position mistake m gives ACTUAL's values at its stage for every
** vertex of each position, by one of its ways (alt) per position. */
static int explains_positions(const d79 *c, const pt_mistake79 *m)
{
    const pt_t79 *a = &c->t[1];
    size_t k = 0, any = 0;
    int ps = prev_stage(c, m->stage);

    while (ps >= 0 && k < a->nvx) {
        const pt_t79v *r = &a->vx[c->ix[1][k]];
        size_t j = k, n, i;
        double (*prev)[4], (*right)[4], (*out)[4], mag = 1;
        int ok = 0, alt, bad = 0;
        if (r->st != m->stage) { k++; continue; }
        while (j < a->nvx && a->vx[c->ix[1][j]].pos == r->pos && a->vx[c->ix[1][j]].st == r->st) j++;
        n = j - k;
        prev = malloc(3 * n * sizeof *prev);
        if (!prev) return 0;
        right = prev + n;
        out = prev + 2 * n;
        for (i = 0; i < n && !bad; i++) {
            const pt_t79v *q = &a->vx[c->ix[1][k + i]];
            const pt_t79v *e = find(c, 0, q->pos, q->st, q->v), *p = find(c, 0, q->pos, ps, q->v);
            int d;
            if (!e || !p) { bad = 1; break; }
            xyzw(p, prev[i]);
            xyzw(e, right[i]);
            for (d = 0; d < 3; d++) mag = fmax(mag, fmax(fabs(prev[i][d]), fabs(right[i][d])));
        }
        for (alt = 0; !bad && !ok && m->position(n, (const double (*)[4])prev,
                                                (const double (*)[4])right, alt, out) == 0; alt++) {
            /* EXPECTED's rounding (or the fit's own, on exact numbers)
            ** through the fit: up to about mag^2 units */
            double tol = a->vtol + (8 * c->t[0].vtol + 64 * DBL_EPSILON) * (1 + mag) * (1 + mag);
            ok = 1;
            for (i = 0; i < n && ok; i++) {
                const pt_t79v *q = &a->vx[c->ix[1][k + i]];
                int d;
                for (d = 0; d < (q->has_w ? 4 : 3) && ok; d++) {
                    double t = fmax(tol, fmax(c->o->tol, c->o->rel * fabs(out[i][d])));
                    if (!(fabs(out[i][d] - q->x[d]) <= t) && out[i][d] != q->x[d]) ok = 0;
                }
            }
        }
        free(prev);
        if (!ok) return 0;
        any = 1;
        k = j;
    }
    return any && all_in_actual(c, m->stage);
}

/* EXPECTED's colour of vertex v of pos at stage st, or the nearest stage
** before it that has one; NULL when none does. */
static const double *color_at(const d79 *c, uint32_t pos, int st, uint32_t v)
{
    for (; st >= 0; st--) {
        const pt_t79v *r = find(c, 0, pos, st, v);
        if (r && r->has_rgb) return r->rgb;
    }
    return NULL;
}

/* The first of side s's primitives of (pos, st) or after: prims sorted by cmp_pr. */
static size_t prim_lower(const d79 *c, int s, uint32_t pos, int st)
{
    size_t lo = 0, hi = c->t[s].npr;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const pt_t79prim *p = &c->t[s].pr[mid];
        if (p->pos < pos || (p->pos == pos && p->st < st)) lo = mid + 1; else hi = mid;
    }
    return lo;
}

/* The primitives entering clip stage st for pos: side s's list (a log's),
** [*first, *first + *n); the rectangle clip takes the near clip's output, or
** the camera's list when there is none (nearclip off). */
static void prims_of(const d79 *c, int s, uint32_t pos, int st, size_t *first, size_t *n)
{
    int want = st == PT_T79_NEARCLIP ? PT_T79_CAMERA : PT_T79_NEARCLIP, pass;
    for (pass = 0; pass < 2; pass++, want = PT_T79_CAMERA) {
        size_t k = *first = prim_lower(c, s, pos, want);
        while (k < c->t[s].npr && c->t[s].pr[k].pos == pos && c->t[s].pr[k].st == want) k++;
        *n = k - *first;
        if (*n || st == PT_T79_NEARCLIP) return;
    }
}

/* How many records side s has of (pos, st). */
static size_t count_at(const d79 *c, int s, uint32_t pos, int st)
{
    size_t lo = 0, hi = c->t[s].nvx, a;
    pt_t79v key;
    key.pos = pos; key.st = (unsigned char)st; key.v = 0;
    while (lo < hi) {                           /* the first at or after (pos, st, 0) */
        size_t mid = lo + (hi - lo) / 2;
        if (key_cmp(&c->t[s].vx[c->ix[s][mid]], &key) < 0) lo = mid + 1; else hi = mid;
    }
    a = lo;
    key.v = UINT32_MAX;
    hi = c->t[s].nvx;
    while (lo < hi) {                           /* the first after (pos, st, max) */
        size_t mid = lo + (hi - lo) / 2;
        if (key_cmp(&c->t[s].vx[c->ix[s][mid]], &key) <= 0) lo = mid + 1; else hi = mid;
    }
    return lo - a;
}

/* 1 when clip mistake m, run on EXPECTED's model entering its stage for pos,
** makes ACTUAL's new vertices of that stage; 0 otherwise or when it cannot be
** run (no primitive list, a colour index not its vertex's). */
static int explains_clip_pos(const d79 *c, const pt_mistake79 *m, const pt_c79cam *cam,
                             uint32_t pos)
{
    int in = m->stage == PT_T79_NEARCLIP ? PT_T79_CAMERA : PT_T79_IMAGE, s, ok = 1;
    size_t first = 0, n = 0, k, nold = 0;
    pt_rv_model mdl;
    const pt_t79 *src;

    for (s = 0; s < 2 && !n; s++) prims_of(c, s, pos, m->stage, &first, &n);
    if (!n) return 0;
    src = &c->t[s - 1];
    memset(&mdl, 0, sizeof mdl);
    for (;; nold++) {                           /* vertices 1, 2, .. of the stage before */
        const pt_t79v *r = find(c, 0, pos, in, (uint32_t)nold + 1);
        const double *rgb = color_at(c, pos, in, (uint32_t)nold + 1);
        pt_vec4 v;
        pt_rgb col;
        if (!r) break;
        if (!rgb) { ok = 0; break; }
        v.x = r->x[0]; v.y = r->x[1]; v.z = r->x[2]; v.w = r->has_w ? r->x[3] : 1.0;
        col.r = (float)rgb[0]; col.g = (float)rgb[1]; col.b = (float)rgb[2];
        if (pt_rv_add_vertex(&mdl, v) != 0 || pt_rv_add_color(&mdl, col) != 0) { ok = 0; break; }
    }
    for (k = first; ok && k < first + n; k++) {
        const pt_t79prim *p = &src->pr[k];
        pt_rv_prim q;
        if (p->v[0] != p->c[0] || p->v[1] != p->c[1] || p->v[0] >= nold || p->v[1] >= nold) {
            ok = 0;
            break;
        }
        memset(&q, 0, sizeof q);
        q.kind = p->point ? PT_RV_POINT : PT_RV_LINE;
        q.v[0] = p->v[0]; q.v[1] = p->v[1]; q.c[0] = p->c[0]; q.c[1] = p->c[1];
        q.radius = p->radius;
        if (pt_rv_add_prim(&mdl, &q) != 0) ok = 0;
    }
    if (ok && m->clip(cam, &mdl) != 0) ok = 0;
    for (k = nold; ok && k < mdl.nv; k++) {     /* each vertex the mistake made */
        const pt_t79v *a = find(c, 1, pos, m->stage, (uint32_t)k + 1);
        double p[3];
        int i;
        if (!a) { ok = 0; break; }
        p[0] = mdl.v[k].x; p[1] = mdl.v[k].y; p[2] = mdl.v[k].z;
        for (i = 0; i < 3 && ok; i++) {
            double tol = c->t[1].vtol + 4 * c->t[0].vtol + 4 * DBL_EPSILON * fabs(p[i]);
            if (!(fabs(p[i] - a->x[i]) <= fmax(tol, c->o->tol)) && p[i] != a->x[i]) ok = 0;
        }
        if (ok && a->has_rgb && k < mdl.nc) {
            const float f[3] = {mdl.c[k].r, mdl.c[k].g, mdl.c[k].b};
            for (i = 0; i < 3; i++) {
                if (c->t[1].cbytes ? (long)pt_color_byte(f[i]) != byte_of(a->rgb[i])
                                   : fabs((double)f[i] - a->rgb[i]) > c->t[1].ctol + 1e-7)
                    ok = 0;
            }
        }
    }
    if (ok && count_at(c, 1, pos, m->stage) != mdl.nv - nold) ok = 0;   /* and none more */
    pt_rv_model_free(&mdl);
    return ok;
}

/* 1 when clip mistake m explains the new vertices of every position. */
static int explains_clip(const d79 *c, const pt_mistake79 *m, const pt_c79cam *cam)
{
    size_t k;
    int in = m->stage == PT_T79_NEARCLIP ? PT_T79_CAMERA : PT_T79_IMAGE, any = 0;
    for (k = 0; k < c->t[0].nvx; k++) {
        const pt_t79v *r = &c->t[0].vx[k];
        if (r->st != in || r->v != 1) continue;
        if (!explains_clip_pos(c, m, cam, r->pos)) return 0;
        any = 1;
    }
    return any;
}

typedef struct pixfit {
    const pt_mistake79 *m;
    int ok;
} pixfit;

static int pixel_fits(const d79 *c, size_t ie, size_t ia, void *ud)
{
    pixfit *f = ud;
    const pt_t79px *p = &c->t[0].px[ie], *q = &c->t[1].px[ia];
    const double *partner = p->pair ? c->t[0].px[p->pair - 1].rgb : p->rgb;
    double lo[3], hi[3], tol = c->t[1].ptol + 1e-6;
    int k;

    if (p->seg_end && f->m->gamma) {
        for (k = 0; k < 3; k++) lo[k] = hi[k] = p->rgb[k];     /* written without gamma */
        tol += c->t[0].ptol;
    } else {
        f->m->pixel(p->rgb, partner, p->pair != 0, c->t[0].ptol, lo, hi);
    }
    for (k = 0; k < 3; k++)
        if (q->rgb[k] < lo[k] - tol || q->rgb[k] > hi[k] + tol) f->ok = 0;
    return 0;
}

/* Print the catalogue's finding for stage st (PT_T79_NSTAGES: the pixels);
** returns how many mistakes explain everything, the first in *which. */
static int fit(const d79 *c, int st, int *which)
{
    pt_c79cam cam;
    int k, n = 0, first = -1;
    char names[1024] = "";
    const char *listed[PT_NMISTAKES79];
    pbuf pb;

    cam.renderer = c->t[0].renderer;
    cam.persp = c->t[0].persp;
    cam.l = c->t[0].l; cam.r = c->t[0].r; cam.b = c->t[0].b; cam.t = c->t[0].t; cam.n = c->t[0].n;
    for (k = 0; k < PT_NMISTAKES79; k++) {
        const pt_mistake79 *m = &pt_mistakes79[k];
        int ok;
        if (m->stage != st || (m->renderer && m->renderer != cam.renderer)) continue;
        if (m->vertex) {
            if (st == PT_T79_CAMERA && !c->t[0].have_cam) continue;
            ok = explains_vertices(c, m, &cam);
        } else if (m->clip) {
            if (st == PT_T79_NEARCLIP && !c->t[0].have_cam) continue;
            ok = explains_clip(c, m, &cam);
        } else if (m->position) {
            ok = explains_positions(c, m);
        } else {
            pixfit f;
            pixcount pc;
            f.m = m;
            f.ok = 1;
            walk_pixels(c, &pc, pixel_fits, &f, 0);
            ok = f.ok && !pc.missing && !pc.extra;
        }
        if (!ok) continue;
        pt_diff_outcome_named(c->o->out, m->name);
        listed[n] = m->name;
        if (n++ == 0) first = k;
        if (strlen(names) + strlen(m->name) + 8 < sizeof names) {
            if (names[0]) strcat(names, " or ");
            strcat(names, m->name);
        }
    }
    if (n == 1) {
        printf("Mistake: %s (%s).\n", pt_mistakes79[first].name,
               st < PT_T79_NSTAGES ? pt_t79_stage_name(st) : "pixels");
        pb.n = 0;
        pt_diff_add(&pb, "%s.", pt_mistakes79[first].how);
        pt_diff_para("  ", pb.b);
    } else if (n > 1) {
        pt_sep *sep = malloc(sizeof *sep);
        printf("Mistake: ambiguous: %s (each gives ACTUAL's %s exactly).\n", names,
               st < PT_T79_NSTAGES ? pt_t79_stage_name(st) : "pixels");
        if (sep) {
            pt_sep_course(&cam, listed, (size_t)n, sep);
            if (pt_sep_emit(sep, sep->ok ? c->o->sep_out : NULL) != 0) c->o->out->sep = -1;
            else if (sep->ok) c->o->out->sep = 1;
            free(sep);
        }
    } else {
        pb.n = 0;
        pt_diff_add(&pb, "Mistake: unknown (no known mistake of %s gives ACTUAL's values for "
                    "every %s).", st < PT_T79_NSTAGES ? pt_t79_stage_name(st) : "the pixels",
                    st < PT_T79_NSTAGES ? "vertex" : "pixel");
        pt_diff_para("", pb.b);
    }
    *which = first;
    return n;
}

/* ===== the command ===== */

static const char *kind_name(pt_t79_kind k)
{
    switch (k) {
    case PT_T79_JSONL: return "JSON Lines trace";
    case PT_T79_TEXT: return "text trace";
    case PT_T79_CSV: return "CSV trace";
    case PT_T79_LOG: return "course log";
    }
    return "?";
}

static int run(d79 *c)
{
    stagecount sc[PT_T79_NSTAGES];
    pixcount pc;
    int st, s, first = -1, pix = 0, nfit = 0, which = -1, proven = 1;
    size_t differ = 0;

    for (s = 0; s < 2; s++) {
        size_t k;
        c->ix[s] = malloc((c->t[s].nvx + 1) * sizeof *c->ix[s]);
        c->px[s] = malloc((c->t[s].npx + 1) * sizeof *c->px[s]);
        if (!c->ix[s] || !c->px[s]) return -1;
        for (k = 0; k < c->t[s].nvx; k++) c->ix[s][k] = k;
        for (k = 0; k < c->t[s].npx; k++) c->px[s][k] = k;
        sort_ctx = c;
        sort_side = s;
        qsort(c->ix[s], c->t[s].nvx, sizeof *c->ix[s], cmp_vx);
        qsort(c->px[s], c->t[s].npx, sizeof *c->px[s], cmp_px);
        if (c->t[s].npr) qsort(c->t[s].pr, c->t[s].npr, sizeof *c->t[s].pr, cmp_pr);
    }
    printf("Renderer %d: EXPECTED %s (%s), ACTUAL %s (%s)\n\n", c->t[0].renderer, c->o->path[0],
           kind_name(c->t[0].kind), c->o->path[1], kind_name(c->t[1].kind));
    compare_vertices(c, sc);
    printf("Stages (vertices compared, differ; only in EXPECTED, only in ACTUAL):\n");
    for (st = 0; st < PT_T79_NSTAGES; st++) {
        const stagecount *k = &sc[st];
        if (!k->both && !k->only[0] && !k->only[1]) continue;
        printf("  %-9s %6zu compared, %zu differ", pt_t79_stage_name(st), k->both, k->differ);
        if (k->only[0] || k->only[1]) printf("; %zu only in EXPECTED, %zu only in ACTUAL",
                                             k->only[0], k->only[1]);
        printf("\n");
        {
            int made = st == PT_T79_NEARCLIP || st == PT_T79_CLIP;  /* may be one-sided */
            size_t one = k->both || made ? k->only[0] + k->only[1] : 0;
            if (first < 0 && (k->differ || one)) first = st;
            if (!k->both && !made) proven = 0;
            differ += k->differ + one;
        }
    }
    printf("\n");
    if (c->t[0].raster && c->t[1].raster) {
        printf("Pixels (EXPECTED | ACTUAL):\n");
        walk_pixels(c, &pc, NULL, NULL, 1);
        printf("  %zu compared: %zu colours differ, %zu only in EXPECTED, %zu only in ACTUAL\n\n",
               pc.both, pc.color, pc.missing, pc.extra);
        pix = 1;
        if (pc.color || pc.missing || pc.extra) differ++;
        c->o->out->px_compared = 1;
        c->o->out->px_missing = pc.missing;
        c->o->out->px_extra = pc.extra + pc.color;  /* a pixel of another colour: extra */
    } else {
        printf("Not compared: the pixels (%s).\n\n",
               !c->t[0].raster && !c->t[1].raster ? "neither has rasterizer lines" :
               !c->t[0].raster ? "EXPECTED has no rasterizer lines" :
                                 "ACTUAL has no rasterizer lines");
        proven = 0;
    }
    for (s = 0; s < 2; s++)
        if (c->t[s].unread)
            printf("Note: %lu line%s of %s not read (the first: line %lu).\n",
                   (unsigned long)c->t[s].unread, c->t[s].unread == 1 ? "" : "s",
                   s ? "ACTUAL" : "EXPECTED", (unsigned long)c->t[s].unread_line);
    c->o->out->vertices = sc[first >= 0 ? first : 0].both;
    if (first >= 0) {
        c->o->out->differ = sc[first].differ;
        c->o->out->only = sc[first].only[0] + sc[first].only[1];
        pt_diff_outcome_stage(c->o->out, pt_t79_stage_name(first));
    } else if (differ) {
        pt_diff_outcome_stage(c->o->out, "pixels");
    }
    if (first >= 0) {
        printf("First stage that differs: %s (%zu of %zu vertices).\n", pt_t79_stage_name(first),
               sc[first].differ + sc[first].only[0] + sc[first].only[1],
               sc[first].both + sc[first].only[0] + sc[first].only[1]);
        nfit = fit(c, first, &which);
    } else if (differ) {
        printf("First stage that differs: the pixels (every vertex agrees).\n");
        nfit = fit(c, PT_T79_NSTAGES, &which);
    }
    if (!c->o->verdict) return differ ? 1 : 0;
    printf("\nVerdict: ");
    if (differ) {
        printf("FAIL: %s goes wrong first; %s.\n",
               first >= 0 ? pt_t79_stage_name(first) : "the rasterizer",
               nfit == 1 ? pt_mistakes79[which].name : nfit ? "ambiguous" : "mistake unknown");
        return 1;
    }
    if (!proven) {
        printf("NOT PROVEN: nothing differs, but not everything was compared:");
        for (st = 0; st < PT_T79_NSTAGES; st++)
            if (!sc[st].both && (sc[st].only[0] || sc[st].only[1]))
                printf(" %s (only in %s)", pt_t79_stage_name(st), sc[st].only[0] ? "EXPECTED" : "ACTUAL");
        if (!pix) printf(" the pixels");
        printf(".\n");
        return PT_EXIT_UNPROVEN;
    }
    printf("PASS: every stage and every pixel agree.\n");
    (void)pix;
    return 0;
}

int pt_diff79(const dopts *o, char *const buf[2], const size_t len[2])
{
    d79 *c = calloc(1, sizeof *c);
    char err[PT_ERRLEN];
    int s, rc = 0;

    if (!c) return -1;
    c->o = o;
    for (s = 0; s < 2 && rc == 0; s++)
        if (pt_t79_parse(&c->t[s], o->path[s], buf[s], len[s], &c->nm, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            rc = PT_EXIT_INPUT;
        }
    if (rc == 0 && c->t[0].renderer != c->t[1].renderer) {
        fprintf(stderr, "pipetrace diff: error: EXPECTED is of renderer %d, ACTUAL of "
                "renderer %d\n", c->t[0].renderer, c->t[1].renderer);
        rc = PT_EXIT_TROUBLE;
    }
    if (rc == 0) rc = run(c);
    for (s = 0; s < 2; s++) {
        pt_t79_free(&c->t[s]);
        free(c->ix[s]);
        free(c->px[s]);
    }
    pt_names_free(&c->nm);
    free(c);
    return rc;
}
