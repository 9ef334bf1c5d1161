/*
** src/tools/catalogue.c -- the classic stages' right formulas and their known mistakes
** See LICENSE for copyright and license.
**
** The right formulas are the reference stages themselves (pt_ref_stage(),
** stages/pt_ref.h); each mistake is written in the order of operations of its
** stage in stages/; rounding and the inside test are pt_round.h's own
** functions.
*/
#include <math.h>
#include <string.h>
#include "tools/catalogue.h"

void pt_cat_val_of(pt_cat_val *v, const pt_vrec *r)
{
    memset(v, 0, sizeof *v);
    v->d[0] = r->x; v->d[1] = r->y; v->d[2] = r->z;
    v->flags = r->flags & (PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y);
    if (pt_stage_infos[r->stage].kind == PT_VAL_INDEX) v->n[0] = r->i;
    else { v->n[0] = r->ix; v->n[1] = r->iy; }
}

/* ===== rounding and the shared shapes of formulas ===== */

typedef double (*rnd_fn)(double);

static double c_round(double x) { return round(x); }            /* ties away from 0 */
static double floor_half(double x) { return floor(x + 0.5); }   /* the sum rounds */
static double trunc_half(double x) { return trunc(x + 0.5); }   /* (int64_t)(x + 0.5) */

/* The viewport stage with rounding rndx of x_pp and rndy of y_pp (NULL:
** Java's Math.round), x_vp = round(x_pp) + dx and y_vp = sy * round(y_pp) +
** oy (the right formula: dx = -1, sy = -1, oy = h).  No value where
** pt_pix_round() finds none, per value (pt_pix_mark(), as the stage). */
static void viewport_xy(rnd_fn rndx, rnd_fn rndy, int64_t dx, int64_t sy, int64_t oy,
                        const pt_cat_val *in, pt_cat_val *out)
{
    int64_t rx, ry;
    double x = rndx ? rndx(in->d[0]) : in->d[0], y = rndy ? rndy(in->d[1]) : in->d[1];
    int has = pt_pix_round(x, &rx) | pt_pix_round(y, &ry) << 1;
    pt_pix p = {rx + dx, sy * ry + oy, 0};

    p = pt_pix_mark(p, has);
    out->flags = pt_pix_flags(p);
    out->n[0] = pt_pix_has(p, 0) ? p.x : 0;
    out->n[1] = pt_pix_has(p, 1) ? p.y : 0;
}

/* The viewport stage with one rounding rnd for both values (viewport_xy). */
static void viewport_with(rnd_fn rnd, int64_t dx, int64_t sy, int64_t oy,
                          const pt_cat_val *in, pt_cat_val *out)
{
    viewport_xy(rnd, rnd, dx, sy, oy, in, out);
}

/* The framebuffer stage with corner (x_ul, y_ul): each value that has one is
** offset, the others stay without (s5). */
static void framebuffer_with(int64_t x_ul, int64_t y_ul, const pt_cat_val *in, pt_cat_val *out)
{
    out->flags = in->flags;
    out->n[0] = pt_cat_has(in, 0) ? x_ul + in->n[0] : 0;
    out->n[1] = pt_cat_has(in, 1) ? y_ul + in->n[1] : 0;
}

/* The index stage with idx = y * mul_y + x * mul_x, no value outside W x H. */
static void index_with(const pt_stage_params *par, int64_t mul_x, int64_t mul_y,
                       const pt_cat_val *in, pt_cat_val *out)
{
    int64_t x = in->n[0], y = in->n[1];

    int none = in->flags != 0 || !pt_inside(x, y, par->W, par->H);

    out->flags = none ? PT_REC_NULL : 0;
    out->n[0] = none ? 0 : y * mul_y + x * mul_x;
}

/* ===== the right formulas: the reference stages ===== */

/* The record of stage st that holds v's values (pt_cat_val_of() backwards). */
static void rec_of(pt_vrec *r, int st, const pt_cat_val *v)
{
    memset(r, 0, sizeof *r);
    r->stage = (pt_stage)st;
    r->flags = v->flags;
    r->x = v->d[0]; r->y = v->d[1]; r->z = v->d[2];
    if (pt_stage_infos[st].kind == PT_VAL_INDEX) r->i = v->n[0];
    else { r->ix = v->n[0]; r->iy = v->n[1]; }
}

int pt_cat_right(int st, const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    pt_vrec a, b;
    int prev;

    memset(out, 0, sizeof *out);
    if (st < 0 || st >= PT_NSTAGES_ALL || !pt_pipeline_ref(&pt_pipe_classic, (pt_stage)st))
        return 0;
    prev = pt_pipeline_prev(&pt_pipe_classic, (pt_stage)st);
    rec_of(&a, prev, in);
    if (!pt_ref_stage((pt_stage)st, par, &a, &b)) return 0;
    pt_cat_val_of(out, &b);
    return 1;
}

unsigned pt_cat_differ(int st, const pt_cat_val *a, const pt_cat_val *b)
{
    pt_vrec ra, rb;

    rec_of(&ra, st, a);
    rec_of(&rb, st, b);
    return pt_ref_differ((pt_stage)st, &ra, &rb);
}

/* ===== the known mistakes ===== */

static void mk_subtract(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    out->d[0] = in->d[0] - par->translate.x;
    out->d[1] = in->d[1] - par->translate.y;
    out->d[2] = in->d[2] - par->translate.z;
}

static void mk_divz(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    (void)par;
    out->d[0] = in->d[0] / in->d[2];
    out->d[1] = in->d[1] / in->d[2];
    out->d[2] = -1.0;
}

static void mk_two(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    out->d[0] = 0.5 + par->w / 2.0 * (in->d[0] + 1);
    out->d[1] = 0.5 + par->h / 2.0 * (in->d[1] + 1);
}

static void mk_two_int(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    out->d[0] = 0.5 + (double)(par->w / 2) * (in->d[0] + 1);
    out->d[1] = 0.5 + (double)(par->h / 2) * (in->d[1] + 1);
}

/* The right pixel stage, given h for w and w for h. */
static void mk_swap_wh(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    pt_vec3 ip = {in->d[0], in->d[1], in->d[2]};
    pt_vec2 pp = ptref_image2pixel(ip, par->h, par->w, NULL);

    out->d[0] = pp.x;
    out->d[1] = pp.y;
}

static void mk_cround(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    viewport_with(c_round, -1, -1, par->h, in, out);
}

static void mk_floor(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    viewport_with(floor_half, -1, -1, par->h, in, out);
}

/* (int64_t)(x + 0.5): the cast truncates toward zero, so below -0.5 it
** rounds up.  trunc() of a double is the cast's value wherever the cast is
** defined, and a value beyond 2^62 has no pixel either way. */
static void mk_trunc(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    viewport_with(trunc_half, -1, -1, par->h, in, out);
}

static void mk_noflip1(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    (void)par;
    viewport_with(NULL, -1, 1, -1, in, out);
}

static void mk_noflip0(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    (void)par;
    viewport_with(NULL, -1, 1, 0, in, out);
}

static void mk_nominus1(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    viewport_with(NULL, 0, -1, par->h, in, out);
}

static void mk_nooffset(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    (void)par;
    framebuffer_with(0, 0, in, out);        /* x_fb = x_vp */
}

static void mk_xh(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    index_with(par, par->H, 1, in, out);
}

/* w for W in the product only: the bounds stay the framebuffer's, as in a
** stage that checks the pixel against W x H and then multiplies by w (so
** pt_fb2index(fb, w, H) would not do: it also checks x_fb < w). */
static void mk_vpw(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    index_with(par, 1, par->w, in, out);
}

/* PT_PIXEL_DIVISOR as the mistakes' names spell it: "2.001". */
#define SPELL_(x) #x
#define SPELL(x) SPELL_(x)
#define DIVISOR SPELL(PT_PIXEL_DIVISOR)

const pt_mistake pt_mistakes[PT_NMISTAKES] = {
    {PT_STAGE_CAMERA, "translation subtracted",
     "x_c = x_m - x_t (likewise y, z) instead of x_m + x_t", 0, mk_subtract},
    {PT_STAGE_IMAGE, "projection divides by z_c instead of -z_c",
     "x_ip = x_c / z_c: the image comes out mirrored, x and y negated", 0, mk_divz},
    {PT_STAGE_PIXEL, "2 instead of " DIVISOR,
     "x_pp = 0.5 + w/2 * (x_ip + 1): every x_pp moves right by w/4002 * (x_ip + 1), "
     "and the right edge x_ip = 1 lands on w + 0.5, between two pixels", 0, mk_two},
    {PT_STAGE_PIXEL, "2 instead of " DIVISOR ", with w/2 in integers",
     "x_pp = 0.5 + w/2 * (x_ip + 1) with w/2 in integer arithmetic (int w): besides the "
     "2, half a pixel of an odd size is lost", 1, mk_two_int},
    {PT_STAGE_PIXEL, "w and h swapped",
     "x_pp = 0.5 + h/" DIVISOR " * (x_ip + 1), y_pp = 0.5 + w/" DIVISOR " * (y_ip + 1)", 0,
     mk_swap_wh},
    {PT_STAGE_VIEWPORT, "C round() instead of Java's Math.round",
     "round() and lround() take ties away from zero: round(-2.5) = -3, "
     "Math.round(-2.5) = -2", 0, mk_cround},
    {PT_STAGE_VIEWPORT, "floor(x + 0.5) instead of Java's Math.round",
     "0.49999999999999994 + 0.5 rounds up to 1.0, so floor gives 1 where "
     "Math.round gives 0", 0, mk_floor},
    {PT_STAGE_VIEWPORT, "truncation toward zero instead of Java's Math.round",
     "(int64_t)(x_pp + 0.5) truncates toward zero: right for x_pp >= -0.5, but a "
     "negative x_pp rounds up (-79.46 + 0.5 = -78.96 becomes -78, Math.round gives -79)",
     0, mk_trunc},
    {PT_STAGE_VIEWPORT, "missing y flip",
     "y_vp = round(y_pp) - 1 instead of h - round(y_pp): the image comes out upside down",
     0, mk_noflip1},
    {PT_STAGE_VIEWPORT, "missing y flip",
     "y_vp = round(y_pp) instead of h - round(y_pp): the image comes out upside down",
     0, mk_noflip0},
    {PT_STAGE_VIEWPORT, "missing -1 in x_vp",
     "x_vp = round(x_pp) instead of round(x_pp) - 1: one pixel too far right",
     0, mk_nominus1},
    {PT_STAGE_FRAMEBUFFER, "viewport offset (x_ul, y_ul) forgotten",
     "x_fb = x_vp, y_fb = y_vp instead of x_ul + x_vp, y_ul + y_vp: the picture sits "
     "in the framebuffer's upper-left corner, not in the viewport", 0, mk_nooffset},
    {PT_STAGE_INDEX, "index x * H + y",
     "idx = x_fb * H + y_fb (column by column) instead of y_fb * W + x_fb", 0, mk_xh},
    {PT_STAGE_INDEX, "viewport width instead of framebuffer width",
     "idx = y_fb * w + x_fb with the viewport's w instead of the framebuffer's W", 0, mk_vpw},
};

/* ===== the rasterizer's mistakes ===== */

/* The viewport stage's formula with roundings rndx, rndy and x_vp =
** round(x_pp) + dx, y_vp = sy * round(y_pp) + oy (viewport_xy), as a
** pt_raster_vp. */
static pt_pix viewport_mapping(rnd_fn rndx, rnd_fn rndy, int64_t dx, int64_t sy, int64_t oy,
                               pt_vec2 pp)
{
    pt_cat_val in, out;
    pt_pix vp;

    memset(&in, 0, sizeof in);
    in.d[0] = pp.x;
    in.d[1] = pp.y;
    viewport_xy(rndx, rndy, dx, sy, oy, &in, &out);
    vp.x = out.n[0];
    vp.y = out.n[1];
    vp.ok = 0;
    return pt_pix_mark(vp, pt_cat_has(&out, 0) | pt_cat_has(&out, 1) << 1);
}

pt_pix pt_cat_vp_floor(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(floor_half, floor_half, -1, -1, h, pp);
}

pt_pix pt_cat_vp_cround(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(c_round, c_round, -1, -1, h, pp);
}

pt_pix pt_cat_vp_trunc(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(trunc_half, trunc_half, -1, -1, h, pp);
}

/* Truncation of the coordinate the DDA accumulates only: y of an x-major
** segment, x of a y-major one.  The course's Java rasterizer rounds that
** one alone, its step being an int: (int)(y + 0.5) there. */
pt_pix pt_cat_vp_trunc_y(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(NULL, trunc_half, -1, -1, h, pp);
}

pt_pix pt_cat_vp_trunc_x(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(trunc_half, NULL, -1, -1, h, pp);
}

pt_pix pt_cat_vp_nominus1(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)sink;
    return viewport_mapping(NULL, NULL, 0, -1, h, pp);
}

pt_pix pt_cat_vp_noflip(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    (void)w; (void)h; (void)sink;
    return viewport_mapping(NULL, NULL, -1, 1, -1, pp);
}

#define IN_ROUNDING "in the rasterizer's rounding (pt_pix_round in s4)"
#define IN_VIEWPORT "in the viewport formula the rasterizer asks each step (s4)"

const pt_raster_mistake pt_raster_mistakes[PT_NRASTER_MISTAKES] = {
    {"floor(x + 0.5) instead of Java's Math.round", IN_ROUNDING,
     "the DDA's running y can be 0.49999999999999994, which floor(y + 0.5) takes to 1 "
     "and Math.round to 0", pt_cat_vp_floor, 0, 0, 0, {NULL, NULL}},
    {"C round() instead of Java's Math.round", IN_ROUNDING,
     "round() takes ties away from zero", pt_cat_vp_cround, 0, 0, 0, {NULL, NULL}},
    {"truncation toward zero instead of Java's Math.round", IN_ROUNDING,
     "(int)(y + 0.5) truncates toward zero: as floor(y + 0.5) at 0.49999999999999994, "
     "and one too high below -0.5, which only steps left of or below the viewport reach",
     pt_cat_vp_trunc, 0, 0, 1, {pt_cat_vp_trunc_y, pt_cat_vp_trunc_x}},
    {"missing -1 in x_vp", IN_VIEWPORT,
     "x_vp = round(x_pp) instead of round(x_pp) - 1: every pixel one to the right, the "
     "steps at x_pp = w clipped", pt_cat_vp_nominus1, 0, 0, 0, {NULL, NULL}},
    {"missing y flip", IN_VIEWPORT,
     "y_vp = round(y_pp) - 1 instead of h - round(y_pp): the picture upside down",
     pt_cat_vp_noflip, 0, 0, 0, {NULL, NULL}},
    {"DDA loop one step short", "in the rasterizer's loop bound",
     "for (x = x0; x < x1; ...) instead of x <= x1: the last step of every segment that "
     "is not a single pixel is not taken, its pixel missing", NULL, -1, 0, 0, {NULL, NULL}},
    {"DDA loop one step too long", "in the rasterizer's loop bound",
     "for (x = x0; x <= x1 + 1; ...) instead of x <= x1: one step past the end of every "
     "segment that is not a single pixel, an extra pixel", NULL, 1, 0, 0, {NULL, NULL}},
    {"viewport offset (x_ul, y_ul) forgotten", "in setPixelVP",
     "the pixel written at (x_vp, y_vp) instead of (x_ul + x_vp, y_ul + y_vp): the "
     "picture sits in the framebuffer's upper-left corner, not in the viewport",
     NULL, 0, 1, 0, {NULL, NULL}},
};
