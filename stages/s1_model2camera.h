/*
** stages/s1_model2camera.h -- model coordinates -> camera coordinates
** See LICENSE for copyright and license.
**
** in : (x_m, y_m, z_m)   a vertex in its model's own coordinates
** out: (x_c, y_c, z_c)   the same point in camera coordinates
**   x_c = x_m + x_t      (x_t, y_t, z_t): the model's translation
**   y_c = y_m + y_t
**   z_c = z_m + z_t
** The camera sits at the origin looking down -z, so placing a model in front of
** it is a translation, usually with z_t < 0.  Full derivation: docs/stages.md#s1.
**
**        y_m                       y_c
**        |  model     + (x_t,y_t,z_t)   |   . model, moved
**        +--- x_m     =========>        +--- x_c   (camera looks down -z_c)
**
** Note: x_m + 0.0 is x_m except that -0.0 becomes +0.0; the stage always adds, so
** a zero translation still gives exactly what the formula gives.
** Warnings: nonfinite (overflow), cancellation (x_m and x_t nearly opposite:
** more than 26 of the 53 bits of x_c are only the operands' rounding error).
*/
#ifndef PT_S1_MODEL2CAMERA_H
#define PT_S1_MODEL2CAMERA_H

#include "pt_stage.h"

/* Return m + t and report the camera record to sink (may be NULL).  Any finite
** or non-finite input is accepted.  This function can't fail. */
pt_vec3 pt_model2camera(pt_vec3 m, pt_vec3 t, const pt_sink *sink);

#endif
