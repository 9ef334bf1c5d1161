/*
** stages/rv_nearclip.h -- renderers 7 and 9: clip the camera-space model at the near plane z = n
** See LICENSE for copyright and license.
**
** in/out: camera coordinates.  n = camera.n: -0.1 perspective, +1 ortho,
** -N after changeNear(N) (nothing checks its sign).  Per primitive in order
** (NearClip_Line.java:49-193, NearClip_Point.java:38-62):
**   both z <= n: keep ("Trivial accept"; on the plane counts as visible)
**   both z >  n: drop ("Trivial delete"); a point: keep iff z <= n
**   else: t = (n - z1)/(z0 - z1)            t runs from v1 (0) to v0 (1)
**         x = (1 - t)*x1 + t*x0,  y likewise,  z = n
**         t_ = (float)t;  r = (1 - t_)*r1 + t_*r0   in float (g, b too)
**   the end with z0 > n (else v1: a NaN z cuts v1) is replaced by the new
**   vertex and colour, appended to the lists even if equal to an old one.
**        z0 > n  *                    near plane z = n
**                 \  <- cut off   ----------o---------  o = (1-t) v1 + t v0
**                  \                         \
**                                              * v1 (z1 <= n, kept)
** Solving z1 + t(z0 - z1) = n for t gives the formula; colours use Java's
** float[] components (getRGBColorComponents), not the 8-bit ints.
*/
#ifndef PT_RV_NEARCLIP_H
#define PT_RV_NEARCLIP_H
#include "rv_model.h"
/* Clip m's primitives at z = n in place: new vertices and colours appended,
** the primitive list replaced; ls (may be NULL) hears each primitive, each
** trivial verdict and each cut.  0; -1 when out of memory, -2 when a new
** colour is one java.awt.Color refuses (the course's render throws): m's
** primitive list then holds what was kept so far. */
int pt_rv_nearclip(pt_rv_model *m, double n, const pt_rv_clip_ls *ls);
#endif
