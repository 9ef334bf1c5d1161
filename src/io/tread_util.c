/*
** src/io/tread_util.c -- what the trace readers share: errors, records, stage names, numbers
** See LICENSE for copyright and license.
**
** The helpers of io/tread_int.h that every format's reader (tread_jsonl.c,
** tread_text.c, tread_kraft.c) fills its records with.  Numbers go through
** strtod() only after their syntax was checked (pt_tr_num_len()), so what
** strtod() reads is exactly the token.
*/
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/tread_int.h"

/* ===== stages ===== */

/* The place of stage st in pt_trace_order. */
static int order_pos(int st)
{
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++) if ((int)pt_trace_order[k] == st) return k;
    return 0;
}

int pt_tr_stage_named(const char *p, size_t n)
{
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++)
        if (strlen(pt_stage_infos[k].name) == n && memcmp(p, pt_stage_infos[k].name, n) == 0)
            return k;
    return -1;
}

/* ===== the reader: errors and records ===== */

int pt_tr_fail(pt_treader *r, const char *at, const char *fmt, ...)
{
    va_list ap;
    int k;
    size_t n, i;
    size_t col = at && at >= r->line ? (size_t)(at - r->line) + 1 : 1;

    k = snprintf(r->err, r->errlen, "%s:%zu:%zu: error: ", r->path, r->lineno, col);
    n = k < 0 ? 0 : (size_t)k;
    if (n < r->errlen) {
        va_start(ap, fmt);
        vsnprintf(r->err + n, r->errlen - n, fmt, ap);
        va_end(ap);
    }
    for (i = 0; r->err[i]; i++)
        if ((unsigned char)r->err[i] < 0x20 || r->err[i] == 0x7f) r->err[i] = '?';
    return -1;
}

int pt_tr_oom(pt_treader *r) { return pt_tr_fail(r, NULL, "out of memory"); }

int pt_tr_grow(pt_treader *r, void **arr, size_t n, size_t *cap, size_t size)
{
    size_t nc;
    void *p;

    if (n < *cap) return 0;
    nc = *cap ? 2 * *cap : 1024;
    if (nc > SIZE_MAX / size) return pt_tr_oom(r);
    p = realloc(*arr, nc * size);
    if (!p) return pt_tr_oom(r);
    *arr = p;
    *cap = nc;
    return 0;
}

uint32_t pt_tr_line32(const pt_treader *r)
{
    return r->lineno > UINT32_MAX ? UINT32_MAX : (uint32_t)r->lineno;
}

unsigned pt_tr_null_flags(unsigned nulls, unsigned sflags)
{
    if (!nulls) return 0;
    return PT_REC_NULL | (sflags & PT_REC_HAS_X && !(nulls & 1u) ? PT_REC_HAS_X : 0u)
                       | (sflags & PT_REC_HAS_Y && !(nulls & 2u) ? PT_REC_HAS_Y : 0u);
}

pt_tvrec *pt_tr_new_vrec(pt_treader *r, uint32_t model, uint64_t v, int st)
{
    pt_tread *t = r->t;
    pt_tvrec *rec;

    if (pt_tr_grow(r, (void **)&t->vx, t->nvx, &t->cap_vx, sizeof *t->vx)) return NULL;
    rec = &t->vx[t->nvx++];
    memset(rec, 0, sizeof *rec);
    rec->line = pt_tr_line32(r);
    rec->model = model;
    rec->v = v;
    rec->stage = (unsigned char)st;
    return rec;
}

pt_tmodel *pt_tr_new_model(pt_treader *r)
{
    pt_thdr *h = &r->t->hdr;
    pt_tmodel *m;

    if (pt_tr_grow(r, (void **)&h->models, h->nmodels, &h->cap, sizeof *h->models)) return NULL;
    m = &h->models[h->nmodels++];
    memset(m, 0, sizeof *m);
    return m;
}

int pt_tr_add_pixel(pt_treader *r, const pt_tpix *px)
{
    pt_tread *t = r->t;

    if (pt_tr_grow(r, (void **)&t->px, t->npx, &t->cap_px, sizeof *t->px)) return -1;
    t->px[t->npx++] = *px;
    return 0;
}

int pt_tr_add_clip(pt_treader *r, const pt_tclip *c)
{
    pt_tread *t = r->t;

    if (pt_tr_grow(r, (void **)&t->cl, t->ncl, &t->cap_cl, sizeof *t->cl)) return -1;
    t->cl[t->ncl++] = *c;
    return 0;
}

int pt_tr_clipv_number(pt_treader *r, uint32_t model, uint64_t seg, int st, const char *at,
                       uint64_t *v)
{
    int pos = order_pos(st);

    if (seg >= (UINT64_C(1) << 62)) return pt_tr_fail(r, at, "segment number out of range");
    if (!r->cv_have || r->cv_model != model || r->cv_seg != seg) r->cv_end = 0;
    else if (pos <= r->cv_pos) r->cv_end++;
    if (r->cv_end > 1) return pt_tr_fail(r, at, "a third clipped end of one segment");
    r->cv_have = 1;
    r->cv_model = model;
    r->cv_seg = seg;
    r->cv_pos = pos;
    *v = PT_TCLIPV | seg << 1 | (uint64_t)r->cv_end;
    return 0;
}

/* ===== numbers and words ===== */

size_t pt_tr_num_len(const char *p, const char *e, int *decimals)
{
    const char *s = p;

    *decimals = 0;
    if (s < e && *s == '-') s++;
    if (s >= e || *s < '0' || *s > '9') return 0;
    if (*s == '0') s++;
    else while (s < e && *s >= '0' && *s <= '9') s++;
    if (s < e && *s == '.') {
        const char *d = ++s;
        while (s < e && *s >= '0' && *s <= '9') s++;
        if (s == d) return 0;
        *decimals = (int)(s - d > 99 ? 99 : s - d);
    }
    if (s < e && (*s == 'e' || *s == 'E')) {
        const char *d;
        s++;
        if (s < e && (*s == '+' || *s == '-')) s++;
        d = s;
        while (s < e && *s >= '0' && *s <= '9') s++;
        if (s == d) return 0;
    }
    return (size_t)(s - p);
}

int pt_tr_is_int_token(const char *p, size_t n)
{
    size_t k;

    for (k = 0; k < n; k++) if (p[k] == '.' || p[k] == 'e' || p[k] == 'E') return 0;
    return 1;
}

int pt_tr_to_i64(const char *p, int64_t *out)
{
    char *end;
    long long v;

    errno = 0;
    v = strtoll(p, &end, 10);
    if (errno) return -1;
    *out = (int64_t)v;
    return 0;
}

int pt_tr_is(const char *p, size_t n, const char *s)
{
    return strlen(s) == n && memcmp(p, s, n) == 0;
}

int pt_tr_nonfinite(const char *p, size_t n, double *x)
{
    if (pt_tr_is(p, n, "nan")) { *x = (double)NAN; return 1; }
    if (pt_tr_is(p, n, "inf")) { *x = (double)INFINITY; return 1; }
    if (pt_tr_is(p, n, "-inf")) { *x = -(double)INFINITY; return 1; }
    return 0;
}

int pt_tr_camera(pt_thdr *h, const char *p, size_t n)
{
    char word[32];                          /* longer than every camera word */
    const pt_pipeline *pl;

    if (n >= sizeof word) return -1;
    memcpy(word, p, n);
    word[n] = '\0';
    if (!(pl = pt_pipeline_by_camera(word))) return -1;
    h->pipe = pl->id;
    h->perspective = pl->camera || strcmp(word, "perspective") == 0;
    return 0;
}
