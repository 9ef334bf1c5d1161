/*
** src/io/jnum.h -- doubles as Java prints them: Double.toString and Formatter's %f
** See LICENSE for copyright and license.
**
** The course's renderers log their numbers through Java 17, so a log written
** to be compared with them byte for byte spells them as JDK 17 does:
**   - Double.toString: the digits of the old FloatingDecimal (JDK 19 and
**     later print the shortest decimal that reads back; JDK 17 often does
**     too, but not always: 2^-31 is 4.6566128730773926E-10, 1e23 is
**     9.999999999999999E22, 2^60 is 1.15292150460684698E18).  Plain "123.45"
**     for 1e-3 <= |x| < 1e7, else "1.2345E-5"; always a digit after the
**     point: "1.0", "1.0E10".
**   - java.util.Formatter's "%W.Pf": FloatingDecimal's digits (at least two)
**     rounded half up at P decimals (0.125 -> "0.13" with P = 2, where C's
**     printf gives "0.12": it rounds the exact binary value, 0.125 exactly,
**     to even).
** The algorithm is in jnum.c; tests/unit/test_jnum.c holds it to what JDK 17
** printed.
*/
#ifndef PT_JNUM_H
#define PT_JNUM_H

#include <stddef.h>

#define PT_JNUM_LEN 400          /* room for any number these functions write
                                 ** (a "%.17f" of 1e308 has 327 characters) */

/* Flags of pt_jnum_f(). */
#define PT_JNUM_SPACE 0x01u      /* Formatter's ' ' flag: a space before a
                                 ** number that is not negative */

/* Write Double.toString(x): "NaN", "Infinity", "-0.0", "0.001", "1.0E-4",
** "1.0E7".  buf has PT_JNUM_LEN bytes.  Returns the length.  Can't fail. */
size_t pt_jnum_dtoa(char *buf, double x);

/* Write String.format("%W.Pf", x) (width W >= 0, 0 <= P <= 30, flags
** PT_JNUM_*) as Java writes it, right-aligned in W characters; "NaN" and
** "Infinity" as Java spells them.  buf has PT_JNUM_LEN bytes.  Returns the
** length.  Can't fail. */
size_t pt_jnum_f(char *buf, double x, int width, int prec, unsigned flags);

#endif
