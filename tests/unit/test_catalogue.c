/*
** tests/unit/test_catalogue.c -- the catalogue's right formulas are stages/' own, bit for bit
** See LICENSE for copyright and license.
**
** src/tools/catalogue.c writes each classic stage's formula out again (a
** student build replaces the stage, the tools must not).  For each NAME.scene
** in the directory given (default tests/reference), run the classic pipeline
** with every stage traced and check, for every vertex, that the catalogue's
** right formula of each stage applied to the previous stage's record gives
** that stage's record bit for bit.  Then a few hand checks: each known mistake
** differs from the right formula on an input chosen for it (so that this test
** could fail), and the edge cases of rounding agree with stages/.
*/
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "refcases.h"
#include "core/pipetrace.h"
#include "tools/catalogue.h"

/* Every record of the vertex being traced, checked when the next begins. */
typedef struct got {
    const pt_scene *s;
    const pt_model *m;           /* the vertex's model, or NULL before the first */
    uint64_t v;
    pt_vrec rec[PT_NSTAGES_ALL];
    unsigned char have[PT_NSTAGES_ALL];
    size_t nvertex, nstage;      /* vertices and stage records checked */
    const char *bad;             /* the first mismatch, or NULL */
    char where[512];
} got;

/* Check the vertex gathered in *g: each stage from the one before. */
static void check_vertex(got *g)
{
    pt_stage_params par;
    int st, i;

    if (!g->m) return;
    pt_stage_params_of(&par, g->s, g->m);
    for (i = 1; i < PT_CLASSIC_NORDER; i++) {
        pt_cat_val in, want, out;
        int prev = pt_classic_order[i - 1];
        st = pt_classic_order[i];
        if (!g->have[st] || !g->have[prev]) continue;
        pt_cat_val_of(&in, &g->rec[prev]);
        pt_cat_val_of(&want, &g->rec[st]);
        if (!pt_cat_right(st, &par, &in, &out) || pt_cat_differ(st, &out, &want)) {
            if (!g->bad) {
                g->bad = pt_stage_infos[st].name;
                snprintf(g->where, sizeof g->where, "%s v%llu", g->m->name,
                         (unsigned long long)g->v);
            }
        }
        g->nstage++;
    }
    g->nvertex++;
    memset(g->have, 0, sizeof g->have);
}

static void on_begin(void *ud, const pt_model *m, uint64_t v)
{
    got *g = ud;
    check_vertex(g);
    g->m = m;
    g->v = v;
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    got *g = ud;
    if (!pt_pipeline_has(&pt_pipe_classic, r->stage)) return;
    g->rec[r->stage] = *r;
    g->have[r->stage] = 1;
}

static void run_case(const char *dir, const char *name)
{
    char descr[PT_ERRLEN + 1200];
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    got g;

    if (pt_ref_load(&s, dir, name, "cat") != 0) return;
    pt_options_default(&o);
    o.all_stages = 1;
    o.rasterize = 0;
    memset(&g, 0, sizeof g);
    g.s = &s;
    memset(&l, 0, sizeof l);
    l.vertex_begin = on_begin;
    l.sink.vertex = on_vertex;
    l.sink.ud = &g;
    l.ud = &g;
    if (pt_plan_make(&p, &s, &o) != 0 || pt_run(&s, &p, &o, &l, NULL, &sum) != 0) {
        snprintf(descr, sizeof descr, "cat %s: runs", name);
        PT_CHECK(descr, 0);
    }
    check_vertex(&g);
    snprintf(descr, sizeof descr, "cat %s: %zu vertices, %zu stage records from the "
             "previous stage's (%s%s%s)", name, g.nvertex, g.nstage,
             g.bad ? g.bad : "ok", g.bad ? " differs at " : "", g.bad ? g.where : "");
    PT_CHECK(descr, g.bad == NULL && ((s.pipe == PT_PIPE_MATRIX) || g.nstage > 0));
    pt_plan_free(&p);
    pt_scene_free(&s);
}

/* The last record each stage reported to keep_sink. */
static pt_vrec kept[PT_NSTAGES_ALL];

static void keep_rec(void *ud, const pt_vrec *r)
{
    (void)ud;
    if (pt_pipeline_has(&pt_pipe_classic, r->stage)) kept[r->stage] = *r;
}

static const pt_sink keep_sink = {keep_rec, NULL};

/* The numbers of tests/data/diff/offset.scene: W != w, H != h, an odd h. */
static pt_stage_params offset_params(void)
{
    pt_stage_params par;

    memset(&par, 0, sizeof par);
    par.translate.x = 0.25; par.translate.y = -0.5; par.translate.z = -3;
    par.perspective = 1;
    par.w = 24; par.h = 17;
    par.x_ul = 5; par.y_ul = 3;
    par.W = 40; par.H = 30;
    return par;
}

/* Each mistake differs from the right formula on an input made for its stage. */
static void hand_checks(void)
{
    pt_stage_params par = offset_params();
    pt_cat_val in[PT_NSTAGES_ALL], right, wrong;
    pt_vec2 pp;
    pt_pix a, b;
    size_t k;
    char descr[256];

    memset(in, 0, sizeof in);
    in[PT_STAGE_MODEL].d[0] = 1; in[PT_STAGE_MODEL].d[1] = 2; in[PT_STAGE_MODEL].d[2] = 3;
    in[PT_STAGE_CAMERA].d[0] = 1; in[PT_STAGE_CAMERA].d[1] = 2; in[PT_STAGE_CAMERA].d[2] = -3;
    in[PT_STAGE_IMAGE].d[0] = 0.3; in[PT_STAGE_IMAGE].d[1] = -0.2; in[PT_STAGE_IMAGE].d[2] = -1;
    in[PT_STAGE_PIXEL].d[0] = -2.5;                 /* a tie: C round() goes to -3 */
    in[PT_STAGE_PIXEL].d[1] = 0.49999999999999994;  /* floor(y + 0.5) gives 1 */
    in[PT_STAGE_FRAMEBUFFER].n[0] = 30;             /* x_fb >= w, inside W */
    in[PT_STAGE_FRAMEBUFFER].n[1] = 4;
    for (k = 0; k < PT_NMISTAKES; k++) {
        const pt_mistake *mk = &pt_mistakes[k];
        memset(&wrong, 0, sizeof wrong);
        pt_cat_right(mk->stage, &par, &in[mk->stage - 1], &right);
        mk->apply(&par, &in[mk->stage - 1], &wrong);
        snprintf(descr, sizeof descr, "cat-2.%zu mistake '%s' (%s) differs from the right "
                 "formula", k + 1, mk->name, pt_stage_infos[mk->stage].name);
        PT_CHECK(descr, pt_cat_differ(mk->stage, &right, &wrong) != 0);
    }

    /* the rasterizer's mistakes: viewport stages that round otherwise */
    pp.x = 0.49999999999999994; pp.y = 3;
    a = pt_pixel2viewport(pp, par.w, par.h, NULL);
    b = pt_raster_mistakes[0].to_vp(pp, par.w, par.h, NULL);
    PT_CHECK("cat-3.1 floor(x + 0.5) as a viewport stage: x_vp 0, not -1",
             a.ok && b.ok && a.x == -1 && b.x == 0 && a.y == b.y);
    pp.x = 3; pp.y = -2.5;
    a = pt_pixel2viewport(pp, par.w, par.h, NULL);
    b = pt_raster_mistakes[1].to_vp(pp, par.w, par.h, NULL);
    PT_CHECK("cat-3.2 C round() as a viewport stage: y_vp h + 3, not h + 2",
             a.ok && b.ok && a.y == par.h + 2 && b.y == par.h + 3 && a.x == b.x);

    /* the right viewport, framebuffer and index formulas on the edges of
    ** rounding, against s4, s5 and s6's own records: ties, huge values and
    ** NaN, one coordinate without value and the other with (null per value) */
    {
        static const double xs[] = {0.49999999999999994, -2.5, 2.5, -0.5, 1e300, -1e300,
                                    4611686018427387904.0, 4611686018427387903.0 / 2, 0.0,
                                    (double)NAN, (double)INFINITY};
        size_t i, j, bad = 0, one = 0;
        for (i = 0; i < sizeof xs / sizeof xs[0]; i++)
            for (j = 0; j < sizeof xs / sizeof xs[0]; j++) {
                pt_cat_val v[PT_NSTAGES_ALL];
                pt_pix vp, fb;
                int st;
                memset(v, 0, sizeof v);
                pp.x = v[PT_STAGE_PIXEL].d[0] = xs[i];
                pp.y = v[PT_STAGE_PIXEL].d[1] = xs[j];
                vp = pt_pixel2viewport(pp, par.w, par.h, &keep_sink);
                fb = pt_viewport2fb(vp, par.x_ul, par.y_ul, &keep_sink);
                (void)pt_fb2index(fb, par.W, par.H, &keep_sink);
                for (st = PT_STAGE_VIEWPORT; st <= PT_STAGE_INDEX; st++) {
                    pt_cat_val want;
                    pt_cat_val_of(&want, &kept[st]);
                    pt_cat_right(st, &par, &v[st - 1], &v[st]);
                    bad += pt_cat_differ(st, &v[st], &want) != 0;
                }
                one += pt_cat_has(&v[PT_STAGE_VIEWPORT], 0) != pt_cat_has(&v[PT_STAGE_VIEWPORT], 1);
            }
        snprintf(descr, sizeof descr, "cat-4.1 right viewport, framebuffer, index = s4, s5, s6 "
                 "on ties, huge, NaN and infinite inputs (%zu with one value of two)", one);
        PT_CHECK(descr, bad == 0 && one > 0);
    }

    /* pt_cat_differ() sees one value of two going missing */
    {
        pt_cat_val x, y;
        memset(&x, 0, sizeof x);
        x.n[0] = 3; x.n[1] = 4;
        y = x;
        y.flags = PT_REC_NULL | PT_REC_HAS_Y;
        y.n[0] = 0;
        PT_CHECK("cat-4.2 x_vp without value, y_vp the same: only x differs",
                 pt_cat_differ(PT_STAGE_VIEWPORT, &x, &y) == 1u);
    }
}

int main(int argc, char **argv)
{
    pt_ref_run(argc, argv, "test_catalogue", run_case);
    hand_checks();
    return pt_test_report();
}
