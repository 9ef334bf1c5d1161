/*
** src/tools/accuracy/acc_shared.c -- what the three arithmetics share: integer stages, DDA steps
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/acc_shared.h"

/* ===== the integer stages ===== */

int64_t pt_acc_index_of(const pt_scene *s, pt_pix fb)
{
    return fb.ok && pt_inside(fb.x, fb.y, s->fb_w, s->fb_h)
           ? fb.y * (int64_t)s->fb_w + fb.x : -1;   /* idx = y_fb * W + x_fb */
}

pt_pix pt_acc_fb_of(const pt_scene *s, pt_pix vp)
{
    pt_pix fb = {0, 0, 0};

    if (vp.ok) {
        fb.x = s->vp_x + vp.x;                      /* x_fb = x_ul + x_vp */
        fb.y = s->vp_y + vp.y;                      /* y_fb = y_ul + y_vp */
        fb.ok = 1;
    }
    return fb;
}

pt_pix pt_acc_vp_of(const pt_scene *s, int ok, int64_t rx, int64_t ry)
{
    const int64_t exact = (int64_t)1 << 53;         /* doubles hold these */
    pt_pix vp = {0, 0, 0};

    if (!ok) return vp;
    if (rx > -exact && rx < exact && ry > -exact && ry < exact) {
        pt_vec2 pp;
        pp.x = (double)rx;
        pp.y = (double)ry;
        return ptref_pixel2viewport(pp, s->vp_w, s->vp_h, NULL);
    }
    vp.x = rx - 1;                                  /* x_vp = round(x_pp) - 1 */
    vp.y = s->vp_h - ry;                            /* y_vp = h - round(y_pp) */
    vp.ok = 1;
    return vp;
}

void pt_acc_mtail_pp(const pt_scene *s, pt_acc_mtail *t, int exact)
{
    pt_pix vp = t->vp;

    if (vp.ok && !exact) {                  /* the stage's own way back, m7 */
        pt_vec2 q = pt_viewport2pixelplane(vp, s->vp_h);
        t->pp[0] = pt_acc_dd(q.x);
        t->pp[1] = pt_acc_dd(q.y);
    } else if (vp.ok) {                     /* the same in whole numbers, exact */
        t->pp[0] = pt_dd_from_i64(vp.x + 1);                      /* x_pp = x_vp + 1 */
        t->pp[1] = pt_dd_from_i64(s->vp_h - vp.y);                /* y_pp = h - y_vp */
    } else {
        t->pp[0] = t->pp[1] = pt_acc_dd((double)NAN);
    }
}

void pt_acc_fb_stage(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    j->fb = pt_acc_fb_of(c->s, j->vp);              /* x_fb = x_ul + x_vp, ... */
}

void pt_acc_index_stage(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    j->idx = pt_acc_index_of(c->s, j->fb);          /* idx = y_fb * W + x_fb */
}

void pt_acc_fb_tail(const pt_scene *s, pt_acc_mtail *t)
{
    t->fb = pt_acc_fb_of(s, t->vp);                 /* x_fb = x_ul + x_vp, ... */
}

void pt_acc_index_tail(const pt_scene *s, pt_acc_mtail *t)
{
    t->idx = pt_acc_index_of(s, t->fb);             /* idx = y_fb * W + x_fb */
}

void pt_acc_no_tail(pt_acc_mtail *t)
{
    memset(t, 0, sizeof *t);
    t->idx = -1;
    t->pp[0] = t->pp[1] = pt_acc_dd((double)NAN);
}

/* ===== the DDA's integer bookkeeping ===== */

/* The product is exact below 2^53, and then so is a quotient that is a double
** (IEEE division is exact when it can be), ties included. */
pt_dd pt_acc_line_y(const pt_acc_line *ln, int64_t s)
{
    pt_dd num = pt_dd_mul(pt_dd_from_i64(s - ln->s0), pt_dd_from_i64(ln->dy));

    return pt_dd_add(pt_dd_from_i64(ln->y0),
                     pt_dd_div(num, pt_dd_from_i64(ln->ds)));  /* y = y0 + k*dy/dx */
}

static void swap64(int64_t *a, int64_t *b)
{
    int64_t t = *a;

    *a = *b;
    *b = t;
}

/* The ends are integers, so ordering them is exact in any arithmetic; only
** the transposition test is the arithmetic's. */
void pt_acc_dda_setup(pt_acc_line *ln, int transposed, int64_t e[4],
                      const pt_acc_dda *o, int64_t *first, int64_t *last)
{
    int64_t band = transposed ? o->h : o->w;

    if (transposed) { swap64(&e[0], &e[1]); swap64(&e[2], &e[3]); }
    if (e[2] < e[0]) { swap64(&e[0], &e[2]); swap64(&e[1], &e[3]); }
    ln->transposed = transposed;
    ln->s0 = e[0]; ln->y0 = e[1];
    ln->ds = e[2] - e[0]; ln->dy = e[3] - e[1];     /* |e| < 2^62: no overflow */
    *first = e[0] < 1 ? 1 : e[0];
    *last = e[2] < band ? e[2] : band;
}

void pt_acc_dda_step(const pt_acc_dda *o, const pt_acc_line *ln, int64_t s, int ok,
                     int64_t r, double y)
{
    pt_pix p;

    if (!ok) r = y > 0 ? (int64_t)PT_PIX_LIMIT : -(int64_t)PT_PIX_LIMIT;
    if (ln->transposed) { p.x = r - 1; p.y = o->h - s; }   /* (round(x) - 1, h - y) */
    else                { p.x = s - 1; p.y = o->h - r; }   /* (x - 1, h - round(y)) */
    if (pt_inside(p.x, p.y, o->w, o->h)) o->pixel(o->ud, p.x, p.y);
    if (o->step) o->step(o->ud, ln, s, y);
}

void pt_acc_dda_dot(const pt_acc_dda *o, int64_t ix, int64_t iy)
{
    if (pt_inside(ix - 1, o->h - iy, o->w, o->h)) o->pixel(o->ud, ix - 1, o->h - iy);
}

int pt_acc_rvcam_exact(pt_acc_rvcam *c)
{
    const pt_scene *s = c->s;
    size_t k;
    int i, j;

    c->world = calloc(s->nmodels ? s->nmodels : 1, sizeof *c->world);
    if (!c->world) return -1;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *md = &s->models[k];
        pt_jmat a = pt_r9_position_matrix(s->renderer == 9 ? md->ops : NULL,
                                          s->renderer == 9 ? md->nops : 0);

        for (j = 0; j < 4; j++) {                   /* column j */
            c->world[k][0][j] = pt_acc_dd(a.col[j].x);
            c->world[k][1][j] = pt_acc_dd(a.col[j].y);
            c->world[k][2][j] = pt_acc_dd(a.col[j].z);
            c->world[k][3][j] = pt_acc_dd(a.col[j].w);
        }
    }
    c->l = pt_acc_dd(s->cam_l); c->r = pt_acc_dd(s->cam_r);
    c->b = pt_acc_dd(s->cam_b); c->t = pt_acc_dd(s->cam_t);
    c->n = pt_acc_dd(s->cam_n);
    c->view[0] = pt_acc_dd(s->view.x);
    c->view[1] = pt_acc_dd(s->view.y);
    c->view[2] = pt_acc_dd(s->view.z);
    for (i = 0; i < 16; i++) c->norm[i / 4][i % 4] = pt_acc_dd(0.0);
    return 0;
}
