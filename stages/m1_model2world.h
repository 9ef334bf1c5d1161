/*
** stages/m1_model2world.h -- matrix camera: model coordinates -> world coordinates
** See LICENSE for copyright and license.
**
** in : (x_m, y_m, z_m)        a vertex in its model's coordinates
** out: (x_w, y_w, z_w, w_w)   the same point in world coordinates
**   (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World
** World is the product of the model's `world` lines in file order, then its
** `translate`: World = M_1 * M_2 * ... * T (row vectors: M_1 acts first).  A
** translation sits in the last row, which the w = 1 of a point picks up:
**
**   (x y z 1) | 1  0  0  0 |  = (x + t_x, y + t_y, z + t_z, 1)
**             | 0  1  0  0 |
**             | 0  0  1  0 |
**             |t_x t_y t_z 1|
**
** A translation that cancels most of a coordinate (x_m = 1000000000.1,
** t_x = -1e9) is flagged `cancellation`, as in the classic camera stage.
** docs/cameras.md#world.
*/
#ifndef PT_M1_MODEL2WORLD_H
#define PT_M1_MODEL2WORLD_H

#include "pt_mat4.h"

/* Return (m, 1) * world and report the world record to sink (may be NULL).
** This function can't fail. */
pt_vec4 pt_model2world(pt_vec3 m, const pt_mat4 *world, const pt_sink *sink);

#endif
