/*
** stages/rv_project.h -- renderers 7 and 9: camera -> image plane (projection)
** See LICENSE for copyright and license.
**
** in : (x_c, y_c, z_c)  camera coordinates, normalized view volume
** out: (x_p, y_p, z_p)  the image plane; the view rectangle is -1..1
**   perspective:  x_p = x_c / -z_c   y_p = y_c / -z_c   z_p = -1
**   orthographic: x_p = x_c          y_p = y_c          z_p = 0
** Similar triangles: a point at depth -z_c seen from the origin crosses the
** plane z = -1 at (x_c/-z_c, y_c/-z_c).  Java: Projection.java:86-121 maps
** every vertex, used or not (behind the near plane too: z_c = 0 gives
** infinities or NaN); renderer 9 ignores w and its new Vertex has w = 1.
**            y                         * (x_c, z_c)
**            |  z = -1     ___-----
**      o-----+------___----         -z
**            |  x_p = x_c / -z_c
*/
#ifndef PT_RV_PROJECT_H
#define PT_RV_PROJECT_H
#include "rv_model.h"
/* v projected, as above; w = 1.  This function can't fail. */
pt_vec4 pt_rv_project(pt_vec4 v, int perspective);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_rv_project_all(pt_vec4 *v, size_t n, int perspective);
#endif
