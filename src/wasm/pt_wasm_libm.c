/*
** src/wasm/pt_wasm_libm.c -- the libm the stages need in WebAssembly (see pt_wasm_libm.h)
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include "wasm/pt_wasm_libm.h"

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

double pt_wasm_fmod(double x, double y)
{
    double r = __builtin_fabs(x), a = __builtin_fabs(y), b;

    if (x != x || y != y || a == 0 || r - r != 0) return __builtin_nan("");
    if (r < a) return x;
    b = a;
    while (b * 2 <= r) b *= 2;              /* the largest a*2^k <= r: exact */
    for (;;) {                              /* long division, one bit at a time */
        if (r >= b) r -= b;                 /* exact: b <= r < 2b (Sterbenz) */
        if (b == a) break;
        b /= 2;                             /* exact: a*2^(k-1) */
    }
    return __builtin_copysign(r, x);
}

double pt_wasm_ldexp(double x, int n)
{
    union { double d; uint64_t u; } s;
    double y = x;

    if (n > 1023) {                         /* in steps no product overflows early */
        y *= 0x1p1023; n -= 1023;
        if (n > 1023) { y *= 0x1p1023; n -= 1023; if (n > 1023) n = 1023; }
    } else if (n < -1022) {                 /* the last step alone may round */
        y *= 0x1p-1022 * 0x1p53; n += 1022 - 53;
        if (n < -1022) {
            y *= 0x1p-1022 * 0x1p53; n += 1022 - 53;
            if (n < -1022) n = -1022;
        }
    }
    s.u = (uint64_t)(0x3ff + n) << 52;      /* 2^n, a normal double */
    return y * s.d;
}

double pt_wasm_frexp(double x, int *e)
{
    if (x == 0 || x - x != 0) { *e = 0; return x; }
    *e = pt_wasm_ilogb(x) + 1;
    return pt_wasm_ldexp(x, -*e);
}

double pt_wasm_sincos[PT_WASM_NSINCOS][3];
int pt_wasm_nsincos;
int pt_wasm_libm_missed;

/* Row k's column c for argument x, or NaN (and the miss noted). */
static double look_up(double x, int c)
{
    int k;

    for (k = 0; k < pt_wasm_nsincos; k++)
        if (pt_wasm_sincos[k][0] == x) return pt_wasm_sincos[k][c];
    pt_wasm_libm_missed = 1;
    return __builtin_nan("");
}

double pt_wasm_sin(double x) { return look_up(x, 1); }
double pt_wasm_cos(double x) { return look_up(x, 2); }
