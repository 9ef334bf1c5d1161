/*
** stages/r9_view2camera.h -- renderer 9, stage 3: view -> camera (the normalize matrix)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_R9_VIEW2CAMERA_H
#define PT_R9_VIEW2CAMERA_H
#include "rv_model.h"
#include "r9_matrix.h"
pt_jmat pt_r9_normalize_matrix(const pt_rv_camera *cam);
pt_vec4 pt_r9_view2camera(pt_vec4 v, const pt_jmat *norm);
#endif
