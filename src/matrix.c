/*
** src/matrix.c -- the matrix camera's part of the pipeline
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "matrix.h"
#include "../stages/m1_model2world.h"
#include "../stages/m2_world2view.h"
#include "../stages/m3_view2clip.h"
#include "../stages/m4_clip2cvv.h"
#include "../stages/m5_clip2ndc.h"
#include "../stages/m6_ndc2screen.h"
#include "../stages/m7_screen2viewport.h"
#include "../stages/s5_viewport2fb.h"
#include "../stages/s6_fb2index.h"

int pt_matrix_plan(pt_plan *p, const pt_scene *s, const pt_options *o)
{
    size_t k;
    int skewed = 0;

    pt_lookat(&p->view, s->eye, s->dir, s->up, o->raw_lookat, &skewed);
    pt_perspective(&p->proj, s->fov, s->aspect, s->znear, s->zfar);
    p->up_skewed = skewed;
    p->up_adjusted = skewed && !o->raw_lookat;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        pt_mat4 t = pt_mat4_translate(m->translate.x, m->translate.y, m->translate.z);
        p->models[k].world = pt_mat4_mul(&m->world, &t);   /* world lines, then translate */
    }
    return 0;
}

pt_vec2 pt_matrix_tail(const pt_scene *s, pt_vec4 clip, double w_scale,
                       const pt_sink *const sinks[PT_NSTAGES_ALL])
{
    pt_vec3 n, sc;
    pt_pix vp, fb;

    n = pt_clip2ndc(clip, w_scale, sinks[PT_STAGE_NDC]);
    sc = pt_ndc2screen(n, s->vp_w, s->vp_h, sinks[PT_STAGE_SCREEN]);
    vp = pt_screen2viewport(sc, s->vp_w, s->vp_h, sinks[PT_STAGE_VIEWPORT]);
    fb = pt_viewport2fb(vp, s->vp_x, s->vp_y, sinks[PT_STAGE_FRAMEBUFFER]);
    pt_fb2index(fb, s->fb_w, s->fb_h, sinks[PT_STAGE_INDEX]);
    if (!vp.ok) {
        pt_vec2 none = {(double)NAN, (double)NAN};
        return none;
    }
    return pt_viewport2pixelplane(vp, s->vp_h);
}

pt_vec2 pt_matrix_journey(const pt_scene *s, const pt_plan *p, size_t k, pt_vec3 v_m,
                          const pt_sink *const sinks[PT_NSTAGES_ALL],
                          pt_vec4 *clip, unsigned *code)
{
    pt_vrec r = {0};
    pt_vec4 w, v;
    pt_vec2 none = {(double)NAN, (double)NAN};
    double s_m[4] = {fabs(v_m.x), fabs(v_m.y), fabs(v_m.z), 1}, s_w[4], w_scale;
    int c;

    r.stage = PT_STAGE_MODEL;
    r.x = v_m.x; r.y = v_m.y; r.z = v_m.z;
    pt_emit(sinks[PT_STAGE_MODEL], &r);
    w = pt_model2world(v_m, &p->models[k].world, sinks[PT_STAGE_WORLD]);
    v = pt_world2view(w, &p->view, sinks[PT_STAGE_VIEW]);
    *clip = pt_view2clip(v, &p->proj, sinks[PT_STAGE_CLIP]);
    *code = pt_clip2cvv(*clip, sinks[PT_STAGE_CVV]);
    if (*code != 0) return none;            /* outside: its segments are clipped */
    /* The magnitude w_k comes from: w_k = z_v exactly (Projection's last
    ** column is (0 0 1 0)), z_v sums the world point's components times View's
    ** third column, and each of those sums the model's times World's. */
    for (c = 0; c < 4; c++) s_w[c] = pt_mat4_col_scale(s_m, &p->models[k].world, c);
    w_scale = pt_mat4_col_scale(s_w, &p->view, 2);
    return pt_matrix_tail(s, *clip, w_scale, sinks);
}
