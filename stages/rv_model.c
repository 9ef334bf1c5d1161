/*
** stages/rv_model.c -- the model renderers 7 and 9 pass between stages: growing its lists
** See LICENSE for copyright and license.
*/
#include <stdlib.h>
#include "rv_model.h"

/* Make room for one more element of size sz in *arr (n used, *cap allocated):
** 0, or -1 when out of memory (*arr unchanged). */
static int grow(void **arr, size_t n, size_t *cap, size_t sz)
{
    size_t ncap;
    void *p;

    if (n < *cap) return 0;
    ncap = *cap ? *cap * 2 : 16;
    if (ncap < *cap || ncap > (size_t)-1 / sz) return -1;
    p = realloc(*arr, ncap * sz);
    if (!p) return -1;
    *arr = p;
    *cap = ncap;
    return 0;
}

/* Room for n more elements of size sz in *arr (used elements, *cap
** allocated): 0 or -1. */
static int room_for(void **arr, size_t used, size_t n, size_t *cap, size_t sz)
{
    void *p;

    if (n <= *cap - used) return 0;                 /* used <= *cap */
    if (n > (size_t)-1 / sz - used) return -1;
    p = realloc(*arr, (used + n) * sz);
    if (!p) return -1;
    *arr = p;
    *cap = used + n;
    return 0;
}

int pt_rv_reserve(pt_rv_model *m, size_t nv, size_t nc, size_t np)
{
    void *v = m->v, *c = m->c, *p = m->p;
    int rc = room_for(&v, m->nv, nv, &m->cap_v, sizeof *m->v);

    m->v = v;
    if (rc == 0) rc = room_for(&c, m->nc, nc, &m->cap_c, sizeof *m->c);
    m->c = c;
    if (rc == 0) rc = room_for(&p, m->np, np, &m->cap_p, sizeof *m->p);
    m->p = p;
    return rc;
}

int pt_rv_add_vertex(pt_rv_model *m, pt_vec4 v)
{
    void *a = m->v;

    if (grow(&a, m->nv, &m->cap_v, sizeof *m->v)) return -1;
    m->v = a;
    m->v[m->nv++] = v;
    return 0;
}

int pt_rv_add_color(pt_rv_model *m, pt_rgb c)
{
    void *a = m->c;

    if (grow(&a, m->nc, &m->cap_c, sizeof *m->c)) return -1;
    m->c = a;
    m->c[m->nc++] = c;
    return 0;
}

int pt_rv_add_prim(pt_rv_model *m, const pt_rv_prim *p)
{
    void *a = m->p;

    if (grow(&a, m->np, &m->cap_p, sizeof *m->p)) return -1;
    m->p = a;
    m->p[m->np++] = *p;
    return 0;
}

void pt_rv_model_empty(pt_rv_model *m)
{
    m->nv = m->nc = m->np = 0;
}

void pt_rv_model_free(pt_rv_model *m)
{
    free(m->v);
    free(m->c);
    free(m->p);
    m->v = NULL; m->c = NULL; m->p = NULL;
    m->nv = m->nc = m->np = 0;
    m->cap_v = m->cap_c = m->cap_p = 0;
}

int pt_rv_color_ok(pt_rgb c)
{
    return !(c.r < 0.0f || c.r > 1.0f || c.g < 0.0f || c.g > 1.0f ||
             c.b < 0.0f || c.b > 1.0f);
}

int pt_rv_cut_finish(pt_rv_model *m, pt_rv_cut *cut, const pt_rv_clip_ls *ls)
{
    float t_ = (float)cut->t;
    pt_rgb a = cut->c[1], b = cut->c[0], *c = &cut->c[2];

    c->r = (1 - t_)*a.r + t_*b.r;              /* float, as Java's float[] */
    c->g = (1 - t_)*a.g + t_*b.g;
    c->b = (1 - t_)*a.b + t_*b.b;
    if (!pt_rv_color_ok(*c)) return -2;
    if (pt_rv_add_vertex(m, cut->p[2])) return -1;
    if (pt_rv_add_color(m, *c)) { m->nv--; return -1; }
    cut->v_new = (uint32_t)(m->nv - 1);
    cut->c_new = (uint32_t)(m->nc - 1);
    if (ls && ls->cut) ls->cut(ls->ud, cut);
    return 0;
}
