/*
** stages/pt_ref.c -- one reference stage on one record, and records compared
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "pt_ref.h"

/* A sink that keeps the one record a stage reports. */
static void keep(void *ud, const pt_vrec *r)
{
    *(pt_vrec *)ud = *r;
}

/* The pixel a viewport or framebuffer record holds, as the stage returned it. */
static pt_pix pix_of(const pt_vrec *r)
{
    pt_pix p = {r->ix, r->iy, 0};

    return pt_pix_mark(p, pt_rec_has(r, 0) | pt_rec_has(r, 1) << 1);
}

int pt_ref_has(pt_stage st)
{
    switch (st) {
    case PT_STAGE_CAMERA: case PT_STAGE_IMAGE: case PT_STAGE_PIXEL:
    case PT_STAGE_VIEWPORT: case PT_STAGE_FRAMEBUFFER: case PT_STAGE_INDEX:
        return 1;
    case PT_STAGE_MODEL: case PT_STAGE_WORLD: case PT_STAGE_VIEW: case PT_STAGE_CLIP:
    case PT_STAGE_CVV: case PT_STAGE_NDC: case PT_STAGE_SCREEN:
        return 0;
    }
    return 0;
}

int pt_ref_stage(pt_stage st, const pt_stage_params *par, const pt_vrec *in, pt_vrec *out)
{
    pt_sink sink;
    pt_vec3 v = {in->x, in->y, in->z};
    pt_vec2 pp = {in->x, in->y};

    memset(out, 0, sizeof *out);
    sink.vertex = keep;
    sink.ud = out;
    switch (st) {
    case PT_STAGE_CAMERA:
        ptref_model2camera(v, par->translate, &sink);
        return 1;
    case PT_STAGE_IMAGE:
        ptref_camera2image(v, fabs(in->z), par->perspective, &sink);
        return 1;
    case PT_STAGE_PIXEL:
        ptref_image2pixel(v, par->w, par->h, &sink);
        return 1;
    case PT_STAGE_VIEWPORT:
        ptref_pixel2viewport(pp, par->w, par->h, &sink);
        return 1;
    case PT_STAGE_FRAMEBUFFER:
        ptref_viewport2fb(pix_of(in), par->x_ul, par->y_ul, &sink);
        return 1;
    case PT_STAGE_INDEX:
        ptref_fb2index(pix_of(in), par->W, par->H, &sink);
        return 1;
    case PT_STAGE_MODEL: case PT_STAGE_WORLD: case PT_STAGE_VIEW: case PT_STAGE_CLIP:
    case PT_STAGE_CVV: case PT_STAGE_NDC: case PT_STAGE_SCREEN:
        return 0;
    }
    return 0;
}

unsigned pt_ref_differ(pt_stage st, const pt_vrec *a, const pt_vrec *b)
{
    const pt_stage_info *in = &pt_stage_infos[st];
    const double da[4] = {a->x, a->y, a->z, a->w}, db[4] = {b->x, b->y, b->z, b->w};
    unsigned m = 0;
    int k;

    for (k = 0; k < in->nreal && k < 4; k++)
        if (memcmp(&da[k], &db[k], sizeof da[k]) != 0 && !(isnan(da[k]) && isnan(db[k])))
            m |= 1u << k;
    for (k = 0; k < in->nint; k++) {
        int has = pt_rec_has(a, k);
        int64_t va = st == PT_STAGE_INDEX ? a->i : k ? a->iy : a->ix;
        int64_t vb = st == PT_STAGE_INDEX ? b->i : k ? b->iy : b->ix;
        if (has != pt_rec_has(b, k) || (has && va != vb)) m |= 1u << k;
    }
    return m;
}
