/*
** src/io/numfmt.h -- numbers as text: shortest round-trip, fixed decimals, integers
** See LICENSE for copyright and license.
*/
#ifndef PT_NUMFMT_H
#define PT_NUMFMT_H

#include <stddef.h>
#include <stdint.h>

#define PT_NUMLEN 40             /* room for any number these functions write */
#define PT_SHORTLEN 24           /* the longest pt_fmt_shortest() spelling, NUL
                                 ** not counted: "-2.2250738585072014e-308" */

/* Write the shortest decimal that reads back (strtod) to exactly x, as "%g"
** would spell it ("0.1", "-1", "1e+300", "5e-324"); non-finite x as "nan",
** "inf", "-inf".  buf has PT_NUMLEN bytes.  Returns the length.  Can't fail. */
size_t pt_fmt_shortest(char *buf, double x);

/* Write x with prec digits after the point ("%.*f"), or in "%.*e" form when
** |x| >= 1e15; non-finite as above.  0 <= prec <= 17.  Returns the length.
** Can't fail. */
size_t pt_fmt_fixed(char *buf, double x, int prec);

/* Write x's decimal digits at buf (20 bytes at most; no NUL: the writers put
** them in place in a longer line).  Returns the length.  Can't fail. */
size_t pt_fmt_u64(char *buf, uint64_t x);

/* The number of digits pt_fmt_u64() writes for x.  Can't fail. */
size_t pt_fmt_ulen(uint64_t x);

#endif
