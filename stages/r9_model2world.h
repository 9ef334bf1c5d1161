/*
** stages/r9_model2world.h -- renderer 9, stage 1: model -> world (the position's matrix)
** See LICENSE for copyright and license.
**
** in : (x_m, y_m, z_m, w_m)  the model's vertex (w_m = 1 from the scene)
** out: (x_w, y_w, z_w, w_w)  world coordinates
**   v_w = M v_m: x_w = (M00*x_m) + (M01*y_m) + (M02*z_m) + (M03*w_m), ...
** M is the Position's Matrix (r9_matrix.h: the scene's matrix lines applied
** to the identity), kept as column vectors; Matrix.times(Vertex) sums each
** row left to right with all four products (Matrix.java:314-318), so a
** `+ 0*y` term turns -0.0 into +0.0 and an infinite coordinate times a 0
** entry gives NaN.  w_w is computed too (a `rows` matrix can change it);
** World2View resets it to 1.
**      | M00 M01 M02 M03 | |x_m|     column vectors: M = [c1 c2 c3 c4],
**      | M10 M11 M12 M13 | |y_m|     v_w = c1*x_m + c2*y_m + c3*z_m + c4*w_m
**      | M20 M21 M22 M23 | |z_m|     summed row by row, left to right
**      | M30 M31 M32 M33 | |w_m|
*/
#ifndef PT_R9_MODEL2WORLD_H
#define PT_R9_MODEL2WORLD_H
#include "rv_model.h"
#include "r9_matrix.h"
/* m times v_m, as above.  This function can't fail. */
pt_vec4 pt_r9_model2world(pt_vec4 v_m, const pt_jmat *m);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_r9_model2world_all(pt_vec4 *v, size_t n, const pt_jmat *m);
#endif
