/*
** src/tools/accuracy/dd.h -- double-double arithmetic: 106-bit values and 4x4 matrices
** See LICENSE for copyright and license.
**
** The reference arithmetic of `pipetrace accuracy` (accuracy.h): a value is
** hi + lo, two doubles, 106 significant bits.  Two-sum and two-product (with
** fma(), exactly rounded) make add, mul and div accurate to about 2^-104
** relative.  Nothing here allocates, prints or fails.
*/
#ifndef PT_DD_H
#define PT_DD_H

#include <stdint.h>
#include "core/pipetrace.h"

/* hi + lo with hi = fl(hi + lo): the unevaluated sum of two doubles.  A
** non-finite value has lo = 0. */
typedef struct pt_dd { double hi, lo; } pt_dd;

#define PT_DD_BITS 106           /* significant bits: 2 x 53 */

/* The double-double nearest 2001/1000, the constant of s3_image2pixel. */
extern const pt_dd pt_dd_2001;

/* x exactly.  This function can't fail. */
pt_dd pt_dd_from(double x);
/* v exactly (any int64_t).  This function can't fail. */
pt_dd pt_dd_from_i64(int64_t v);
/* a + b, a - b, a * b, a / b, -a: accurate to about 2^-104 relative; an
** infinite or NaN result is what double gives for hi.  These functions can't
** fail. */
pt_dd pt_dd_add(pt_dd a, pt_dd b);
pt_dd pt_dd_sub(pt_dd a, pt_dd b);
pt_dd pt_dd_mul(pt_dd a, pt_dd b);
pt_dd pt_dd_div(pt_dd a, pt_dd b);
pt_dd pt_dd_neg(pt_dd a);
/* 1 when a < b for the values hi + lo (both normalised).  This function can't
** fail. */
int pt_dd_lt(pt_dd a, pt_dd b);
/* sqrt(a): one Newton step from the double sqrt, about 2^-104 relative; 0, a
** negative a, inf and NaN give what double's sqrt gives for hi.  This function
** can't fail. */
pt_dd pt_dd_sqrt(pt_dd a);
/* cot(deg degrees) for 0 < deg < 90: Taylor series of sin and cos on an angle
** of at most 45 degrees (cot(deg) = tan(90 - deg) above 45), about 2^-104
** relative; exactly 1 at 45.  This function can't fail. */
pt_dd pt_dd_cot_deg(double deg);

/* Java's Math.round of the exact value hi + lo, as pt_pix_round() does for a
** double: returns 1 and the integer in *out, or 0 (and *out = 0) when x is not
** finite or the result is at least 2^62 in magnitude.  This function can't fail. */
int pt_dd_pix_round(pt_dd x, int64_t *out);

/* A 4x4 matrix of double-doubles on row vectors, as in stages/pt_mat4.h. */
typedef struct pt_dd_mat4 { pt_dd m[4][4]; } pt_dd_mat4;

/* a * b, each entry summed in k order; v * m into r[4] (not v), each
** component summed in row order.  These functions can't fail. */
pt_dd_mat4 pt_dd_mat4_mul(const pt_dd_mat4 *a, const pt_dd_mat4 *b);
void pt_dd_vec4_mul(const pt_dd v[4], const pt_dd_mat4 *m, pt_dd r[4]);

#endif
