/*
** src/core/numparse.h -- decimal text -> the nearest double, fast for ordinary numbers
** See LICENSE for copyright and license.
**
** The scene parser reads three numbers a vertex; strtod() spent most of the
** parse in its multiprecision path.  pt_parse_decimal() checks the scene
** format's decimal syntax and converts in the same pass, exactly:
**
**   fast path (Clinger 1990): at most 19 significant digits, giving a mantissa
**     m <= 2^53, and a power of ten 10^k with |k| <= 22: m and 10^k are both
**     doubles exactly, so the one IEEE multiplication or division m * 10^k,
**     m / 10^k rounds once, to the nearest double, as the exact value would.
**     Also m * 10^k for 22 < k <= 22 + 15 when m * 10^(k-22) stays an exact
**     integer below 2^53 (then times 1e22, one rounding).  Zero keeps its sign.
**   every other number (more digits, larger powers, subnormals, halfway
**     cases near them): strtod(), which is exact in glibc and musl.
**
** So the result is strtod()'s, bit for bit; tests/unit/test_numparse.c compares the
** two on random and adversarial strings (a sample in `make test`, millions
** in `make bench`).  Needs FLT_EVAL_METHOD == 0 (SSE2 doubles, no x87 excess
** precision); elsewhere every number takes the strtod() path.
*/
#ifndef PT_NUMPARSE_H
#define PT_NUMPARSE_H

#include <stddef.h>

/* Parse p[0..n) (need not be NUL-terminated), which must match
**     [+-]?(digits[.digits*]|.digits)([eE][+-]?digits)?
** in full, into *out: the double nearest its value (ties to even), +-inf when
** it is too large, as strtod() gives.  Returns 0; -1 when the text does not
** match (nothing stored); -2 when out of memory (a number of 128 bytes or
** more needs a copy for strtod()).  "C" locale rules: '.' is the point. */
int pt_parse_decimal(const char *p, size_t n, double *out);

#endif
