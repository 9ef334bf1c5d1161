/*
** stages/wasm/pt_wasm_libm.h -- the few libm functions the classic stages call, for WebAssembly
** See LICENSE for copyright and license.
**
** The stages compiled to WebAssembly (stages/wasm/pt_wasm.c) have no libc and
** no libm: clang --target=wasm32 -nostdlib.  They call fabs, floor, fmax and
** ilogb (and isnan, isinf, isfinite, which are clang builtins).  fabs and
** floor are single WebAssembly instructions (f64.abs, f64.floor), exact as
** libm's; fmax and ilogb are written here with C99's meaning: fmax returns
** the other operand when one is NaN (WebAssembly's f64.max would return
** NaN), ilogb the binary exponent of x, subnormals included.  Each is exact,
** so there is nothing to round differently: tests/test_wasm_libm.c compares
** them with the host's libm bit for bit.
*/
#ifndef PT_WASM_LIBM_H
#define PT_WASM_LIBM_H

/* fmax(x, y) as C99 defines it: the larger; y when x is NaN, x when y is
** NaN.  This function can't fail. */
double pt_wasm_fmax(double x, double y);

/* ilogb(x): the binary exponent e with 1 <= |x| / 2^e < 2, for every finite
** x other than 0 (subnormals too); 0 and NaN give INT_MIN, an infinity
** INT_MAX, as glibc does.  This function can't fail. */
int pt_wasm_ilogb(double x);

#endif
