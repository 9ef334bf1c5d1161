/*
** stages/wasm/pt_wasm_libm.c -- fmax and ilogb without libm, for the stages in WebAssembly
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include "pt_wasm_libm.h"

double pt_wasm_fmax(double x, double y)
{
    if (x != x) return y;                   /* NaN: the other one */
    if (y != y) return x;
    return x > y ? x : y;
}

int pt_wasm_ilogb(double x)
{
    union { double d; uint64_t u; } b;
    int e;
    uint64_t m;

    b.d = x;
    e = (int)((b.u >> 52) & 0x7ff);         /* the biased exponent */
    m = b.u << 12;                          /* the 52 fraction bits, at the top */
    if (e == 0x7ff) return m ? -2147483647 - 1 : 2147483647;    /* NaN, infinity */
    if (e != 0) return e - 1023;            /* normal: 1.m * 2^(e - 1023) */
    if (m == 0) return -2147483647 - 1;     /* zero */
    e = -1023;                              /* subnormal: 0.m * 2^-1022 */
    while (!(m >> 63)) { m <<= 1; e--; }    /* one less per leading zero */
    return e;
}
