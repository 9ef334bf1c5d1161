/*
** src/tools/catalogue.h -- the classic stages' right formulas and their known mistakes
** See LICENSE for copyright and license.
**
** What `pipetrace diff` and `pipetrace step` check a stage's numbers against:
**
**   right      each classic stage's formula (camera .. index), computed from
**              the previous stage's values and the scene's numbers
**              (pt_stage_params: w, h, W, H, x_ul, y_ul, perspective, the
**              model's translation);
**   mistakes   the known wrong versions of those formulas, each with a name,
**              an explanation and the wrong formula itself;
**   raster     the rasterizer's mistakes: viewport stages that round or map
**              otherwise (pt_raster_vp, to hand to pt_raster_segment()), the
**              DDA's loop bound off by one, setPixelVP without the offset.
**
** The right formulas are not written again here: a student build replaces a
** stage's .c file (make STAGE_pixel=FILE.c), so they are the reference copy
** of the stages that every build holds (ptref_*, pt_ref_stage(),
** stages/pt_ref.h).  tests/unit/test_catalogue.c checks, on every reference case,
** that they give the stage's record bit for bit.  The mistakes round and test
** "inside" with stages/pt_round.h, which a student does not replace; a mistake
** that is the right formula with wrong inputs (w and h swapped) calls the
** reference stage with those inputs.
*/
#ifndef PT_CATALOGUE_H
#define PT_CATALOGUE_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"

/* One stage's values, as a trace holds them.  A real stage (camera, image,
** pixel) uses d[0..2] (x, y, z); the viewport and framebuffer n[0..1] (x, y);
** the index n[0].  flags: which integer values have one, as a record says it
** (0, or PT_REC_NULL with PT_REC_HAS_X/Y: null per value); ask pt_cat_has(). */
typedef struct pt_cat_val {
    unsigned flags;              /* integer stage: PT_REC_NULL, PT_REC_HAS_X/Y */
    double d[3];                 /* real stages: x, y, z */
    int64_t n[2];                /* integer stages: x, y; the index: n[0] (0 without value) */
} pt_cat_val;

/* 1 when integer value k (0: x or the index, 1: y) of v has a value.  This
** function can't fail. */
static inline int pt_cat_has(const pt_cat_val *v, int k) { return pt_flags_have(v->flags, k); }

/* The values of record r (of stage r->stage) into *v.  This function can't
** fail. */
void pt_cat_val_of(pt_cat_val *v, const pt_vrec *r);

/* The right formula of classic stage st (camera .. index) applied to in, the
** previous stage's values, with the numbers of par; the result into *out,
** as the reference stage (pt_ref_stage()) computes it, in a student build too.  Returns 1, or 0 (and *out
** zeroed) when st has no formula here (model, the matrix camera's stages).
** Requires par->w, h, W, H >= 1.  This function can't fail. */
int pt_cat_right(int st, const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out);

/* Which values of stage st differ between a and b, bit for bit (-0.0 differs
** from 0.0; NaN agrees with NaN): bit k for value k; all of an integer stage's
** bits when one has a value and the other none.  0 when they agree.  This
** function can't fail. */
unsigned pt_cat_differ(int st, const pt_cat_val *a, const pt_cat_val *b);

/* A known mistake of a classic stage. */
typedef struct pt_mistake {
    int stage;                   /* pt_stage it is made in */
    const char *name;            /* what was done, a few words (two forms of one
                                 ** mistake share it) */
    const char *how;             /* the wrong formula, and why it goes wrong */
    int odd_only;                /* 1: differs from another form only when w or
                                 ** h is odd (w/2 in integers) */
    void (*apply)(const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out);
                                 /* the stage with the mistake, as pt_cat_right */
} pt_mistake;

#define PT_NMISTAKES 14
extern const pt_mistake pt_mistakes[PT_NMISTAKES];

/* A known mistake of the rasterizer (the course's renderer 4: its DDA and
** setPixelVP), replayed by pipetrace diff from EXPECTED's rounded endpoints:
**   to_vp      a viewport stage that rounds or maps otherwise, asked each step;
**   steps      the DDA's loop bound off by one: -1 its last step not taken
**              (x < x1), +1 one step more (x <= x1 + 1);
**   no_offset  setPixelVP writing each pixel at its viewport coordinates,
**              the viewport's corner (x_ul, y_ul) forgotten.
** twin: a mistake that lights the same pixels wherever every step's
** coordinate + 0.5 is at least 0 (truncation and floor(x + 0.5)): only the
** clip records of steps left of or below the viewport tell them apart. */
typedef struct pt_raster_mistake {
    const char *name;            /* as the stage's mistake of that name */
    const char *where;           /* where it is made, a few words */
    const char *how;             /* what goes wrong in the DDA */
    pt_raster_vp to_vp;          /* the viewport stage with the mistake, or NULL:
                                 ** the right one (pt_pixel2viewport) */
    int steps;                   /* -1, +1: the loop's last step; 0: right */
    int no_offset;               /* 1: pixels without the offset (x_ul, y_ul) */
    int twin;                    /* 1 + the mistake it is told from only by
                                 ** negative coordinates, or 0 */
    pt_raster_vp running[2];     /* the mistake in the coordinate the DDA
                                 ** accumulates only, of an x-major [0] and a
                                 ** y-major [1] segment, as the course's Java
                                 ** rasterizer makes it (its step an int):
                                 ** tried on a course log; or NULL */
} pt_raster_mistake;

#define PT_NRASTER_MISTAKES 8
extern const pt_raster_mistake pt_raster_mistakes[PT_NRASTER_MISTAKES];

/* The viewport stage's formula (x_vp = r(x_pp) - 1, y_vp = h - r(y_pp)) with
** r(x) = floor(x + 0.5), C's round() (ties away from zero), resp. trunc(x +
** 0.5) ((int)(x + 0.5)), instead of Java's Math.round; pt_cat_vp_nominus1
** with x_vp = r(x_pp), pt_cat_vp_noflip with y_vp = r(y_pp) - 1 (Math.round).
** No value beyond PT_PIX_LIMIT as pt_pixel2viewport().  Report nothing (sink
** is ignored).  These functions can't fail. */
pt_pix pt_cat_vp_floor(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_cround(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_trunc(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_trunc_y(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_trunc_x(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_nominus1(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix pt_cat_vp_noflip(pt_vec2 pp, int w, int h, const pt_sink *sink);

#endif
