/*
** src/io/jnum.c -- doubles as Java prints them: Double.toString and Formatter's %f
** See LICENSE for copyright and license.
**
** Both start from the same decimal: x = 0.d1d2...dn * 10^dexp, n <= 19
** digits, found as JDK 17's FloatingDecimal.dtoa finds them (fd_dtoa(),
** which says how).  toString spells them as FloatingDecimal's getChars does;
** %f rounds them half up at the requested decimal (Java's Formatter rounds
** the decimal string, not the binary value).  Integer arithmetic but for one
** estimate in doubles, no locale: the same digits everywhere.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "io/jnum.h"

/* ===== JDK 17's digits: FloatingDecimal.dtoa ===== */

/* The result: x = 0.d[0]d[1]...d[n-1] * 10^dexp (Java's "decExponent"),
** n <= 19 digits; a zero at the end is kept and printed, as in Java (a carry
** in roundup() would leave one). */
typedef struct {
    char d[24];                  /* the digits, '0'..'9' */
    int n;                       /* how many */
    int dexp;                    /* the decimal point's place */
} jdigits;

/* 5^0..5^26: the powers that fit a Java long (FDBigInteger.LONG_5_POW). */
static const int64_t pow5[27] = {
    1, 5, 25, 125, 625, 3125, 15625, 78125, 390625, 1953125, 9765625, 48828125,
    244140625, 1220703125, 6103515625, 30517578125, 152587890625, 762939453125,
    3814697265625, 19073486328125, 95367431640625, 476837158203125,
    2384185791015625, 11920928955078125, 59604644775390625, 298023223876953125,
    1490116119384765625,
};
/* ceil(log2(5^i)) for i < 27, "approximately" (FloatingDecimal.N_5_BITS) */
static const int n5bits[27] = {
    0, 3, 5, 7, 10, 12, 14, 17, 19, 21, 24, 26, 28, 31, 33, 35, 38, 40, 42, 45,
    47, 49, 52, 54, 56, 59, 61,
};
/* the decimal digits of 2^i minus one, for i < 64 (insignificantDigitsForPow2) */
static const int insig2[64] = {
    0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 5, 5, 5, 6, 6, 6, 6, 7, 7,
    7, 8, 8, 8, 9, 9, 9, 9, 10, 10, 10, 11, 11, 11, 12, 12, 12, 12, 13, 13, 13,
    14, 14, 14, 15, 15, 15, 15, 16, 16, 16, 17, 17, 17, 18, 18, 18, 19,
};

/* Java's int (w = 32) or long (w = 64) arithmetic wraps: v taken modulo 2^w,
** as a signed number. */
static int64_t wrap(uint64_t v, int w)
{
    if (w == 32) {
        v &= 0xffffffffu;
        return v >= 0x80000000u ? (int64_t)v - (int64_t)0x100000000 : (int64_t)v;
    }
    return v >= UINT64_C(0x8000000000000000) ? -(int64_t)(~v) - 1 : (int64_t)v;
}

/* The easy case, an integer below 2^63 (developLongDigits): its digits
** without trailing zeros, the last `insig` of them dropped first, rounding
** half up on what is dropped. */
static void long_digits(jdigits *r, uint64_t v, int insig)
{
    char tmp[24];
    int k = 0, i;

    if (insig != 0) {
        uint64_t p10 = (uint64_t)pow5[insig] << insig, rem = v % p10;

        v /= p10;
        if (rem >= p10 >> 1) v++;
    }
    while (v % 10 == 0) v /= 10, insig++;        /* trailing zeros */
    for (; v != 0; v /= 10) tmp[k++] = (char)('0' + v % 10);
    for (i = 0; i < k; i++) r->d[i] = tmp[k - 1 - i];
    r->n = k;
    r->dexp = k + insig;
}

/* A big natural number for the hard case, little-endian 32-bit words; the
** largest, 10 * 2^1100 or so, has fewer than 40. */
#define BIG_WORDS 48
typedef struct { uint32_t w[BIG_WORDS]; int n; } big;

static void big_set(big *a, uint64_t v)
{
    a->n = 0;
    for (; v; v >>= 32) a->w[a->n++] = (uint32_t)v;
}

static void big_mul(big *a, uint32_t m)              /* a *= m */
{
    uint64_t c = 0;
    int i;

    for (i = 0; i < a->n; i++) {
        c += (uint64_t)a->w[i] * m;
        a->w[i] = (uint32_t)c;
        c >>= 32;
    }
    if (c) a->w[a->n++] = (uint32_t)c;
}

static void big_shl(big *a, int s)                   /* a *= 2^s */
{
    int words = s / 32, bits = s % 32, i;

    if (a->n == 0) return;
    a->w[a->n] = 0;
    if (bits)
        for (i = a->n; i > 0; i--)
            a->w[i] = a->w[i] << bits | a->w[i - 1] >> (32 - bits);
    a->w[0] <<= bits;
    a->n++;
    if (words) {
        memmove(a->w + words, a->w, (size_t)a->n * sizeof a->w[0]);
        memset(a->w, 0, (size_t)words * sizeof a->w[0]);
        a->n += words;
    }
    while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
}

static void big_pow52(big *a, uint64_t v, int p5, int p2)   /* v * 5^p5 * 2^p2 */
{
    big_set(a, v);
    for (; p5 >= 13; p5 -= 13) big_mul(a, 1220703125u);    /* 5^13 */
    if (p5 > 0) big_mul(a, (uint32_t)pow5[p5]);
    big_shl(a, p2);
}

static int big_cmp(const big *a, const big *b)
{
    int i;

    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    for (i = a->n - 1; i >= 0; i--)
        if (a->w[i] != b->w[i]) return a->w[i] < b->w[i] ? -1 : 1;
    return 0;
}

static void big_add(big *s, const big *a, const big *b)   /* s = a + b */
{
    uint64_t c = 0;
    int i, n = a->n > b->n ? a->n : b->n;

    for (i = 0; i < n; i++) {
        c += (uint64_t)(i < a->n ? a->w[i] : 0) + (i < b->n ? b->w[i] : 0);
        s->w[i] = (uint32_t)c;
        c >>= 32;
    }
    s->n = n;
    if (c) s->w[s->n++] = (uint32_t)c;
}

static void big_sub(big *a, const big *b)            /* a -= b, a >= b */
{
    int64_t c = 0;
    int i;

    for (i = 0; i < a->n; i++) {
        c += (int64_t)a->w[i] - (i < b->n ? b->w[i] : 0);
        a->w[i] = (uint32_t)c;
        c = c < 0 ? -1 : 0;
    }
    while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
}

/* q = a / s, a = 10 * (a % s) (FDBigInteger.quoRemIteration, exact). */
static int big_quorem10(big *a, const big *s)
{
    int q = 0;

    while (big_cmp(a, s) >= 0) { big_sub(a, s); q++; }
    big_mul(a, 10);
    return q;
}

/* Add one to the last digit, carrying (FloatingDecimal.roundup): a carry
** out of the first digit makes it "1" and the rest zeros, n unchanged. */
static void roundup(jdigits *r)
{
    int i = r->n - 1;

    while (r->d[i] == '9' && i > 0) r->d[i--] = '0';
    if (r->d[i] == '9') { r->d[0] = '1'; r->dexp++; return; }
    r->d[i]++;
}

/* The digits of the positive finite double with bits `bits`, as JDK 17's
** FloatingDecimal.dtoa finds them; compat: Double.toString's form (at
** least two digits only where it prints an exponent), else Formatter's
** (always two).  The algorithm (Steele and White's, 1990, as the JDK
** writes it): with binExp and the 53 (fewer for a subnormal) significant
** bits of x,
**   - an integer below 2^63 with no bits after the point: its decimal
**     digits, those beyond the double's precision rounded off (the number
**     of decimal digits of 2^(binExp - nSignificantBits - 1) minus one);
**   - else estimate decExp ~ floor(log10 x) in doubles, set up integers
**     B/S = x / 10^decExp and M = half an ulp scaled alike (a quarter
**     below a power of two), and take digits q = B/S, B = 10(B mod S),
**     M = 10M until B < M (low) or B + M > 10S (high; >= with big
**     numbers); a first digit 0 that is not "high" moves decExp down;
**     ints, longs or big numbers as the sizes allow, overflows as Java's;
**   - round the last digit up when only high, or both and 2B > 10S (a tie:
**     when the digit is odd).
** Not always the shortest, nor the nearest of the shortest: 2^-31 gives
** 4.6566128730773926E-10, 2.0E-3 gives 0.0020, 1.0E23 9.999999999999999E22. */
static void fd_dtoa(uint64_t bits, int compat, jdigits *r)
{
    uint64_t fract = bits & ((UINT64_C(1) << 52) - 1);
    int binexp = (int)(bits >> 52 & 0x7ff), nsig, tailz, nfract, ntiny;
    int decexp, b2, b5, s2, s5, m2, m5, common, bbits, tensbits, low, high, q;
    int64_t lowdiff = 0;

    r->n = 0;
    if (binexp == 0) {                           /* subnormal: normalize */
        int lz = 0, shift;

        while (!(fract >> (63 - lz) & 1)) lz++;
        shift = lz - 11;
        fract <<= shift;
        binexp = 1 - shift;
        nsig = 64 - lz;
    } else {
        fract |= UINT64_C(1) << 52;
        nsig = 53;
    }
    binexp -= 1023;
    for (tailz = 0; !(fract >> tailz & 1); tailz++) {}
    nfract = 53 - tailz;
    ntiny = nfract - binexp - 1 > 0 ? nfract - binexp - 1 : 0;
    if (binexp <= 62 && binexp >= -21 && ntiny == 0) {     /* an integer < 2^63 */
        int insig = binexp > nsig && binexp - nsig - 1 < 64 ? insig2[binexp - nsig - 1] : 0;

        long_digits(r, binexp >= 52 ? fract << (binexp - 52) : fract >> (52 - binexp), insig);
        return;
    }
    {
        uint64_t d2bits = UINT64_C(0x3ff0000000000000) | (fract & ((UINT64_C(1) << 52) - 1));
        double d2, d;

        memcpy(&d2, &d2bits, sizeof d2);
        d = (d2 - 1.5) * 0.289529654 + 0.176091259 + (double)binexp * 0.301029995663981;
        decexp = (int)d;                         /* estimateDecExp: floor(d) */
        if (d < 0 && (double)decexp != d) decexp--;
    }
    b5 = decexp < 0 ? -decexp : 0;
    b2 = b5 + ntiny + binexp;
    s5 = decexp > 0 ? decexp : 0;
    s2 = s5 + ntiny;
    m5 = b5;
    m2 = b2 - nsig;
    fract >>= tailz;
    b2 -= nfract - 1;
    common = b2 < s2 ? b2 : s2;
    b2 -= common;
    s2 -= common;
    m2 -= common;
    if (nfract == 1) m2 -= 1;                    /* a power of two */
    if (m2 < 0) { b2 -= m2; s2 -= m2; m2 = 0; }
    bbits = nfract + b2 + (b5 < 27 ? n5bits[b5] : b5 * 3);
    tensbits = s2 + 1 + (s5 + 1 < 27 ? n5bits[s5 + 1] : (s5 + 1) * 3);
    if (bbits < 64 && tensbits < 64) {           /* Java's ints or longs */
        int w = bbits < 32 && tensbits < 32 ? 32 : 64;
        int64_t b = wrap((fract * (uint64_t)pow5[b5]) << b2, w);
        int64_t s = wrap((uint64_t)pow5[s5] << s2, w);
        int64_t m = wrap((uint64_t)pow5[m5] << m2, w);
        int64_t tens = wrap((uint64_t)s * 10u, w);

        q = (int)(b / s);
        b = wrap(10u * (uint64_t)(b % s), w);
        m = wrap((uint64_t)m * 10u, w);
        low = b < m;
        high = wrap((uint64_t)b + (uint64_t)m, w) > tens;
        if (q == 0 && !high) decexp--;           /* the estimate was one high */
        else r->d[r->n++] = (char)('0' + q);
        if (!compat || decexp < -3 || decexp >= 8) high = low = 0;
        while (!low && !high) {
            q = (int)(b / s);
            b = wrap(10u * (uint64_t)(b % s), w);
            m = wrap((uint64_t)m * 10u, w);
            if (m > 0) {
                low = b < m;
                high = wrap((uint64_t)b + (uint64_t)m, w) > tens;
            } else low = high = 1;               /* m overflowed */
            r->d[r->n++] = (char)('0' + q);
        }
        lowdiff = wrap(((uint64_t)b << 1) - (uint64_t)tens, w);
    } else {                                     /* big numbers */
        big bv, sv, mv, tensv, sum;

        big_pow52(&sv, 1, s5, s2);
        big_pow52(&bv, fract, b5, b2);
        big_pow52(&mv, 1, m5 + 1, m2 + 1);       /* 10M */
        big_pow52(&tensv, 1, s5 + 1, s2 + 1);    /* 10S */
        q = big_quorem10(&bv, &sv);
        low = big_cmp(&bv, &mv) < 0;
        big_add(&sum, &bv, &mv);
        high = big_cmp(&tensv, &sum) <= 0;
        if (q == 0 && !high) decexp--;
        else r->d[r->n++] = (char)('0' + q);
        if (!compat || decexp < -3 || decexp >= 8) high = low = 0;
        while (!low && !high) {
            q = big_quorem10(&bv, &sv);
            big_mul(&mv, 10);
            low = big_cmp(&bv, &mv) < 0;
            big_add(&sum, &bv, &mv);
            high = big_cmp(&tensv, &sum) <= 0;
            r->d[r->n++] = (char)('0' + q);
        }
        if (high && low) {
            big_shl(&bv, 1);
            lowdiff = big_cmp(&bv, &tensv);
        }
    }
    r->dexp = decexp + 1;
    if (high && (!low || lowdiff > 0 || (lowdiff == 0 && (r->d[r->n - 1] & 1))))
        roundup(r);
}

/* ===== Double.toString ===== */

/* The digits of |x|, x finite and not zero, as JDK 17 finds them. */
static void java_digits(double x, int compat, jdigits *r)
{
    uint64_t bits;

    memcpy(&bits, &x, sizeof bits);
    fd_dtoa(bits & ~(UINT64_C(1) << 63), compat, r);
}

/* Spelled as FloatingDecimal's getChars: every digit it found is shown. */
size_t pt_jnum_dtoa(char *buf, double x)
{
    jdigits r;
    size_t len = 0;
    int k, e;

    if (isnan(x)) { strcpy(buf, "NaN"); return 3; }
    if (signbit(x)) buf[len++] = '-';
    if (isinf(x)) { strcpy(buf + len, "Infinity"); return len + 8; }
    if (x == 0.0) { strcpy(buf + len, "0.0"); return len + 3; }
    java_digits(x, 1, &r);
    if (r.dexp > 0 && r.dexp < 8) {              /* 1 <= |x| < 1e7: ddd.ddd */
        for (k = 0; k < r.dexp; k++) buf[len++] = k < r.n ? r.d[k] : '0';
        buf[len++] = '.';
        if (r.n <= r.dexp) buf[len++] = '0';
        for (k = r.dexp; k < r.n; k++) buf[len++] = r.d[k];
    } else if (r.dexp <= 0 && r.dexp > -3) {     /* 1e-3 <= |x| < 1: 0.00ddd */
        buf[len++] = '0';
        buf[len++] = '.';
        for (k = r.dexp; k < 0; k++) buf[len++] = '0';
        for (k = 0; k < r.n; k++) buf[len++] = r.d[k];
    } else {                                     /* d.dddE-n */
        buf[len++] = r.d[0];
        buf[len++] = '.';
        if (r.n == 1) buf[len++] = '0';
        for (k = 1; k < r.n; k++) buf[len++] = r.d[k];
        e = r.dexp - 1;
        buf[len++] = 'E';
        if (e < 0) { buf[len++] = '-'; e = -e; }
        if (e >= 100) buf[len++] = (char)('0' + e / 100);
        if (e >= 10) buf[len++] = (char)('0' + e / 10 % 10);
        buf[len++] = (char)('0' + e % 10);
    }
    buf[len] = '\0';
    return len;
}

/* ===== Formatter's %f ===== */

size_t pt_jnum_f(char *buf, double x, int width, int prec, unsigned flags)
{
    char body[PT_JNUM_LEN], dig[24];
    size_t len = 0, k;
    int n, e, i, neg = signbit(x) != 0;

    if (isnan(x)) { strcpy(body, "NaN"); len = 3; }
    else {
        if (neg) body[len++] = '-';
        else if (flags & PT_JNUM_SPACE) body[len++] = ' ';
        if (isinf(x)) { strcpy(body + len, "Infinity"); len += 8; }
        else {
            /* r[0..nr): the digits of |x| from 10^top down to 10^-prec */
            char r[PT_JNUM_LEN];
            int top, nr;

            jdigits jd;

            n = 0;
            e = 0;
            if (x != 0.0) {                      /* Formatter's digits: not compat */
                java_digits(x, 0, &jd);
                n = jd.n;
                e = jd.dexp - 1;
                memcpy(dig, jd.d, (size_t)n);
            }
            top = e > 0 ? e : 0;
            nr = top + 1 + prec;
            for (i = 0; i < nr; i++) {           /* digit of 10^(top - i) */
                int pos = e - (top - i);         /* its index in dig */
                r[i] = pos >= 0 && pos < n ? dig[pos] : '0';
            }
            /* half up: look at the first digit dropped, 10^-(prec+1) */
            i = e - (top - nr);
            if (n > 0 && i >= 0 && i < n && dig[i] >= '5') {
                for (i = nr - 1; i >= 0; i--) {
                    if (r[i] != '9') { r[i]++; break; }
                    r[i] = '0';
                }
                if (i < 0) {                     /* 9.99 -> 10.00 */
                    memmove(r + 1, r, (size_t)nr);
                    r[0] = '1';
                    nr++;
                    top++;
                }
            }
            for (i = 0; i <= top; i++) body[len++] = r[i];
            if (prec > 0) {
                body[len++] = '.';
                for (i = top + 1; i < nr; i++) body[len++] = r[i];
            }
        }
    }
    k = 0;
    while ((int)(len + k) < width) buf[k++] = ' ';
    memcpy(buf + k, body, len);
    buf[k + len] = '\0';
    return k + len;
}
