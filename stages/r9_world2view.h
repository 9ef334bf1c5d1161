/*
** stages/r9_world2view.h -- renderer 9, stage 2: world -> view (the camera's translation)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_R9_WORLD2VIEW_H
#define PT_R9_WORLD2VIEW_H
#include "rv_model.h"
pt_vec4 pt_r9_world2view(pt_vec4 v, pt_vec3 view);
#endif
