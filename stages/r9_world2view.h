/*
** stages/r9_world2view.h -- renderer 9, stage 2: world -> view (the camera's translation)
** See LICENSE for copyright and license.
**
** in : (x_w, y_w, z_w, w_w)  world coordinates
** out: (x_v, y_v, z_v, 1)    view coordinates: the camera moved to the origin
**   x_v = (-1*e_x) + x_w    y_v = (-1*e_y) + y_w    z_v = (-1*e_z) + z_w
** e is the camera's view vector (camera.translate(x, y, z) replaces it; 0 by
** default).  Moving the camera by e is moving the world by -e.  Java:
** World2View.java:39-52, negViewVector = viewVector.times(-1) (each -1*e
** exact), then negViewVector.plus(v) = new Vertex(n.x + v.x, n.y + v.y,
** n.z + v.z): the three-argument constructor, so w becomes 1.0 again whatever
** stage 1 gave (a `rows` matrix with a w row shows only in stage 1).
**      world:  o(e) ---> *          view:  o(0) ---> * - e
*/
#ifndef PT_R9_WORLD2VIEW_H
#define PT_R9_WORLD2VIEW_H
#include "rv_model.h"
/* v - view as above, w = 1.  This function can't fail. */
pt_vec4 pt_r9_world2view(pt_vec4 v, pt_vec3 view);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_r9_world2view_all(pt_vec4 *v, size_t n, pt_vec3 view);
#endif
