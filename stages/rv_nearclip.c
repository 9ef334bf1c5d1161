/*
** stages/rv_nearclip.c -- renderers 7 and 9: clip at the near plane z = n (NearClip)
** See LICENSE for copyright and license.
*/
#include "rv_nearclip.h"

/* interpolateNewVertex: cut segment *p at z = n (its ends on either side, or
** a NaN z), append the new vertex and colour, give the kept piece in *out.
** 0, or pt_rv_cut_finish's -1 or -2. */
static int cut_near(pt_rv_model *m, const pt_rv_prim *p, double n,
                    pt_rv_prim *out, const pt_rv_clip_ls *ls)
{
    pt_vec4 v0 = m->v[p->v[0]], v1 = m->v[p->v[1]];
    double t = (n - v1.z) / (v0.z - v1.z);      /* t from v1 (0) to v0 (1) */
    pt_rv_cut cut;
    int rc;

    cut.edge = PT_RV_NEAR;
    cut.off = v0.z > n ? 0 : 1;                 /* NaN: v1 is cut off */
    cut.plane = n;
    cut.t = t;
    cut.p[0] = v0;
    cut.p[1] = v1;
    cut.p[2].x = (1 - t)*v1.x + t*v0.x;         /* x = (1-t) x1 + t x0 */
    cut.p[2].y = (1 - t)*v1.y + t*v0.y;
    cut.p[2].z = n;
    cut.p[2].w = 1.0;
    cut.c[0] = m->c[p->c[0]];
    cut.c[1] = m->c[p->c[1]];
    if ((rc = pt_rv_cut_finish(m, &cut, ls)) != 0) return rc;
    *out = *p;
    out->v[cut.off] = cut.v_new;
    out->c[cut.off] = cut.c_new;
    return 0;
}

int pt_rv_nearclip(pt_rv_model *m, double n, const pt_rv_clip_ls *ls)
{
    pt_rv_prim *old = m->p, q;
    size_t nold = m->np, i;
    int rc = 0, keep;

    m->np = 0;                                  /* the kept, in place: never past i */
    for (i = 0; i < nold; i++) {
        const pt_rv_prim *p = &old[i];

        if (ls && ls->begin) ls->begin(ls->ud, m, p);
        q = *p;
        if (p->kind == PT_RV_POINT) {
            keep = m->v[p->v[0]].z <= n;        /* NearClip_Point */
        } else {
            double z0 = m->v[p->v[0]].z, z1 = m->v[p->v[1]].z;

            if (z0 <= n && z1 <= n) keep = 1;   /* on the plane counts as in */
            else if (z0 > n && z1 > n) keep = 0;
            else keep = -1;
            if (keep >= 0 && ls && ls->trivial) ls->trivial(ls->ud, keep);
            if (keep < 0) {
                if ((rc = cut_near(m, p, n, &q, ls)) != 0) break;
                keep = 1;
            }
        }
        if (keep) m->p[m->np++] = q;
        if (ls && ls->end) ls->end(ls->ud, m, keep ? &q : p, keep);
    }
    return rc;
}
