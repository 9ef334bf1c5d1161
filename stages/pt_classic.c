/*
** stages/pt_classic.c -- the classic camera's six stages, run in order
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "pt_classic.h"
#include "s1_model2camera.h"
#include "s2_camera2image.h"
#include "s3_image2pixel.h"
#include "s4_pixel2viewport.h"
#include "s5_viewport2fb.h"
#include "s6_fb2index.h"

pt_vec2 pt_classic_journey(const pt_stage_params *par, pt_vec3 v_m,
                           const pt_sink *const sinks[PT_NSTAGES_ALL], double *z_c)
{
    pt_vec3 c, ip;
    pt_vec2 pp;
    pt_pix vp, fb;

    if (sinks[PT_STAGE_MODEL]) {          /* nobody listens: no record */
        pt_vrec r = {0};
        r.stage = PT_STAGE_MODEL;
        r.x = v_m.x; r.y = v_m.y; r.z = v_m.z;
        pt_emit(sinks[PT_STAGE_MODEL], &r);
    }
    c = pt_model2camera(v_m, par->translate, sinks[PT_STAGE_CAMERA]);
    *z_c = c.z;
    /* z_c's digits come from z_m and z_t: the larger sets its rounding error */
    ip = pt_camera2image(c, fmax(fabs(v_m.z), fabs(par->translate.z)),
                         par->perspective, sinks[PT_STAGE_IMAGE]);
    pp = pt_image2pixel(ip, par->w, par->h, sinks[PT_STAGE_PIXEL]);
    /* the rasterizer asks the viewport stage again for every step: the
    ** vertex's own pixel and index are wanted only by a listener */
    if (!sinks[PT_STAGE_VIEWPORT] && !sinks[PT_STAGE_FRAMEBUFFER] && !sinks[PT_STAGE_INDEX])
        return pp;
    vp = pt_pixel2viewport(pp, par->w, par->h, sinks[PT_STAGE_VIEWPORT]);
    fb = pt_viewport2fb(vp, par->x_ul, par->y_ul, sinks[PT_STAGE_FRAMEBUFFER]);
    pt_fb2index(fb, par->W, par->H, sinks[PT_STAGE_INDEX]);
    return pp;
}
