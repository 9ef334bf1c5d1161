/*
** stages/rv_clip.c -- renderers 7 and 9: clip the image-plane model to the square -1..1 (Clip)
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "rv_clip.h"

/* Java's recursion ends: each cut puts one end exactly on an edge.  A guard
** all the same, far above what a finite segment needs (at most a few cuts). */
#define MAX_CUTS 64

/* Clip_Line.clip's tests: 1 trivial accept, 0 trivial delete, -1 cut.
** NaN compares false, so a NaN coordinate is never outside. */
static int trivial(pt_vec4 a, pt_vec4 b)
{
    if (!(fabs(a.x) > 1 || fabs(a.y) > 1 || fabs(b.x) > 1 || fabs(b.y) > 1)) return 1;
    if ((a.x > 1 && b.x > 1) || (a.x < -1 && b.x < -1) ||
        (a.y > 1 && b.y > 1) || (a.y < -1 && b.y < -1)) return 0;
    return -1;
}

/* clipOneTime: cut *p at the first edge in Java's order that an end lies
** beyond; append the new vertex and colour and replace the outside end in *p.
** 0, or pt_rv_cut_finish's -1 or -2. */
static int cut_once(pt_rv_model *m, pt_rv_prim *p, const pt_rv_clip_ls *ls)
{
    pt_vec4 a = m->v[p->v[0]], b = m->v[p->v[1]], vo, vi, nv;
    pt_rv_cut cut;
    double t;
    int o, on_x, rc;                    /* the outside end; cut at x = +-1 or y = +-1 */

    if      (a.x > 1)  { o = 0; on_x = 1; cut.plane = 1;  cut.edge = PT_RV_XPOS; }
    else if (b.x > 1)  { o = 1; on_x = 1; cut.plane = 1;  cut.edge = PT_RV_XPOS; }
    else if (a.x < -1) { o = 0; on_x = 1; cut.plane = -1; cut.edge = PT_RV_XNEG; }
    else if (b.x < -1) { o = 1; on_x = 1; cut.plane = -1; cut.edge = PT_RV_XNEG; }
    else if (a.y > 1)  { o = 0; on_x = 0; cut.plane = 1;  cut.edge = PT_RV_YPOS; }
    else if (b.y > 1)  { o = 1; on_x = 0; cut.plane = 1;  cut.edge = PT_RV_YPOS; }
    else if (a.y < -1) { o = 0; on_x = 0; cut.plane = -1; cut.edge = PT_RV_YNEG; }
    else               { o = 1; on_x = 0; cut.plane = -1; cut.edge = PT_RV_YNEG; }
    vo = o ? b : a;
    vi = o ? a : b;
    if (on_x) {
        t = (cut.plane - vo.x) / (vi.x - vo.x);     /* t from outside (0) to inside (1) */
        nv.x = cut.plane;
        nv.y = (1 - t)*vo.y + t*vi.y;
    } else {
        t = (cut.plane - vo.y) / (vi.y - vo.y);
        nv.x = (1 - t)*vo.x + t*vi.x;
        nv.y = cut.plane;
    }
    nv.z = 0;                                       /* new Vertex(x, y, 0) */
    nv.w = 1.0;
    cut.off = o;
    cut.t = t;
    cut.p[0] = vi; cut.p[1] = vo; cut.p[2] = nv;
    cut.c[0] = m->c[p->c[1 - o]];                   /* inside, outside: t runs */
    cut.c[1] = m->c[p->c[o]];                       /* from the outside colour */
    if ((rc = pt_rv_cut_finish(m, &cut, ls)) != 0) return rc;
    p->v[o] = cut.v_new;
    p->c[o] = cut.c_new;
    return 0;
}

int pt_rv_clip(pt_rv_model *m, const pt_rv_clip_ls *ls)
{
    pt_rv_prim *old = m->p, q;
    size_t nold = m->np, i;
    int rc = 0, keep, k;

    m->np = 0;                                  /* the kept, in place: never past i */
    for (i = 0; i < nold && rc == 0; i++) {
        const pt_rv_prim *p = &old[i];

        if (ls && ls->begin) ls->begin(ls->ud, m, p);
        q = *p;
        if (p->kind == PT_RV_POINT) {
            pt_vec4 v = m->v[p->v[0]];

            keep = !(fabs(v.x) > 1 || fabs(v.y) > 1);
        } else {
            for (k = 0; (keep = trivial(m->v[q.v[0]], m->v[q.v[1]])) < 0; k++) {
                if (k == MAX_CUTS) { rc = -3; break; }
                if ((rc = cut_once(m, &q, ls)) != 0) break;
            }
            if (rc) break;
            if (ls && ls->trivial) ls->trivial(ls->ud, keep);
        }
        if (keep) m->p[m->np++] = q;
        if (ls && ls->end) ls->end(ls->ud, m, keep ? &q : p, keep);
    }
    return rc;
}
