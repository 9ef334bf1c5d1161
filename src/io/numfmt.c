/*
** src/io/numfmt.c -- doubles as text: shortest round-trip, and fixed decimals
** See LICENSE for copyright and license.
**
** Shortest round-trip.  A finite x > 0 is exactly v = c 2^q (integer c < 2^53),
** and every real in its rounding interval R reads back to x (strtod rounds to
** nearest, ties to even):
**     R = [v - 2^q/2, v + 2^q/2], width 2^q, or at a binade edge (c = 2^52 above
**     the least normal exponent, where the gap below is half the gap above)
**     R = [v - 2^q/4, v + 2^q/2], width 3/4 2^q;
** both ends in R when c is even, neither when c is odd.  The answer is the
** decimal in R with the fewest digits, of those the nearest to v (a tie: even
** last digit).  The way to it is Schubfach's (R. Giulietti, "The Schubfach way
** to render doubles", 2020).  Take k = floor(log10 width), so 10^k <= width <
** 10^(k+1): R holds at most one multiple of 10^(k+1), and at least one of s 10^k,
** (s+1) 10^k, where s = floor(v / 10^k).  With sp = 10 floor(s/10), sp 10^k <= v
** < (sp+10) 10^k, and
**   - when sp 10^k or (sp+10) 10^k is in R, that is the answer: the only
**     multiple of 10^(k+1) in R, so no decimal in R has fewer digits;
**   - else s 10^k or (s+1) 10^k, whichever is in R; the nearer to v if both are.
** scaled() decides each "is in R" and "nearer" exactly, from 128-bit powers of
** ten, so the digits are the true shortest (17 at most).
**
** Spelling, as the printf-and-strtod search this replaced spelled it (kept in
** tests/unit/test_numfmt.c as the oracle, byte for byte): integers below 1e15 digit by
** digit; else "%.*g" style, trailing zeros dropped, exponent form when the
** decimal exponent is < -4 or >= P, where P = 15 when the answer has at most 15
** digits (it is then x's 15-digit rounding: no two 15-digit decimals read back
** to one double, DBL_DIG = 15) and P = its 16 or 17 digits otherwise.
** Subnormals always take the exponent form, so P does not matter for them.
** Most doubles of a trace take one of the two fixed forms with a point,
** ddd.ddd or 0.000ddd: fixed_form() spells those from x's own comparisons
** and sixteen digits at a time, g_style() the rest.
**
** Fixed decimals ("%.*f") are exact integer arithmetic too: see fixed().
*/
#include <assert.h>
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "io/numfmt.h"

/* SSE2 (every x86-64) spells sixteen digits at once; elsewhere, and in
** $B/test_numfmt_portable, two digits a step (sixteen_digits). */
#if defined(__SSE2__) && !defined(PT_NUMFMT_PORTABLE)
#include <emmintrin.h>
#define PT_NUMFMT_SSE2 1
#else
#define PT_NUMFMT_SSE2 0
#endif

/* ===== integers ===== */

/* "00" "01" ... "99": the digits of 0..99, two by two. */
static const char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* The number of decimal digits of x (1 for 0). */
static int u64_len(uint64_t x)
{
    const uint64_t e8 = 100000000;

    if (x < 10000) return x < 100 ? 1 + (x >= 10) : 3 + (x >= 1000);
    if (x < e8) return x < 1000000 ? 5 + (x >= 100000) : 7 + (x >= 10000000);
    if (x < e8 * 10000)                     /* 9 .. 12 digits */
        return x < e8 * 100 ? 9 + (x >= e8 * 10) : 11 + (x >= e8 * 1000);
    if (x < e8 * e8)                        /* 13 .. 16: most doubles' digits */
        return x < e8 * 1000000 ? 13 + (x >= e8 * 100000) : 15 + (x >= e8 * 10000000);
    return x < e8 * e8 * 100 ? 17 + (x >= e8 * e8 * 10) : 19 + (x >= e8 * e8 * 1000);
}

/* x's u64_len(x) digits, written backwards to end just before end: two a
** step from digit_pairs, in 32-bit arithmetic below 10^8 (stores of two
** bytes, no library call: these are most of a trace's bytes). */
static void eight_digits(char *o, uint32_t y)     /* y < 10^8, zeros too */
{
    uint32_t a = y / 10000, b = y % 10000;  /* two halves that do not wait */
                                            /* for each other */
    memcpy(o, digit_pairs + 2 * (a / 100), 2);
    memcpy(o + 2, digit_pairs + 2 * (a % 100), 2);
    memcpy(o + 4, digit_pairs + 2 * (b / 100), 2);
    memcpy(o + 6, digit_pairs + 2 * (b % 100), 2);
}

static void digits_back(char *end, uint64_t x)
{
    uint32_t y;

    while (x >= 100000000) {                /* the low 8 digits */
        end -= 8;
        eight_digits(end, (uint32_t)(x % 100000000));
        x /= 100000000;
    }
    for (y = (uint32_t)x; y >= 100; y /= 100) { end -= 2; memcpy(end, digit_pairs + 2 * (y % 100), 2); }
    if (y >= 10) { end -= 2; memcpy(end, digit_pairs + 2 * y, 2); }
    else *--end = (char)('0' + y);
}

/* y < 10^16 as sixteen digits, zeros in front, at o.  SSE2: the four
** groups of four digits in the 16-bit lanes 0, 2, 4, 6; each group g splits
** into g / 100 = (g * 5243) >> 19 (exact below 43699) and g % 100, one to a
** lane; each of those p into p / 10 = (p * 6554) >> 16 (exact below 16389)
** and p % 10, one to a byte, tens first. */
static void sixteen_digits(char *o, uint64_t y)
{
    uint32_t hi = (uint32_t)(y / 100000000), lo = (uint32_t)(y % 100000000);
#if PT_NUMFMT_SSE2
    __m128i g = _mm_set_epi32((int)(lo % 10000), (int)(lo / 10000),
                              (int)(hi % 10000), (int)(hi / 10000));
    __m128i q = _mm_srli_epi16(_mm_mulhi_epu16(g, _mm_set1_epi32(5243)), 3);
    __m128i r = _mm_sub_epi16(g, _mm_mullo_epi16(q, _mm_set1_epi32(100)));
    __m128i p = _mm_or_si128(q, _mm_slli_epi32(r, 16));        /* 8 lanes < 100 */
    __m128i t = _mm_mulhi_epu16(p, _mm_set1_epi16(6554));
    __m128i u = _mm_sub_epi16(p, _mm_mullo_epi16(t, _mm_set1_epi16(10)));
    __m128i d = _mm_or_si128(t, _mm_slli_epi16(u, 8));          /* 16 bytes < 10 */
    _mm_storeu_si128((__m128i *)(void *)o, _mm_add_epi8(d, _mm_set1_epi8('0')));
#else
    eight_digits(o, hi);
    eight_digits(o + 8, lo);
#endif
}

/* x < 10^4: its 1 to 4 digits at buf. */
static size_t small_digits(char *buf, uint32_t x)
{
    uint32_t hi = x / 100, lo = x % 100;

    if (x < 10) { buf[0] = (char)('0' + x); return 1; }
    if (x < 100) { memcpy(buf, digit_pairs + 2 * lo, 2); return 2; }
    if (x < 1000) { buf[0] = (char)('0' + hi); memcpy(buf + 1, digit_pairs + 2 * lo, 2); return 3; }
    memcpy(buf, digit_pairs + 2 * hi, 2);
    memcpy(buf + 2, digit_pairs + 2 * lo, 2);
    return 4;
}

size_t pt_fmt_u64(char *buf, uint64_t x)
{
    int n;

    if (x < 10000) return small_digits(buf, (uint32_t)x);  /* most integers of a trace */
    if (x < 100000000) {                    /* indexes: the high digits, then four */
        uint32_t y = (uint32_t)x, lo = y % 10000;
        size_t k = small_digits(buf, y / 10000);
        memcpy(buf + k, digit_pairs + 2 * (lo / 100), 2);
        memcpy(buf + k + 2, digit_pairs + 2 * (lo % 100), 2);
        return k + 4;
    }
    n = u64_len(x);
    digits_back(buf + n, x);
    return (size_t)n;
}

void pt_digits4_init(pt_digits4 *t)
{
    int k;

    for (k = 0; k < 10000; k++) {
        memcpy(t->d + 4 * k, digit_pairs + 2 * (k / 100), 2);
        memcpy(t->d + 4 * k + 2, digit_pairs + 2 * (k % 100), 2);
        t->n[k] = (unsigned char)(1 + (k >= 10) + (k >= 100) + (k >= 1000));
    }
    memset(t->d + 4 * 10000, '0', 4);
}

size_t pt_fmt_ulen(uint64_t x)
{
    return (size_t)u64_len(x);
}

/* ===== big integers, for exact powers of ten ===== */

#define BIG_LIMBS 40             /* 1280 bits; the largest made is 10^324 */

/* A natural number in base 2^32.  Limbs w[n..] are garbage; n = 0 is zero. */
typedef struct big {
    uint32_t w[BIG_LIMBS];       /* value = sum of w[i] * 2^(32 i), i < n */
    int n;                       /* limbs in use */
} big;

static void big_mul(big *b, uint32_t m)                     /* b *= m */
{
    uint64_t carry = 0;
    int i;

    for (i = 0; i < b->n; i++) {
        uint64_t t = (uint64_t)b->w[i] * m + carry;         /* < 2^64 */
        b->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry) { assert(b->n < BIG_LIMBS); b->w[b->n++] = (uint32_t)carry; }
}

/* b = floor(b / d), d > 0.  Returns 1 when the remainder is not 0. */
static int big_div(big *b, uint32_t d)
{
    uint64_t r = 0;
    int i;

    for (i = b->n - 1; i >= 0; i--) {
        uint64_t t = r << 32 | b->w[i];                     /* r < d: no overflow */
        b->w[i] = (uint32_t)(t / d);
        r = t % d;
    }
    while (b->n > 0 && b->w[b->n - 1] == 0) b->n--;
    return r != 0;
}

static void big_shl(big *b, int s)                          /* b *= 2^s */
{
    int limbs = s / 32;

    if (b->n == 0) return;
    assert(b->n + limbs < BIG_LIMBS);
    memmove(b->w + limbs, b->w, (size_t)b->n * sizeof b->w[0]);
    memset(b->w, 0, (size_t)limbs * sizeof b->w[0]);
    b->n += limbs;
    big_mul(b, (uint32_t)1 << s % 32);
}

/* b = floor(b / 2^s).  Returns 1 when bits were lost. */
static int big_shr(big *b, int s)
{
    int limbs = s / 32, lost = 0, i;

    if (limbs >= b->n) { lost = b->n > 0; b->n = 0; return lost; }
    for (i = 0; i < limbs; i++) lost |= b->w[i] != 0;
    memmove(b->w, b->w + limbs, (size_t)(b->n - limbs) * sizeof b->w[0]);
    b->n -= limbs;
    return big_div(b, (uint32_t)1 << s % 32) | lost;
}

static uint64_t pow5(int j)                                 /* 5^j, j <= 27 */
{
    uint64_t p = 1;
    while (j-- > 0) p *= 5;
    return p;
}

/* *hi * 2^64 + *lo = floor(n 2^e / 10^k) = floor(n 5^-k 2^(e-k)), which must
** be below 2^128.  Returns 1 when that is exact (no remainder). */
static int exact_scaled(uint64_t n, int e, int k, uint64_t *hi, uint64_t *lo)
{
    big b;
    int inexact = 0, j;

    b.w[0] = (uint32_t)n; b.w[1] = (uint32_t)(n >> 32);
    b.n = n >> 32 ? 2 : n ? 1 : 0;
    for (j = -k; j > 0; j -= 13)            /* 5^13 < 2^32 */
        big_mul(&b, (uint32_t)pow5(j < 13 ? j : 13));    /* b = n 5^-k (k < 0) */
    if (e - k >= 0) big_shl(&b, e - k);                  /* b *= 2^(e-k) */
    else inexact |= big_shr(&b, k - e);
    for (j = k; j > 0; j -= 13)                          /* b /= 5^k (k > 0) */
        inexact |= big_div(&b, (uint32_t)pow5(j < 13 ? j : 13));
    assert(b.n <= 4);
    for (j = b.n; j < 4; j++) b.w[j] = 0;
    *hi = (uint64_t)b.w[3] << 32 | b.w[2];
    *lo = (uint64_t)b.w[1] << 32 | b.w[0];
    return !inexact;
}

/* ===== powers of ten, made at first use ===== */

#define K_MIN (-324)             /* k for the subnormals: floor(log10 2^-1074) */
#define K_MAX 292                /* k for the top binade: floor(log10 2^971) */

/* 10^-k ~= g 2^beta, g rounded up to an integer in [2^126, 2^127]:
**     g = ceil(10^-k 2^-beta) = ceil(5^-k 2^(-k-beta)),
** exact when -k-beta >= 0 and 5^-k < 2^127, that is for -54 <= k <= 0. */
typedef struct tenpow {
    uint64_t hi, lo;             /* g = hi * 2^64 + lo */
    int beta;                    /* the binary exponent */
    int exact;                   /* g equals 10^-k * 2^-beta */
} tenpow;

/* Made one by one as they are needed, each with a few microseconds of
** big-integer work, once.  Two threads may ask at once (tlanes.c): an entry is
** read once its `made` says it is whole, and one thread at a time makes. */
static tenpow tenpow_tab[K_MAX - K_MIN + 1];
static atomic_uchar tenpow_made[K_MAX - K_MIN + 1];
static pthread_mutex_t tenpow_lock = PTHREAD_MUTEX_INITIALIZER;

static void tenpow_make(tenpow *p, int k)
{
    big t;
    uint32_t top;
    int j, bits;

    t.w[0] = 1; t.n = 1;                    /* t = 10^|k|, 2^(bits-1) <= t < 2^bits */
    for (j = k < 0 ? -k : k; j > 0; j -= 9) {
        uint32_t m = 1;
        int i;
        for (i = 0; i < j && i < 9; i++) m *= 10;
        big_mul(&t, m);
    }
    top = t.w[t.n - 1];
    for (bits = 32 * (t.n - 1); top; top >>= 1) bits++;
    p->beta = k <= 0 ? bits - 127           /* 10^-k 2^-beta in [2^126, 2^127) */
                     : -bits - 126;         /* 10^-k in (2^-bits, 2^(1-bits)) */
    p->exact = exact_scaled(1, -p->beta, k, &p->hi, &p->lo);
    if (!p->exact && ++p->lo == 0) p->hi++; /* round up: g = floor(..) + 1 */
}

static const tenpow *tenpow_of(int k)
{
    tenpow *p = &tenpow_tab[k - K_MIN];
    atomic_uchar *made = &tenpow_made[k - K_MIN];

    assert(k >= K_MIN && k <= K_MAX);
    if (!atomic_load_explicit(made, memory_order_acquire)) {
        pthread_mutex_lock(&tenpow_lock);
        if (!atomic_load_explicit(made, memory_order_relaxed)) {
            tenpow_make(p, k);
            atomic_store_explicit(made, 1, memory_order_release);
        }
        pthread_mutex_unlock(&tenpow_lock);
    }
    return p;
}

/* ===== shortest digits ===== */

/* *hi * 2^64 + lo = a * b.  One 64x64 -> 128-bit multiplication where the
** compiler has a 128-bit integer (gcc and clang on 64-bit targets: an
** extension of C11, hence __extension__); else four 32x32-bit products
** (PT_NUMFMT_PORTABLE picks them: $B/test_numfmt_portable tests that path).
** Returns the high half. */
#if defined(__SIZEOF_INT128__) && !defined(PT_NUMFMT_PORTABLE)
__extension__ typedef unsigned __int128 u128;

static uint64_t mul_64x64(uint64_t a, uint64_t b, uint64_t *lo)
{
    u128 p = (u128)a * b;

    *lo = (uint64_t)p;
    return (uint64_t)(p >> 64);
}
#else
static uint64_t mul_64x64(uint64_t a, uint64_t b, uint64_t *lo)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu); /* < 3 2^32 */

    *lo = mid << 32 | (p00 & 0xffffffffu);
    return p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}
#endif

/* floor(y), and whether y is an integer, for
**     y = n 2^(q-2) / 10^k,   0 < n < 2^56,
** with k = floor_log10_width(q, .), so that 2^q / 10^k is in [1, 40/3).
** With 10^-k = g_true 2^beta (g_true in [2^126, 2^127)) and h = q + beta + 126:
**     y = m g_true / 2^128,   m = n 2^h,
** and 2^q / 10^k = 2^h g_true / 2^126 puts h in 0..3, so m < 2^59, y < 2^58.
** The 192-bit P = m g is exact when g is; else g_true < g < g_true + 1 and
** m g_true lies in (P - m, P]: when P's low 128 bits are at least m, no integer
** lies between y and P / 2^128, so floor(y) = P >> 128 and y is no integer.
** Else y is within m / 2^128 < 2^-69 of an integer.  It may be one only when
** k > 0 (y = n 2^(q-2-k) / 5^k, q-2-k >= 0: when 5^k divides n, so k <= 24);
** for k < -54, y = n 5^-k / 2^(2-q+k) with 2-q+k > 57 never is.  Non-integers
** never come that close: by the continued fractions of 2^(q-2) / 10^k, the
** nearest any n < 2^56 gets is 2^-64.5 (found once for every q by a script
** outside this repository, as in Schubfach's and Ryu's proofs; nothing here
** relies on it: big integers settle any case that comes that close). */
static uint64_t scaled_near(uint64_t n, int q, int k, uint64_t p2, int *exact);

static inline uint64_t scaled(uint64_t n, int q, int k, const tenpow *p, int *exact)
{
    int h = q + p->beta + 126;
    uint64_t m, p0, p1, p2, t;

    assert(h >= 0 && h <= 3);
    m = n << h;
    p1 = mul_64x64(m, p->lo, &p0);          /* m lo = p1:p0 */
    p2 = mul_64x64(m, p->hi, &t);           /* m hi = p2:t, at 2^64 */
    p1 += t;                                /* P = p2:p1:p0 */
    p2 += p1 < t;
    if (p->exact) { *exact = (p1 | p0) == 0; return p2; }
    if (p1 != 0 || p0 >= m) { *exact = 0; return p2; }
    return scaled_near(n, q, k, p2, exact);
}

/* scaled() when y is within 2^-69 of an integer: settled exactly (rare). */
static uint64_t scaled_near(uint64_t n, int q, int k, uint64_t p2, int *exact)
{
    uint64_t hi, t;

    if (k > 0 && k <= 24 && n % pow5(k) == 0) { *exact = 1; return p2; }
    *exact = exact_scaled(n, q - 2, k, &hi, &t);
    assert(hi == 0);
    return t;
}

/* v's interval R scaled by 10^-k: ends yl, yr, as floor and integer flag. */
typedef struct bounds {
    uint64_t fl, fr;             /* floor(yl), floor(yr) */
    int xl, xr;                  /* yl, yr are integers */
    int closed;                  /* R holds its ends (c even) */
} bounds;

/* The two tests, in & and | of 0s and 1s: which way they go follows the
** digits, so branches on them would be mispredicted half the time. */
static int above_low(const bounds *b, uint64_t n)   /* n >= yl (closed), n > yl */
{
    return (n > b->fl) | ((n == b->fl) & b->xl & b->closed);
}

static int below_high(const bounds *b, uint64_t n)  /* n <= yr (closed), n < yr */
{
    return (n < b->fr) | ((n == b->fr) & (b->closed | (b->xr == 0)));
}

/* floor(log10 width) for width 2^q (lop = 0) or 3/4 2^q (lop = 1), |q| <= 1100:
** floor(q log10 2 + lop log10 3/4), the logs times 2^32 rounded.  The sum stays
** 8.7e-5 (376662 / 2^32) away from integers over that range (q != 0), more than
** the constants' error (< 1100 * 0.5 / 2^32); the tests cover every q. */
static int floor_log10_width(int q, int lop)
{
    int64_t t = (int64_t)q * 1292913986 - (lop ? 536607788 : 0);
    return (int)((t + ((int64_t)1 << 50)) >> 32) - (1 << 18);   /* t + 2^50 >= 0 */
}

/* d * 10^e with d's trailing zeros moved into e (d > 0): fewest divisions. */
static void drop_zeros(uint64_t *d, int *e)
{
    while (*d % 100000000 == 0) { *d /= 100000000; *e += 8; }
    if (*d % 10000 == 0) { *d /= 10000; *e += 4; }
    if (*d % 100 == 0) { *d /= 100; *e += 2; }
    if (*d % 10 == 0) { *d /= 10; ++*e; }
}

/* The shortest decimal that reads back to finite x > 0, nearest x: d * 10^e,
** d not a multiple of 10. */
static void shortest(double x, uint64_t *d, int *e)
{
    uint64_t bits, c, f2, s, sp;
    int be, q, k, lop, x2;
    const tenpow *p;
    bounds b;

    memcpy(&bits, &x, sizeof bits);
    be = (int)(bits >> 52 & 0x7ff);
    c = bits & ((UINT64_C(1) << 52) - 1);
    if (be == 0) q = -1074;                             /* subnormal: v = c 2^-1074 */
    else { q = be - 1075; c |= UINT64_C(1) << 52; }     /* v = c 2^q, 2^52 <= c < 2^53 */
    lop = c == UINT64_C(1) << 52 && be > 1;             /* gap below = half gap above */
    k = floor_log10_width(q, lop);
    p = tenpow_of(k);

    /* In units of 2^(q-2) R's ends are 4c - 2 (4c - 1 when lop) and 4c + 2. */
    b.fl = scaled(4 * c - (lop ? 1 : 2), q, k, p, &b.xl);   /* yl = (v - gap) / 10^k */
    b.fr = scaled(4 * c + 2, q, k, p, &b.xr);               /* yr = (v + 2^q/2) / 10^k */
    b.closed = c % 2 == 0;
    f2 = scaled(8 * c, q, k, p, &x2);                       /* floor(2 v / 10^k) */
    s = f2 >> 1;                                            /* s = floor(v / 10^k) */

    sp = s / 10 * 10;                       /* sp <= s <= v/10^k < s+1 <= sp+10 */
    *e = k;
    if (above_low(&b, sp) || below_high(&b, sp + 10)) {
        *d = (above_low(&b, sp) ? sp : sp + 10) / 10;
        *e = k + 1;
        if (*d % 10 == 0) drop_zeros(d, e);
    } else {                                /* s or s + 1: no multiple of 10 */
        int u_in = above_low(&b, s), w_in = below_high(&b, s + 1);
        /* One is in R: the nearer is within 10^k/2 <= width/2 of v.  At a
        ** binade edge, when s 10^k is more than 2^q/4 below v, then (s+1) 10^k
        ** is less than 10^k - 2^q/4 <= 3/4 2^q - 2^q/4 = 2^q/2 above it. */
        assert(u_in || w_in);
        /* s + 1 when only it is in R, or both are and 2 v/10^k > 2s + 1 (f2
        ** is 2s + 1 and not exact), or a tie (exact) and s is odd; without
        ** a branch, as above */
        *d = s + (uint64_t)((u_in == 0) | (w_in & (f2 != 2 * s) & ((x2 == 0) | (int)(s & 1))));
    }
}

/* ===== short decimals: a scene's own numbers ===== */

/* 10^0 .. 10^22, each exactly a double (5^22 < 2^53). */
static const double pow10_dbl[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
};

/* shortest()'s answer for finite x > 0 when x is a decimal of at most 15
** significant digits (1.873376, -0.098717: what a scene file says, and sums
** of such), found with three double operations instead of the 128-bit ones;
** returns 0 when it can't tell, and shortest() decides.  With
** 2^be <= x < 2^(be+1) and e10 = floor(be log10 2), so that 10^e10 <= x <
** 10^(e10+2):
**     n = floor(x 10^k + 1/2),  k = 13 - e10  (0 <= k <= 22: 10^k is exact),
** 10^13 <= x 10^k < 10^15, so n <= 10^15 < 2^53 is exact as a double.  When
** n / 10^k, IEEE division, gives back x, the decimal n 10^-k reads back to
** x: strtod rounds the same exact quotient the same way (to nearest, ties
** to even).  No two decimals of at most 15 significant digits read back to
** one normal double (DBL_DIG = 15), so n 10^-k is the only one in x's
** interval R: the shortest, and the only candidate of its length.  A miss
** (x needs 16 or 17 digits, or 15 and the product's rounding moved n)
** costs the three operations; the digits are shortest()'s either way
** (tests/unit/test_numfmt.c, num-4.9).  Where doubles may be evaluated in a
** wider format (FLT_EVAL_METHOD != 0: x87) the division could round twice,
** so the path is left out there. */
static int short_decimal(double x, uint64_t *d, int *e)
{
#if FLT_EVAL_METHOD == 0
    uint64_t bits, n;
    int be, k;

    memcpy(&bits, &x, sizeof bits);
    be = (int)(bits >> 52) - 1023;          /* 2^be <= x < 2^(be+1) */
    if (be < -29 || be > 46) return 0;      /* else k would leave 0..22 */
    k = 13 - floor_log10_width(be, 0);      /* e10 = floor(be log10 2) */
    n = (uint64_t)(x * pow10_dbl[k] + 0.5); /* + 1/2 is exact: x 10^k < 2^50 */
    if ((double)n / pow10_dbl[k] != x) return 0;
    *d = n;
    *e = -k;
    drop_zeros(d, e);
    return 1;
#else
    (void)x; (void)d; (void)e;
    return 0;
#endif
}

/* ===== spelling ===== */

static size_t nonfinite(char *buf, double x)
{
    const char *s = isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
    strcpy(buf, s);
    return strlen(s);
}

/* x is an integer with |x| < 1e15: write it digit by digit ("-0" for -0.0). */
static size_t int_digits(char *buf, double x)
{
    size_t neg = signbit(x) != 0, n;

    buf[0] = '-';                           /* overwritten when x >= 0 */
    n = neg + pt_fmt_u64(buf + neg, (uint64_t)fabs(x));
    buf[n] = '\0';
    return n;
}

/* d's digits written backwards to end just before end, with a point before
** the last f of them (0 < f < digits of d).  Each byte is stored once, at
** its place: moving digits after they were written costs a stall (a load
** of bytes from several stores waits for them to reach the cache). */
static void digits_point(char *end, uint64_t d, int f)
{
    if (f >= 8) {
        end -= 8;
        eight_digits(end, (uint32_t)(d % 100000000));
        d /= 100000000;
        f -= 8;
    }
    for (; f >= 2; f -= 2) { end -= 2; memcpy(end, digit_pairs + 2 * (d % 100), 2); d /= 100; }
    if (f) { *--end = (char)('0' + d % 10); d /= 10; }
    *--end = '.';
    digits_back(end, d);
}

/* Spell [-]d * 10^e (d > 0, not a multiple of 10) the way "%.*g" does with
** precision P = max(15, digits of d); see the top of the file.  Not for
** 10^-4 <= D < 1 (fixed_form() spells those). */
static size_t g_style(char *buf, int neg, uint64_t d, int e)
{
    char *o = buf + (neg != 0);
    int n = u64_len(d), exp10 = e + n - 1, i;   /* x = d.ddd 10^exp10 */

    buf[0] = '-';                           /* overwritten when not neg */
    if (exp10 < -4 || exp10 >= (n > 15 ? n : 15)) {        /* d.ddde+XX */
        int a = exp10 < 0 ? -exp10 : exp10;
        digits_back(o + 1 + n, d);          /* at o[1..n] */
        o[0] = o[1];
        if (n > 1) { o[1] = '.'; o += n + 1; } else o++;
        *o++ = 'e';
        *o++ = exp10 < 0 ? '-' : '+';
        if (a >= 100) *o++ = (char)('0' + a / 100);
        *o++ = (char)('0' + a / 10 % 10);
        *o++ = (char)('0' + a % 10);
    } else if (n > exp10 + 1) {             /* ddd.ddd (0.000ddd: fixed_form) */
        assert(exp10 >= 0);
        o += n + 1;
        digits_point(o, d, n - exp10 - 1);
    } else {                                /* ddd000 */
        digits_back(o + n, d);
        o += n;
        for (i = n; i <= exp10; i++) *o++ = '0';
    }
    *o = '\0';
    return (size_t)(o - buf);
}

/* 10^0 .. 10^17. */
static const uint64_t pow10_tab[18] = {
    UINT64_C(1), UINT64_C(10), UINT64_C(100), UINT64_C(1000), UINT64_C(10000),
    UINT64_C(100000), UINT64_C(1000000), UINT64_C(10000000), UINT64_C(100000000),
    UINT64_C(1000000000), UINT64_C(10000000000), UINT64_C(100000000000),
    UINT64_C(1000000000000), UINT64_C(10000000000000), UINT64_C(100000000000000),
    UINT64_C(1000000000000000), UINT64_C(10000000000000000),
    UINT64_C(100000000000000000),
};

/* g_style() for the two fixed forms most of a trace's doubles take, with a
** point and digits after it: ddd.ddd for 1 <= |x| < 10^15 and 0.000ddd for
** 10^-4 <= |x| < 1.  x is no integer here (those went to int_digits), and
** the decimal D = d 10^e that reads back to x is none either: an integer N
** in x's interval would be a double (|N| < 2^53) reading back to itself.
** So e < 0, and comparisons of x decide what g_style() derives from D's
** digits.  floor(D) = floor(|x|): no integer lies between the two.  D < 1
** exactly when |x| < 1, and D >= 0.1 exactly when |x| >= 0.1 (the double
** nearest 0.1), as for 0.01, 0.001 and 10^-4: each such power lies inside
** the interval of the double nearest it (it is no dyadic number, so no end
** of one), and D and x lie on the same side of it.  The digits after the point
** go out sixteen at a time (sixteen_digits), left-aligned, the bytes past
** D's end to be overwritten (buf has PT_NUMLEN bytes).  Returns 0 for the
** other forms, which g_style() spells. */
static size_t fixed_form(char *buf, double x, uint64_t d, int e)
{
    double ax = fabs(x);
    char *o = buf + (x < 0);
    int f = -e;                             /* digits after the point */

    buf[0] = '-';                           /* overwritten when x > 0 */
    if (ax >= 1 && ax < 1e15) {             /* ddd.ddd, ip = floor(D) */
        uint64_t ip = (uint64_t)ax;         /* d = ip 10^f + frac, f <= 16 */
        size_t n = pt_fmt_u64(o, ip);
        assert(f >= 1 && f <= 16);
        o[n] = '.';
        sixteen_digits(o + n + 1, (d - ip * pow10_tab[f]) * pow10_tab[16 - f]);
        o += n + 1 + f;
    } else if (ax < 1 && ax >= 1e-4) {      /* 0.[z zeros]ddd, d of f - z digits */
        int z = (ax < 0.1) + (ax < 0.01) + (ax < 0.001);
        uint64_t dl;
        assert(f - z >= 1 && f - z <= 17);
        dl = d * pow10_tab[17 - (f - z)];   /* 17 digits, 1 to 9 first */
        memcpy(o, "0.000000", 8);
        o[2 + z] = (char)('0' + dl / UINT64_C(10000000000000000));
        sixteen_digits(o + 3 + z, dl % UINT64_C(10000000000000000));
        o += 2 + f;
    } else {
        return 0;
    }
    *o = '\0';
    return (size_t)(o - buf);
}

size_t pt_fmt_shortest(char *buf, double x)
{
    uint64_t d;
    size_t n;
    int e;

    if (!isfinite(x)) return nonfinite(buf, x);
    if (fabs(x) < 1e15 && x == (double)(int64_t)x)  /* an integer: its digits, */
        return int_digits(buf, x);                  /* as %.15g writes them */
    if (!short_decimal(fabs(x), &d, &e)) shortest(fabs(x), &d, &e);
    if ((n = fixed_form(buf, x, d, e)) != 0) return n;
    return g_style(buf, signbit(x) != 0, d, e);
}

/* ===== fixed decimals ===== */

/* hi * 2^64 + lo shifted right by s, 0 <= s < 128; only the low 64 bits. */
static uint64_t shr_128(uint64_t hi, uint64_t lo, int s)
{
    if (s == 0) return lo;
    if (s < 64) return hi << (64 - s) | lo >> s;
    return hi >> (s - 64);
}

/* Whether (hi * 2^64 + lo) mod 2^s is not 0, 0 <= s < 128. */
static int low_bits(uint64_t hi, uint64_t lo, int s)
{
    if (s < 64) return (lo & ((UINT64_C(1) << s) - 1)) != 0;
    return lo != 0 || (hi & ((UINT64_C(1) << (s - 64)) - 1)) != 0;
}

/* "%.*f" for finite |x| < 1e15, 0 <= prec <= 17, exactly as glibc's printf
** rounds it in the default rounding mode, which pipetrace never changes: to
** nearest, ties to even (0.125 -> "0.12", 2.5 -> "2"; tests/unit/test_numfmt.c
** compares the two byte for byte).  |x| = c / 2^s (integer c < 2^53), s > 0,
** splits into
**     ip = floor(|x|) = c >> s  (< 1e15)   and   f / 2^s,  f = c mod 2^s,
** and the digits after the point are
**     fp = round(f 10^prec / 2^s),   f 10^prec < 2^53 2^57 = 2^110,
** the product in two uint64 (C11 has no 128-bit integer).  When s > 110 that
** is below 2^(s-1), half the divisor: fp = 0, no tie.  fp = 10^prec carries
** into ip.  A tie goes to the even last digit: fp's when prec > 0 (10^prec is
** even), else ip's.  The sign is signbit's: -0.0 and small negatives give
** "-0.000", as printf does.  |x| < 1e15 < 2^50 and c >= 2^52 (or subnormal)
** make s >= 3. */
static size_t fixed(char *buf, double x, int prec)
{
    uint64_t bits, c, ip, fp = 0, u, f, hi, lo;
    int be, s, k, up = 0;
    char *o, *end;

    memcpy(&bits, &x, sizeof bits);
    be = (int)(bits >> 52 & 0x7ff);
    c = bits & ((UINT64_C(1) << 52) - 1);
    if (be == 0) s = 1074;                          /* subnormal: |x| = c 2^-1074 */
    else { s = 1075 - be; c |= UINT64_C(1) << 52; } /* |x| = c 2^-s, c >= 2^52 */
    ip = s < 64 ? c >> s : 0;                       /* s >= 53: c < 2^s */
    f = s < 64 ? c & ((UINT64_C(1) << s) - 1) : c;
    hi = mul_64x64(f, pow10_tab[prec], &lo);        /* hi:lo = f 10^prec */
    if (s <= 110) {
        fp = shr_128(hi, lo, s);                    /* floor(f 10^prec / 2^s) */
        if (shr_128(hi, lo, s - 1) & 1)             /* the half bit: round up if */
            up = low_bits(hi, lo, s - 1) ||         /* above half, or a tie and */
                 ((prec ? fp : ip) & 1);            /* the last digit is odd */
    }
    fp += (uint64_t)up;
    if (fp == pow10_tab[prec]) { fp = 0; ip++; }
    end = buf + (signbit(x) != 0) + 1 + (prec ? 1 + prec : 0);  /* [-]ip[.fp] */
    for (u = ip; u >= 10; u /= 10) end++;           /* ip's digits but one */
    *end = '\0';
    o = end;                                        /* written backwards */
    for (k = 0; k < prec; k++) { *--o = (char)('0' + fp % 10); fp /= 10; }
    if (prec) *--o = '.';
    do { *--o = (char)('0' + ip % 10); ip /= 10; } while (ip);
    if (o > buf) *--o = '-';
    return (size_t)(end - buf);
}

size_t pt_fmt_fixed(char *buf, double x, int prec)
{
    assert(prec >= 0 && prec <= 17);
    if (!isfinite(x)) return nonfinite(buf, x);
    if (fabs(x) >= 1e15) return (size_t)snprintf(buf, PT_NUMLEN, "%.*e", prec, x);
    return fixed(buf, x, prec);
}
