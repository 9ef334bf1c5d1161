/*
** src/io/numfmt.h -- doubles as text: shortest round-trip, and fixed decimals
** See LICENSE for copyright and license.
*/
#ifndef PT_NUMFMT_H
#define PT_NUMFMT_H

#include <stddef.h>

#define PT_NUMLEN 40             /* room for any number these functions write */

/* Write the shortest decimal that reads back (strtod) to exactly x, as "%g"
** would spell it ("0.1", "-1", "1e+300", "5e-324"); non-finite x as "nan",
** "inf", "-inf".  buf has PT_NUMLEN bytes.  Returns the length.  Can't fail. */
size_t pt_fmt_shortest(char *buf, double x);

/* Write x with prec digits after the point ("%.*f"), or in "%.*e" form when
** |x| >= 1e15; non-finite as above.  0 <= prec <= 17.  Returns the length.
** Can't fail. */
size_t pt_fmt_fixed(char *buf, double x, int prec);

#endif
