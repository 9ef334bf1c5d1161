/*
** stages/r7_model2view.h -- renderer 7, stage 1: model -> view (the position's translation)
** See LICENSE for copyright and license.
**
** in : (x_m, y_m, z_m)  the model's vertex
** out: (x_v, y_v, z_v)  view coordinates (camera at the origin, looking down -z)
**   x_v = t_x + x_m     y_v = t_y + y_m     z_v = t_z + z_m
** Java: Model2View.java:40-62 adds the Position's translation Vector t with
** Vector.plus(Vertex), new Vertex(t.x + v.x, t.y + v.y, t.z + v.z): t on the
** left (x + y = y + x in IEEE, but -0.0 + 0.0 is +0.0 either way).  The
** translation replaces, it does not accumulate (Position.translate).  Renderer
** 7's Vertex has no w: the result's w is 1.
**
**      model             view
**        +--+     + t     .     +--+
**        |  |    ====>    o-->  |  |   the camera o sits at the origin
**        +--+                   +--+
*/
#ifndef PT_R7_MODEL2VIEW_H
#define PT_R7_MODEL2VIEW_H
#include "rv_model.h"
/* v_m + t, as above.  This function can't fail. */
pt_vec4 pt_r7_model2view(pt_vec4 v_m, pt_vec3 t);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_r7_model2view_all(pt_vec4 *v, size_t n, pt_vec3 t);
#endif
