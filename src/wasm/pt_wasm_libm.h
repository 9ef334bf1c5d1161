/*
** src/wasm/pt_wasm_libm.h -- the few libm functions the stages call, for WebAssembly
** See LICENSE for copyright and license.
**
** The stages compiled to WebAssembly (src/wasm/pt_wasm.c) have no libc and
** no libm: clang --target=wasm32 -nostdlib.  They call fabs, floor, sqrt,
** fmax, ilogb, fmod, frexp, ldexp, sin and cos (and isnan, isinf, isfinite,
** which are clang builtins).  fabs, floor and sqrt are single WebAssembly
** instructions (f64.abs, f64.floor, f64.sqrt), exact or correctly rounded as
** libm's; fmax, ilogb, fmod, frexp and ldexp are written here with C99's
** meaning, and each is exact or correctly rounded, so there is nothing to
** round differently: tests/unit/test_wasm_libm.c compares them with the host's
** libm bit for bit.
**
** sin and cos are not: glibc's are not correctly rounded, and no sin written
** here would match it everywhere.  So the module has none.  pt_wasm_sin and
** pt_wasm_cos look their argument up in a table the page hands over,
** computed by the host's libm when pipetrace wrote the page (the arguments
** pt_perspective() gives them for the fov slider's steps); an argument not in
** the table gives NaN and sets pt_wasm_libm_missed, never a wrong value.
*/
#ifndef PT_WASM_LIBM_H
#define PT_WASM_LIBM_H

#include "stages/wasm/pt_wasm_in.h"

/* fmax(x, y) as C99 defines it: the larger; y when x is NaN, x when y is
** NaN.  This function can't fail. */
double pt_wasm_fmax(double x, double y);

/* ilogb(x): the binary exponent e with 1 <= |x| / 2^e < 2, for every finite
** x other than 0 (subnormals too); 0 and NaN give INT_MIN, an infinity
** INT_MAX, as glibc does.  This function can't fail. */
int pt_wasm_ilogb(double x);

/* fmod(x, y), exact: x - n*y with n = trunc(x/y), the sign of x; NaN when x
** is infinite or NaN or y is 0 or NaN.  This function can't fail. */
double pt_wasm_fmod(double x, double y);

/* ldexp(x, n) = x * 2^n, correctly rounded (one rounding, in the subnormal
** range only).  This function can't fail. */
double pt_wasm_ldexp(double x, int n);

/* frexp(x, e): f with 0.5 <= |f| < 1 and x = f * 2^*e; x itself and *e = 0
** for 0, an infinity or NaN.  This function can't fail. */
double pt_wasm_frexp(double x, int *e);

/* The table of sin and cos: row k is (argument, sin, cos), n rows in use
** (PT_WASM_NSINCOS: pt_wasm_in.h). */
extern double pt_wasm_sincos[PT_WASM_NSINCOS][3];
extern int pt_wasm_nsincos;
extern int pt_wasm_libm_missed;     /* set when an argument was not in the table */

/* sin(x), cos(x) from the table (NaN, and pt_wasm_libm_missed set, for an x
** not in it).  These functions can't fail. */
double pt_wasm_sin(double x);
double pt_wasm_cos(double x);

#endif
