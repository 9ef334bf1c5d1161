/*
** src/io/trace_kraft_check.c -- can the course's renderer log a scene's pixels; its switches
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/trace_kraft.h"

/* 1 when x is beyond Java's int. */
static int out_of_int(int64_t x)
{
    return x < INT32_MIN || x > INT32_MAX;
}

/* The course's renderer can log segment seg of model m (setup su): its
** its loop ends, its endpoints round to ints and it has at most
** PT_KRAFT_MAX_STEPS steps.
** Returns 0, or -1 with a message. */
static int seg_check(const pt_scene *s, const pt_model *m, uint64_t seg,
                     const pt_raster_setup *su, char *err, size_t errlen)
{
    int64_t n = su->s1 - su->s0;                     /* steps - 1 */

    if (su->kind == PT_RASTER_DRAWN && su->s1 == INT32_MAX) {
        snprintf(err, errlen, "%s: error: model '%s', segment %llu: its last step is "
                 "(int) %lld, the largest int: the course's renderer steps on forever "
                 "(its int wraps), and so would its log (docs/renderer4.md)",
                 s->path, m->name, (unsigned long long)seg, (long long)su->s1);
        return -1;
    }
    if (su->kind != PT_RASTER_SKIPPED) {
        if (n >= PT_KRAFT_MAX_STEPS) {
            snprintf(err, errlen, "%s: error: model '%s', segment %llu: %lld steps, more than "
                     "the %ld lines a segment's pixel log may have", s->path, m->name,
                     (unsigned long long)seg, (long long)n + 1, PT_KRAFT_MAX_STEPS);
            return -1;
        }
    }
    if (su->kind == PT_RASTER_SKIPPED || out_of_int(su->x0) || out_of_int(su->y0) ||
        out_of_int(su->x1) || out_of_int(su->y1)) {
        snprintf(err, errlen, "%s: error: model '%s', segment %llu: an endpoint is beyond "
                 "the int pixel range of the course's renderer (its log would not end)",
                 s->path, m->name, (unsigned long long)seg);
        return -1;
    }
    return 0;
}

/* The first segment or point of the scene the course's renderer cannot log
** (seg_check), from the setup records of one pt_run(). */
typedef struct kraft_check {
    const pt_scene *s;
    char *err;
    size_t errlen;
    int rc;
} kraft_check;

static void check_setup(void *ud, const pt_model *m, uint64_t seg, const pt_raster_setup *su)
{
    kraft_check *kc = ud;

    if (kc->rc == 0) kc->rc = seg_check(kc->s, m, seg, su, kc->err, kc->errlen);
}

int pt_kraft_point_check(const pt_scene *s, const char *model, int radius, char *err,
                         size_t errlen)
{
    int64_t n = (2 * (int64_t)radius + 1) * (2 * (int64_t)radius + 1);

    if (radius < 0 || n <= PT_KRAFT_MAX_STEPS) return 0;
    snprintf(err, errlen, "%s: error: model '%s': a point of radius %d has %lld pixels, more "
             "than the %ld lines a point's pixel log may have", s->path, model, radius,
             (long long)n, PT_KRAFT_MAX_STEPS);
    return -1;
}

/* The course's renderer can log the points of model m: their centres are
** finite and in the int range, and each has at most PT_KRAFT_MAX_STEPS
** pixels.  Returns 0, or -1 with a message. */
static int points_check(const pt_scene *s, const pt_model *m, char *err, size_t errlen)
{
    pt_journey *js;
    size_t q;
    int rc = 0;

    if (m->npts == 0 || m->hidden_position || m->hidden_model) return 0;
    js = pt_run_journeys(s, m, 0);
    if (!js) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    for (q = 0; q < m->npts && rc == 0; q++) {
        pt_raster_dot dt;
        pt_vec2 pp;
        int64_t n;

        pp.x = js[m->pts[q].v].rec[PT_STAGE_PIXEL].x;
        pp.y = js[m->pts[q].v].rec[PT_STAGE_PIXEL].y;
        n = pt_raster_point(pp, m->pts[q].radius, s->vp_w, s->vp_h, 1, 0, &dt, NULL, NULL);
        if (n < 0) {
            snprintf(err, errlen, "%s: error: model '%s', point %zu: its centre is beyond the "
                     "int pixel range of the course's renderer (its log would not end)",
                     s->path, m->name, q + 1);
            rc = -1;
        } else {
            rc = pt_kraft_point_check(s, m->name, m->pts[q].radius, err, errlen);
        }
    }
    free(js);
    return rc;
}

int pt_kraft_check(const pt_scene *s, char *err, size_t errlen)
{
    kraft_check kc;
    pt_options o;
    pt_listener l;
    size_t k;

    kc.s = s; kc.err = err; kc.errlen = errlen; kc.rc = 0;
    pt_options_default(&o);
    memset(&l, 0, sizeof l);
    l.setup = check_setup;       /* the setups alone: the walk skips, as ever */
    l.ud = &kc;
    if (pt_run_plain(s, &o, &l) != 0) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    for (k = 0; k < s->nmodels && kc.rc == 0; k++)
        kc.rc = points_check(s, &s->models[k], err, errlen);
    return kc.rc;
}

int pt_kraft_debug_parse(const char *list, unsigned *dbg)
{
    static const struct { const char *name; unsigned bits; } items[] = {
        {"scene", PT_KDBG_SCENE}, {"position", PT_KDBG_POSITION},
        {"rasterize", PT_KDBG_RASTERIZE}, {"clip", PT_KDBG_CLIP},
        {"nearclip", PT_KDBG_NEARCLIP}, {"all", PT_KDBG_ALL}, {"none", 0}
    };
    unsigned bits = 0;
    const char *p = list;

    for (;;) {
        size_t len = strcspn(p, ","), i;

        for (i = 0; i < sizeof items / sizeof items[0]; i++)
            if (strlen(items[i].name) == len && !strncmp(p, items[i].name, len)) break;
        if (i == sizeof items / sizeof items[0]) return -1;
        bits |= items[i].bits;
        if (p[len] == '\0') break;
        p += len + 1;
    }
    *dbg = bits;
    return 0;
}
