/*
** tests/unit/test_wasm_libm.c -- the journey page's fmax, ilogb, fmod, ldexp, frexp (src/wasm/) against libm
** See LICENSE for copyright and license.
**
** The stages compiled to WebAssembly have no libm; src/wasm/pt_wasm_libm.c
** stands in for the functions that are not single instructions.  Compiled
** here natively, each must give libm's answer bit for bit: on zeros, NaN,
** infinities, subnormals, powers of two and their neighbours, and a million
** doubles of every exponent.
*/
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "wasm/pt_wasm_libm.c"
#include "testhelp.h"

static uint64_t bits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static double from_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static uint64_t state = 0x9e3779b97f4a7c15u;
static uint64_t next(void)             /* xorshift64*: any bits, any exponent */
{
    state ^= state >> 12; state ^= state << 25; state ^= state >> 27;
    return state * 0x2545f4914f6cdd1du;
}

int main(void)
{
    static const double special[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 3.0, DBL_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX,
        DBL_TRUE_MIN, -DBL_TRUE_MIN, 4.9e-320, 2.2250738585072009e-308, 1e300, -1e-300,
        0.49999999999999994, 4503599627370496.0, 9007199254740993.0, 1e-7, 6.0, -5.0
    };
    int n = (int)(sizeof special / sizeof special[0]), a, b, bad = 0;
    long k;

    for (a = 0; a < n; a++) {
        double x = special[a];
        if (x != 0) PT_CHECK("wasm-libm-1 ilogb of a special value", pt_wasm_ilogb(x) == ilogb(x));
        for (b = 0; b < n; b++)
            PT_CHECK("wasm-libm-2 fmax of two special values",
                     bits(pt_wasm_fmax(x, special[b])) == bits(fmax(x, special[b]))
                     || (x == 0 && special[b] == 0));   /* +-0: C leaves the sign open */
        PT_CHECK("wasm-libm-3 fmax(NaN, x) = x", bits(pt_wasm_fmax((double)NAN, x)) == bits(x));
        PT_CHECK("wasm-libm-4 fmax(x, NaN) = x", bits(pt_wasm_fmax(x, (double)NAN)) == bits(x));
    }
    PT_CHECK("wasm-libm-5 ilogb(inf) = INT_MAX", pt_wasm_ilogb((double)INFINITY) == INT_MAX);
    PT_CHECK("wasm-libm-6 ilogb(0) = INT_MIN", pt_wasm_ilogb(0.0) == INT_MIN);
    PT_CHECK("wasm-libm-7 ilogb(NaN) = INT_MIN", pt_wasm_ilogb((double)NAN) == INT_MIN);
    PT_CHECK("wasm-libm-8 the smallest subnormal: -1074", pt_wasm_ilogb(DBL_TRUE_MIN) == -1074);
    for (k = 0; k < 1000000; k++) {    /* random doubles of every exponent */
        double x = from_bits(next()), y = from_bits(next());
        if (isfinite(x) && x != 0 && pt_wasm_ilogb(x) != ilogb(x)) bad++;
        if (!isnan(x) && !isnan(y) && bits(pt_wasm_fmax(x, y)) != bits(fmax(x, y))) bad++;
        if (k % 4 == 0) {              /* subnormals: exponent bits 0 */
            double s = from_bits(next() & 0x800fffffffffffffu);
            if (s != 0 && pt_wasm_ilogb(s) != ilogb(s)) bad++;
        }
    }
    PT_CHECK("wasm-libm-9 a million random doubles: ilogb and fmax as libm's", bad == 0);
    bad = 0;
    for (a = 0; a < n; a++)
        for (b = 0; b < n; b++) {
            double x = special[a], y = special[b];
            int e1, e2;
            double f1 = pt_wasm_frexp(x, &e1), f2 = frexp(x, &e2);
            if (y != 0 && bits(pt_wasm_fmod(x, y)) != bits(fmod(x, y))) bad++;
            if (bits(f1) != bits(f2) || e1 != e2) bad++;
            for (e1 = -2200; e1 <= 2200; e1 += 37)
                if (bits(pt_wasm_ldexp(x, e1)) != bits(ldexp(x, e1))) bad++;
        }
    PT_CHECK("wasm-libm-10 fmod, frexp, ldexp of the special values as libm's", bad == 0);
    PT_CHECK("wasm-libm-11 fmod(x, 0), fmod(inf, y): NaN",
             isnan(pt_wasm_fmod(1.0, 0.0)) && isnan(pt_wasm_fmod((double)INFINITY, 2.0)));
    for (k = 0; k < 300000; k++) {     /* random doubles; y near x, where loops run longest */
        double x = from_bits(next()), y = k % 2 ? from_bits(next()) : x / (double)(k % 1000 + 3);
        int e1, e2, m = (int)(next() % 4400) - 2200;
        double f1 = pt_wasm_frexp(x, &e1), f2 = frexp(x, &e2);
        if (!isnan(x) && !isnan(y) && y != 0 && isfinite(x)
            && bits(pt_wasm_fmod(x, y)) != bits(fmod(x, y))) bad++;
        if (!isnan(x) && (bits(f1) != bits(f2) || e1 != e2)) bad++;
        if (!isnan(x) && bits(pt_wasm_ldexp(x, m)) != bits(ldexp(x, m))) bad++;
        if (k % 4 == 0) {              /* subnormal results and arguments */
            double sub = from_bits(next() & 0x800fffffffffffffu);
            if (bits(pt_wasm_ldexp(x, -1100 + (int)(k % 200))) != bits(ldexp(x, -1100 + (int)(k % 200)))) bad++;
            if (bits(pt_wasm_frexp(sub, &e1)) != bits(frexp(sub, &e2)) || e1 != e2) bad++;
        }
    }
    PT_CHECK("wasm-libm-12 random doubles: fmod, frexp, ldexp as libm's", bad == 0);
    pt_wasm_nsincos = 1;
    pt_wasm_sincos[0][0] = 0.5; pt_wasm_sincos[0][1] = sin(0.5); pt_wasm_sincos[0][2] = cos(0.5);
    pt_wasm_libm_missed = 0;
    PT_CHECK("wasm-libm-13 sin and cos of an argument in the table: the table's",
             pt_wasm_sin(0.5) == sin(0.5) && pt_wasm_cos(0.5) == cos(0.5) && !pt_wasm_libm_missed);
    PT_CHECK("wasm-libm-14 an argument not in the table: NaN and the miss noted",
             isnan(pt_wasm_sin(0.25)) && pt_wasm_libm_missed);
    return pt_test_report();
}
