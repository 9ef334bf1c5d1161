/*
** stages/pt_jmath.h -- Java's Math.atan, bit for bit
** See LICENSE for copyright and license.
**
** The course's renderers 7 and 9 log a camera's fovy as
**   fovy = (180/PI)*Math.atan(top) + (180/PI)*Math.atan(-bottom)
** and on JDK 17 (HotSpot, x86_64) Math.atan is StrictMath.atan: fdlibm's
** s_atan.c, correct to within 1 ulp but not always to the nearest, so the C
** library's atan (glibc's is correctly rounded) differs from it in the last
** bit for some arguments, and the log's fovy with it.  pt_jmath_atan is
** fdlibm's algorithm step for step, in the order it computes:
**   |x| >= 2^66: +-(atanhi[3] + atanlo[3]); NaN stays NaN
**   |x| <  2^-29: x itself (+-0 and subnormals too)
**   |x| <  7/16: t = x,                       atan = t - t*(s1 + s2)
**   else reduce |x| to t and a table entry i:
**     7/16  <= |x| < 11/16: t = (2|x| - 1)/(2 + |x|)    i = 0 (atan(1/2))
**     11/16 <= |x| < 19/16: t = (|x| - 1)/(|x| + 1)     i = 1 (atan(1))
**     19/16 <= |x| < 39/16: t = (|x| - 1.5)/(1 + 1.5|x|) i = 2 (atan(3/2))
**     39/16 <= |x| < 2^66:  t = -1/|x|                  i = 3 (atan(inf))
**     atan = +-(atanhi[i] - ((t*(s1 + s2) - atanlo[i]) - t))
**   with z = t*t, w = z*z and the odd polynomial aT[0..10] split in two,
**     s1 = z*(aT0 + w*(aT2 + w*(aT4 + w*(aT6 + w*(aT8 + w*aT10)))))
**     s2 = w*(aT1 + w*(aT3 + w*(aT5 + w*(aT7 + w*aT9))))
** The thresholds test the high 32 bits of x, as fdlibm does.  Constants:
** fdlibm 5.3 s_atan.c (also java.lang.FdLibm.Atan).  tests/unit/test_jmath.c
** checks it against values Java printed (tests/data/jmath/).
*/
#ifndef PT_JMATH_H
#define PT_JMATH_H

/* Java's StrictMath.atan(x) (= Math.atan(x) on JDK 17 HotSpot x86_64), the
** same double for every x.  This function can't fail. */
double pt_jmath_atan(double x);

#endif
