/*
** stages/pt_matrix.c -- the matrix camera's stages, run in order
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "pt_matrix.h"
#include "m1_model2world.h"
#include "m2_world2view.h"
#include "m3_view2clip.h"
#include "m4_clip2cvv.h"
#include "m5_clip2ndc.h"
#include "m6_ndc2screen.h"
#include "m7_screen2viewport.h"
#include "s5_viewport2fb.h"
#include "s6_fb2index.h"

pt_mat4 pt_matrix_world(const pt_mat4 *lines, pt_vec3 translate)
{
    pt_mat4 t = pt_mat4_translate(translate.x, translate.y, translate.z);

    return pt_mat4_mul(lines, &t);          /* row vectors: the lines act first */
}

pt_vec2 pt_matrix_tail(const pt_stage_params *par, pt_vec4 clip, double w_scale,
                       const pt_sink *const sinks[PT_NSTAGES_ALL])
{
    pt_vec3 n, sc;
    pt_pix vp, fb;

    n = pt_clip2ndc(clip, w_scale, sinks[PT_STAGE_NDC]);
    sc = pt_ndc2screen(n, par->w, par->h, sinks[PT_STAGE_SCREEN]);
    vp = pt_screen2viewport(sc, par->w, par->h, sinks[PT_STAGE_VIEWPORT]);
    fb = pt_viewport2fb(vp, par->x_ul, par->y_ul, sinks[PT_STAGE_FRAMEBUFFER]);
    pt_fb2index(fb, par->W, par->H, sinks[PT_STAGE_INDEX]);
    if (!vp.ok) {
        pt_vec2 none = {(double)NAN, (double)NAN};
        return none;
    }
    return pt_viewport2pixelplane(vp, par->h);
}

pt_vec2 pt_matrix_journey(const pt_stage_params *par, const pt_matrices *mx, pt_vec3 v_m,
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
    w = pt_model2world(v_m, mx->world, sinks[PT_STAGE_WORLD]);
    v = pt_world2view(w, mx->view, sinks[PT_STAGE_VIEW]);
    *clip = pt_view2clip(v, mx->proj, sinks[PT_STAGE_CLIP]);
    *code = pt_clip2cvv(*clip, sinks[PT_STAGE_CVV]);
    if (*code != 0) return none;            /* outside: its segments are clipped */
    /* The magnitude w_k comes from: w_k = z_v exactly (Projection's last
    ** column is (0 0 1 0)), z_v sums the world point's components times View's
    ** third column, and each of those sums the model's times World's. */
    for (c = 0; c < 4; c++) s_w[c] = pt_mat4_col_scale(s_m, mx->world, c);
    w_scale = pt_mat4_col_scale(s_w, mx->view, 2);
    return pt_matrix_tail(par, *clip, w_scale, sinks);
}
