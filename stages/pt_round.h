/*
** stages/pt_round.h -- Java's rounding, the pixel limit, the inside tests
** See LICENSE for copyright and license.
**
** The rules the viewport and index stages lean on, kept apart from them so that
** a student's stage (make STAGE_viewport=FILE.c) replaces the formula and never
** these: the rasterizer, the trace readers and diff's catalogue all round and
** test "inside" with the functions below.
**
**   round(x)   Java's Math.round: the nearest integer, ties toward +infinity
**              (round(-2.5) = -2, round(0.49999999999999994) = 0)
**   limit      |x| < 2^62, or the pixel has no integer value (Java's int would
**              have wrapped long before: docs/stability.md)
**   inside     0 <= x < w and 0 <= y < h  (viewport w x h, framebuffer W x H)
*/
#ifndef PT_ROUND_H
#define PT_ROUND_H

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include "pt_stage.h"

/* 2^62: beyond it, x_vp, x_fb and the rasterizer's step counts could overflow. */
#define PT_PIX_LIMIT 4611686018427387904.0

/* Java's Math.round(x) as a double: floor(x) plus one when x - floor(x) >= 0.5.
** Exact for every double (see the .c file).  NaN gives 0, infinities stay
** infinite.  This function can't fail. */
double pt_java_round(double x);

/* Round pixel-plane coordinate x to an integer in *out.  Returns 1, or 0 (and
** *out = 0) when x is not finite or |round(x)| >= PT_PIX_LIMIT.  This function
** can't fail.
**
** It is pt_java_round() for |x| < 2^62, in integers, inline and without a
** branch on the digits, because it runs for every step the rasterizer
** takes: the cast truncates toward zero exactly, and the fraction
** f = x - trunc(x) is exact too (for |x| >= 1, trunc(x) and x lie within a
** factor of 2 (Sterbenz); below, trunc(x) = 0; from 2^52 on, f = 0).  Then f
** in (-1, 1) says which way to the nearest: up when f >= 0.5, down when
** f < -0.5 (a tie, f = -0.5, goes up, to trunc(x)).  The step is multiplied
** by (trunc(x) != x), which changes nothing (f = 0 then) and takes no
** branch; it is there for the compiler: where x is (double) of an int, as
** the coordinate the rasterizer steps is, it sees that trunc(x) == x and that
** x is in range, and drops the rounding altogether.
** tests/unit/test_stages.c compares it with pt_java_round(). */
static inline int pt_pix_round(double x, int64_t *out)
{
    int64_t i;
    double t, f;

    if (!(x > -PT_PIX_LIMIT && x < PT_PIX_LIMIT)) { *out = 0; return 0; }  /* NaN too */
    i = (int64_t)x;                         /* toward zero */
    t = (double)i;
    f = x - t;                              /* the fraction, exact */
    i += (int64_t)(t != x) * ((f >= 0.5) - (f < -0.5));  /* ties go up: to +infinity */
    *out = i;
    return 1;
}

/* pt_pix_round() of an x known to be finite with |x| < PT_PIX_LIMIT: the
** same integer, without the range test and without the multiplier by
** (trunc(x) != x), for a loop that checked its range once (renderers 7 and
** 9's DDA, whose y stays between its ends).  tests/unit/test_stages.c
** compares it with pt_java_round().  This function can't fail. */
static inline int64_t pt_pix_round_in(double x)
{
    int64_t i = (int64_t)x;                 /* toward zero */
    double f = x - (double)i;               /* the fraction, exact */

    return i + (f >= 0.5) - (f < -0.5);     /* ties go up: to +infinity */
}

/* p as a stage returns it, when bit 0 of has says x has a value and bit 1
** that y has: ok when both; with one, the other becomes PT_PIX_NONE (null
** per value); with neither, {0, 0, 0}.  This function can't fail. */
static inline pt_pix pt_pix_mark(pt_pix p, int has)
{
    p.ok = has == 3;
    if (!has) p.x = p.y = 0;
    else if (has != 3) {
        if (!(has & 1)) p.x = PT_PIX_NONE;
        if (!(has & 2)) p.y = PT_PIX_NONE;
    }
    return p;
}

/* 1 when (x, y) lies inside a w x h rectangle whose upper-left pixel is (0, 0),
** 0 <= x < w and 0 <= y < h: a viewport pixel inside its viewport, or a
** framebuffer pixel inside the framebuffer.  w, h >= 1 (a scene's sizes
** are), so each pair of tests is one unsigned comparison: a negative x
** becomes a number above any w.  This function can't fail. */
static inline int pt_inside(int64_t x, int64_t y, int w, int h)
{
    assert(w >= 1 && h >= 1);
    return ((uint64_t)x < (uint64_t)w) & ((uint64_t)y < (uint64_t)h);
}

/* Report viewport pixel vp of a w x h viewport to sink, as both cameras'
** viewport stages do: null with a range warning when !vp.ok, else flagged
** inside or not by pt_inside().  Nothing when sink is NULL: the test is
** inline, as the rasterizer asks the viewport stage about every step with a
** NULL sink, and the record is built out of line.  This function can't fail. */
void pt_emit_viewport_record(const pt_sink *sink, pt_pix vp, int w, int h);
static inline void pt_emit_viewport(const pt_sink *sink, pt_pix vp, int w, int h)
{
    if (sink) pt_emit_viewport_record(sink, vp, w, h);
}

#endif
