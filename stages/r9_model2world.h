/*
** stages/r9_model2world.h -- renderer 9, stage 1: model -> world (the position's matrix)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_R9_MODEL2WORLD_H
#define PT_R9_MODEL2WORLD_H
#include "rv_model.h"
#include "r9_matrix.h"
pt_vec4 pt_r9_model2world(pt_vec4 v_m, const pt_jmat *m);
#endif
