/*
** src/wasm/math.h -- <math.h> for the stages compiled to WebAssembly (no libc)
** See LICENSE for copyright and license.
**
** Only what the stages use (stages/pt_stage.c, pt_round.c, s1..s6,
** pt_classic.c; pt_mat4.c, pt_matrix.c, m1..m7): the classification macros
** and NAN as clang's builtins, fabs, floor and sqrt as WebAssembly's f64.abs,
** f64.floor and f64.sqrt, the rest from pt_wasm_libm.c (sin and cos: a
** table, see pt_wasm_libm.h).  Found first because the Makefile compiles
** with -isystem src/wasm for the wasm32 target only.
*/
#ifndef PT_WASM_MATH_H
#define PT_WASM_MATH_H

#include "wasm/pt_wasm_libm.h"

#define isnan(x)     __builtin_isnan(x)
#define isinf(x)     __builtin_isinf(x)
#define isfinite(x)  __builtin_isfinite(x)
#define fabs(x)      __builtin_fabs(x)
#define floor(x)     __builtin_floor(x)
#define sqrt(x)      __builtin_sqrt(x)
#define NAN          __builtin_nan("")
#define fmax(x, y)   pt_wasm_fmax((x), (y))
#define fmod(x, y)   pt_wasm_fmod((x), (y))
#define ldexp(x, n)  pt_wasm_ldexp((x), (n))
#define frexp(x, e)  pt_wasm_frexp((x), (e))
#define sin(x)       pt_wasm_sin(x)
#define cos(x)       pt_wasm_cos(x)
#define ilogb(x)     pt_wasm_ilogb(x)

#endif
