/*
** stages/wasm/math.h -- <math.h> for the stages compiled to WebAssembly (no libc)
** See LICENSE for copyright and license.
**
** Only what the classic stages use (stages/pt_stage.c, pt_round.c,
** s1_model2camera.c, pt_classic.c): the classification macros as clang's
** builtins, fabs and floor as WebAssembly's f64.abs and f64.floor, fmax and
** ilogb from pt_wasm_libm.c.  Found first because the Makefile compiles
** with -isystem stages/wasm for the wasm32 target only.
*/
#ifndef PT_WASM_MATH_H
#define PT_WASM_MATH_H

#include "pt_wasm_libm.h"

#define isnan(x)     __builtin_isnan(x)
#define isinf(x)     __builtin_isinf(x)
#define isfinite(x)  __builtin_isfinite(x)
#define fabs(x)      __builtin_fabs(x)
#define floor(x)     __builtin_floor(x)
#define fmax(x, y)   pt_wasm_fmax((x), (y))
#define ilogb(x)     pt_wasm_ilogb(x)

#endif
