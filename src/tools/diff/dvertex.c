/*
** src/tools/diff/dvertex.c -- pipetrace diff: the vertex table and the comparison, vertex by vertex
** See LICENSE for copyright and license.
**
** Records are matched by (model, vertex, stage): one hash table keyed by
** (model, v) holds, for each side and stage, the index of that record.  Only
** the FIRST stage where a vertex differs is explained (dexplain.c), since
** every later stage computes from it: its differences are consequences, and
** are only counted.  Doubles agree within the tolerance (--tol, --rel) plus,
** for a text trace, half a unit in its last printed digit.
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/diff/diff.h"

static size_t vhash(uint32_t model, uint64_t v)
{
    uint64_t h = v * 0x9E3779B97F4A7C15u ^ ((uint64_t)model * 0xC2B2AE3D27D4EB4Fu);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9u;
    h ^= h >> 32;
    return (size_t)h;
}

static int vt_rehash(vtab *t, size_t nslot)
{
    uint32_t *slot = calloc(nslot, sizeof *slot);
    size_t k;

    if (!slot) return -1;
    for (k = 0; k < t->n; k++) {
        size_t s = vhash(t->e[k].model, t->e[k].v) & (nslot - 1);
        while (slot[s]) s = (s + 1) & (nslot - 1);
        slot[s] = (uint32_t)k + 1;
    }
    free(t->slot);
    t->slot = slot;
    t->nslot = nslot;
    return 0;
}

/* The entry of (model, v), added when new; NULL when out of memory. */
static vent *vt_get(vtab *t, uint32_t model, uint64_t v)
{
    size_t s;
    vent *e;
    int side, st;

    if (2 * (t->n + 1) >= t->nslot && vt_rehash(t, t->nslot ? 2 * t->nslot : 1024) != 0)
        return NULL;
    s = vhash(model, v) & (t->nslot - 1);
    for (; t->slot[s]; s = (s + 1) & (t->nslot - 1)) {
        e = &t->e[t->slot[s] - 1];
        if (e->model == model && e->v == v) return e;
    }
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 1024;
        vent *ne = cap < UINT32_MAX ? realloc(t->e, cap * sizeof *ne) : NULL;
        if (!ne) return NULL;
        t->e = ne;
        t->cap = cap;
    }
    e = &t->e[t->n];
    e->v = v;
    e->model = model;
    for (side = 0; side < 2; side++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) e->rec[side][st] = PT_DIFF_NONE;
    t->slot[s] = (uint32_t)++t->n;
    return e;
}

/* Fill the vertex table from both sides.  Returns 0, 2 on a duplicate record
** (message printed), -1 when out of memory. */
int pt_diff_fill_table(dctx *c)
{
    int s;
    size_t k;

    for (s = 0; s < 2; s++) {
        for (k = 0; k < c->t[s].nvx; k++) {
            const pt_tvrec *r = &c->t[s].vx[k];
            vent *e;
            if (k >= PT_DIFF_NONE) return -1;
            if (!(e = vt_get(&c->vt, r->model, r->v))) return -1;
            if (e->rec[s][r->stage] != PT_DIFF_NONE) {
                char name[128];
                fprintf(stderr, "%s:%" PRIu32 ":1: error: a second %s record for %s (the "
                        "first is on line %" PRIu32 ")\n", c->o->path[s], r->line,
                        pt_stage_infos[r->stage].name, pt_diff_who(c, r->model, r->v, name, sizeof name),
                        c->t[s].vx[e->rec[s][r->stage]].line);
                return PT_EXIT_INPUT;
            }
            e->rec[s][r->stage] = (uint32_t)k;
        }
    }
    return 0;
}

/* EXPECTED's translations by model id. */
int pt_diff_fill_translations(dctx *c)
{
    const pt_thdr *hd = &c->t[0].hdr;
    size_t k, n = c->nm.n ? c->nm.n : 1;

    c->tr = calloc(n, sizeof *c->tr);
    c->has_tr = calloc(n, 1);
    if (!c->tr || !c->has_tr) return -1;
    for (k = 0; k < hd->nmodels; k++) {
        memcpy(c->tr[hd->models[k].name], hd->models[k].t, sizeof *c->tr);
        c->has_tr[hd->models[k].name] = 1;
    }
    return 0;
}

/* Slack of the number x read from side s: for a text trace, half a unit in
** its last printed digit ("%.Nf"; "%.Ne" from 1e15 up), plus strtod's half ulp.
** For JSON Lines 0: its numbers are the doubles themselves. */
double pt_diff_slack(const dctx *c, int s, double x)
{
    int prec = c->t[s].prec;
    double half, ax = fabs(x);

    if (prec < 0 || !isfinite(x)) return 0.0;
    half = 0.5 * pow(10.0, -prec);
    if (ax >= 1e15) half = 0.5 * pow(10.0, floor(log10(ax)) - prec);
    return half * (1 + 1e-9) + ax * 0x1p-52;
}

/* 1 when x and y agree within the tolerance plus `extra`.  Non-finite values
** agree only with themselves (nan with nan). */
static int near(const dctx *c, double x, double y, double extra)
{
    double allow;

    if (isnan(x) || isnan(y)) return isnan(x) && isnan(y);
    if (isinf(x) || isinf(y)) return x == y;
    allow = fmax(c->o->tol, c->o->rel * fmax(fabs(x), fabs(y)));
    return fabs(y - x) <= allow + extra;
}

/* 1 when a (EXPECTED) and b (ACTUAL) agree. */
int pt_diff_same_real(const dctx *c, double a, double b)
{
    return near(c, a, b, pt_diff_slack(c, 0, a) + pt_diff_slack(c, 1, b));
}

#define D_NULL 0x20u             /* stage_diff: one side has no value (bits 0-3: values) */
#define D_FLAG 0x40u             /* stage_diff: inside or behind differs */

/* Which parts of stage st differ between a and b: bit k for value k, D_NULL,
** D_FLAG.  0 when they agree. */
static unsigned stage_diff(const dctx *c, int st, const pt_tvrec *a, const pt_tvrec *b)
{
    unsigned m = 0;
    int k;

    if (pt_diff_is_real(st)) {
        for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++)
            if (!pt_diff_same_real(c, a->u.d[k], b->u.d[k])) m |= 1u << k;
    } else if ((a->flags ^ b->flags) & PT_REC_NULL) {
        m |= D_NULL;
    } else {                                /* null per value */
        for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
            int ha = pt_flags_have(a->flags, k), hb = pt_flags_have(b->flags, k);
            if (ha != hb || (ha && a->u.n[k] != b->u.n[k])) m |= 1u << k;
        }
    }
    if ((a->flags ^ b->flags) & (PT_REC_INSIDE | PT_REC_BEHIND)) m |= D_FLAG;
    return m;
}

/* Print the differing parts of stage st. */
static void print_stage_diff(int st, const pt_tvrec *a, const pt_tvrec *b, unsigned m)
{
    char b1[PT_NUMLEN], b2[PT_NUMLEN], b3[PT_NUMLEN];
    int k;

    for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
        if (!(m & (D_NULL | 1u << k))) continue;
        printf("    %-5s expected ", pt_diff_coord_name(st, k));
        if (pt_diff_is_real(st)) {
            printf("%s, actual %s", pt_diff_num(a->u.d[k], b1), pt_diff_num(b->u.d[k], b2));
            if (isfinite(a->u.d[k]) && isfinite(b->u.d[k]))
                printf(", difference %s", pt_diff_num(b->u.d[k] - a->u.d[k], b3));
        } else if (!pt_flags_have(a->flags, k)) {
            printf("none, actual %" PRId64, b->u.n[k]);
        } else if (!pt_flags_have(b->flags, k)) {
            printf("%" PRId64 ", actual none", a->u.n[k]);
        } else {
            printf("%" PRId64 ", actual %" PRId64, a->u.n[k], b->u.n[k]);
            if (pt_diff_small(a->u.n[k]) && pt_diff_small(b->u.n[k]))
                printf(", difference %+" PRId64, b->u.n[k] - a->u.n[k]);
        }
        printf("\n");
    }
    if ((a->flags ^ b->flags) & PT_REC_INSIDE)
        printf("    inside the viewport: expected %s, actual %s\n",
               a->flags & PT_REC_INSIDE ? "yes" : "no", b->flags & PT_REC_INSIDE ? "yes" : "no");
    if ((a->flags ^ b->flags) & PT_REC_BEHIND)
        printf("    behind the camera: expected %s, actual %s\n",
               a->flags & PT_REC_BEHIND ? "yes" : "no", b->flags & PT_REC_BEHIND ? "yes" : "no");
}

int pt_diff_first_stage(const dctx *c, const vent *e)
{
    int k, st, here[2] = {0, 0};

    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        here[0] |= e->rec[0][st] != PT_DIFF_NONE;
        here[1] |= e->rec[1][st] != PT_DIFF_NONE;
    }
    if (!here[0] || !here[1]) return -2;
    for (k = 0; k < PT_NSTAGES_ALL; k++) {
        uint32_t i, j;
        st = pt_trace_order[k];
        i = e->rec[0][st];
        j = e->rec[1][st];
        if (i == PT_DIFF_NONE || j == PT_DIFF_NONE) continue;
        if (stage_diff(c, st, &c->t[0].vx[i], &c->t[1].vx[j])) return st;
    }
    return -1;
}

void pt_diff_evidence(const dctx *c, const vent *e, int st, pbuf *s)
{
    const pt_tvrec *a = &c->t[0].vx[e->rec[0][st]], *b = &c->t[1].vx[e->rec[1][st]];
    unsigned m = stage_diff(c, st, a, b);
    char b1[PT_NUMLEN], b2[PT_NUMLEN];
    int k, n = 0;

    for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
        if (!(m & (D_NULL | 1u << k))) continue;
        pt_diff_add(s, "%s%s expected ", n++ ? ", " : "", pt_diff_coord_name(st, k));
        if (pt_diff_is_real(st)) {
            pt_diff_add(s, "%s, actual %s", pt_diff_num(a->u.d[k], b1), pt_diff_num(b->u.d[k], b2));
        } else {
            if (a->flags & PT_REC_NULL) pt_diff_add(s, "none");
            else pt_diff_add(s, "%" PRId64, a->u.n[k]);
            if (b->flags & PT_REC_NULL) pt_diff_add(s, ", actual none");
            else pt_diff_add(s, ", actual %" PRId64, b->u.n[k]);
        }
    }
    if (!n && (m & D_FLAG)) pt_diff_add(s, "its inside or behind flag differs");
}

/* Compare one vertex present on both sides, stage by stage in pipeline order. */
void pt_diff_compare_vertex(dctx *c, const vent *e)
{
    int k, st, first = -1, nlater = 0;
    unsigned m = 0, later = 0;
    const pt_tvrec *a = NULL, *b = NULL;
    char name[128];

    for (k = 0; k < PT_NSTAGES_ALL; k++) {
        uint32_t i, j;
        unsigned d;
        st = pt_trace_order[k];
        i = e->rec[0][st];
        j = e->rec[1][st];
        if (i == PT_DIFF_NONE || j == PT_DIFF_NONE) {       /* a silent stage, or one left out */
            int lacking = i == PT_DIFF_NONE ? 0 : 1;    /* the side without it */
            if (i == PT_DIFF_NONE && j == PT_DIFF_NONE) continue;
            if (c->silent[lacking][e->model] & 1u << st) c->silent_recs[lacking][st]++;
            else c->stage_only[!lacking][st]++;
            continue;
        }
        d = stage_diff(c, st, &c->t[0].vx[i], &c->t[1].vx[j]);
        if (!d) continue;
        if (first < 0) {
            first = st;
            m = d;
            a = &c->t[0].vx[i];
            b = &c->t[1].vx[j];
        } else {
            later |= 1u << st;
        }
    }
    if (first < 0) {
        c->agree++;
        c->agree_clip += (e->v & PT_TCLIPV) != 0;
        return;
    }
    c->differ++;
    c->differ_clip += (e->v & PT_TCLIPV) != 0;
    c->first_at[first]++;
    if (!c->first_ex[first]) c->first_ex[first] = (size_t)(e - c->vt.e) + 1;
    if (c->shown >= c->o->show) return;
    c->shown++;
    printf("%s: differs first at %s", pt_diff_who(c, e->model, e->v, name, sizeof name),
                   pt_stage_infos[first].name);
    for (k = 0; k < PT_NSTAGES_ALL; k++)
        if (later & 1u << pt_trace_order[k])
            printf("%s%s", nlater++ ? ", " : ", later at ", pt_stage_infos[pt_trace_order[k]].name);
    printf("\n");
    print_stage_diff(first, a, b, m);
    for (k = 0; k < PT_NSTAGES_ALL && (int)pt_trace_order[k] != first; k++) {
        int sd;
        for (sd = 0; sd < 2; sd++)
            if (c->silent[sd][e->model] & 1u << pt_trace_order[k])
                printf("    but %s has no %s record: that stage did not report, and the "
                       "difference may start there\n", pt_diff_side[sd],
                       pt_stage_infos[pt_trace_order[k]].name);
    }
    pt_diff_explain(c, e, first);
}
