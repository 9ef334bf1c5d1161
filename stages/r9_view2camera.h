/*
** stages/r9_view2camera.h -- renderer 9, stage 3: view -> camera (the normalize matrix)
** See LICENSE for copyright and license.
**
** in : (x_v, y_v, z_v, 1)  view coordinates, view rectangle l..r, b..t
** out: (x_c, y_c, z_c, w)  camera coordinates, the rectangle -1..1
**   v_c = N v_v,  N = m2.times(m1)   (m1 first, then m2)
**   perspective:  m1 = skew, column 3 = ((r+l)/2, (t+b)/2, 1, 0)
**   orthographic: m1 = translate, column 4 = (-(r+l)/2, -(t+b)/2, 0, 1)
**   m2 = diag(2/(r-l), 2/(t-b), 1, 1)
** The same map as renderer 7's View2Camera (r7_view2camera.h), built as a
** matrix: PerspectiveNormalizeMatrix / OrthographicNormalizeMatrix.build
** (Java sources :110-128, :66-84), rebuilt on every getNormalizeMatrix().
** Each entry of N is itself a 4-term row sum with `+ 0*...` terms, and
** v_c = N v_v another, so x_c = ((2/(r-l))*x + 0*y) + N02*z + N03*w with
** N02 = (2/(r-l))*((r+l)/2) rounded once more: renderer 7 and 9 differ in
** the last bits for asymmetric volumes (NOTES section 3).
*/
#ifndef PT_R9_VIEW2CAMERA_H
#define PT_R9_VIEW2CAMERA_H
#include "rv_model.h"
#include "r9_matrix.h"
/* N for cam (its perspective, l, r, b, t).  This function can't fail. */
pt_jmat pt_r9_normalize_matrix(const pt_rv_camera *cam);
/* norm times v.  This function can't fail. */
pt_vec4 pt_r9_view2camera(pt_vec4 v, const pt_jmat *norm);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_r9_view2camera_all(pt_vec4 *v, size_t n, const pt_jmat *norm);
#endif
