/*
** stages/r7_view2camera.h -- renderer 7, stage 2: view -> camera (normalize the view volume)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_R7_VIEW2CAMERA_H
#define PT_R7_VIEW2CAMERA_H
#include "rv_model.h"
pt_vec4 pt_r7_view2camera(pt_vec4 v, const pt_rv_camera *cam);
#endif
