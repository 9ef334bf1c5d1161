/*
** stages/r7_model2view.h -- renderer 7, stage 1: model -> view (the position's translation)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_R7_MODEL2VIEW_H
#define PT_R7_MODEL2VIEW_H
#include "rv_model.h"
pt_vec4 pt_r7_model2view(pt_vec4 v_m, pt_vec3 t);
#endif
