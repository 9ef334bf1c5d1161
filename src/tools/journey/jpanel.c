/*
** src/tools/journey/jpanel.c -- what every pipeline's panels share: points, segments, wireframe
** See LICENSE for copyright and license.
**
** The rasterized pixels the viewport and framebuffer panels draw are the
** pixel records of the one pt_run() of the model that pt_jmodel_init()
** makes (journey.c keeps them, per segment, in jm->pix): what the renderer
** drew, never a segment walked again here.
*/
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include "tools/journey/jpanel.h"

static int by_index(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;

    return x < y ? -1 : x > y;
}

const pt_journey *pt_jmodel_journey(const pt_jmodel *jm, size_t k)
{
    const size_t *f = jm->nkeep ? bsearch(&k, jm->keep, jm->nkeep, sizeof k, by_index) : NULL;

    assert(f);                               /* a vertex drawn is kept */
    return f ? &jm->kept[f - jm->keep] : &jm->kept[0];
}

int pt_jseg_drawn(const pt_jmodel *jm, size_t s)
{
    return s < PT_JOURNEY_MAXSEG || jm->show[jm->m->seg[s].a] || jm->show[jm->m->seg[s].b];
}

void pt_jspan_start(pt_jspan *sp)
{
    int st, i;

    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        sp->b[st][0] = sp->b[st][1] = (double)INFINITY;
        sp->b[st][2] = sp->b[st][3] = -(double)INFINITY;
    }
    for (i = 0; i < 4; i++) {
        sp->world[i] = i < 2 ? (double)INFINITY : -(double)INFINITY;
        sp->clip[0][i] = sp->clip[1][i] = sp->clip[2][i] = sp->world[i];
    }
    sp->big = sp->deep = sp->wbig = 0;
    sp->depth = -(double)INFINITY;
}

void pt_jspan_merge(double b[4], const double a[4])
{
    if (a[0] < b[0]) b[0] = a[0];
    if (a[1] < b[1]) b[1] = a[1];
    if (a[2] > b[2]) b[2] = a[2];
    if (a[3] > b[3]) b[3] = a[3];
}

int pt_jseg_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb)
{
    return jm->rows->ends(jm, s, st, ja, jb);
}

int pt_jstage_xy(const pt_journey *j, pt_stage st, double *x, double *y)
{
    const pt_vrec *r = &j->rec[st];

    *x = *y = (double)NAN;
    if (pt_journey_stopped(j, st)) return 0;        /* stopped at the cvv */
    switch (pt_jlooks[st].kind) {
    case PT_JKIND_SPACE:
        if (!isfinite(r->x) || !isfinite(r->y) || !isfinite(r->z)) return 0;
        pt_jproj(st, r->x, r->y, r->z, x, y);
        break;
    case PT_JKIND_PLANE:
        *x = r->x; *y = r->y;
        break;
    case PT_JKIND_PIXELS:
        if (r->flags & PT_REC_NULL) return 0;
        *x = (double)r->ix + 0.5; *y = (double)r->iy + 0.5;
        break;
    case PT_JKIND_NONE:
        return 0;
    }
    return isfinite(*x) && isfinite(*y);
}

void pt_jwireframe(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_model *m = jm->m;
    const pt_jview *v = &jm->view[st];
    size_t k, n = m->nseg < PT_JOURNEY_MAXSEG ? m->nseg : PT_JOURNEY_MAXSEG;
    pt_journey ja, jb;
    double ax, ay, bx, by;
    pt_jpath pw;

    pt_jpath_start(&pw, sb);
    for (k = 0; k < n; k++) {
        if (!pt_jseg_ends(jm, k, st, &ja, &jb)) continue;
        if (!pt_jstage_xy(&ja, st, &ax, &ay) || !pt_jstage_xy(&jb, st, &bx, &by)) continue;
        if (!pt_jview_clip(v, &ax, &ay, &bx, &by)) continue;
        pt_jpath_cmd(&pw, "M", 2, pt_jview_x(v, ax), pt_jview_y(v, ay));
        pt_jpath_cmd(&pw, "L", 2, pt_jview_x(v, bx), pt_jview_y(v, by));
    }
    pt_jpath_end(&pw, "fill=\"none\" stroke=\"" PT_JC_FAINT "\" stroke-width=\"1\"");
}

void pt_jraster_segs(const pt_jmodel *jm, size_t k, void (*px)(void *, int64_t, int64_t),
                     void *ud)
{
    const pt_model *m = jm->m;
    size_t s, i;

    for (s = 0; s < m->nseg; s++) {
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        for (i = jm->pixat[s]; i < jm->pixat[s + 1]; i++)
            px(ud, jm->pix[i].x_vp, jm->pix[i].y_vp);
    }
}

void pt_jsegments(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, pt_stage st, size_t k,
                  double width)
{
    const pt_model *m = jm->m;
    pt_journey ja, jb;
    size_t s;

    for (s = 0; s < m->nseg; s++) {
        double ax, ay, bx, by;
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        if (!pt_jseg_ends(jm, s, st, &ja, &jb)) continue;
        if (!pt_jstage_xy(&ja, st, &ax, &ay) || !pt_jstage_xy(&jb, st, &bx, &by)) continue;
        pt_jview_line(sb, v, ax, ay, bx, by, PT_JC_SEG, width, "stroke-linecap=\"round\"");
        if (m->seg[s].a == k) { ax = bx; ay = by; }       /* the other end */
        if (pt_jview_in(v, ax, ay)) pt_jcircle(sb, pt_jview_x(v, ax), pt_jview_y(v, ay), 2.5, PT_JC_SEG, "");
    }
}

void pt_jfg_path(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    const pt_vrec *r = &j->rec[st];
    double p0[3] = {0, 0, 0}, p1[3], p2[3], p3[3];

    p1[0] = r->x; p1[1] = 0; p1[2] = 0;
    p2[0] = r->x; p2[1] = r->y; p2[2] = 0;
    p3[0] = r->x; p3[1] = r->y; p3[2] = r->z;
    pt_jline3(sb, v, st, p0, p1, PT_JC_VTX, 1, "stroke-dasharray=\"3 3\"");
    pt_jline3(sb, v, st, p1, p2, PT_JC_VTX, 1, "stroke-dasharray=\"3 3\"");
    pt_jline3(sb, v, st, p2, p3, PT_JC_VTX, 1, "stroke-dasharray=\"3 3\"");
}

void pt_jfg_point(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    double x, y;
    int ok = pt_jstage_xy(j, st, &x, &y);

    pt_jsegments(sb, jm, v, st, k, 2);
    pt_jmarker(sb, v, ok, x, y, (uint64_t)k + 1, 0, NULL, NULL);
}
