/*
** tests/test_wasm_libm.c -- the journey page's fmax and ilogb (stages/wasm/) against libm
** See LICENSE for copyright and license.
**
** The stages compiled to WebAssembly have no libm; stages/wasm/pt_wasm_libm.c
** stands in for the two functions that are not single instructions.  Compiled
** here natively, each must give libm's answer bit for bit: on zeros, NaN,
** infinities, subnormals, powers of two and their neighbours, and a million
** doubles of every exponent.
*/
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "stages/wasm/pt_wasm_libm.c"
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
    return pt_test_report();
}
